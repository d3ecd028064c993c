/* Beckmann's Hermite series against closed forms.
 * - g the identity (target gauss with sd 1): c_1 = 1, the rest 0.
 * - g = Phi (target uniform on (0, 1)): Cov(Phi(Z1), Phi(Z2)) =
 *   arcsin(rho / 2) / (2 pi) for standard Gaussians with correlation rho.
 * - an odd g (hyperbolic) has no even coefficients.
 * Quadrature with 400 nodes of a smooth g is exact to ~1e-12; the series
 * truncated at 40 terms of a bounded g to better than 1e-6 at |rho| <= 0.9. */
#include "../analysis/nonlin.h"
#include "../core/dist.h"
#include "../core/nl_error.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <string.h>

static nl_hermite expand(const char *spec, int K)
{
    nl_dist *d;
    nl_hermite h;
    cr_assert_eq(nl_dist_parse(spec, &d), 0);
    cr_assert_eq(nl_hermite_expand(d, K, &h), 0);
    nl_dist_free(d);
    return h;
}

Test(nonlin, identity)
{
    nl_hermite h = expand("gauss", 12);
    cr_expect_float_eq(h.c[1], 1.0, 1e-10);
    for (int n = 0; n < 12; n++)
        if (n != 1)
            cr_expect_lt(fabs(h.c[n]), 1e-10, "c_%d = %g", n, h.c[n]);
    cr_expect_float_eq(nl_hermite_cov(&h, 0.37), 0.37, 1e-10);
}

Test(nonlin, uniform_closed_form)
{
    nl_hermite h = expand("uniform", 40);
    cr_expect_float_eq(h.c[0], 0.5, 1e-10);
    cr_expect_float_eq(h.variance, 1.0 / 12, 1e-9);
    for (double r = -0.9; r <= 0.9; r += 0.15)
        cr_expect_float_eq(nl_hermite_cov(&h, r), asin(r / 2) / (2 * M_PI), 1e-6, "rho = %g", r);
    cr_expect_float_eq(nl_hermite_invert(&h, asin(0.3) / (2 * M_PI)), 0.6, 1e-6);
}

Test(nonlin, odd_map_has_odd_terms_only)
{
    nl_hermite h = expand("hyperbolic", 24);
    for (int n = 0; n < 24; n += 2)
        cr_expect_lt(fabs(h.c[n]), 1e-9, "c_%d = %g", n, h.c[n]);
    cr_expect_gt(fabs(h.c[3]), 0.01);
    cr_expect_lt(fabs(h.truncation), 1e-6);
}

/* Design: a Markov target after a Laplace shaping is reachable, and the
 * designed input reproduces it after the projection to rounding; an
 * oscillatory target through the one-sided chi2-1 map is not (its strong
 * negative correlations are out of reach), and the design says so.  The
 * round trip through synthesis and measurement is the experiment
 * experiments/fig-design.sh. */
Test(nonlin, design_round_trip)
{
    nl_dist *d;
    nl_hermite h;
    size_t n = 4096;
    double T[4096], rho[4096], err;
    size_t bad;
    cr_assert_eq(nl_dist_parse("laplace", &d), 0);
    cr_assert_eq(nl_hermite_expand(d, 32, &h), 0);
    for (size_t j = 0; j < n; j++) {
        double t = (double)(j <= n / 2 ? j : n - j);
        T[j] = 2.0 * exp(-t / 8);
    }
    cr_assert_eq(nl_nonlin_design(&h, T, n, 1.0, rho, NULL, &err, &bad), 0);
    cr_expect_eq(bad, 0);
    cr_expect_lt(err, 1e-9, "projection error %g", err);
    /* an unreachable target: negative correlation through a one-sided map */
    for (size_t j = 0; j < n; j++) {
        double t = (double)(j <= n / 2 ? j : n - j);
        T[j] = cos(0.3 * t) * exp(-t / 20);
    }
    nl_dist_free(d);
    cr_assert_eq(nl_dist_parse("chi2-1", &d), 0);
    cr_assert_eq(nl_hermite_expand(d, 32, &h), 0);
    cr_assert_eq(nl_nonlin_design(&h, T, n, 1.0, rho, NULL, &err, &bad), 0);
    cr_expect_gt(bad, 0, "chi2-1 cannot produce strongly negative correlations");
    cr_expect_gt(err, 0.05);
    nl_dist_free(d);
}

/* The predicted output ACF scales with r0: acf = r0 rho gives the
 * covariance at rho (to rounding of the division), and the identity (a
 * standard normal target: g(x) = x for unit input variance, c_1 = 1 and
 * every other c_n ~ 0) passes rho through to 1e-9 (the quadrature's
 * error). */
Test(nonlin, output_acf)
{
    nl_dist *d;
    nl_hermite he;
    double rho[5] = {1, 0.7, 0.2385, -0.4, 0}, acf[5], out[5], id[5];
    cr_assert_eq(nl_dist_parse("laplace", &d), 0);
    cr_assert_eq(nl_hermite_expand(d, 24, &he), 0);
    for (int i = 0; i < 5; i++)
        acf[i] = 3.7 * rho[i];
    nl_nonlin_output_acf(&he, acf, 5, 3.7, out);
    for (int i = 0; i < 5; i++)
        cr_assert_float_eq(out[i], nl_hermite_cov(&he, rho[i]), 1e-14);
    nl_dist_free(d);
    cr_assert_eq(nl_dist_parse("gauss", &d), 0);
    cr_assert_eq(nl_hermite_expand(d, 8, &he), 0);
    nl_nonlin_output_acf(&he, rho, 5, 1, id);
    for (int i = 0; i < 5; i++)
        cr_assert_float_eq(id[i], rho[i], 1e-9);
    nl_dist_free(d);
}

/* nl_nonlin_verify through the identity shaping measures the input's own
 * ACF: exp(-|t|/8) on 4096 samples, 16 realizations.  A realization has
 * about 4096 / 16 independent stretches, so an ACF value has a standard
 * error near sqrt(2 / 256) / sqrt(16) = 0.022; 0.1 is 4.5 of them. */
Test(nonlin, verify_identity)
{
    nl_dist *d;
    size_t n = 4096;
    nl_field *S = nl_field_alloc(1, &n, NULL, NULL);
    double meas[17], target[17];
    for (size_t k = 0; k < n; k++) {
        double f = (double)(k <= n / 2 ? k : n - k) / (double)n;
        S->data[k] = 2 * 8.0 / (1 + 4 * M_PI * M_PI * 64 * f * f);  /* the Markov spectrum, scale 8 */
    }
    cr_assert_eq(nl_dist_parse("gauss", &d), 0);
    cr_assert_eq(nl_nonlin_verify(S, d, 16, 17, meas), 0);
    for (int i = 0; i < 17; i++) {
        target[i] = exp(-i / 8.0);
        cr_assert(fabs(meas[i] - target[i]) < 0.1, "lag %d: %g against %g", i, meas[i], target[i]);
    }
    cr_assert_eq(nl_nonlin_max_deviation(meas, target, 17, 1, 1) < 0.1, 1);
    cr_assert_eq(nl_nonlin_max_deviation(target, target, 17, 1, 1), 0);
    nl_field_free(S), nl_dist_free(d);
}

/* Any memoryless nonlinearity (expr:, GI '86 section 4): Beckmann's series
 * against the closed forms of the output covariance at input correlation
 * rho, for a standard Gaussian input:
 *     x^2:     2 rho^2            x^3:  9 rho + 6 rho^3
 *     exp(x):  e (e^rho - 1)      sign: (2/pi) asin(rho)
 * The first three are polynomials or entire with c_n = sqrt(e)/n!, so 24
 * terms leave nothing at |rho| <= 0.9 (exp: e sum_{n>=24} 0.9^n/n! < 1e-23);
 * the adaptive quadrature is good to about 1e-12 relative.  sign's series
 * converges slowly (c_n^2 n! ~ n^-3/2): with 64 terms the tail at
 * |rho| <= 0.7 is below 0.7^64 < 1e-9. */
static double closed(int k, double r)
{
    switch (k) {
    case 0: return 2 * r * r;
    case 1: return 9 * r + 6 * r * r * r;
    case 2: return M_E * (exp(r) - 1);
    default: return 2 / M_PI * asin(r);
    }
}

Test(nonlin, expression_closed_forms)
{
    static const char *const g[] = {"expr:x^2", "expr:x^3", "expr:exp(x)", "expr:2*step(x)-1"};
    for (int k = 0; k < 4; k++) {
        nl_dist *d;
        nl_hermite h;
        double rmax = k == 3 ? 0.7 : 0.9, tol = k == 3 ? 1e-8 : 1e-10;
        cr_assert_eq(nl_dist_parse(g[k], &d), NL_OK, "%s: %s", g[k], nl_errmsg());
        cr_assert(nl_dist_is_function(d));
        cr_assert_eq(nl_hermite_expand(d, k == 3 ? 64 : 24, &h), NL_OK, "%s: %s", g[k], nl_errmsg());
        for (double r = -rmax; r <= rmax + 1e-12; r += 0.05)
            cr_expect(fabs(nl_hermite_cov(&h, r) - closed(k, r)) <= tol * fmax(1, fabs(closed(k, r))),
                      "%s at rho %g: series %.12g, closed form %.12g", g[k], r, nl_hermite_cov(&h, r), closed(k, r));
        nl_dist_free(d);
    }
}

/* The expression is a function, not a distribution: no CDF; g must be
 * finite over the input range. */
Test(nonlin, expression_parsing)
{
    nl_dist *d;
    cr_assert_eq(nl_dist_parse("expr:x^2", &d), NL_OK);
    cr_expect(isnan(nl_dist_cdf(d, 1)) && isnan(nl_dist_quantile(d, 0.5)));
    cr_expect_eq(nl_dist_transform(d, -3), 9.0);
    nl_dist_free(d);
    cr_expect_eq(nl_dist_parse("expr:log(x)", &d), NL_EINVAL, "log is not finite for x <= 0");
    cr_expect(strstr(nl_errmsg(), "expected a function finite"), "%s", nl_errmsg());
    cr_expect_eq(nl_dist_parse("expr:y^2", &d), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "unknown variable \"y\""), "%s", nl_errmsg());
    cr_expect_eq(nl_dist_parse("expr:", &d), NL_EINVAL);
    cr_expect_eq(nl_dist_parse("gauss", &d), NL_OK);
    cr_expect(!nl_dist_is_function(d));
    cr_expect_eq(nl_dist_transform(d, 1.5), nl_dist_quantile(d, gsl_cdf_ugaussian_P(1.5)));
    nl_dist_free(d);
}

/* An even g: g(x) = x^2 of a standard Gaussian has Cov(g(Z1), g(Z2)) =
 * 2 rho^2 (Isserlis), so every output covariance in [0, 2] is reached by
 * rho = sqrt(cov / 2) >= 0, and a negative one by none (the nearest is
 * rho = 0).  A Markov target 2 exp(-t/8) is then met exactly by the input
 * correlation exp(-t/16), itself a valid (Markov) correlation: the design
 * reaches every lag and the projection leaves it alone, to the quadrature's
 * ~1e-12 and the bisection's 2^-100. */
Test(nonlin, design_even_g_closed_form)
{
    nl_dist *d;
    nl_hermite h;
    size_t n = 512, bad = 1;
    double T[512], rho[512], err, worst = 0;
    cr_assert_eq(nl_dist_parse("expr:x^2", &d), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_hermite_expand(d, 16, &h), 0, "%s", nl_errmsg());
    cr_expect_float_eq(nl_hermite_cov(&h, 0.6), 2 * 0.36, 1e-9);
    cr_expect_float_eq(nl_hermite_invert(&h, 0.72), 0.6, 1e-9);
    cr_expect_float_eq(nl_hermite_invert(&h, 2.0), 1.0, 1e-9);
    cr_expect(isnan(nl_hermite_invert(&h, -0.1)), "x^2 gives no negative covariance");
    cr_expect(isnan(nl_hermite_invert(&h, 2.1)), "nor one above its variance 2");
    for (size_t j = 0; j < n; j++) {
        double t = (double)(j <= n / 2 ? j : n - j);
        T[j] = 2.0 * exp(-t / 8);
    }
    cr_assert_eq(nl_nonlin_design(&h, T, n, 1.0, rho, NULL, &err, &bad), 0, "%s", nl_errmsg());
    cr_expect_eq(bad, 0, "%zu lags unreachable", bad);
    cr_expect_lt(err, 1e-9, "projection error %g", err);
    for (size_t j = 0; j < n; j++) {
        double t = (double)(j <= n / 2 ? j : n - j);
        worst = fmax(worst, fabs(rho[j] - exp(-t / 16)));
    }
    cr_expect_lt(worst, 1e-9, "designed rho off exp(-t/16) by %g", worst);
    /* a negative target lag is out of reach; its stand-in is rho = 0
     * (output 0), not rho = -1 (output 2, the far end) */
    T[3] = T[n - 3] = -0.5;
    cr_assert_eq(nl_nonlin_design(&h, T, n, 1.0, rho, NULL, &err, &bad), 0, "%s", nl_errmsg());
    cr_expect_eq(bad, 2);
    cr_expect_lt(err, 0.6, "nearest stand-in keeps the error near 0.5 / 2, got %g", err);
    nl_dist_free(d);
}
