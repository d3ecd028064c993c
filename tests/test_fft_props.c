/* FFT synthesis: exact properties (reproducibility, common random numbers,
 * variance) and the not-positive-definite detector, both ways. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/fft.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static nl_synth_fft_plan *plan(const char *spec, int dim, const size_t *n, unsigned flags, int *st)
{
    nl_model *m;
    nl_synth_fft_plan *p = NULL;
    cr_assert_eq(nl_model_parse(spec, &m), 0, "%s", spec);
    *st = nl_synth_fft_plan_alloc(m, dim, n, NULL, flags, &p);
    nl_model_free(m);
    return p;
}

/* The same seed gives the same bits, with 1 or 2 threads. */
Test(fft, bit_reproducible_across_runs_and_threads)
{
    size_t n[2] = {96, 80};
    int st;
    nl_synth_fft_plan *p = plan("markov:scale=5", 2, n, 0, &st);
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    omp_set_num_threads(1);
    cr_assert_eq(nl_synth_fft_execute(p, 42, a), 0);
    omp_set_num_threads(2);
    cr_assert_eq(nl_synth_fft_execute(p, 42, b), 0);
    cr_assert_eq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    cr_assert_eq(nl_synth_fft_execute(p, 43, b), 0);
    cr_assert_neq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    nl_field_free(a), nl_field_free(b), nl_synth_fft_plan_free(p);
}

/* Plans made with FFTW_ESTIMATE on one thread and FFTW_MEASURE on two give
 * the same field to rounding: the largest difference is below 1e-12 of the
 * largest value (the transforms differ only in the order of their sums).
 * The wisdom cache points at an empty folder, so MEASURE really measures
 * (and would overwrite any array planned on after it was filled). */
Test(fft_slow, any_plan_gives_the_same_field_to_rounding)
{
    size_t n[2] = {512, 512};
    int st;
    double dmax = 0, vmax = 0;
    const char *was = getenv("NOISELAB_FFTW");
    char saved[32];
    nl_synth_fft_plan *p, *q;
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    snprintf(saved, sizeof saved, "%s", was ? was : "");
    setenv("XDG_CACHE_HOME", scratch_dir(), 1); /* before the first plan of this process */
    omp_set_num_threads(1);
    setenv("NOISELAB_FFTW", "estimate", 1);
    p = plan("markov:scale=5", 2, n, 0, &st);
    omp_set_num_threads(2);
    setenv("NOISELAB_FFTW", "measure", 1);
    q = plan("markov:scale=5", 2, n, 0, &st);
    if (was)
        setenv("NOISELAB_FFTW", saved, 1);
    else
        unsetenv("NOISELAB_FFTW");
    cr_assert_eq(nl_synth_fft_execute(p, 42, a), 0);
    cr_assert_eq(nl_synth_fft_execute(q, 42, b), 0);
    for (size_t i = 0; i < a->count; i++) {
        dmax = fmax(dmax, fabs(a->data[i] - b->data[i]));
        vmax = fmax(vmax, fabs(a->data[i]));
    }
    cr_expect(dmax <= 1e-12 * vmax, "largest difference %g of largest value %g", dmax, vmax);
    cr_expect(vmax > 1, "the field is not empty");
    nl_field_free(a), nl_field_free(b), nl_synth_fft_plan_free(p), nl_synth_fft_plan_free(q);
}

/* A white spectrum S = 1 at unit spacing has lambda = 1: the field's DFT
 * is the white spectrum itself, X_k = sqrt(N/2) G_k with G_k = g_2k + i
 * g_2k+1, the pair nl_rng_gauss_pair(seed, 0, k), for 0 < k < N/2, and
 * sqrt(N) g_2k at the self-conjugate k = 0 and N/2 (synth/fft.h).  The
 * direct DFT's rounding is about N eps |x| ~ 1e-12 here, hence 1e-9.  Any
 * other model filters that same G (common random numbers): the ratio
 * DFT(x_model) / DFT(x_white) is then real and non-negative, which we check
 * through the transfer at one frequency. */
Test(fft, white_spectrum_returns_the_white_noise)
{
    size_t n[1] = {1024};
    int st;
    nl_synth_fft_plan *p = plan("spectrum:1", 1, n, 0, &st);
    nl_field *x = nl_field_alloc(1, n, NULL, NULL);
    cr_assert_eq(st, 0);
    cr_assert_eq(nl_synth_fft_execute(p, 2385, x), 0);
    for (size_t k = 0; k <= n[0] / 2; k++) {
        double g[2], re = 0, im = 0, s = sqrt(n[0] / 2.0);
        for (size_t j = 0; j < n[0]; j++) {
            double th = -2 * M_PI * (double)(k * j % n[0]) / (double)n[0];
            re += x->data[j] * cos(th), im += x->data[j] * sin(th);
        }
        nl_rng_gauss_pair(2385, NL_STREAM_WHITE, k, g);
        if (k == 0 || k == n[0] / 2)
            g[0] *= M_SQRT2, g[1] = 0;
        cr_assert_float_eq(re, s * g[0], 1e-9, "k=%zu", k);
        cr_assert_float_eq(im, s * g[1], 1e-9, "k=%zu", k);
    }
    nl_field_free(x), nl_synth_fft_plan_free(p);
}

Test(fft, common_random_numbers_across_models)
{
    size_t n[1] = {512};
    int st;
    nl_synth_fft_plan *pw = plan("spectrum:1", 1, n, 0, &st), *pm = plan("markov:scale=4", 1, n, 0, &st);
    nl_field *w = nl_field_alloc(1, n, NULL, NULL), *x = nl_field_alloc(1, n, NULL, NULL);
    double q = exp(-0.25), re_w = 0, im_w = 0, re_x = 0, im_x = 0, k = 7;
    cr_assert_eq(nl_synth_fft_execute(pw, 9, w), 0);
    cr_assert_eq(nl_synth_fft_execute(pm, 9, x), 0);
    for (size_t j = 0; j < n[0]; j++) {
        double th = -2 * M_PI * k * (double)j / (double)n[0];
        re_w += w->data[j] * cos(th), im_w += w->data[j] * sin(th);
        re_x += x->data[j] * cos(th), im_x += x->data[j] * sin(th);
    }
    /* X_k = sqrt(lambda_k) W_k with lambda_k the DFT of q^|j| */
    double th = 2 * M_PI * k / (double)n[0], g = sqrt((1 - q * q) / (1 - 2 * q * cos(th) + q * q));
    cr_assert_float_eq(re_x, g * re_w, 1e-9);
    cr_assert_float_eq(im_x, g * im_w, 1e-9);
    nl_field_free(w), nl_field_free(x), nl_synth_fft_plan_free(pw), nl_synth_fft_plan_free(pm);
}

Test(fft, reports_the_model_variance)
{
    size_t n[2] = {64, 64};
    int st;
    nl_synth_fft_info info;
    nl_synth_fft_plan *p = plan("matern:nu=1.5,scale=3,var=2.385", 2, n, 0, &st);
    nl_synth_fft_plan_info(p, &info);
    cr_assert_float_eq(info.variance, 2.385, 1e-12);
    cr_assert_eq(info.negatives, 0);
    nl_synth_fft_plan_free(p);
}

/* Must raise: R = cos(omega r) exp(-r) in 2D violates the isotropic bound
 * (Lewis 1987, "Multi-dimensional Autocorrelation"); a markaussian with
 * alpha = 3 > 2 (written as an expr, the parser refuses it) is not positive definite in any dimension. */
Test(fft, refuses_models_that_are_not_positive_definite)
{
    size_t n2[2] = {128, 128}, n1[1] = {256};
    int st;
    nl_synth_fft_plan *p = plan("oscillatory:omega=2,scale=10", 2, n2, 0, &st);
    cr_assert_null(p);
    cr_assert_eq(st, NL_ENOTPD);
    cr_assert(strstr(nl_errmsg(), "not positive definite") != NULL, "%s", nl_errmsg());
    p = plan("expr:exp(-abs(t/5)^3)", 1, n1, 0, &st);
    cr_assert_eq(st, NL_ENOTPD);
    /* with the clamp flag it is synthesised, and the clamping is reported */
    p = plan("expr:exp(-abs(t/5)^3)", 1, n1, NL_SYNTH_FFT_CLAMP, &st);
    cr_assert_eq(st, 0);
    nl_synth_fft_info info;
    nl_synth_fft_plan_info(p, &info);
    cr_assert_gt(info.negatives, 0);
    cr_assert_gt(info.clamp_error, NL_SYNTH_FFT_CLAMP_TOL);
    cr_assert_lt(info.min_lambda, 0);
    nl_synth_fft_plan_free(p);
}

/* Must not raise: positive definite models, including a Gaussian whose grid
 * spectrum has rounding-level negatives far below the tolerance, and the
 * separable oscillatory product. */
Test(fft, accepts_positive_definite_models)
{
    size_t n2[2] = {128, 128};
    const char *ok[] = {"markov:scale=8", "gauss:scale=6", "oscillatory:omega=2,scale=10,sep",
                        "markaussian:alpha=1.4,scale=4", "matern:nu=2.5,scale=3", "markov:angle=40,ratio=0.2"};
    for (size_t i = 0; i < sizeof ok / sizeof *ok; i++) {
        int st;
        nl_synth_fft_info info;
        nl_synth_fft_plan *p = plan(ok[i], 2, n2, 0, &st);
        cr_assert_eq(st, 0, "%s: %s", ok[i], nl_errmsg());
        nl_synth_fft_plan_info(p, &info);
        cr_assert_leq(info.clamp_error, 1e-12, "%s", ok[i]);
        nl_synth_fft_plan_free(p);
    }
}
