/* Kriging (Stam and Fiume 1991, eqs. 19-22). */
#include "../analysis/krige.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/fft.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

/* random points in [0, 1]^dim and values */
static void data(size_t n, int dim, uint64_t seed, double *pts, double *val)
{
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < dim; a++)
            pts[i * dim + a] = nl_rng_uniform(seed, 1, i * 3 + (uint64_t)a);
        val[i] = 2.385 + nl_rng_gauss(seed, 2, i);
    }
}

Test(krige, interpolates_the_data_exactly)
{
    nl_model *m = test_model("gauss:scale=0.3,angle=25,ratio=0.5");
    double pts[2 * 12], val[12];
    nl_krige_plan *p;
    data(12, 2, 1, pts, val);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 12, pts, val, 0, 0, 1, &p), 0, "%s", nl_errmsg());
    for (int i = 0; i < 12; i++) {
        double e, v;
        cr_assert_eq(nl_krige_eval(p, pts + 2 * i, &e, &v, NULL), 0);
        cr_expect_float_eq(e, val[i], 1e-9, "datum %d", i);
        cr_expect_lt(v, 1e-9, "kriging variance %g at datum %d", v, i);
    }
    nl_krige_plan_free(p), nl_model_free(m);
}

/* Ordinary kriging weights sum to 1 and equal a direct dense solve of the
 * bordered system [C 1; 1^T 0][lambda; nu] = [c0; 1] (GSL LU) to 1e-10. */
Test(krige, matches_the_bordered_system)
{
    nl_model *m = test_model("markov:scale=0.4,angle=10,ratio=0.7,zratio=0.5");
    enum { N = 25 };
    double pts[3 * N], val[N], lam[N];
    nl_krige_plan *p;
    data(N, 3, 7, pts, val);
    cr_assert_eq(nl_krige_plan_alloc(m, 3, N, pts, val, 0, 0, 1, &p), 0, "%s", nl_errmsg());
    for (int t = 0; t < 5; t++) {
        double x[3] = {0.13 * t, 0.5, 1 - 0.2 * t}, e, v, ed = 0, sum = 0;
        gsl_matrix *A = gsl_matrix_alloc(N + 1, N + 1);
        gsl_vector *b = gsl_vector_alloc(N + 1), *s = gsl_vector_alloc(N + 1);
        gsl_permutation *perm = gsl_permutation_alloc(N + 1);
        int sgn;
        for (int i = 0; i <= N; i++) {
            for (int j = 0; j <= N; j++) {
                double lag[3];
                for (int a = 0; a < 3; a++)
                    lag[a] = i < N && j < N ? pts[3 * i + a] - pts[3 * j + a] : 0;
                gsl_matrix_set(A, i, j, i < N && j < N ? nl_model_acf(m, 3, lag) : (i == N && j == N ? 0 : 1));
            }
            double lag[3];
            for (int a = 0; a < 3; a++)
                lag[a] = i < N ? x[a] - pts[3 * i + a] : 0;
            gsl_vector_set(b, i, i < N ? nl_model_acf(m, 3, lag) : 1);
        }
        gsl_linalg_LU_decomp(A, perm, &sgn);
        gsl_linalg_LU_solve(A, perm, b, s);
        cr_assert_eq(nl_krige_eval(p, x, &e, &v, lam), 0);
        for (int i = 0; i < N; i++) {
            cr_expect_float_eq(lam[i], gsl_vector_get(s, i), 1e-10, "lambda_%d", i);
            ed += gsl_vector_get(s, i) * val[i];
            sum += lam[i];
        }
        cr_expect_float_eq(sum, 1.0, 1e-10);
        cr_expect_float_eq(e, ed, 1e-10);
        gsl_matrix_free(A), gsl_vector_free(b), gsl_vector_free(s), gsl_permutation_free(perm);
    }
    nl_krige_plan_free(p), nl_model_free(m);
}

/* The variance grows away from the data and reaches the sill far away:
 * R(0) plus the variance of the estimated mean, 1 / 1^T C^-1 1, for
 * ordinary kriging; R(0) exactly for simple kriging. */
Test(krige, variance_reaches_the_sill)
{
    nl_model *m = test_model("markov:scale=0.1");
    double pts[2 * 10], val[10], last = -1;
    nl_krige_plan *po, *ps;
    data(10, 2, 3, pts, val);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 10, pts, val, 0, 0, 1, &po), 0);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 10, pts, val, 1, 2.385, 1, &ps), 0);
    for (double d = 0; d <= 3; d += 0.25) {
        double x[2] = {pts[0] + d, pts[1]}, e, v;
        nl_krige_eval(po, x, &e, &v, NULL);
        cr_expect_geq(v, last - 1e-12, "variance falls at distance %g", d);
        last = v;
    }
    double far[2] = {100, 100}, e, v;
    nl_krige_eval(ps, far, &e, &v, NULL);
    cr_expect_float_eq(v, 1.0, 1e-12);
    cr_expect_float_eq(e, 2.385, 1e-12, "far from data the simple kriging estimate is the mean");
    nl_krige_eval(po, far, &e, &v, NULL);
    cr_expect_gt(v, 1.0);
    cr_expect_lt(v, 1.5);
    nl_krige_plan_free(po), nl_krige_plan_free(ps), nl_model_free(m);
}

/* Singular systems both ways: duplicate points are solved by the
 * pseudo-inverse and flagged, or refused when strict; distinct points of a
 * Markov model are regular. */
Test(krige, singular_systems)
{
    nl_model *m = test_model("gauss:scale=0.5");
    double pts[6] = {0.1, 0.2, 0.1, 0.2, 0.7, 0.4}, val[3] = {1, 1, 2};
    nl_krige_plan *p;
    nl_krige_info info;
    cr_expect_eq(nl_krige_plan_alloc(m, 2, 3, pts, val, 0, 0, 1, &p), NL_EINVAL);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 3, pts, val, 0, 0, 0, &p), 0);
    nl_krige_plan_info(p, &info);
    cr_expect(info.pseudo_inverse);
    double e;
    nl_krige_eval(p, pts, &e, NULL, NULL);
    cr_expect_float_eq(e, 1.0, 1e-6, "the duplicate datum is still interpolated");
    nl_krige_plan_free(p), nl_model_free(m);
    m = test_model("markov:scale=0.5");
    double q[6] = {0.1, 0.2, 0.3, 0.2, 0.7, 0.4};
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 3, q, val, 0, 0, 1, &p), 0);
    nl_krige_plan_info(p, &info);
    cr_expect_not(info.pseudo_inverse);
    nl_krige_plan_free(p), nl_model_free(m);
}

/* Calibration: on FFT-synthesised fields with the same model, krige from
 * 300 sampled grid points and compare the squared error at 2000 held-out
 * points with the predicted kriging variance.  The ratio of the mean
 * squared error to the mean variance is 1 for a correct predictor; over 10
 * fields and 20000 (correlated) errors its sampling spread is a few
 * percent; 20% bounds it with margin. */
Test(krige_slow, calibration)
{
    nl_model *m = test_model("markov:scale=8");
    size_t n[2] = {128, 128};
    nl_synth_fft_plan *fp;
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    double se = 0, sv = 0;
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &fp), 0);
    for (uint64_t s = 1; s <= 10; s++) {
        double pts[600], val[300];
        nl_krige_plan *p;
        nl_synth_fft_execute(fp, s, f);
        for (int i = 0; i < 300; i++) {
            size_t q = (size_t)(nl_rng_uniform(s, 9, (uint64_t)i) * 128 * 128);
            pts[2 * i] = (double)(q % 128), pts[2 * i + 1] = (double)(q / 128), val[i] = f->data[q];
        }
        cr_assert_eq(nl_krige_plan_alloc(m, 2, 300, pts, val, 0, 0, 0, &p), 0);
        for (int i = 0; i < 2000; i++) {
            /* held-out points away from the borders (the field is periodic, kriging is not) */
            size_t x = 16 + (size_t)(nl_rng_uniform(s, 10, (uint64_t)i) * 96), y = 16 + (size_t)(nl_rng_uniform(s, 11, (uint64_t)i) * 96);
            double xy[2] = {(double)x, (double)y}, e, v;
            nl_krige_eval(p, xy, &e, &v, NULL);
            se += (e - f->data[y * 128 + x]) * (e - f->data[y * 128 + x]);
            sv += v;
        }
        nl_krige_plan_free(p);
    }
    cr_log_info("kriging calibration: mean squared error / mean kriging variance = %.3f", se / sv);
    cr_expect_float_eq(se / sv, 1.0, 0.2, "calibration ratio %.3f", se / sv);
    nl_synth_fft_plan_free(fp), nl_field_free(f), nl_model_free(m);
}

/* The blocked evaluation gives nl_krige_eval's estimates and variances to
 * rounding (1e-10 absolute; both are O(1)), for ordinary and simple kriging,
 * with a last block shorter than NL_KRIGE_BLOCK. */
Test(krige, blocked_evaluation_equals_pointwise)
{
    enum { N = 300, Q = 2 * NL_KRIGE_BLOCK + 17 };
    double *pts = malloc(2 * N * sizeof *pts), *val = malloc(N * sizeof *val), x[2 * Q], e[Q], v[Q];
    nl_model *m = test_model("markov:scale=0.2,angle=30,ratio=0.5");
    data(N, 2, 11, pts, val);
    for (size_t q = 0; q < 2 * Q; q++)
        x[q] = nl_rng_uniform(12, 0, q);
    for (int simple = 0; simple < 2; simple++) {
        nl_krige_plan *p;
        double dmax = 0;
        cr_assert_eq(nl_krige_plan_alloc(m, 2, N, pts, val, simple, 2.0, 1, &p), 0);
        cr_assert_eq(nl_krige_eval_block(p, Q, x, e, v), 0);
        for (size_t q = 0; q < Q; q++) {
            double e1, v1;
            cr_assert_eq(nl_krige_eval(p, x + 2 * q, &e1, &v1, NULL), 0);
            dmax = fmax(dmax, fmax(fabs(e1 - e[q]), fabs(v1 - v[q])));
            cr_expect(v[q] > 0.01, "variance %g at a point away from the data", v[q]);
        }
        cr_expect_leq(dmax, 1e-10, "simple %d: largest difference %g", simple, dmax);
        nl_krige_plan_free(p);
    }
    nl_model_free(m), free(pts), free(val);
}

/* Kriging a grid gives the same bits with 1 and 2 OpenMP threads: each
 * block's arithmetic does not depend on which thread runs it. */
Test(krige, bit_reproducible_across_threads)
{
    enum { N = 200, Q = 4096 };
    double *pts = malloc(2 * N * sizeof *pts), *val = malloc(N * sizeof *val), *x = malloc(2 * Q * sizeof *x);
    double *e[2] = {malloc(Q * sizeof(double)), malloc(Q * sizeof(double))};
    double *v[2] = {malloc(Q * sizeof(double)), malloc(Q * sizeof(double))};
    nl_model *m = test_model("markov:scale=0.2");
    nl_krige_plan *p;
    data(N, 2, 13, pts, val);
    for (size_t q = 0; q < 2 * Q; q++)
        x[q] = nl_rng_uniform(14, 0, q);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, N, pts, val, 0, 0, 1, &p), 0);
    for (int t = 0; t < 2; t++) {
        omp_set_num_threads(t + 1);
#pragma omp parallel for schedule(dynamic, 1)
        for (size_t q0 = 0; q0 < Q; q0 += NL_KRIGE_BLOCK)
            nl_krige_eval_block(p, NL_KRIGE_BLOCK, x + 2 * q0, e[t] + q0, v[t] + q0);
    }
    cr_expect_eq(memcmp(e[0], e[1], Q * sizeof(double)), 0);
    cr_expect_eq(memcmp(v[0], v[1], Q * sizeof(double)), 0);
    nl_krige_plan_free(p), nl_model_free(m);
    free(pts), free(val), free(x), free(e[0]), free(e[1]), free(v[0]), free(v[1]);
}

/* nl_krige_eval_grid evaluates at the cell centres lo + (i + 1/2) h: it
 * equals nl_krige_eval_block on those points bit for bit (the same code
 * path), and nl_krige_eval to rounding (1e-12 of R(0)). */
Test(krige, eval_grid_at_cell_centres)
{
    nl_model *m;
    nl_krige_plan *p;
    double pts[8] = {0.11, 0.23, 0.71, 0.35, 0.42, 0.87, 0.93, 0.94}, val[4] = {1.5, -0.5, 0.25, 2.385};
    double lo[2] = {-0.2, 0.1};
    size_t n[2] = {13, 9};
    double h[2] = {1.4 / 13, 0.9 / 9};
    cr_assert_eq(nl_model_parse("gauss:scale=0.3", &m), NL_OK);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 4, pts, val, 0, 0, 0, &p), NL_OK);
    nl_field *e = nl_field_alloc(2, n, h, NULL), *v = nl_field_alloc(2, n, h, NULL);
    cr_assert_eq(nl_krige_eval_grid(p, lo, e, v), NL_OK);
    double *x = malloc(2 * e->count * sizeof *x), *be = malloc(e->count * sizeof *be), *bv = malloc(e->count * sizeof *bv);
    for (size_t q = 0; q < e->count; q++)
        x[2 * q] = lo[0] + ((double)(q % 13) + 0.5) * e->h[0], x[2 * q + 1] = lo[1] + ((double)(q / 13) + 0.5) * e->h[1];
    cr_assert_eq(nl_krige_eval_block(p, e->count, x, be, bv), NL_OK);
    cr_assert_arr_eq(be, e->data, e->count * sizeof *be);
    cr_assert_arr_eq(bv, v->data, e->count * sizeof *bv);
    for (size_t q = 0; q < e->count; q++) {
        double est, var;
        cr_assert_eq(nl_krige_eval(p, x + 2 * q, &est, &var, NULL), NL_OK);
        cr_assert_float_eq(e->data[q], est, 1e-12);
        cr_assert_float_eq(v->data[q], var, 1e-12);
    }
    free(x), free(be), free(bv);
    nl_field_free(e), nl_field_free(v);
    nl_krige_plan_free(p), nl_model_free(m);
}

/* A singular system (every point given twice) is solved by the
 * pseudo-inverse up to NL_KRIGE_PINV_MAX points and flagged; above that its
 * SVD (minutes at 2000 points) is refused with NL_ETOOBIG at once, naming
 * the limit and the ways out. */
Test(krige, pseudo_inverse_bounded)
{
    nl_model *m = test_model("markov:scale=0.3");
    size_t n = NL_KRIGE_PINV_MAX + 2;
    double *pts = malloc(2 * n * sizeof *pts), *val = malloc(n * sizeof *val);
    nl_krige_plan *p;
    nl_krige_info info;
    for (size_t i = 0; i < n; i++) {
        size_t k = i / 2; /* pairs of one point */
        pts[2 * i] = (double)(k % 37) / 37.0, pts[2 * i + 1] = (double)(k / 37) / 37.0, val[i] = sin(2.385 * (double)k);
    }
    cr_expect_eq(nl_krige_plan_alloc(m, 2, n, pts, val, 0, 0, 0, &p), NL_ETOOBIG);
    cr_expect(strstr(nl_errmsg(), "pseudo-inverse") != NULL, "%s", nl_errmsg());
    cr_expect_null(p);
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 40, pts, val, 0, 0, 0, &p), NL_OK, "%s", nl_errmsg());
    nl_krige_plan_info(p, &info);
    cr_expect(info.pseudo_inverse);
    nl_krige_plan_free(p), nl_model_free(m);
    free(pts), free(val);
}
