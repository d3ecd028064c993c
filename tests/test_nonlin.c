/* Beckmann's Hermite series against closed forms.
 * - g the identity (target gauss with sd 1): c_1 = 1, the rest 0.
 * - g = Phi (target uniform on (0, 1)): Cov(Phi(Z1), Phi(Z2)) =
 *   arcsin(rho / 2) / (2 pi) for standard Gaussians with correlation rho.
 * - an odd g (hyperbolic) has no even coefficients.
 * Quadrature with 400 nodes of a smooth g is exact to ~1e-12; the series
 * truncated at 40 terms of a bounded g to better than 1e-6 at |rho| <= 0.9. */
#include "../analysis/nonlin.h"
#include "../core/dist.h"

#include <criterion/criterion.h>
#include <math.h>

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
