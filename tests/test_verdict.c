/* The ensemble verdict (analysis/verdict.h): its standard errors, its
 * threshold and its Isserlis variance against closed forms, and the verdict
 * itself passing a correct target and failing a wrong one. */
#include "../analysis/acf.h"
#include "../analysis/verdict.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

static void white(nl_field *x, uint64_t seed)
{
    for (size_t i = 0; i < x->count; i++)
        x->data[i] = nl_rng_gauss(seed, 11, i);
}

static double delta(long dx, long dy, void *ctx)
{
    (void)ctx;
    return dx == 0 && dy == 0 ? 1.0 : 0.0;
}

/* White noise: Var r(0) = 2/P and Var r(l) = 1/P for l != 0 (P pairs), the
 * Isserlis sum reduced by hand; only rounding separates them (1e-12). */
Test(verdict, isserlis_white_noise)
{
    size_t n[2] = {23, 9};
    cr_assert_float_eq(nl_verdict_isserlis_var(delta, NULL, n, 0, 0), 2.0 / (23 * 9), 1e-12);
    cr_assert_float_eq(nl_verdict_isserlis_var(delta, NULL, n, 3, 2), 1.0 / (20 * 7), 1e-12);
    cr_assert_float_eq(nl_verdict_isserlis_var(delta, NULL, (size_t[]){40, 1}, 5, 0), 1.0 / 35, 1e-12);
}

/* The thresholds printed by the statistical tests and the FFT experiment
 * (4.17 for 33 lags, normal; 4.69 for 66 lags, t(63)), and GSL's quantiles
 * exactly. */
Test(verdict, threshold)
{
    cr_assert_eq(nl_verdict_threshold(1e-3, 33, 0), gsl_cdf_ugaussian_Qinv(1e-3 / 66.0));
    cr_assert_eq(nl_verdict_threshold(1e-3, 66, 63), gsl_cdf_tdist_Qinv(1e-3 / 132.0, 63.0));
    cr_assert_float_eq(nl_verdict_threshold(1e-3, 33, 0), 4.17, 0.005);
    cr_assert_float_eq(nl_verdict_threshold(1e-3, 66, 63), 4.69, 0.005);
    cr_assert(isnan(nl_verdict_threshold(0, 3, 0)) && isnan(nl_verdict_threshold(1e-3, 0, 0)));
}

/* Mean and se are the ensemble's sample mean and sd / sqrt(M) of the
 * unbiased, known-mean estimates at the lags (negative lags wrapped). */
Test(verdict, ensemble_statistics)
{
    size_t n[2] = {32, 20}, M = 5;
    long lags[3][2] = {{0, 0}, {3, 1}, {-2, 4}};
    double mean[3], se[3], s1[3] = {0}, s2[3] = {0};
    nl_field *x = nl_field_alloc(2, n, NULL, NULL), *full;
    nl_verdict *v;
    cr_assert_eq(nl_verdict_alloc(2, n, 3, (const long (*)[2])lags, &v), 0);
    for (uint64_t s = 1; s <= M; s++) {
        white(x, s);
        cr_assert_eq(nl_verdict_add(v, x), 0);
        cr_assert_eq(nl_acf_full(x, 0.0, NL_ACF_UNBIASED, &full), 0);
        for (int i = 0; i < 3; i++) {
            size_t ix = (size_t)(lags[i][0] + (lags[i][0] < 0 ? 64 : 0)), iy = (size_t)lags[i][1];
            double r = full->data[iy * 64 + ix];
            s1[i] += r, s2[i] += r * r;
        }
        nl_field_free(full);
    }
    cr_assert_eq(nl_verdict_count(v), M);
    cr_assert_eq(nl_verdict_stats(v, mean, se), 0);
    for (int i = 0; i < 3; i++) {
        double mu = s1[i] / (double)M, sd = sqrt((s2[i] - (double)M * mu * mu) / ((double)M - 1));
        cr_assert_float_eq(mean[i], mu, 1e-15);
        cr_assert_float_eq(se[i], sd / sqrt((double)M), 1e-15);
    }
    nl_verdict_free(v);
    nl_field_free(x);
}

/* 100 white fields: target delta passes at the ensemble threshold; a
 * variance 10% off (10 standard errors at these sizes) fails. */
Test(verdict, passes_truth_fails_a_wrong_target)
{
    size_t n[2] = {256, 1}, M = 100, worst;
    long lags[11][2];
    double mean[11], se[11], truth[11] = {1}, wrong[11] = {1.1};
    nl_field *x = nl_field_alloc(1, n, NULL, NULL);
    nl_verdict *v;
    for (int i = 0; i < 11; i++)
        lags[i][0] = i, lags[i][1] = 0;
    cr_assert_eq(nl_verdict_alloc(1, n, 11, (const long (*)[2])lags, &v), 0);
    for (uint64_t s = 1; s <= M; s++) {
        white(x, s);
        cr_assert_eq(nl_verdict_add(v, x), 0);
    }
    cr_assert_eq(nl_verdict_stats(v, mean, se), 0);
    double zcrit = nl_verdict_threshold(1e-3, 11, M - 1);
    cr_expect_leq(nl_verdict_zmax(11, mean, se, truth, NULL), zcrit);
    cr_expect_gt(nl_verdict_zmax(11, mean, se, wrong, &worst), zcrit);
    cr_expect_eq(worst, 0);
    nl_verdict_free(v);
    nl_field_free(x);
}

/* Lags in 3D (nl_verdict_alloc3): the accumulator reads the full estimate
 * at each lag's wrapped index, negative components included; a lag at or
 * beyond the field's extent, or a z lag below 3D, is refused. */
Test(verdict, lags_in_3d)
{
    size_t n[3] = {8, 6, 5};
    long lags[3][3] = {{0, 0, 0}, {1, -2, 3}, {-3, 1, -4}}, bad[1][3] = {{0, 0, 5}}, flat[1][3] = {{0, 0, 1}};
    double mean[3];
    nl_field *x = nl_field_alloc(3, n, NULL, NULL), *full;
    nl_verdict *v;
    white(x, 7);
    cr_assert_eq(nl_verdict_alloc3(3, n, 3, (const long (*)[3])lags, &v), 0);
    cr_assert_eq(nl_verdict_add(v, x), 0);
    cr_assert_eq(nl_verdict_stats(v, mean, NULL), 0);
    cr_assert_eq(nl_acf_full(x, 0.0, NL_ACF_UNBIASED, &full), 0);
    for (int i = 0; i < 3; i++) {
        size_t at = 0;
        for (int a = 2; a >= 0; a--)
            at = at * full->n[a] + (size_t)(lags[i][a] + (lags[i][a] < 0 ? (long)full->n[a] : 0));
        cr_expect_eq(mean[i], full->data[at], "lag %d", i);
    }
    cr_expect_eq(nl_verdict_alloc3(3, n, 1, (const long (*)[3])bad, &(nl_verdict *){NULL}), NL_EINVAL);
    cr_expect_eq(nl_verdict_alloc3(2, n, 1, (const long (*)[3])flat, &(nl_verdict *){NULL}), NL_EINVAL);
    nl_verdict_free(v);
    nl_field_free(full);
    nl_field_free(x);
}
