/* Writes tests/data/expr_compat.tsv: expressions of libmatheval's syntax
 * with their values computed by libmatheval 1.1.11 (Debian's
 * libmatheval-dev), the parser noiselab used before muParser, so that
 * tests/test_expr_funcs.c can check that each still evaluates the same.
 * Built and run by hand where libmatheval is installed:
 *   cc tools/expr-compat.c -lmatheval -o /tmp/expr-compat && /tmp/expr-compat > tests/data/expr_compat.tsv */
#include <matheval.h>
#include <math.h>
#include <stdio.h>

static const char *const exprs[] = {
    "-2^2", "2^-1", "2^3^2", "2^-3^2", "t^0.5^2", "-t^-t^-t", "2*-3^2", "1/-2*t", "-(t)^2", "--t", "- - -t",
    "2- -t", "t^--2", "3-2-t", "8/2/t", "exp(-abs(t))*cos(10*t)", "exp(-t^2)", "exp(-(x^2+y^2+z^2))",
    "1/(1+r^2)^1.5", "r^2*exp(-r)", "(1+r+r^2/3)*exp(-r)", "sin (t) + cos(t)", "tan(t)*cot(t)+sec(t)-csc(t)",
    "asin(t/4)+acos(t/4)+atan(t)", "acot(t)+asec(t*2)+acsc(t*2)", "sinh(t)-cosh(t)+tanh(t)",
    "coth(t)+sech(t)+csch(t)", "asinh(t)+acosh(abs(t)+1)+atanh(t/4)", "acoth(t*2)+asech(abs(t)/4)+acsch(t)",
    "sqrt(abs(t))*log(r)", "step(t)+step(-t)", "delta(t)+nandelta(t-1)", "erf(t)", "e^t*pi", "log2e+log10e+ln2+ln10",
    "pi_2*pi_4+1_pi+2_pi*2_sqrtpi", "sqrt2*sqrt1_2*t", "1.5e-3*t+.5+5.+1E2", "((((t))))*(((x)))",
    "x*y-z/(r+1)", "exp(-abs(x)-abs(y)/2)", "cos(10*t)*exp(-abs(t))+0*r - 0*x^2", "t*-t", "-t*-t", "2^-t^2",
};

int main(void)
{
    static const char *const names[] = {"t", "x", "y", "z", "r"};
    static const double ts[] = {0.7, -1.3, 2.5, 1e-3, 3.7};
    printf("# expression\tt\tx\ty\tz\tr\tlibmatheval 1.1.11 (tools/expr-compat.c)\n");
    for (size_t i = 0; i < sizeof exprs / sizeof *exprs; i++) {
        void *ev = evaluator_create((char *)exprs[i]);
        if (!ev) {
            fprintf(stderr, "libmatheval refuses %s\n", exprs[i]);
            return 1;
        }
        for (size_t k = 0; k < sizeof ts / sizeof *ts; k++) {
            double v[5] = {ts[k], 0.3 * ts[k], -ts[k], 0.25, fabs(ts[k])};
            printf("%s\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", exprs[i], v[0], v[1], v[2], v[3], v[4],
                   evaluator_evaluate(ev, 5, (char **)names, v));
        }
        evaluator_destroy(ev);
    }
    return 0;
}
