/* The model's band of the biased ACF estimate (nl_acf_model_band) against
 * closed forms (white noise, AR(1)) and against a brute-force sum over
 * every pair of samples of a small 2D field. */
#include "../analysis/acf.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

/* The band's half-width over 1.959964: the model's sd of the estimate. */
static double sd_of(const double *mean, const double *hi, size_t k) { return (hi[k] - mean[k]) / 1.959964; }

/* White noise of variance s2 on N samples, n along the axis: E c(0) =
 * s2 (N - 1)/N, E c(k) = -(1 - k/n) s2 / N; Var c(0) = 2 s2^2 (N - 1) / N^2
 * exactly (N c(0) / s2 is chi-square with N - 1 degrees of freedom), and
 * the header's sum with R - V (V = s2 / N), whose terms are s2 - V at
 * r = 0, -V elsewhere, and whose pair counts w(r) add up to P^2 (P =
 * N (1 - k/n) pairs at lag k; w(0) = P, w(-+k e) = (n - 2k)+ N / n = w2):
 *     Var c(k) = s2^2 / N^2 [P (1 - 2/N) + 2 P^2 / N^2 - 2 w2 / N], k > 0.
 * Each is a sum of at most a few thousand terms: 1e-12 relative covers the
 * rounding. */
Test(acf_band, white_noise)
{
    nl_model *m = test_model("nugget:var=2.385");
    double s2 = 2.385, mean[9], lo[9], hi[9];
    size_t n1 = 100, n2[2] = {21, 13};
    struct { int dim, axis; const size_t *n; } cs[3] = {{1, 0, &n1}, {2, 0, n2}, {2, 1, n2}};
    for (int c = 0; c < 3; c++) {
        double N = cs[c].dim == 1 ? 100 : 21 * 13, na = (double)cs[c].n[cs[c].axis];
        cr_assert_eq(nl_acf_model_band(m, cs[c].dim, cs[c].n, NULL, cs[c].axis, 8, mean, lo, hi), NL_OK, "%s",
                     nl_errmsg());
        cr_expect_float_eq(mean[0], s2 * (N - 1) / N, 1e-12 * s2);
        cr_expect_float_eq(sd_of(mean, hi, 0), sqrt(2 * s2 * s2 * (N - 1)) / N, 1e-12 * s2);
        for (size_t k = 1; k <= 8; k++) {
            double f = 1 - (double)k / na, P = N * f, w2 = (na > 2.0 * k ? na - 2.0 * k : 0) * N / na;
            double var = s2 * s2 / (N * N) * (P * (1 - 2 / N) + 2 * P * P / (N * N) - 2 * w2 / N);
            cr_expect_float_eq(mean[k], -f * s2 / N, 1e-12 * s2, "case %d lag %zu: %g", c, k, mean[k]);
            cr_expect_float_eq(sd_of(mean, hi, k), sqrt(var), 1e-12 * s2, "case %d lag %zu", c, k);
            cr_expect_float_eq(mean[k] - lo[k], hi[k] - mean[k], 1e-12 * s2);
        }
    }
    nl_model_free(m);
}

/* AR(1), R(k) = phi^|k| (markov sampled at unit spacing, phi = exp(-1/s)).
 * Bartlett's asymptotic variance at lags where phi^2k is negligible is
 * (1/N)(1 + phi^2)/(1 - phi^2) (Priestley 1981, eq. (5.3.23) with the
 * series' sum of R^2).  The finite-N weights (N - k - |r|)/N^2 take a
 * relative k/N plus E|r|/N off it (E|r| = 0.83 under the weights phi^2|r|
 * for phi = 0.6), the sample mean V (~ 4/N) about 2 V sum R / sum R^2 = 16/N;
 * so after dividing by (1 - k/N) the ratio lies within 20/N of 1, while a
 * band made with the sample's plug-in or a missing factor would be off by
 * O(1).  The mean is (1 - k/N)(R(k) + V) - 2 S/N, with S/N within V of
 * (1 - k/N)V: it must lie within 2 V = 8/N of (1 - k/N) R(k). */
Test(acf_band, ar1_closed_form)
{
    size_t n = 4000;
    double s = 1 / log(1 / 0.6), phi = 0.6, N = 4000, mean[41], lo[41], hi[41];
    char spec[64];
    snprintf(spec, sizeof spec, "markov:scale=%.17g", s);
    nl_model *m = test_model(spec);
    cr_assert_eq(nl_acf_model_band(m, 1, &n, NULL, 0, 40, mean, lo, hi), NL_OK, "%s", nl_errmsg());
    for (size_t k = 25; k <= 40; k += 5) {
        double f = 1 - (double)k / N, sd = sd_of(mean, hi, k);
        double asym = (1 + phi * phi) / (1 - phi * phi) / N;
        cr_expect_leq(fabs(sd * sd / f / asym - 1), 20 / N, "lag %zu: var %g, Bartlett %g", k, sd * sd, asym);
    }
    for (size_t k = 0; k <= 40; k += 4)
        cr_expect_leq(fabs(mean[k] - (1 - (double)k / N) * pow(phi, (double)k)), 8 / N, "lag %zu", k);
    nl_model_free(m);
}

/* R of the model at the lag vector (i, j) samples of spacing h. */
static double R_at(const nl_model *m, const double *h, long i, long j)
{
    double v[3] = {(double)i * h[0], (double)j * h[1], 0};
    return nl_model_acf(m, 2, v);
}

/* The header's formulas summed the slow way, over every pair of samples of
 * a 9 x 7 field (spacing 0.7 x 1.3, markov:scale=2.1 with a nugget): E c(k)
 * from E (x_s - m)(x_t - m) = R(t-s) - g(s) - g(t) + V sample by sample,
 * Var as the header's sum with R - V, pair by pair over the overlap.
 * Both are sums of ~4000 terms of size <= 1: agreement to 1e-10. */
Test(acf_band, brute_force_2d)
{
    nl_model *m = test_model("markov:scale=2.1,var=1.7,nugget=0.3");
    size_t n[2] = {9, 7};
    double h[2] = {0.7, 1.3}, mean[6], lo[6], hi[6], g[63], V = 0, N = 63;
    for (int t = 0; t < 63; t++) {
        g[t] = 0;
        for (int s = 0; s < 63; s++)
            g[t] += R_at(m, h, s % 9 - t % 9, s / 9 - t / 9) / N;
        V += g[t] / N;
    }
    for (int axis = 0; axis < 2; axis++) {
        cr_assert_eq(nl_acf_model_band(m, 2, n, h, axis, 5, mean, lo, hi), NL_OK, "%s", nl_errmsg());
        for (long k = 0; k <= 5; k++) {
            long di = axis == 0 ? k : 0, dj = axis == 1 ? k : 0;
            double e = 0, var = 0;
            for (int s = 0; s < 63; s++) {
                long si = s % 9, sj = s / 9;
                if (si + di >= 9 || sj + dj >= 7)
                    continue;
                e += R_at(m, h, di, dj) - g[s] - g[(sj + dj) * 9 + si + di] + V;
                for (int t = 0; t < 63; t++) {
                    long ti = t % 9, tj = t / 9;
                    if (ti + di >= 9 || tj + dj >= 7)
                        continue;
                    double r = R_at(m, h, ti - si, tj - sj) - V;
                    var += r * r + (R_at(m, h, ti - si + di, tj - sj + dj) - V) *
                                       (R_at(m, h, ti - si - di, tj - sj - dj) - V);
                }
            }
            e /= N, var /= N * N;
            cr_expect_float_eq(mean[k], e, 1e-10, "axis %d lag %ld: %.12g, brute force %.12g", axis, k, mean[k], e);
            cr_expect_float_eq(sd_of(mean, hi, (size_t)k), sqrt(var), 1e-10, "axis %d lag %ld", axis, k);
        }
    }
    nl_model_free(m);
}

/* The stationary treatment of the deviations from the sample mean against
 * the exact variance (Isserlis on y = x - m, covariance R(t-s) - g(s) -
 * g(t) + V, summed over every pair) on 64 samples of markov:scale=4, 16
 * correlation lengths: the header's 0.5% (measured 0.51% at most), checked
 * at 1%; the mean is exact (1e-12).  Dropping V, or treating the mean as
 * known, is off by 5% here. */
Test(acf_band, sample_mean_against_exact)
{
    nl_model *m = test_model("markov:scale=4");
    size_t n = 64;
    double mean[17], lo[17], hi[17], g[64], V = 0;
    cr_assert_eq(nl_acf_model_band(m, 1, &n, NULL, 0, 16, mean, lo, hi), NL_OK, "%s", nl_errmsg());
    for (int s = 0; s < 64; s++) {
        g[s] = 0;
        for (int t = 0; t < 64; t++)
            g[s] += exp(-fabs((double)(t - s)) / 4) / 64;
        V += g[s] / 64;
    }
#define C(s, t) (exp(-fabs((double)((t) - (s))) / 4) - g[s] - g[t] + V)
    for (int k = 0; k <= 16; k += 2) {
        double e = 0, var = 0;
        for (int s = 0; s + k < 64; s++) {
            e += C(s, s + k) / 64;
            for (int t = 0; t + k < 64; t++)
                var += C(s, t) * C(s, t) + C(s, t + k) * C(s + k, t);
        }
        var /= 64.0 * 64.0;
        cr_expect_float_eq(mean[k], e, 1e-12, "lag %d: %.15g against %.15g", k, mean[k], e);
        cr_expect_leq(fabs(sd_of(mean, hi, (size_t)k) / sqrt(var) - 1), 0.01, "lag %d: sd %g against %g", k,
                      sd_of(mean, hi, (size_t)k), sqrt(var));
    }
#undef C
    nl_model_free(m);
}

/* A spectral model goes through its sampled R: spectrum: with markov's
 * Lorentzian 2 s / (1 + (2 pi f s)^2) gives the R of the spectrum cut at
 * the Nyquist frequency 1/2, short of markov's by at most the tail
 * 2 int_{1/2}^inf S df = (2/pi) atan(1/(pi s)) = 0.0101 at s = 20 (var 1)
 * at every lag: the means agree within 0.012 (the tail, with a fifth for
 * the Riemann sum of the grid and the sample mean's V); the variances,
 * sums of products of two R's, within twice the tail relatively (sd:
 * about the same), 0.03 with room. */
Test(acf_band, spectral_model)
{
    nl_model *r = test_model("markov:scale=20"), *S = test_model("spectrum:2*20/(1+(2*pi*f*20)^2)");
    size_t n = 512;
    double m1[11], l1[11], h1[11], m2[11], l2[11], h2[11];
    cr_assert_eq(nl_acf_model_band(r, 1, &n, NULL, 0, 10, m1, l1, h1), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_acf_model_band(S, 1, &n, NULL, 0, 10, m2, l2, h2), NL_OK, "%s", nl_errmsg());
    for (size_t k = 0; k <= 10; k++) {
        cr_expect_leq(fabs(m2[k] - m1[k]), 0.012, "lag %zu: %g against %g", k, m2[k], m1[k]);
        cr_expect_leq(fabs(sd_of(m2, h2, k) / sd_of(m1, h1, k) - 1), 0.03, "lag %zu", k);
    }
    nl_model_free(r), nl_model_free(S);
}

Test(acf_band, refuses_bad_arguments)
{
    nl_model *m = test_model("gauss:scale=2"), *p = test_model("powvar:alpha=1");
    size_t n[2] = {16, 8};
    double a[9], b[9], c[9];
    cr_expect_eq(nl_acf_model_band(m, 2, n, NULL, 1, 8, a, b, c), NL_EINVAL, "max-lag = n refused");
    cr_expect_eq(nl_acf_model_band(m, 2, n, NULL, 2, 4, a, b, c), NL_EINVAL, "axis beyond dim refused");
    cr_expect_eq(nl_acf_model_band(m, 0, n, NULL, 0, 4, a, b, c), NL_EINVAL, "dim 0 refused");
    cr_expect_neq(nl_acf_model_band(p, 2, n, NULL, 0, 4, a, b, c), NL_OK, "an intrinsic model has no band");
    nl_model_free(m), nl_model_free(p);
}
