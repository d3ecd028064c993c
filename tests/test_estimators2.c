/* Estimators against known answers: white noise, a pure sinusoid, an AR(1)
 * process; the direct sum of eq. (15) against the FFT; the coverage of
 * Bartlett's bands. */
#include "../analysis/acf.h"
#include "../analysis/psd.h"
#include "../analysis/slope.h"
#include "../analysis/spectral.h"
#include "../core/model.h"
#include "../synth/fft.h"
#include "../analysis/welch.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include "util.h"

#include <criterion/criterion.h>
#include <jansson.h>
#include <math.h>
#include <stdlib.h>

static nl_field *ar1(size_t n, double phi, uint64_t seed)
{
    nl_field *f = nl_field_alloc(1, &n, NULL, NULL);
    double x = nl_rng_gauss(seed, 0, 0) / sqrt(1 - phi * phi);  /* stationary start */
    for (size_t i = 0; i < n; i++) {
        f->data[i] = x;
        x = phi * x + nl_rng_gauss(seed, 0, i + 1);
    }
    return f;
}

Test(estimators, direct_sum_equals_fft)
{
    size_t n[2] = {37, 29};
    nl_field *x = nl_field_alloc(2, n, NULL, NULL), *full;
    double d[20], lag[20], v[20];
    for (size_t i = 0; i < x->count; i++)
        x->data[i] = nl_rng_gauss(4, 1, i) + 0.1 * (double)(i % 7);
    for (int ub = 0; ub <= 1; ub++)
        for (int axis = 0; axis < 2; axis++) {
            cr_assert_eq(nl_acf_full(x, NAN, ub, &full), 0);
            cr_assert_eq(nl_acf_axis(full, axis, 19, lag, v), 0);
            cr_assert_eq(nl_acf_direct(x, NAN, ub, axis, 19, d), 0);
            for (int k = 0; k < 20; k++)
                cr_expect_float_eq(d[k], v[k], 1e-12 * fabs(v[0]), "unbiased %d axis %d lag %d", ub, axis, k);
            nl_field_free(full);
        }
    nl_field_free(x);
}

/* Welch on white noise: the density is sigma^2 h at every frequency; the
 * mean over the 4096/2 usable frequencies of an average of 127 segments has
 * relative sd ~ 1/sqrt(127 * 2048 / 3) (overlap and window correlate
 * neighbours), far below the 2% allowed.  A cosine lands in its bin. */
Test(estimators, welch_known_answers)
{
    size_t n = 65536, seg;
    double h = 0.5;
    nl_field *x = nl_field_alloc(1, &n, &h, NULL), *P;
    for (size_t i = 0; i < n; i++)
        x->data[i] = 1.7 * nl_rng_gauss(8, 2, i);
    cr_assert_eq(nl_psd_welch(x, 1024, 0.0, &P, &seg), 0);
    cr_expect_eq(seg, 127);
    double m = 0;
    for (size_t k = 1; k < 512; k++)
        m += P->data[k] / 511;
    cr_expect_float_eq(m, 1.7 * 1.7 * h, 0.02 * 1.7 * 1.7 * h, "white level %g", m);
    nl_field_free(P);
    for (size_t i = 0; i < n; i++)
        x->data[i] = cos(2 * M_PI * 100.0 / 1024 * (double)i);
    cr_assert_eq(nl_psd_welch(x, 1024, 0.0, &P, &seg), 0);
    size_t best = 0;
    for (size_t k = 1; k < 512; k++)
        if (P->data[k] > P->data[best])
            best = k;
    cr_expect_eq(best, 100);
    nl_field_free(P), nl_field_free(x);
}

/* AR(1): S(f) = h / |1 - phi exp(-2 pi i f h)|^2 for unit innovations.  The
 * Welch estimate (256-sample segments of 2^18 samples) averaged over eight
 * octave-wide bands matches it within 5% (each band averages thousands of
 * nearly independent ordinates: sd < 1%; the Hann window's smoothing of this
 * smooth spectrum biases by under 1%). */
Test(estimators, ar1_spectrum)
{
    double phi = 0.8;
    size_t seg;
    nl_field *x = ar1(1 << 18, phi, 5), *P;
    cr_assert_eq(nl_psd_welch(x, 256, 0.0, &P, &seg), 0);
    for (size_t lo = 2; lo < 128; lo *= 2) {
        double a = 0, b = 0;
        for (size_t k = lo; k < 2 * lo && k < 128; k++) {
            double w = 2 * M_PI * (double)k / 256;
            a += P->data[k];
            b += 1 / (1 - 2 * phi * cos(w) + phi * phi);
        }
        cr_expect_float_eq(a / b, 1.0, 0.05, "band from bin %zu: ratio %g", lo, a / b);
    }
    nl_field_free(P), nl_field_free(x);
}

/* Coverage of the 95% Bartlett band for AR(1) (R(k) = phi^k / (1 - phi^2)):
 * over 400 series the fraction of bands holding E c_k = (1 - k/N) R(k)
 * estimates the coverage with sd sqrt(.95 .05 / 400) = 1.1%; it must lie
 * within 4 sd of 95% at lags 1..5 (measured values logged). */
Test(estimators, bartlett_band_coverage)
{
    size_t N = 2048;
    double phi = 0.6, r0 = 1 / (1 - phi * phi);
    int hit[6] = {0};
    for (uint64_t s = 1; s <= 400; s++) {
        nl_field *x = ar1(N, phi, 100 + s), *full;
        double c[41], var[6];
        cr_assert_eq(nl_acf_full(x, 0.0, 0, &full), 0);
        for (int i = 0; i < 41; i++)
            c[i] = full->data[i];
        cr_assert_eq(nl_acf_bartlett(c, 41, N, 5, var), 0);
        for (int k = 1; k <= 5; k++) {
            double truth = (1 - (double)k / (double)N) * r0 * pow(phi, k), half = 1.959964 * sqrt(var[k]);
            hit[k] += fabs(c[k] - truth) <= half;
        }
        nl_field_free(full), nl_field_free(x);
    }
    for (int k = 1; k <= 5; k++) {
        cr_log_info("Bartlett 95%% band coverage at lag %d: %.3f", k, hit[k] / 400.0);
        cr_expect_leq(fabs(hit[k] / 400.0 - 0.95), 4 * 0.0109, "lag %d coverage %.3f", k, hit[k] / 400.0);
    }
}

/* The slope's 95% interval on a 2D periodogram is honest: 40 FFT fields of
 * S = k^-3.6 (128 x 128, seeds 1..40), slope over 0.02 <= |f| <= 0.25.
 * Coverage of -3.6 by the 40 intervals is Binomial(40, 0.95) if they are
 * right: P(X <= 32) = 7e-4, so at least 33 must cover.  Coverage cannot see
 * intervals that are too wide, so the reported half-width / 1.96 is also
 * compared with the spread of the 40 slopes: log(sd_hat / sd) has sd
 * 1 / sqrt(2 * 39) = 0.113, and 3.3 of those (two-sided 1e-3) allow the
 * ratio to lie in [0.69, 1.45].  (The radial-average fit this replaced gave
 * a ratio of 0.36.) */
Test(estimators, slope_interval_on_a_2d_periodogram_is_honest)
{
    nl_model *m;
    nl_synth_fft_plan *p;
    size_t n[2] = {128, 128};
    nl_field *x = nl_field_alloc(2, n, NULL, NULL), *P;
    double s1 = 0, s2 = 0, se = 0;
    int cover = 0;
    const int M = 40;
    cr_assert_eq(nl_model_parse("power:d=3.6,fmin=0.001", &m), 0);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p), 0);
    for (int s = 1; s <= M; s++) {
        nl_slope sl;
        cr_assert_eq(nl_synth_fft_execute(p, (uint64_t)s, x), 0);
        cr_assert_eq(nl_psd_periodogram(x, NAN, &P), 0);
        cr_assert_eq(nl_psd_slope_grid(P, 0.02, 0.25, &sl), 0);
        s1 += sl.slope, s2 += sl.slope * sl.slope, se += sl.ci95 / 1.96 / M;
        cover += fabs(sl.slope + 3.6) <= sl.ci95;
        nl_field_free(P);
    }
    double mean = s1 / M, sd = sqrt((s2 - M * mean * mean) / (M - 1));
    cr_expect_geq(cover, 33, "coverage %d of %d", cover, M);
    cr_expect(se / sd >= 0.69 && se / sd <= 1.45, "reported se %g against the slopes' sd %g (mean %g)", se, sd, mean);
    nl_field_free(x), nl_synth_fft_plan_free(p), nl_model_free(m);
}

/* psd --welch S --target: row i of the target stands for the frequency of
 * row i of the estimate, i / (S h): the model's profile on the S-point grid
 * (nl_psd_model_profile), to the 10 digits of the JSON.  On 65536 samples
 * (511 segments of 256) each Welch ordinate has a relative sd of about
 * 1/sqrt(511 * 0.95) = 4.5% (Hann windows overlapping by half keep ~95% of
 * the segments' worth); over 0.05..0.45 cycles per sample the window's
 * smoothing of this markov spectrum is below 1%, so every ordinate lies
 * within 25% (5.5 sd) of the target and their mean ratio, over ~100
 * ordinates of which neighbours share half their information, within 5%
 * (7 sd).  The target sampled on the full 65536-point grid instead is off
 * by up to 75x near Nyquist.  2D: the radial profile of the S x S grid. */
Test(estimators, welch_target_on_the_segment_grid)
{
    size_t S = 256, S2[2] = {32, 32}, nt;
    double h = 1, h2[2] = {1, 1}, tg[129], tg2[64], sum = 0;
    int cnt = 0;
    nl_model *m = test_model("markov:scale=8");
    char err[4096];
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=8 --size 65536 --seed 11 -o w.tsv", 0, 0, err, sizeof err),
                 0, "%s", err);
    json_t *j = run_noiselab_json("psd w.tsv --welch 256 --target markov:scale=8 --json");
    json_t *fr = json_object_get(j, "freq"), *ps = json_object_get(j, "psd"), *tj = json_object_get(j, "target");
    cr_assert_eq(nl_psd_model_profile(m, 1, &S, &h, tg, &nt), 0);
    cr_assert_eq(json_array_size(tj), nt);
    for (size_t i = 0; i < nt; i++) {
        double f = json_real_value(json_array_get(fr, i)), p = json_real_value(json_array_get(ps, i));
        double t = json_real_value(json_array_get(tj, i));
        cr_expect_float_eq(f, (double)i / 256, 1e-12);
        cr_expect_float_eq(t, tg[i], 1e-9 * tg[i], "row %zu: target %g, the model on the segment grid %g", i, t, tg[i]);
        if (f >= 0.05 && f <= 0.45) {
            cr_expect(fabs(p / t - 1) < 0.25, "f %g: Welch %g, target %g", f, p, t);
            sum += p / t, cnt++;
        }
    }
    cr_expect(fabs(sum / cnt - 1) < 0.05, "mean Welch / target over the band: %g", sum / cnt);
    json_decref(j);
    cr_assert_eq(run_noiselab("synth fft --acf markov:scale=8 --size 128x128 --seed 11 -o w2.exr", 0, 0, err,
                              sizeof err), 0, "%s", err);
    j = run_noiselab_json("psd w2.exr --welch 32 --target markov:scale=8 --json");
    tj = json_object_get(j, "target");
    cr_assert_eq(nl_psd_model_profile(m, 2, S2, h2, tg2, &nt), 0);
    cr_assert_eq(json_array_size(tj), nt);
    for (size_t i = 0; i < nt; i++)
        cr_expect_float_eq(json_real_value(json_array_get(tj, i)), tg2[i], 1e-9 * tg2[i], "2D row %zu", i);
    json_decref(j);
    nl_model_free(m);
}
