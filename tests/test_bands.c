/* The spectrum and histogram bands of analysis/bands.h against closed
 * forms and a slow independent sum. */
#include "../analysis/bands.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>

/* One periodogram ordinate is S chi-square_2 / 2, an exponential: its 95%
 * band is S [-ln 0.975, -ln 0.025] in closed form.  For large nu the band
 * tends to 1 -+ 1.96 sqrt(2 / nu): at nu = 20000 the skew leaves 1e-4. */
Test(bands, chisq_closed_forms)
{
    double lo, hi;
    cr_assert_eq(nl_band_chisq(2, &lo, &hi), NL_OK);
    cr_expect_float_eq(lo, -log(0.975), 1e-12);
    cr_expect_float_eq(hi, -log(0.025), 1e-12);
    cr_assert_eq(nl_band_chisq(20000, &lo, &hi), NL_OK);
    cr_expect_float_eq(lo, 1 - 1.959964 * sqrt(2 / 20000.0), 2e-4);
    cr_expect_float_eq(hi, 1 + 1.959964 * sqrt(2 / 20000.0), 2e-4);
    cr_expect_eq(nl_band_chisq(0, &lo, &hi), NL_EINVAL);
    cr_expect_eq(nl_band_chisq(NAN, &lo, &hi), NL_EINVAL);
}

/* Welch's EDF in closed form: the Hann window sin^2(pi (t + 1/2) / S)
 * overlaps its half-shifted copy by sum sin^2 cos^2 = S/16 against
 * sum sin^4 = 3S/8 (exact discrete sums for S >= 4), rho = (1/6)^2; K
 * segments per axis give sum rho = K + 2 (K - 1) / 36 (a product over
 * the axes in 2D).  One segment has the periodogram's 2. */
Test(bands, welch_edf_closed_form)
{
    size_t n1 = 1024, n2[2] = {256, 160}, one = 64;
    double nu;
    cr_assert_eq(nl_welch_edf(1, &n1, 64, &nu), NL_OK);  /* K = 31 */
    cr_expect_float_eq(nu, 2.0 * 31 * 31 / (31 + 2 * 30 / 36.0), 1e-9, "%g", nu);
    cr_assert_eq(nl_welch_edf(2, n2, 64, &nu), NL_OK);   /* K = 7 x 4 */
    cr_expect_float_eq(nu, 2.0 * 28 * 28 / ((7 + 2 * 6 / 36.0) * (4 + 2 * 3 / 36.0)), 1e-9, "%g", nu);
    cr_assert_eq(nl_welch_edf(1, &one, 64, &nu), NL_OK);
    cr_expect_float_eq(nu, 2, 1e-12);
    cr_expect_eq(nl_welch_edf(1, &one, 128, &nu), NL_EINVAL);
    cr_expect_eq(nl_welch_edf(3, n2, 16, &nu), NL_EINVAL);
}

/* P(x in [a, b), y in [a, b)) for standard Gaussians of correlation r, by
 * Simpson's rule over x of phi(x) P(y in [a, b) | x) on 4000 intervals
 * (the integrand is smooth: error far below 1e-10). */
static double both_in(double a, double b, double r)
{
    double s = sqrt(1 - r * r), lo = fmax(a, -9), hi = fmin(b, 9), dx = (hi - lo) / 4000, sum = 0;
    for (int i = 0; i <= 4000; i++) {
        double x = lo + i * dx, f = exp(-0.5 * x * x) / sqrt(2 * M_PI) *
                                    (gsl_cdf_ugaussian_P((b - r * x) / s) - gsl_cdf_ugaussian_P((a - r * x) / s));
        sum += f * (i == 0 || i == 4000 ? 1 : i % 2 ? 4 : 2);
    }
    return sum * dx / 3;
}

/* The variance of a bin's count summed the slow way, lag by lag, with the
 * bivariate probabilities integrated numerically, on a 1D field of 60
 * samples of markov:scale=2.5,var=2.4 (rho up to 0.67: the Mehler series
 * is left at 0.67^401), and white noise's binomial.  Both are sums of
 * terms below 1 accurate to 1e-10: agreement to 1e-8 relative. */
Test(bands, hist_against_bivariate_sums)
{
    nl_model *m = test_model("markov:scale=2.5,var=2.4"), *w = test_model("nugget:var=2.4");
    double edges[6] = {-INFINITY, -1.1, -0.2, 0.45, 1.9, INFINITY}, dens[5], sd[5], s = sqrt(2.4), N = 60;
    size_t n = 60;
    cr_assert_eq(nl_hist_model_band(m, 1, &n, NULL, edges, 5, dens, sd), NL_OK, "%s", nl_errmsg());
    for (int b = 0; b < 5; b++) {
        double a = edges[b] / s, z = edges[b + 1] / s, p = gsl_cdf_ugaussian_P(z) - gsl_cdf_ugaussian_P(a);
        double var = N * p * (1 - p), width = isfinite(edges[b] + edges[b + 1]) ? edges[b + 1] - edges[b] : INFINITY;
        for (long v = 1; v < 60; v++)
            var += 2 * (N - (double)v) * (both_in(a, z, exp(-(double)v / 2.5)) - p * p);
        if (!isfinite(width))
            continue;  /* an open bin has density 0 */
        cr_expect_float_eq(dens[b], p / width, 1e-12, "bin %d", b);
        cr_expect_float_eq(sd[b] * N * width, sqrt(var), 1e-8 * sqrt(var), "bin %d: %g against %g", b,
                           sd[b] * N * width, sqrt(var));
    }
    cr_assert_eq(nl_hist_model_band(w, 1, &n, NULL, edges, 5, dens, sd), NL_OK, "%s", nl_errmsg());
    for (int b = 1; b < 4; b++) {
        double p = gsl_cdf_ugaussian_P(edges[b + 1] / s) - gsl_cdf_ugaussian_P(edges[b] / s);
        cr_expect_float_eq(sd[b] * N * (edges[b + 1] - edges[b]), sqrt(N * p * (1 - p)), 1e-12, "white bin %d", b);
    }
    nl_model_free(m), nl_model_free(w);
}

Test(bands, hist_refuses_bad_arguments)
{
    nl_model *m = test_model("gauss:scale=2");
    size_t n = 32;
    double e[3] = {0, -1, 1}, d[2], s[2];
    cr_expect_eq(nl_hist_model_band(m, 1, &n, NULL, e, 2, d, s), NL_EINVAL, "decreasing edges refused");
    cr_expect_eq(nl_hist_model_band(m, 1, &n, NULL, e, 0, d, s), NL_EINVAL, "no bins refused");
    cr_expect_eq(nl_hist_model_band(m, 4, &n, NULL, e, 1, d, s), NL_EINVAL, "dim 4 refused");
    nl_model_free(m);
}
