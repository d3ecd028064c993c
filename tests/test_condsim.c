/* Conditional simulation by kriging (analysis/condsim.h, Journel 1974). */
#include "../analysis/condsim.h"
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../core/field_sample.h"
#include "../core/io.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/circulant.h"
#include "../synth/fft.h"
#include "stat.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* n data on distinct grid samples (cell centres lo + (i + 0.5) h) of an
 * nx x ny grid, the samples drawn at random within columns c0 .. c1 - 1,
 * values 2.385 + N(0, 1). */
static void data_on_samples(size_t n, const size_t *g, const double *lo, const double *h, size_t c0, size_t c1,
                            uint64_t seed, double *pts, double *val)
{
    for (size_t i = 0; i < n; i++) {
        size_t cx, cy, dup;
        uint64_t k = 0;
        do { /* distinct samples */
            cx = c0 + (size_t)(nl_rng_uniform(seed, 1, 2 * (i + 64 * k)) * (double)(c1 - c0));
            cy = (size_t)(nl_rng_uniform(seed, 1, 2 * (i + 64 * k) + 1) * (double)g[1]);
            dup = 0;
            for (size_t j = 0; j < i; j++)
                dup |= pts[2 * j] == lo[0] + ((double)cx + 0.5) * h[0] && pts[2 * j + 1] == lo[1] + ((double)cy + 0.5) * h[1];
            k++;
        } while (dup);
        pts[2 * i] = lo[0] + ((double)cx + 0.5) * h[0];
        pts[2 * i + 1] = lo[1] + ((double)cy + 0.5) * h[1];
        val[i] = 2.385 + nl_rng_gauss(seed, 2, i);
    }
}

/* Property: Z = U + K[d - U(t)] equals d at data on samples (kriging
 * interpolates), for fft and circulant fields, every realization.
 * Tolerance 1e-9: the kriging system of 25 points of markov:scale=3 is
 * well conditioned (rcond ~ 1e-2), so the interpolation error is a few
 * hundred ulps of the O(1) values. */
Test(condsim, honours_data_on_samples_exactly)
{
    nl_model *m = test_model("markov:scale=3");
    const size_t g[2] = {40, 30};
    const double h[2] = {0.5, 0.5}, lo[2] = {-3.7, 1.2};
    double pts[2 * 25], val[25];
    data_on_samples(25, g, lo, h, 0, g[0], 5, pts, val);
    nl_field *f = nl_field_alloc(2, g, h, NULL);
    nl_condsim_plan *p;
    nl_synth_fft_plan *fp;
    nl_synth_circulant_plan *cp;
    cr_assert_eq(nl_condsim_plan_alloc(m, 25, pts, val, lo, f, NULL, 0, NULL, &p), 0, "%s", nl_errmsg());
    nl_condsim_info info;
    nl_condsim_plan_info(p, &info);
    cr_expect(info.on_samples == 25 && info.sites == 0 && info.screening == 0 && info.max_move < 1e-12,
              "%zu %zu %g %g", info.on_samples, info.sites, info.screening, info.max_move);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, g, h, NL_SYNTH_FFT_CLAMP, &fp), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, g, h, 0, 16, &cp), 0, "%s", nl_errmsg());
    for (uint64_t s = 1; s <= 6; s++) {
        if (s % 2)
            cr_assert_eq(nl_synth_fft_execute(fp, s, f), 0);
        else
            cr_assert_eq(nl_synth_circulant_execute(cp, s, f), 0);
        cr_assert_eq(nl_condsim_execute(p, f, s, NULL), 0, "%s", nl_errmsg());
        double z[25];
        cr_assert_eq(nl_field_sample(f, (double[]){lo[0] + h[0] / 2, lo[1] + h[1] / 2}, NL_INTERP_NEAREST, 25, pts,
                                     z), 0);
        for (int i = 0; i < 25; i++)
            cr_expect(fabs(z[i] - val[i]) < 1e-9, "seed %d datum %d: %.17g vs %.17g", (int)s, i, z[i], val[i]);
    }
    nl_synth_fft_plan_free(fp), nl_synth_circulant_plan_free(cp), nl_condsim_plan_free(p);
    nl_field_free(f), nl_model_free(m);
}

/* Property: over realizations of an exact unconditional field (circulant
 * embedding: covariance exactly R), Z(x) is Gaussian with mean the kriging
 * estimate K[d](x) and variance the kriging variance s2(x) (Z(x) - K[d](x)
 * = U(x) - K[U(t)](x), the kriging error of U).  Bands, derived: with M
 * independent realizations (seeds 1..M), the ensemble mean is
 * N(K[d], s2 / M) exactly, so z = (mean - K[d]) / sqrt(s2 / M) ~ N(0, 1);
 * the variance about the known mean, v = (1/M) sum (Z - K[d])^2, has
 * M v / s2 ~ chi2_M exactly.  Over G grid samples (those with s2 > 1e-6
 * R(0); the data samples are checked for exactness above) at a family-wise
 * false-alarm rate of 1e-3 (Bonferroni, valid under any dependence between
 * samples): |z| <= Phi^-1(1 - 1e-3 / (4 G)) and chi2_M quantiles
 * 1e-3 / (4 G) and 1 - 1e-3 / (4 G) (the 1e-3 split between the two
 * tests).  Ordinary and simple kriging, global and local (nmax nearest
 * data: still a linear unbiased predictor, so the same argument holds with
 * that kriging's estimate and variance). */
static void ensemble_matches_kriging(int simple, size_t nmax)
{
    enum { M = 2000, N = 20 };
    nl_model *m = test_model("markov:scale=2.5");
    const size_t g[2] = {24, 20};
    const double h[2] = {1, 1}, lo[2] = {0, 0};
    double pts[2 * N], val[N], mu = simple ? 1.9 : 0;
    data_on_samples(N, g, lo, h, 0, g[0], 11, pts, val);
    nl_field *f = nl_field_alloc(2, g, h, NULL), *est = nl_field_alloc(2, g, h, NULL),
             *var = nl_field_alloc(2, g, h, NULL);
    size_t G = f->count;
    double *s1 = calloc(G, sizeof *s1), *s2 = calloc(G, sizeof *s2);
    nl_krige_plan *kp;
    nl_condsim_plan *p;
    nl_synth_circulant_plan *cp;
    if (nmax) {
        nl_krige_local *kl;
        nl_krige_local_options o = {.nmax = nmax, .drift = simple ? NL_DRIFT_NONE : NL_DRIFT_CONSTANT, .mean = mu};
        cr_assert_eq(nl_krige_local_alloc(m, 2, N, pts, val, &o, &kl), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_krige_local_grid(kl, lo, est, var), 0, "%s", nl_errmsg());
        nl_krige_local_free(kl);
        kp = NULL;
    } else {
        cr_assert_eq(nl_krige_plan_alloc(m, 2, N, pts, val, simple, mu, 1, &kp), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_krige_eval_grid(kp, lo, est, var), 0);
    }
    nl_condsim_options o = {.simple = simple, .mean = mu, .nmax = nmax};
    cr_assert_eq(nl_condsim_plan_alloc(m, N, pts, val, lo, f, &o, 0, NULL, &p), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, g, h, 0, 16, &cp), 0, "%s", nl_errmsg());
    for (uint64_t s = 1; s <= M; s++) {
        cr_assert_eq(nl_synth_circulant_execute(cp, s, f), 0);
        cr_assert_eq(nl_condsim_execute(p, f, s, NULL), 0, "%s", nl_errmsg());
        for (size_t i = 0; i < G; i++) {
            double e = f->data[i] - est->data[i];
            s1[i] += e, s2[i] += e * e;
        }
    }
    size_t used = 0;
    for (size_t i = 0; i < G; i++)
        used += var->data[i] > 1e-6;
    double a = 1e-3 / (4 * (double)used), zc = gsl_cdf_ugaussian_Qinv(a);
    double clo = gsl_cdf_chisq_Pinv(a, M) / M, chi = gsl_cdf_chisq_Qinv(a, M) / M, zmax = 0, rlo = INFINITY,
           rhi = 0;
    for (size_t i = 0; i < G; i++) {
        if (var->data[i] <= 1e-6)
            continue;
        double z = s1[i] / M / sqrt(var->data[i] / M), r = s2[i] / M / var->data[i];
        zmax = fmax(zmax, fabs(z)), rlo = fmin(rlo, r), rhi = fmax(rhi, r);
        cr_expect(fabs(z) <= zc, "sample %zu: ensemble mean %.3g sd of the mean from the kriging estimate", i, z);
        cr_expect(r >= clo && r <= chi, "sample %zu: ensemble variance / kriging variance %.3f outside %.3f..%.3f", i,
                  r, clo, chi);
    }
    cr_log_info("%s kriging (nmax %zu), %zu samples, M = %d: max |z| of the mean %.2f (band %.2f); variance ratio %.3f..%.3f "
                "(band %.3f..%.3f)", simple ? "simple" : "ordinary", nmax, used, M, zmax, zc, rlo, rhi, clo, chi);
    nl_synth_circulant_plan_free(cp), nl_condsim_plan_free(p), nl_krige_plan_free(kp);
    nl_field_free(f), nl_field_free(est), nl_field_free(var), nl_model_free(m);
    free(s1), free(s2);
}

Test(condsim, ensemble_mean_and_variance_are_ordinary_kriging)
{
    ensemble_matches_kriging(0, 0);
}

Test(condsim, ensemble_mean_and_variance_are_local_kriging)
{
    ensemble_matches_kriging(0, 6);
}

Test(condsim, ensemble_mean_and_variance_are_simple_kriging)
{
    ensemble_matches_kriging(1, 0);
}

/* Far from the data, the conditional field is the unconditional one: with
 * simple kriging (mean 0) the estimate and the kriging correction decay as
 * R(distance), e^-16 here (data in the first 16 of 96 columns of
 * markov:scale=2, the window from column 48 on).  The window's ensemble
 * ACF must then be the model's within the Isserlis bands of tests/stat.h. */
typedef struct {
    nl_synth_circulant_plan *cp; /* unconditional synthesis on the full grid */
    nl_condsim_plan *p;          /* conditioning */
    nl_field *full;              /* the full grid */
} far_ctx;

static int far_window(void *ctx, uint64_t seed, nl_field *out)
{
    far_ctx *c = ctx;
    int st = nl_synth_circulant_execute(c->cp, seed, c->full);
    if (!st)
        st = nl_condsim_execute(c->p, c->full, seed, NULL);
    for (size_t j = 0; !st && j < out->n[1]; j++)
        for (size_t i = 0; i < out->n[0]; i++)
            out->data[j * out->n[0] + i] = c->full->data[j * c->full->n[0] + 48 + i];
    return st;
}

static double r_markov2(double x, double y)
{
    return exp(-sqrt(x * x + y * y) / 2);
}

Test(condsim, far_from_the_data_the_covariance_is_the_models)
{
    nl_model *m = test_model("markov:scale=2");
    const size_t g[2] = {96, 32}, w[2] = {48, 32};
    const double lo[2] = {0, 0};
    double pts[2 * 30], val[30];
    far_ctx c = {0};
    long lags[64][2];
    size_t L = stat_lags_2d(lags);
    data_on_samples(30, g, lo, (double[]){1, 1}, 0, 16, 3, pts, val);
    c.full = nl_field_alloc(2, g, NULL, NULL);
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, g, NULL, 0, 16, &c.cp), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_condsim_plan_alloc(m, 30, pts, val, lo, c.full, &(nl_condsim_options){.simple = 1}, 0, NULL,
                                       &c.p), 0, "%s", nl_errmsg());
    stat_check_acf("conditional, far window", far_window, &c, w, r_markov2, 0, 200, (const long(*)[2])lags, L);
    nl_synth_circulant_plan_free(c.cp), nl_condsim_plan_free(c.p), nl_field_free(c.full), nl_model_free(m);
}

/* Between samples: the stated screening error is the standard deviation
 * of the change in a site's conditional mean between 4 and 6 samples per
 * axis.  The 1D exponential is Markov: given the two samples around a
 * point, the others tell nothing more, so the error is 0 (to rounding:
 * 1e-7, the square root of a difference of O(1) variances near 1e-16);
 * in 2D it is not (markov:scale=4 here: the error is positive but small,
 * below 0.05).  A datum outside the extent is refused, named. */
Test(condsim, states_the_screening_error)
{
    nl_model *m = test_model("markov:scale=4");
    const size_t g2[2] = {8, 8}, g1[1] = {16};
    const double lo[2] = {0, 0};
    double pt[2] = {3, 4.3}, v = 1;
    nl_field *f = nl_field_alloc(2, g2, NULL, NULL), *f1 = nl_field_alloc(1, g1, NULL, NULL);
    nl_condsim_plan *p;
    nl_condsim_info info;
    cr_assert_eq(nl_condsim_plan_alloc(m, 1, pt, &v, lo, f, NULL, 0, NULL, &p), 0, "%s", nl_errmsg());
    nl_condsim_plan_info(p, &info);
    cr_expect(info.sites == 1 && info.hood == NL_CONDSIM_HOOD && info.groups == 1 && info.largest == 16);
    cr_expect(info.screening > 1e-4 && info.screening < 0.05, "2D: %g", info.screening);
    cr_expect(info.on_samples == 0 && fabs(info.max_move - sqrt(0.5 * 0.5 + 0.2 * 0.2)) < 1e-12, "%g",
              info.max_move);
    nl_condsim_plan_free(p);
    cr_assert_eq(nl_condsim_plan_alloc(m, 1, pt, &v, lo, f1, NULL, 0, NULL, &p), 0, "%s", nl_errmsg());
    nl_condsim_plan_info(p, &info);
    cr_expect(info.screening < 1e-7, "1D: %g", info.screening);
    nl_condsim_plan_free(p);
    pt[0] = 9; /* outside the extent 0:8 */
    cr_expect_eq(nl_condsim_plan_alloc(m, 1, pt, &v, lo, f, NULL, 0, NULL, &p), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "datum 1") != NULL, "%s", nl_errmsg());
    pt[0] = 3;
    cr_expect_eq(nl_condsim_plan_alloc(m, 1, pt, &v, lo, f, NULL, 1, (double[]){1, -1}, &p), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "point 1") != NULL, "%s", nl_errmsg());
    nl_field_free(f), nl_field_free(f1), nl_model_free(m);
}

/* The command: K realizations in K files, each honouring data on samples
 * to float32 rounding (EXR stores floats: |error| <= 2^-24 |d| < 1e-6 for
 * |d| < 4), each from its own seed, and the report counts the data on
 * samples. */
Test(condsim, cli_realizations_honour_the_data)
{
    char cmd[1024], path[512];
    const char *d = scratch_dir();
    const size_t g[2] = {32, 32};
    const double lo[2] = {-0.5, -0.5}, h[2] = {1, 1};
    double pts[2 * 15], val[15];
    data_on_samples(15, g, lo, h, 0, g[0], 8, pts, val);
    snprintf(path, sizeof path, "%s/cond.tsv", d);
    FILE *fp = fopen(path, "w");
    fputs("x\ty\tvalue\n", fp);
    for (int i = 0; i < 15; i++)
        fprintf(fp, "%.17g\t%.17g\t%.17g\n", pts[2 * i], pts[2 * i + 1], val[i]);
    fclose(fp);
    snprintf(cmd, sizeof cmd, "synth circulant --acf markov:scale=3 --size 32x32 --condition %s --extent "
             "-0.5:31.5,-0.5:31.5 --realizations 3 --seed 7 --json -o %s/z.exr", path, d);
    json_t *j = run_noiselab_json(cmd);
    cr_expect_eq(json_integer_value(json_object_get(json_object_get(j, "condition"), "on_samples")), 15);
    json_decref(j);
    double first[15];
    for (int k = 1; k <= 3; k++) {
        nl_field *f;
        nl_meta meta;
        double z[15];
        snprintf(path, sizeof path, "%s/z-%d.exr", d, k);
        cr_assert_eq(nl_field_read(path, &f, &meta), 0, "%s", nl_errmsg());
        cr_expect_eq(strtoull(meta.seed, NULL, 10), 6 + (unsigned)k);
        cr_assert_eq(nl_field_sample(f, (double[]){0, 0}, NL_INTERP_NEAREST, 15, pts, z), 0);
        for (int i = 0; i < 15; i++)
            cr_expect(fabs(z[i] - val[i]) < 1e-6, "realization %d datum %d: %.9g vs %.9g", k, i, z[i], val[i]);
        if (k == 1)
            memcpy(first, f->data, sizeof first);
        else
            cr_expect(memcmp(first, f->data, sizeof first) != 0, "realization %d repeats the first", k);
        nl_field_free(f);
    }
}
