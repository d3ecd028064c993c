/* Kriging and Cholesky synthesis give the same bits for 1, 2 and 4 threads.
 *
 * Both run on BLAS: the factorisations (GSL's recursive Cholesky on
 * dtrsm/dsyrk) and the triangular solves of the kriging variance (dtrsm).
 * We link OpenBLAS's serial build (deps.txt) and take the threads from our
 * own OpenMP loops over blocks; a threaded OpenBLAS put in its place by the
 * system's alternatives splits calls made outside an OpenMP region between
 * omp_get_max_threads() threads, so the sizes are large enough that it would
 * (a 2304 x 2304 and a 1500 x 1500 factorisation, dtrsm on 1500 x
 * NL_KRIGE_BLOCK blocks, 600 x NL_KRIGE_BLOCK for universal kriging).  The
 * property checked is exact equality (memcmp), not a tolerance: a thread
 * count must not change a result. */
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../core/field.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/cholesky.h"
#include "util.h"

#include <criterion/criterion.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

static const int threads[] = {1, 2, 4};
enum { T = sizeof threads / sizeof threads[0] };

Test(blas_threads, cholesky_synthesis)
{
    size_t n[2] = {48, 48};
    nl_model *m = test_model("markov:scale=7.3");
    nl_field *f[T];
    int st, saved = omp_get_max_threads();
    for (int t = 0; t < T; t++) {
        nl_synth_cholesky_plan *p;
        omp_set_num_threads(threads[t]);
        cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 2, n, NULL, &p), NL_OK);
        f[t] = nl_field_alloc(2, n, NULL, &st);
        cr_assert_not_null(f[t]);
        cr_assert_eq(nl_synth_cholesky_execute(p, 11, f[t]), NL_OK);
        nl_synth_cholesky_plan_free(p);
    }
    omp_set_num_threads(saved);
    for (int t = 1; t < T; t++)
        cr_expect_eq(memcmp(f[0]->data, f[t]->data, f[0]->count * sizeof(double)), 0,
                     "cholesky field with %d threads differs from 1 thread", threads[t]);
    for (int t = 0; t < T; t++)
        nl_field_free(f[t]);
    nl_model_free(m);
}

/* The plan (factorisation), a grid (blocks in parallel, BLAS on one thread
 * each) and a direct nl_krige_eval_block call (outside any region: dtrsm
 * itself threaded), ordinary kriging with the variance. */
Test(blas_threads, kriging)
{
    enum { N = 1500, Q = 2 * NL_KRIGE_BLOCK + 17 };
    size_t g[2] = {96, 80};
    double *pts = malloc(2 * N * sizeof *pts), *val = malloc(N * sizeof *val), *x = malloc(2 * Q * sizeof *x);
    double *e[T], *v[T];
    nl_field *ge[T], *gv[T];
    nl_model *m = test_model("markov:scale=0.2");
    int st, saved = omp_get_max_threads();
    for (size_t i = 0; i < N; i++) {
        pts[2 * i] = nl_rng_uniform(21, 1, 2 * i), pts[2 * i + 1] = nl_rng_uniform(21, 1, 2 * i + 1);
        val[i] = 2.385 + nl_rng_gauss(21, 2, i);
    }
    for (size_t q = 0; q < 2 * Q; q++)
        x[q] = nl_rng_uniform(22, 0, q);
    for (int t = 0; t < T; t++) {
        nl_krige_plan *p;
        double lo[2] = {0, 0}, h[2] = {1.0 / 96, 1.0 / 80};
        omp_set_num_threads(threads[t]);
        cr_assert_eq(nl_krige_plan_alloc(m, 2, N, pts, val, 0, 0, 1, &p), NL_OK);
        e[t] = malloc(Q * sizeof(double)), v[t] = malloc(Q * sizeof(double));
        cr_assert_eq(nl_krige_eval_block(p, Q, x, e[t], v[t]), NL_OK);
        ge[t] = nl_field_alloc(2, g, h, &st), gv[t] = nl_field_alloc(2, g, h, &st);
        cr_assert(ge[t] && gv[t]);
        cr_assert_eq(nl_krige_eval_grid(p, lo, ge[t], gv[t]), NL_OK);
        nl_krige_plan_free(p);
    }
    omp_set_num_threads(saved);
    for (int t = 1; t < T; t++) {
        cr_expect_eq(memcmp(e[0], e[t], Q * sizeof(double)), 0, "estimates, %d threads", threads[t]);
        cr_expect_eq(memcmp(v[0], v[t], Q * sizeof(double)), 0, "variances, %d threads", threads[t]);
        cr_expect_eq(memcmp(ge[0]->data, ge[t]->data, ge[0]->count * sizeof(double)), 0, "grid, %d threads",
                     threads[t]);
        cr_expect_eq(memcmp(gv[0]->data, gv[t]->data, gv[0]->count * sizeof(double)), 0,
                     "grid variance, %d threads", threads[t]);
    }
    for (int t = 0; t < T; t++)
        free(e[t]), free(v[t]), nl_field_free(ge[t]), nl_field_free(gv[t]);
    nl_model_free(m), free(pts), free(val), free(x);
}

/* Universal kriging (linear drift) with the global neighbourhood: blocks of
 * locations solved together (dtrsm, dgemm) in an OpenMP region. */
Test(blas_threads, universal_kriging_global_neighbourhood)
{
    enum { N = 600 };
    size_t g[2] = {64, 48};
    double *pts = malloc(2 * N * sizeof *pts), *val = malloc(N * sizeof *val), lo[2] = {0, 0};
    double h[2] = {1.0 / 64, 1.0 / 48};
    nl_field *ge[T], *gv[T];
    nl_model *m = test_model("markov:scale=0.3");
    nl_krige_local_options o = {.nmax = 0, .drift = NL_DRIFT_LINEAR};
    int st, saved = omp_get_max_threads();
    for (size_t i = 0; i < N; i++) {
        pts[2 * i] = nl_rng_uniform(23, 1, 2 * i), pts[2 * i + 1] = nl_rng_uniform(23, 1, 2 * i + 1);
        val[i] = 2.385 + pts[2 * i] + nl_rng_gauss(23, 2, i);
    }
    for (int t = 0; t < T; t++) {
        nl_krige_local *k;
        omp_set_num_threads(threads[t]);
        cr_assert_eq(nl_krige_local_alloc(m, 2, N, pts, val, &o, &k), NL_OK);
        ge[t] = nl_field_alloc(2, g, h, &st), gv[t] = nl_field_alloc(2, g, h, &st);
        cr_assert(ge[t] && gv[t]);
        cr_assert_eq(nl_krige_local_grid(k, lo, ge[t], gv[t]), NL_OK);
        nl_krige_local_free(k);
    }
    omp_set_num_threads(saved);
    for (int t = 1; t < T; t++) {
        cr_expect_eq(memcmp(ge[0]->data, ge[t]->data, ge[0]->count * sizeof(double)), 0, "estimates, %d threads",
                     threads[t]);
        cr_expect_eq(memcmp(gv[0]->data, gv[t]->data, gv[0]->count * sizeof(double)), 0, "variances, %d threads",
                     threads[t]);
    }
    for (int t = 0; t < T; t++)
        nl_field_free(ge[t]), nl_field_free(gv[t]);
    nl_model_free(m), free(pts), free(val);
}
