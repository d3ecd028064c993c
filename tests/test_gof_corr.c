/* Goodness of fit on correlated fields (analysis/gof_dep.h): the thinned
 * test keeps its false-alarm rate where the plain one rejects nearly every
 * correct field, and still rejects a wrong distribution. */
#include "../analysis/gof.h"
#include "../analysis/gof_dep.h"
#include "../core/dist.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/fft.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdlib.h>

/* A sample of a process whose marginal is `to`: a Gaussian field (variance
 * 1) mapped by F^-1(Phi(x)), the exact transform (noiselab shape fits each
 * field's own mean and spread instead, which is not a sample of the null). */
static void map_exact(nl_field *f, const nl_dist *to)
{
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = nl_dist_quantile(to, f->data[i] < 0 ? gsl_cdf_ugaussian_P(f->data[i])
                                                          : 1 - gsl_cdf_ugaussian_Q(f->data[i]));
}

/* Rejections at 5% out of K fields of markov:scale=8, 128 x 128, seeds
 * 1..K, mapped to `shape` and tested against hyperbolic: [0] thinned KS,
 * [1] thinned chi-square, [2] plain KS. */
static void rejections(size_t K, const char *shape, size_t rej[3])
{
    size_t n[2] = {128, 128};
    nl_model *m = test_model("markov:scale=8");
    nl_dist *d, *to;
    nl_synth_fft_plan *p;
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_eq(nl_dist_parse("hyperbolic", &d), 0);
    cr_assert_eq(nl_dist_parse(shape, &to), 0);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p), 0);
    rej[0] = rej[1] = rej[2] = 0;
    for (size_t s = 1; s <= K; s++) {
        nl_gof_dep dep;
        nl_gof g, g0;
        cr_assert_eq(nl_synth_fft_execute(p, s, f), 0);
        map_exact(f, to);
        cr_assert_eq(nl_gof_test_thinned((const nl_field *const *)&f, 1, d, 50, &dep, NULL, &g), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_gof_test(f->data, f->count, d, 50, &g0), 0);
        rej[0] += g.p_ks < 0.05, rej[1] += g.p_chi2 < 0.05, rej[2] += g0.p_ks < 0.05;
    }
    nl_synth_fft_plan_free(p), nl_field_free(f), nl_model_free(m), nl_dist_free(d), nl_dist_free(to);
}

/* 40 correct fields: the number rejected is Binomial(40, a).  At the
 * largest rate allowed, a = 10% (twice the nominal 5%), P(X >= 12) =
 * 0.0004, so "at most 11" fails a correct implementation by chance less
 * than once in 2000 runs (the seeds are fixed: it is decided once); at the
 * nominal 5% the expected count is 2.  The plain KS test, blind to the
 * correlation, rejects about 98% of them (experiments/hist_false_alarm.c):
 * at least 30 of 40 here.  Fields of variance 8 (laplace:a=2) are wrong:
 * the thinned tests rejected 93% to 98% of them in the experiment; at
 * least 30 of 40 fails a power of 90% with probability 0.001. */
Test(gof_corr_slow, false_alarms_and_power_on_correlated_fields)
{
    size_t rej[3];
    rejections(40, "hyperbolic", rej);
    cr_expect_leq(rej[0], 11, "KS rejected %zu of 40 correct fields", rej[0]);
    cr_expect_leq(rej[1], 11, "chi-square rejected %zu of 40 correct fields", rej[1]);
    cr_expect_geq(rej[2], 30, "the plain KS test rejected only %zu of 40 correct correlated fields", rej[2]);
    rejections(40, "laplace:a=2", rej);
    cr_expect_geq(rej[0], 30, "KS rejected only %zu of 40 wrong fields", rej[0]);
    cr_expect_geq(rej[1], 30, "chi-square rejected only %zu of 40 wrong fields", rej[1]);
}

/* White noise needs no thinning: the median indicator's correlation at
 * lag 1 is ~N(0, 1/N), far below 0.05 for N = 4096, so every sample is
 * kept; tau sums at most a few lags of such noise (sd ~0.03), below 1.2. */
Test(gof_corr, white_noise_is_kept_whole)
{
    size_t n[2] = {64, 64};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    nl_dist *d;
    nl_gof_dep dep;
    cr_assert_eq(nl_dist_parse("gauss", &d), 0);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = nl_rng_gauss(21, 0, i);
    cr_assert_eq(nl_gof_dependence(f, d, &dep), 0);
    cr_expect_eq(dep.stride, 1);
    cr_expect_eq(dep.kept, 4096);
    cr_expect_lt(dep.tau, 1.2, "tau %g", dep.tau);
    nl_dist_free(d), nl_field_free(f);
}

/* The stride follows the correlation length: for markov:scale=L the median
 * indicator's correlation (2/pi) asin(exp(-r/L)) reaches 0.05 at r = 2.55 L;
 * the biased estimate (mean removed) falls a little sooner.  L = 8: between
 * 1.5 L and 3 L.  With n_eff = n and design effect 1 the corrected test is
 * the plain one, bit for bit. */
Test(gof_corr, stride_and_plain_limit)
{
    size_t n[2] = {256, 256};
    nl_model *m = test_model("markov:scale=8");
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    nl_synth_fft_plan *p;
    nl_dist *d;
    nl_gof_dep dep;
    nl_gof a, b;
    cr_assert_eq(nl_dist_parse("gauss", &d), 0);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p), 0);
    cr_assert_eq(nl_synth_fft_execute(p, 4, f), 0);
    cr_assert_eq(nl_gof_dependence(f, d, &dep), 0);
    cr_expect(dep.stride >= 12 && dep.stride <= 24, "stride %zu", dep.stride);
    cr_expect(dep.n_eff <= (double)dep.kept && dep.tau >= 1);
    cr_assert_eq(nl_gof_test(f->data, f->count, d, 20, &a), 0);
    cr_assert_eq(nl_gof_test_dep(f->data, f->count, d, 20, (double)f->count, 1, &b), 0);
    cr_expect(a.p_ks == b.p_ks && a.p_chi2 == b.p_chi2 && a.D == b.D && a.chi2 == b.chi2);
    cr_expect_eq(nl_gof_test_dep(f->data, f->count, d, 20, 0.5, 1, &b), NL_EINVAL);
    cr_expect_eq(nl_gof_test_dep(f->data, f->count, d, 20, 100, 0.5, &b), NL_EINVAL);
    nl_synth_fft_plan_free(p), nl_field_free(f), nl_model_free(m), nl_dist_free(d);
}
