/* Removable singularities of expression models taken as limits
 * (core/expr_limit.c) where every user meets them, nl_model_acf and
 * nl_model_spectrum; refused where no limit exists; R''(0) of expressions
 * by extrapolated differences. */
#include "../analysis/check.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

static nl_model *parse_ok(const char *spec)
{
    nl_model *m = NULL;
    cr_assert_eq(nl_model_parse(spec, &m), NL_OK, "%s: %s", spec, nl_errmsg());
    return m;
}

static double r_at(const char *spec, int dim, const double *lag)
{
    nl_model *m = parse_ok(spec);
    double y = nl_model_acf(m, dim, lag);
    nl_model_free(m);
    return y;
}

/* The limit within 1e-10 relative, in 1, 2 and 3 dimensions, at the
 * origin (the measured errors are below 1e-11: Richardson's tableau on
 * steps 2^-k removes the powers of h; what is left is the rounding of the
 * expression near 0, 1e-16 / h^2 relative for 1 - cos h). */
static void limit(const char *spec, double want)
{
    static const double zero[3] = {0, 0, 0};
    for (int dim = 1; dim <= 3; dim++) {
        double got = r_at(spec, dim, zero);
        cr_expect(fabs(got - want) <= 1e-10 * fabs(want), "%s in %dD: R(0) = %.17g, expected %.17g", spec, dim, got,
                  want);
    }
}

Test(expr_limit, removable)
{
    limit("expr:sin(r)/r", 1);
    limit("expr:sin(t)/t", 1);
    limit("expr:(1-cos(r))/r^2", 0.5);
    limit("expr:r^2/(1-exp(-r^2))", 1);
    limit("expr:(1-exp(-r))/r", 1);
    limit("expr:sin(1000*r)/(1000*r)", 1);     /* feature at 1e-3: found by the decade scan */
    limit("expr:sin(r/1000)/(r/1000)", 1);     /* feature at 1e3 */
    limit("expr:r*besselk(1, r)", 1);           /* x K_1(x) -> 1, with an h^2 log h term */
    limit("expr:r^1.5*besselk(1.5, r)", sqrt(2) * tgamma(1.5)); /* 2^(nu-1) Gamma(nu) */
    limit("expr:2*besselj(1, r)/r", 1);
    limit("expr:sin(r)/r*exp(-(r/0.001)^2)", 1); /* 0 (underflow) at steps above 1e-2 */
    limit("expr:0*t/t + 2", 2);
    /* a jump only at the singular point: the nugget is added after */
    {
        double zero = 0;
        cr_expect(fabs(r_at("expr:sin(r)/r;nugget=0.25", 1, &zero) - 1.25) < 1e-10);
    }
}

Test(expr_limit, away_from_origin)
{
    /* sin(x - 1)/(x - 1) is singular on the line x = 1 in 2D */
    double lag[2] = {1, 0.4}, y = r_at("expr:sin(x-1)/(x-1)*exp(-y^2)", 2, lag);
    cr_expect(fabs(y - exp(-0.16)) < 1e-10 * exp(-0.16), "%.17g", y);
}

Test(expr_limit, no_limit)
{
    static const double zero[3] = {0, 0, 0};
    static const char *const none[] = {"expr:1/r", "expr:sin(1/r)", "expr:x/abs(x)", "expr:log(r)",
                                       "expr:exp(1/r)"};
    for (size_t i = 0; i < sizeof none / sizeof *none; i++)
        for (int dim = 1; dim <= 3; dim++)
            cr_expect(!isfinite(r_at(none[i], dim, zero)), "%s in %dD: %g", none[i], dim, r_at(none[i], dim, zero));
    /* r log r -> 0, but slowly (h log h defeats the extrapolation): no
     * limit found, or 0; never f(1/2) = f(1/4) = -0.3466, where a tableau
     * that compares each entry with two neighbours only meets itself */
    {
        double y = r_at("expr:r*log(r)", 1, zero);
        cr_expect(isnan(y) || fabs(y) < 1e-6, "%.17g", y);
    }
    /* depends on the direction of approach: none in 2D */
    cr_expect(isnan(r_at("expr:x^2/(x^2+y^2)", 2, zero)));
}

Test(expr_limit, spectrum)
{
    nl_model *m = parse_ok("spectrum:(sin(k)/k)^2");
    double f0[3] = {0, 0, 0};
    for (int dim = 1; dim <= 3; dim++)
        cr_expect(fabs(nl_model_spectrum(m, dim, f0) - 1) < 1e-10, "%dD: %.17g", dim, nl_model_spectrum(m, dim, f0));
    nl_model_free(m);
    m = parse_ok("spectrum:1/k^2");
    cr_expect(isinf(nl_model_spectrum(m, 2, f0)));
    nl_model_free(m);
}

/* check takes the limit (it refused sin(r)/r: "R(0) is not a finite
 * number") and still refuses 1/r. */
Test(expr_limit, check)
{
    nl_model *m = parse_ok("expr:sin(r)/r");
    nl_check c;
    cr_expect_eq(nl_check_model(m, 1, &c), NL_OK, "%s", nl_errmsg());
    cr_expect(fabs(c.variance - 1) < 1e-10);
    nl_model_free(m);
    m = parse_ok("expr:1/r");
    cr_expect_eq(nl_check_model(m, 1, &c), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "not a finite number") != NULL, "%s", nl_errmsg());
    nl_model_free(m);
}

/* R''(0) by extrapolated central differences, against closed forms:
 * -2 for exp(-t^2) and 1/(1+t^2), -1/3 for sin(t)/t, -2 for
 * cos(t) exp(-t^2/2), -2e-6 for exp(-(t/1000)^2); 1e-9 relative (measured:
 * below 1e-11; the rounding of R(0) over h^2 bounds it); NAN at a kink. */
Test(expr_limit, second_derivative)
{
    static const struct {
        const char *spec;
        double d2;
    } cases[] = {{"expr:exp(-t^2)", -2},        {"expr:1/(1+r^2)", -2},
                 {"expr:sin(r)/r", -1.0 / 3},    {"expr:cos(t)*exp(-t^2/2)", -2},
                 {"expr:exp(-(t/1000)^2)", -2e-6}, {"expr:exp(-(t/0.001)^2)", -2e6},
                 {"expr:2*besselj(1, r)/r", -0.25}};
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        nl_model *m = parse_ok(cases[i].spec);
        double d = nl_model_acf_d2(m, 0), d9 = nl_model_acf_d2(m, 4.3e-9);
        cr_expect(fabs(d - cases[i].d2) <= 1e-9 * fabs(cases[i].d2), "%s: %.17g", cases[i].spec, d);
        cr_expect(fabs(d9 - cases[i].d2) <= 1e-9 * fabs(cases[i].d2), "%s at 4.3e-9: %.17g", cases[i].spec, d9);
        nl_model_free(m);
    }
    {
        nl_model *m = parse_ok("expr:exp(-abs(t))");
        cr_expect(isnan(nl_model_acf_d2(m, 0)));
        nl_model_free(m);
    }
}
