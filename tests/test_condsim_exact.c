/* Conditional simulation with data and points between samples
 * (analysis/condsim.h): the exact joint law, and the kept kriging weights
 * against kriging anew. */
#include "../analysis/condsim.h"
#include "../analysis/krige.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/circulant.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <omp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Property: in 1D with the exponential covariance (markov:, a Markov
 * process: given the samples on either side of a point, the rest of the
 * grid tells nothing more), the field at data between samples drawn given
 * its neighbourhood has exactly the joint law of the process with the
 * grid, so over realizations Z has the kriging estimate as mean and the
 * kriging variance s2 as variance at every cell and at every point (the
 * points between samples too, one of them in the interval of two data).
 * Reading U at the data by interpolation instead (the old way) makes the
 * variance next to such data wrong by tens of percent with scale 1 and
 * unit spacing.
 * Bands, derived: with M independent realizations (circulant embedding is
 * exact; seeds 1..M), z = (mean - K[d]) / sqrt(s2 / M) ~ N(0, 1) and
 * M v / s2 ~ chi2_M for v = (1/M) sum (Z - K[d])^2; over the G cells and
 * points with s2 > 1e-6 at a family-wise false-alarm rate of 1e-3
 * (Bonferroni, valid under dependence), |z| <= Phi^-1(1 - 1e-3 / (4 G))
 * and v / s2 within the chi2_M quantiles 1e-3 / (4 G), 1 - 1e-3 / (4 G):
 * about +-9% at M = 4000, G = 43. */
Test(condsim_exact, markov_1d_has_the_kriging_law_between_samples)
{
    enum { N = 40, D = 6, P = 3, M = 4000 };
    nl_model *m = test_model("markov:scale=1");
    const size_t g[1] = {N};
    const double lo[1] = {0};
    double pts[D] = {5.0, 5.3, 12.8, 20.1, 28.0, 33.77}, val[D], at[P] = {8.25, 12.6, 30.0};
    for (int i = 0; i < D; i++)
        val[i] = 2.385 + nl_rng_gauss(7, 1, (uint64_t)i);
    nl_field *f = nl_field_alloc(1, g, NULL, NULL);
    size_t G = N + P;
    double est[N + P], var[N + P], s1[N + P] = {0}, s2[N + P] = {0}, x[N + P], z[P];
    for (int i = 0; i < N; i++)
        x[i] = lo[0] + i + 0.5;
    memcpy(x + N, at, sizeof at);
    nl_krige_plan *kp;
    cr_assert_eq(nl_krige_plan_alloc(m, 1, D, pts, val, 0, 0, 1, &kp), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_krige_eval_block(kp, G, x, est, var), 0);
    nl_condsim_plan *p;
    nl_synth_circulant_plan *cp;
    cr_assert_eq(nl_condsim_plan_alloc(m, D, pts, val, lo, f, NULL, P, at, &p), 0, "%s", nl_errmsg());
    nl_condsim_info info;
    nl_condsim_plan_info(p, &info);
    cr_expect(info.sites == D + P && info.on_samples == 0 && info.reuse == 1, "%zu %zu", info.sites, info.on_samples);
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 1, g, NULL, 0, 16, &cp), 0, "%s", nl_errmsg());
    for (uint64_t s = 1; s <= M; s++) {
        cr_assert_eq(nl_synth_circulant_execute(cp, s, f), 0);
        cr_assert_eq(nl_condsim_execute(p, f, s, z), 0, "%s", nl_errmsg());
        for (size_t i = 0; i < G; i++) {
            double e = (i < N ? f->data[i] : z[i - N]) - est[i];
            s1[i] += e, s2[i] += e * e;
        }
    }
    size_t used = 0;
    for (size_t i = 0; i < G; i++)
        used += var[i] > 1e-6;
    double a = 1e-3 / (4 * (double)used), zc = gsl_cdf_ugaussian_Qinv(a);
    double clo = gsl_cdf_chisq_Pinv(a, M) / M, chi = gsl_cdf_chisq_Qinv(a, M) / M, zmax = 0, rlo = INFINITY, rhi = 0;
    for (size_t i = 0; i < G; i++) {
        if (var[i] <= 1e-6)
            continue;
        double zz = s1[i] / M / sqrt(var[i] / M), r = s2[i] / M / var[i];
        zmax = fmax(zmax, fabs(zz)), rlo = fmin(rlo, r), rhi = fmax(rhi, r);
        cr_expect(fabs(zz) <= zc, "%s %zu at %g: ensemble mean %.3g sd of the mean from the kriging estimate",
                  i < N ? "cell" : "point", i < N ? i : i - N, x[i], zz);
        cr_expect(r >= clo && r <= chi, "%s %zu at %g: ensemble variance / kriging variance %.3f outside %.3f..%.3f",
                  i < N ? "cell" : "point", i < N ? i : i - N, x[i], r, clo, chi);
    }
    cr_log_info("1D markov, %zu cells and points, M = %d: max |z| %.2f (band %.2f), variance ratio %.3f..%.3f "
                "(band %.3f..%.3f)", used, M, zmax, zc, rlo, rhi, clo, chi);
    nl_synth_circulant_plan_free(cp), nl_condsim_plan_free(p), nl_krige_plan_free(kp);
    nl_field_free(f), nl_model_free(m);
}

/* The kept weights give the field that kriging each realization's
 * residual anew gives (analysis/krige.h globally, krige_local.h with nmax),
 * at the cells and at the points, for ordinary and simple kriging, with a
 * nugget and data on and between samples.  Tolerance 1e-9 on O(1) values:
 * the two compute the same linear combination by different orders of
 * operations (one Cholesky and the weights, or GSL's Cholesky and dual
 * weights); their difference is the rounding error, a few hundred ulps
 * times the condition number of the systems (rcond ~ 1e-3 here). */
static void weights_match(int simple, size_t nmax)
{
    enum { N = 40, P = 7 };
    nl_model *m = test_model("spherical:var=1.3,scale=9,nugget=0.1");
    const size_t g[2] = {30, 25};
    const double h[2] = {0.7, 0.7}, lo[2] = {-2.1, 3.4};
    double pts[2 * N], val[N], at[2 * P], za[P], zb[P];
    for (int i = 0; i < N; i++) {
        for (int a = 0; a < 2; a++)
            pts[2 * i + a] = lo[a] + nl_rng_uniform(3, (uint32_t)a, (uint64_t)i) * (double)g[a] * h[a];
        val[i] = 2.385 + nl_rng_gauss(3, 2, (uint64_t)i);
    }
    for (int i = 0; i < 3; i++) /* three on samples */
        pts[2 * i] = lo[0] + (4.0 * i + 0.5) * h[0], pts[2 * i + 1] = lo[1] + (3.0 * i + 2.5) * h[1];
    for (int j = 0; j < P; j++)
        for (int a = 0; a < 2; a++)
            at[2 * j + a] = lo[a] + nl_rng_uniform(4, (uint32_t)a, (uint64_t)j) * (double)g[a] * h[a];
    nl_field *fa = nl_field_alloc(2, g, h, NULL), *fb = nl_field_alloc(2, g, h, NULL);
    nl_condsim_plan *pa, *pb;
    nl_condsim_options oa = {.simple = simple, .mean = 2.1, .nmax = nmax}, ob = oa;
    ob.rekrige = 1;
    cr_assert_eq(nl_condsim_plan_alloc(m, N, pts, val, lo, fa, &oa, P, at, &pa), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_condsim_plan_alloc(m, N, pts, val, lo, fb, &ob, P, at, &pb), 0, "%s", nl_errmsg());
    nl_condsim_info ia, ib;
    nl_condsim_plan_info(pa, &ia), nl_condsim_plan_info(pb, &ib);
    cr_expect(ia.reuse == 1 && ib.reuse == 0 && ia.on_samples == 3, "%d %d %zu", ia.reuse, ib.reuse, ia.on_samples);
    nl_synth_circulant_plan *cp;
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, g, h, 0, 16, &cp), 0, "%s", nl_errmsg());
    double dmax = 0;
    for (uint64_t s = 1; s <= 3; s++) {
        cr_assert_eq(nl_synth_circulant_execute(cp, s, fa), 0);
        memcpy(fb->data, fa->data, fa->count * sizeof *fa->data);
        cr_assert_eq(nl_condsim_execute(pa, fa, s, za), 0, "%s", nl_errmsg());
        cr_assert_eq(nl_condsim_execute(pb, fb, s, zb), 0, "%s", nl_errmsg());
        for (size_t i = 0; i < fa->count; i++)
            dmax = fmax(dmax, fabs(fa->data[i] - fb->data[i]));
        for (int j = 0; j < P; j++)
            dmax = fmax(dmax, fabs(za[j] - zb[j]));
    }
    cr_expect(dmax < 1e-9, "%s kriging, nmax %zu: kept weights and kriging anew differ by %.3g", simple ? "simple"
              : "ordinary", nmax, dmax);
    nl_synth_circulant_plan_free(cp), nl_condsim_plan_free(pa), nl_condsim_plan_free(pb);
    nl_field_free(fa), nl_field_free(fb), nl_model_free(m);
}

Test(condsim_exact, kept_weights_are_kriging_anew_global)
{
    weights_match(0, 0);
    weights_match(1, 0);
}

Test(condsim_exact, kept_weights_are_kriging_anew_local)
{
    weights_match(0, 8);
    weights_match(1, 8);
}

/* A realization is a function of its seed: the same seed gives the same
 * bits, another seed other values at data between samples (their draws
 * come from the seed's stream NL_STREAM_CONDSIM), whatever the thread
 * count (parallel loops fill fixed per-cell sums). */
Test(condsim_exact, draws_come_from_the_seed)
{
    nl_model *m = test_model("markov:scale=2");
    const size_t g[2] = {16, 16};
    const double lo[2] = {0, 0};
    double pts[4] = {3.3, 4.1, 9.7, 12.2}, val[2] = {1, -1}, z1[1], z2[1], z3[1];
    nl_field *f = nl_field_alloc(2, g, NULL, NULL), *u = nl_field_alloc(2, g, NULL, NULL);
    nl_condsim_plan *p;
    cr_assert_eq(nl_condsim_plan_alloc(m, 2, pts, val, lo, f, NULL, 1, (double[]){7.6, 7.6}, &p), 0, "%s",
                 nl_errmsg());
    for (size_t i = 0; i < u->count; i++)
        u->data[i] = nl_rng_gauss(5, 0, i);
    memcpy(f->data, u->data, u->count * sizeof *u->data);
    cr_assert_eq(nl_condsim_execute(p, f, 11, z1), 0);
    double first = f->data[0];
    memcpy(f->data, u->data, u->count * sizeof *u->data);
    cr_assert_eq(nl_condsim_execute(p, f, 11, z2), 0);
    cr_expect(f->data[0] == first && z1[0] == z2[0]);
    memcpy(f->data, u->data, u->count * sizeof *u->data);
    cr_assert_eq(nl_condsim_execute(p, f, 12, z3), 0);
    cr_expect(f->data[0] != first && z3[0] != z1[0]);
    nl_condsim_plan_free(p), nl_field_free(f), nl_field_free(u), nl_model_free(m);
}

/* The bits do not depend on the thread count: the weights of the 750
 * cells are computed in parallel (above 256 locations), each cell's from
 * its own neighbourhood, and the draws per group; one thread and two give
 * the same field and the same values at the points, bit for bit. */
Test(condsim_exact, bits_do_not_depend_on_the_thread_count)
{
    enum { N = 30, P = 4 };
    nl_model *m = test_model("spherical:var=1.3,scale=9,nugget=0.1");
    const size_t g[2] = {30, 25};
    const double lo[2] = {0, 0};
    double pts[2 * N], val[N], at[2 * P] = {3.3, 4.4, 10.1, 20.7, 29.5, 0.2, 15.55, 12.45}, z[2][P];
    for (int i = 0; i < N; i++) {
        pts[2 * i] = nl_rng_uniform(6, 0, (uint64_t)i) * 30, pts[2 * i + 1] = nl_rng_uniform(6, 1, (uint64_t)i) * 25;
        val[i] = nl_rng_gauss(6, 2, (uint64_t)i);
    }
    nl_field *f[2] = {nl_field_alloc(2, g, NULL, NULL), nl_field_alloc(2, g, NULL, NULL)};
    int threads = omp_get_max_threads();
    for (int t = 0; t < 2; t++) {
        nl_condsim_plan *p;
        omp_set_num_threads(t + 1);
        cr_assert_eq(nl_condsim_plan_alloc(m, N, pts, val, lo, f[t], &(nl_condsim_options){.nmax = 10}, P, at, &p), 0,
                     "%s", nl_errmsg());
        for (size_t i = 0; i < f[t]->count; i++)
            f[t]->data[i] = nl_rng_gauss(9, 0, i);
        cr_assert_eq(nl_condsim_execute(p, f[t], 4, z[t]), 0, "%s", nl_errmsg());
        nl_condsim_plan_free(p);
    }
    omp_set_num_threads(threads);
    cr_expect(memcmp(f[0]->data, f[1]->data, f[0]->count * sizeof *f[0]->data) == 0, "the fields differ");
    cr_expect(memcmp(z[0], z[1], sizeof z[0]) == 0, "the points differ");
    nl_field_free(f[0]), nl_field_free(f[1]), nl_model_free(m);
}
