/* libmatheval's syntax under muParser (core/expr_internal.h): every
 * expression of tests/data/expr_compat.tsv (written by tools/expr-compat.c
 * with libmatheval 1.1.11, the parser used before) evaluates as it did;
 * precedence and associativity; the messages; very long and deeply nested
 * expressions are refused or evaluated, never a crash. */
#include "../core/expr_internal.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[] = {"t", "x", "y", "z", "r"};

static double ev5(const char *text, const double *v)
{
    nl_expr *e = NULL;
    double y;
    cr_assert_eq(nl_expr_create("test", text, &e), NL_OK, "%s: %s", text, nl_errmsg());
    cr_assert_null(nl_expr_bind(e, names, 5), "%s", text);
    y = nl_expr_eval(e, v);
    nl_expr_free(e);
    return y;
}

static double ev(const char *text)
{
    double v[5] = {0.7, 0.21, -0.7, 0.25, 0.7};
    return ev5(text, v);
}

/* The same value as libmatheval to 1e-13 relative: equal to the last bit
 * everywhere but asinh and atanh, which libmatheval computed as logarithms
 * (log(x + sqrt(x^2 + 1))) and we take from libm (5e-14 apart at 1.3). */
Test(expr_syntax, as_libmatheval)
{
    FILE *fp = fopen("tests/data/expr_compat.tsv", "r");
    char line[512];
    int n = 0, bad = 0;
    cr_assert_not_null(fp, "tests/data/expr_compat.tsv (run from the source tree)");
    while (fgets(line, sizeof line, fp)) {
        char *tab = strchr(line, '\t'), *p;
        double v[5], want, got;
        if (line[0] == '#' || !tab)
            continue;
        *tab = 0, p = tab + 1;
        for (int i = 0; i < 5; i++)
            v[i] = strtod(p, &p);
        want = strtod(p, &p);
        got = ev5(line, v);
        if (!(got == want || (isnan(got) && isnan(want)) || fabs(got - want) <= 1e-13 * fabs(want))) {
            cr_log_error("%s at t = %g: %.17g, libmatheval %.17g", line, v[0], got, want);
            bad++;
        }
        n++;
    }
    fclose(fp);
    cr_expect_geq(n, 200, "%d values read", n);
    cr_expect_eq(bad, 0, "%d of %d values differ", bad, n);
}

Test(expr_syntax, precedence)
{
    /* libmatheval's grammar: %left '-' '+', %left '*' '/', %left NEG,
     * %left '^' (unary minus below ^, ^ left-associative) */
    cr_expect_eq(ev("-2^2"), -4);
    cr_expect_eq(ev("2^-1"), 0.5);
    cr_expect_eq(ev("2^3^2"), 64);
    cr_expect_eq(ev("2 ^ 3 ^ 2"), 64);
    cr_expect_eq(ev("2^-3^2"), 1.0 / 512);
    cr_expect_eq(ev("2*-3^2"), -18);
    cr_expect_eq(ev("--2"), 2);
    cr_expect_eq(ev("- - -2"), -2);
    cr_expect_eq(ev("2--2"), 4);
    cr_expect_eq(ev("8/2/2"), 2);
    cr_expect_eq(ev("3-2-1"), 0);
    cr_expect_eq(ev("1_pi*pi"), M_1_PI * M_PI);
    cr_expect_eq(ev("e"), M_E);
    cr_expect_eq(ev("log(e)"), 1);
    cr_expect_eq(ev("1e400"), INFINITY);
    cr_expect_eq(ev("1e-400 + t"), 0.7);
    cr_expect_eq(ev("sin (t)"), sin(0.7));
    cr_expect_eq(ev("besselj( 0 , r )"), ev("besselj(0,r)"));
}

static void bad(const char *text, const char *needle)
{
    nl_expr *e = (nl_expr *)1;
    cr_expect_eq(nl_expr_create("expr", text, &e), NL_EINVAL, "%s should be refused", text);
    cr_expect_null(e);
    cr_expect(strstr(nl_errmsg(), needle) != NULL, "%s: \"%s\" should contain \"%s\"", text, nl_errmsg(), needle);
    cr_expect(strchr(nl_errmsg(), '\n') == NULL, "%s: one line", text);
}

Test(expr_syntax, messages)
{
    bad("foo(t)", "unknown function \"foo\" at position 1");
    bad("2*Besselj(0, r)", "unknown function \"Besselj\" at position 3");
    bad("sin t", "function \"sin\" at position 1 takes its arguments in parentheses");
    bad("besselj(1)", "too few arguments");
    bad("exp(1, t)", "too many arguments");
    bad("1, 2", "',' outside the arguments of a function");
    bad("sin(t", "missing parenthesis");
    bad("(t)(t)", "unexpected parenthesis at position 4");
    bad("t t", "unexpected variable at position 3");
    bad("2e", "at position 2");
    bad("t.", "unexpected '.' at position 2");
    bad("", "empty");
    bad("t#2", "unexpected character '#' at position 2");
    bad("t?", "unexpected character '?' at position 2");
}

Test(expr_syntax, model_messages)
{
    nl_model *m = NULL;
    cr_assert_eq(nl_model_parse("expr:besselj(0, q)", &m), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "unknown variable \"q\"") != NULL, "%s", nl_errmsg());
    cr_assert_eq(nl_model_parse("expr:besselj(0, r);nugget=0.1", &m), NL_OK, "%s", nl_errmsg());
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("spectrum:besselk(0.5, 1 + k)", &m), NL_OK, "%s", nl_errmsg());
    nl_model_free(m);
    cr_assert_eq(nl_model_parse("spectrum:gammainc(2, t)", &m), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "unknown variable \"t\"") != NULL, "%s", nl_errmsg());
}

/* n copies of `open`, then `mid`, then n copies of `close`. */
static char *nest(const char *open, const char *mid, const char *close, size_t n)
{
    size_t lo = strlen(open), lc = strlen(close), lm = strlen(mid);
    char *s = malloc(n * (lo + lc) + lm + 1), *p = s;
    cr_assert_not_null(s);
    for (size_t i = 0; i < n; i++, p += lo)
        memcpy(p, open, lo);
    memcpy(p, mid, lm), p += lm;
    for (size_t i = 0; i < n; i++, p += lc)
        memcpy(p, close, lc);
    *p = 0;
    return s;
}

/* muParser parses with explicit stacks (no recursion): deep nesting costs
 * memory, not the C stack; past 20000 characters of rewritten text it
 * refuses the expression as too long. */
Test(expr_syntax, hostile_sizes)
{
    static const size_t depth[] = {1000, 5000, 100000, 1000000};
    nl_expr *e = NULL;
    double v[5] = {0.3, 0, 0, 0, 0.3};
    for (size_t i = 0; i < sizeof depth / sizeof *depth; i++) {
        char *s = nest("(", "t", ")", depth[i]);
        int st = nl_expr_create("expr", s, &e);
        if (depth[i] <= 5000) {
            cr_expect_eq(st, NL_OK, "depth %zu: %s", depth[i], nl_errmsg());
            cr_expect_null(nl_expr_bind(e, names, 5));
            cr_expect_eq(nl_expr_eval(e, v), 0.3);
        } else {
            cr_expect_eq(st, NL_EINVAL, "depth %zu", depth[i]);
            cr_expect(strstr(nl_errmsg(), "too long") != NULL, "%s", nl_errmsg());
        }
        nl_expr_free(e), e = NULL;
        free(s);
        s = nest("sin(", "t", ")", depth[i]);
        st = nl_expr_create("expr", s, &e);
        cr_expect_eq(st, depth[i] <= 1000 ? NL_OK : NL_EINVAL, "sin depth %zu: %s", depth[i], nl_errmsg());
        nl_expr_free(e), e = NULL;
        free(s);
        s = nest("-", "t", "", depth[i]);
        cr_expect_eq(nl_expr_create("expr", s, &e), NL_OK, "%zu signs", depth[i]);
        nl_expr_free(e), e = NULL;
        free(s);
    }
}
