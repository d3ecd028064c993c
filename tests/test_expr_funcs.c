/* The expression language (core/expr_internal.h): the special functions
 * against closed forms, GSL called directly and R; libmatheval's syntax,
 * evaluated as libmatheval 1.1.11 did (tests/data/expr_compat.tsv, written
 * by tools/expr-compat.c); the messages; hostile sizes. */
#include "../core/expr_internal.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "gstat.h"

#include <criterion/criterion.h>
#include <gsl/gsl_sf_bessel.h>
#include <gsl/gsl_sf_expint.h>
#include <gsl/gsl_sf_gamma.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The expression in the one variable x at x. */
static double ev(const char *text, double x)
{
    static const char *const names[] = {"x"};
    nl_expr *e = NULL;
    double y;
    cr_assert_eq(nl_expr_create("test", text, &e), NL_OK, "%s: %s", text, nl_errmsg());
    cr_assert_null(nl_expr_bind(e, names, 1), "%s", text);
    y = nl_expr_eval(e, &x);
    nl_expr_free(e);
    return y;
}

/* Relative agreement to tol (|want| below 1e-300: absolute).  The special
 * functions are GSL's, accurate to a few 1e-16 relative where they are
 * not near a zero; the closed forms below lose no more than 1e-15; so
 * 1e-12 leaves room for the identities (reflection formulas) and catches
 * any wrong order, argument or normalisation. */
static void near(const char *text, double x, double want, double tol)
{
    double got = ev(text, x);
    cr_expect(fabs(got - want) <= tol * fmax(fabs(want), 1e-300), "%s at x = %g: %.17g, expected %.17g", text, x,
              got, want);
}

Test(expr_funcs, bessel_closed_forms)
{
    /* DLMF 10.16.1: J_1/2, Y_1/2, J_-1/2; DLMF 10.39.2: K_1/2 */
    for (double x = 0.37; x < 30; x *= 1.9) {
        double c = sqrt(2 / (M_PI * x));
        near("besselj(0.5, x)", x, c * sin(x), 1e-12);
        near("besselj(-0.5, x)", x, c * cos(x), 1e-12);
        near("bessely(0.5, x)", x, -c * cos(x), 1e-12);
        near("bessely(-0.5, x)", x, c * sin(x), 1e-12);
        near("besselk(0.5, x)", x, sqrt(M_PI / (2 * x)) * exp(-x), 1e-12);
        near("besselk(-0.5, x)", x, sqrt(M_PI / (2 * x)) * exp(-x), 1e-12);
        near("besselj(1.5, x)", x, c * (sin(x) / x - cos(x)), 1e-12);
    }
}

Test(expr_funcs, bessel_against_gsl)
{
    static const double nus[] = {0, 1, 2.7, 3.25, 10};
    for (size_t i = 0; i < sizeof nus / sizeof *nus; i++)
        for (double x = 0.123; x < 60; x *= 2.3) {
            char j[64], y[64], k[64];
            snprintf(j, sizeof j, "besselj(%.17g, x)", nus[i]);
            snprintf(y, sizeof y, "bessely(%.17g, x)", nus[i]);
            snprintf(k, sizeof k, "besselk(%.17g, x)", nus[i]);
            /* absolute near the zeros of J and Y (their size is about
             * sqrt(2 / (pi x))) */
            cr_expect(fabs(ev(j, x) - gsl_sf_bessel_Jnu(nus[i], x)) <= 1e-13, "%s at %g", j, x);
            cr_expect(fabs(ev(y, x) - gsl_sf_bessel_Ynu(nus[i], x)) <= 1e-13 * fmax(1, fabs(ev(y, x))), "%s at %g",
                      y, x);
            near(k, x, gsl_sf_bessel_Knu(nus[i], x), 1e-12);
        }
}

Test(expr_funcs, bessel_domains)
{
    /* integer orders: J_n(-x) = (-1)^n J_n(x), J_-n = (-1)^n J_n (DLMF 10.4.1) */
    near("besselj(3, x)", -2.1, -gsl_sf_bessel_Jn(3, 2.1), 1e-14);
    near("besselj(2, x)", -2.1, gsl_sf_bessel_Jn(2, 2.1), 1e-14);
    near("besselj(-3, x)", 2.1, -gsl_sf_bessel_Jn(3, 2.1), 1e-14);
    near("besselj(-3, x)", -2.1, gsl_sf_bessel_Jn(3, 2.1), 1e-14);
    near("bessely(-3, x)", 2.1, -gsl_sf_bessel_Yn(3, 2.1), 1e-14);
    near("besselj(0, x)", 0, 1, 0);
    near("besselj(2.5, x)", 0, 0, 0);
    near("besselk(-2.3, x)", 1.7, gsl_sf_bessel_Knu(2.3, 1.7), 1e-14);
    /* complex, infinite or undefined: NAN (K_nu(0) = +inf for every order) */
    cr_expect(isnan(ev("besselj(0.3, x)", -1)));
    cr_expect(isnan(ev("besselj(-0.3, x)", 0)));
    cr_expect(isnan(ev("bessely(1, x)", 0)));
    cr_expect(isnan(ev("bessely(1, x)", -2)));
    cr_expect(isnan(ev("besselk(1, x)", -2)));
    cr_expect(isinf(ev("besselk(1, x)", 0)));
    cr_expect(isnan(ev("besselj(x, 1)", NAN)));
    /* no abort under GSL's default handler for overflow and huge orders */
    cr_expect(ev("besselk(0.5, x)", 1e5) == 0);
    cr_expect(isinf(ev("besselk(200, x)", 1e-3)));
    cr_expect(fabs(ev("besselj(x, 1)", 1e6)) < 1e-300 || isnan(ev("besselj(x, 1)", 1e6)));
}

Test(expr_funcs, gamma_family)
{
    near("gamma(x)", 0.5, sqrt(M_PI), 1e-14);
    near("gamma(x)", 5, 24, 1e-14);
    near("gamma(x)", -0.5, -2 * sqrt(M_PI), 1e-14);
    near("gamma(x)", 3.7, gsl_sf_gamma(3.7), 1e-14);
    near("lgamma(x)", 100.5, gsl_sf_lngamma(100.5), 1e-14);
    cr_expect(isnan(ev("gamma(x)", 0)));
    cr_expect(isnan(ev("gamma(x)", -2)));
    cr_expect(isinf(ev("gamma(x)", 200)));
    for (double x = 0.05; x < 40; x *= 1.7) {
        /* P(1, x) = 1 - e^-x, P(1/2, x) = erf(sqrt x) (DLMF 8.4.1, 8.4.4 with 7.11.1) */
        near("gammainc(1, x)", x, -expm1(-x), 1e-12);
        near("gammaincc(1, x)", x, exp(-x), 1e-12);
        near("gammainc(0.5, x)", x, erf(sqrt(x)), 1e-12);
        near("gammaincc(0.5, x)", x, erfc(sqrt(x)), 1e-12);
        /* Gamma(0, x) = E_1(x) (DLMF 8.4.4); Gamma(-1/2, x) = 2 e^-x / sqrt x
         * - 2 sqrt(pi) erfc(sqrt x) (DLMF 8.8.2 with 8.4.6) */
        near("gammaupper(0, x)", x, gsl_sf_expint_E1(x), 1e-12);
        near("gammaupper(-0.5, x)", x, 2 * exp(-x) / sqrt(x) - 2 * sqrt(M_PI) * erfc(sqrt(x)), 1e-11);
        near("gammaupper(2.5, x)", x, gsl_sf_gamma_inc_Q(2.5, x) * gsl_sf_gamma(2.5), 1e-12);
    }
    near("gammaupper(2.5, x)", 0, gsl_sf_gamma(2.5), 1e-14);
    cr_expect(isnan(ev("gammainc(0, x)", 1)));
    cr_expect(isnan(ev("gammainc(1, x)", -1)));
    cr_expect(isnan(ev("gammaupper(-1, x)", 0)));
}

Test(expr_funcs, erf_sinc)
{
    near("erf(x)", 0.73, erf(0.73), 0);
    near("erfc(x)", 5.5, erfc(5.5), 0);
    near("sinc(x)", 0, 1, 0);
    near("sinc(x)", 1e-200, 1, 0);
    near("sinc(x)", -2.3, sin(2.3) / 2.3, 1e-15);
}

/* R's besselJ, besselY, besselK, gamma and pgamma (an evaluation
 * independent of GSL), where R is installed. */
Test(expr_funcs, against_r)
{
    static const char *const e[] = {
        "besselj(2.7, x)", "bessely(1.3, x)", "besselk(0.75, x)", "gamma(x)", "gammainc(2.5, x)", "gammaincc(2.5, x)"};
    double v[64];
    long n;
    if (!gstat_available("special functions vs R"))
        return;
    n = gstat_run("x <- c(0.3, 1.7, 4.9, 12.5)\n"
                  "v <- c(besselJ(x, 2.7), besselY(x, 1.3), besselK(x, 0.75), gamma(x), pgamma(x, 2.5),\n"
                  "       pgamma(x, 2.5, lower.tail = FALSE))\n"
                  "cat(sprintf('%.17g', v), sep = '\\n')\n",
                  v, 64);
    cr_assert_eq(n, 24, "R printed %ld numbers", n);
    for (int f = 0; f < 6; f++)
        for (int i = 0; i < 4; i++) {
            static const double xs[] = {0.3, 1.7, 4.9, 12.5};
            near(e[f], xs[i], v[4 * f + i], 1e-12);
        }
}
