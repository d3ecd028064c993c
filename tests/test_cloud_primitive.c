/* Stam and Fiume's primitive (render/cloud.h, synth/sparse_point.h):
 * ordinary kriging's weights sum to one (eq. (22)) and the shape honours
 * the data (eq. (19)); simple kriging tends to 0 far away, ordinary kriging
 * to its estimated mean; the three rotation angles orient the ellipsoid
 * (principal axes from the shape's second moments); the point-evaluated
 * noise is a pure function of (seed, point), refuses what it cannot do and
 * has the model's ACF; the scene keys parse, and explicit defaults change
 * no bit of a picture. */
#include "../analysis/krige.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../render/cloud_scene.h"
#include "../synth/sparse_point.h"
#include "util.h"

#include <criterion/criterion.h>
#include <gsl/gsl_eigen.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double pts[] = {0, 0.3, 0, 1.0, -1.1, 0, 0.3, 0.8, 1.2, 0.1, -0.2, 0.85, 0.3, 0.9, 0.1, 0.9,
                       -2.2, -0.3, 0, 0, 2.3, -0.3, 0, 0, 0, 2, 0, 0, 0, -1.5, 0.4, 0};

static void scene(nl_cloud_scene *s)
{
    memset(s, 0, sizeof *s);
    s->width = 8, s->height = 6;
    for (int a = 0; a < 3; a++)
        s->lo[a] = -3, s->hi[a] = 3;
    s->npoints = 8, s->points = pts;
    s->shape = test_model("gauss:scale=0.9,ratio=0.7,zratio=0.4");
    s->noise = test_model("gauss:scale=0.3");
    s->amplitude = 0.5, s->period = 1.5, s->noise_grid = 8, s->seed = 3, s->noise_density = 4;
    s->threshold = 0.2, s->extinction = 8, s->grid = 12;
    s->cam[2] = -8, s->fov = 40, s->sun[1] = 1;
    s->rotation[0] = 20.5, s->rotation[1] = -35, s->rotation[2] = 71;
}

/* The weights of ordinary kriging are a solution of [C 1; 1' 0]: their sum
 * is 1 up to the rounding of an 8 x 8 solve with entries of order 1 (about
 * n eps cond; 1e-12 leaves room for a condition number near 1e3).  At the
 * data, the estimate is the datum (an exact interpolator) to the same
 * rounding. */
Test(cloud_primitive, ordinary_weights_and_data)
{
    nl_cloud_scene s;
    scene(&s);
    enum { N = 500 };
    double x[3 * (N + 8)], K[N + 8], w[N + 8];
    for (size_t i = 0; i < 8; i++)
        memcpy(x + 3 * i, pts + 4 * i, 3 * sizeof *x);
    for (size_t i = 8; i < N + 8; i++)
        for (int a = 0; a < 3; a++)
            x[3 * i + a] = -3 + 6 * nl_rng_uniform(5, (uint32_t)a, i);
    cr_assert_eq(nl_cloud_shape_eval(&s, N + 8, x, K, w), NL_OK, "%s", nl_errmsg());
    for (size_t i = 0; i < N + 8; i++)
        cr_expect_leq(fabs(w[i] - 1), 1e-12, "point %zu: weights sum to %.17g", i, w[i]);
    for (size_t i = 0; i < 8; i++)
        cr_expect_leq(fabs(K[i] - pts[4 * i + 3]), 1e-12, "datum %zu: %.17g, not %g", i, K[i], pts[4 * i + 3]);
    nl_model_free(s.shape), nl_model_free(s.noise);
}

/* Far from every datum (1e6 away: every covariance underflows to 0) the
 * ordinary estimate is the generalised-least-squares mean b of the plan
 * and the simple one its mean, 0: both exactly. */
Test(cloud_primitive, far_value)
{
    nl_cloud_scene s;
    scene(&s);
    double far[3] = {1e6, -1e6, 1e6}, K, q[24], val[8];
    nl_krige_plan *kp;
    nl_krige_info info;
    s.rotation[0] = s.rotation[1] = s.rotation[2] = 0;  /* the plan below is unrotated */
    cr_assert_eq(nl_cloud_shape_eval(&s, 1, far, &K, NULL), NL_OK);
    for (int i = 0; i < 8; i++)
        memcpy(q + 3 * i, pts + 4 * i, 3 * sizeof *q), val[i] = pts[4 * i + 3];
    cr_assert_eq(nl_krige_plan_alloc(s.shape, 3, 8, q, val, 0, 0, 0, &kp), NL_OK);
    nl_krige_plan_info(kp, &info);
    cr_expect_eq(K, info.mean, "far value %.17g, mean %.17g", K, info.mean);
    cr_expect_gt(info.mean, 0.01, "the data's mean estimate is positive: %g", info.mean);
    s.kriging = NL_CLOUD_SIMPLE;
    cr_assert_eq(nl_cloud_shape_eval(&s, 1, far, &K, NULL), NL_OK);
    cr_expect_eq(K, 0, "simple kriging far away: %g", K);
    nl_krige_plan_free(kp), nl_model_free(s.shape), nl_model_free(s.noise);
}

/* One datum, simple kriging: K(p) = exp(-|D^-1 R^T p|^2), a Gaussian whose
 * second moments are R D^2 R^T / 2.  Summed on a grid of spacing 0.12 (the
 * grid sum of a Gaussian of standard deviation >= 0.177 is exact to
 * exp(-2 pi^2 sigma^2 / h^2) ~ 1e-18 relative) over [-4.2, 4.2]^3 (tails
 * below exp(-17)), the eigenvectors are R's columns to rounding (1e-6
 * degrees allows for the eigen solver's and the sums' rounding) and the
 * axis ratios are 0.5 and 0.25. */
Test(cloud_primitive, oriented_axes)
{
    static double one[4] = {0, 0, 0, 1};
    const double deg[3] = {30, 35, 25};
    nl_cloud_scene s = {0};
    s.npoints = 1, s.points = one, s.kriging = NL_CLOUD_SIMPLE, s.shape = test_model("gauss:scale=1,ratio=0.5,zratio=0.25");
    memcpy(s.rotation, deg, sizeof deg);
    enum { G = 71 };
    const double h = 0.12;
    double M[9] = {0}, tot = 0, *x = malloc(3 * G * G * sizeof *x), *K = malloc(G * G * sizeof *K);
    for (int k = 0; k < G; k++) {
        for (int q = 0; q < G * G; q++)
            x[3 * q] = (q % G - G / 2) * h, x[3 * q + 1] = (q / G - G / 2) * h, x[3 * q + 2] = (k - G / 2) * h;
        cr_assert_eq(nl_cloud_shape_eval(&s, G * G, x, K, NULL), NL_OK);
        for (int q = 0; q < G * G; q++) {
            tot += K[q];
            for (int i = 0; i < 9; i++)
                M[i] += K[q] * x[3 * q + i / 3] * x[3 * q + i % 3];
        }
    }
    gsl_matrix_view mv = gsl_matrix_view_array(M, 3, 3);
    gsl_vector *ev = gsl_vector_alloc(3);
    gsl_matrix *V = gsl_matrix_alloc(3, 3);
    gsl_eigen_symmv_workspace *ws = gsl_eigen_symmv_alloc(3);
    gsl_eigen_symmv(&mv.matrix, ev, V, ws);
    gsl_eigen_symmv_sort(ev, V, GSL_EIGEN_SORT_VAL_DESC);
    /* R = Rz(25) Ry(35) Rx(30), columns */
    double a = deg[0] * M_PI / 180, b = deg[1] * M_PI / 180, c = deg[2] * M_PI / 180;
    double R[3][3] = {{cos(c) * cos(b), cos(c) * sin(b) * sin(a) - sin(c) * cos(a), cos(c) * sin(b) * cos(a) + sin(c) * sin(a)},
                      {sin(c) * cos(b), sin(c) * sin(b) * sin(a) + cos(c) * cos(a), sin(c) * sin(b) * cos(a) - cos(c) * sin(a)},
                      {-sin(b), cos(b) * sin(a), cos(b) * cos(a)}};
    const double want[3] = {1, 0.5, 0.25};
    for (int j = 0; j < 3; j++) {
        /* The angle from |r x v| (accurate near 0; 1 - |r . v| cannot
         * resolve angles below sqrt(2 eps) = 1.2e-6 degrees). */
        double r[3] = {R[0][j], R[1][j], R[2][j]}, v[3], cx[3];
        for (int i = 0; i < 3; i++)
            v[i] = gsl_matrix_get(V, (size_t)i, (size_t)j);
        for (int i = 0; i < 3; i++)
            cx[i] = r[(i + 1) % 3] * v[(i + 2) % 3] - r[(i + 2) % 3] * v[(i + 1) % 3];
        double off = asin(fmin(1, sqrt(cx[0] * cx[0] + cx[1] * cx[1] + cx[2] * cx[2]))) * 180 / M_PI;
        cr_expect_leq(off, 1e-6, "axis %d off by %g degrees", j, off);
        cr_expect_leq(fabs(sqrt(gsl_vector_get(ev, (size_t)j) / gsl_vector_get(ev, 0)) - want[j]), 1e-9,
                      "axis %d ratio", j);
    }
    gsl_eigen_symmv_free(ws), gsl_matrix_free(V), gsl_vector_free(ev);
    free(x), free(K), nl_model_free(s.shape);
}

/* A value is a pure function of (seed, point): the cached cubes and the
 * cubes drawn on the fly give the same bits; other seeds other values. */
Test(cloud_primitive, point_noise_pure)
{
    nl_model *m = test_model("gauss:scale=0.37");
    nl_synth_sparse_point *a, *b, *c;
    double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1}, x[3 * 64], va[64], vb[64], vc[64];
    cr_assert_eq(nl_synth_sparse_point_alloc(m, 6, 11, lo, hi, &a), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_sparse_point_alloc(m, 6, 11, NULL, NULL, &b), NL_OK);
    cr_assert_eq(nl_synth_sparse_point_alloc(m, 6, 12, lo, hi, &c), NL_OK);
    for (int i = 0; i < 3 * 64; i++)
        x[i] = -2.5 + 5 * nl_rng_uniform(3, 0, (uint64_t)i);  /* inside and outside the cached box */
    cr_assert_eq(nl_synth_sparse_point_eval(a, 64, x, va), NL_OK);
    cr_assert_eq(nl_synth_sparse_point_eval(b, 64, x, vb), NL_OK);
    cr_assert_eq(nl_synth_sparse_point_eval(c, 64, x, vc), NL_OK);
    cr_expect_eq(memcmp(va, vb, sizeof va), 0, "cached and drawn values differ");
    int same = 0;
    for (int i = 0; i < 64; i++)
        same += va[i] == vc[i];
    cr_expect_lt(same, 4, "seed 12 repeats %d values of seed 11", same);
    nl_synth_sparse_point_free(a), nl_synth_sparse_point_free(b), nl_synth_sparse_point_free(c), nl_model_free(m);
}

Test(cloud_primitive, point_noise_refusals)
{
    nl_model *m = test_model("markov:scale=1"), *g = test_model("gauss:scale=1");
    nl_synth_sparse_point *p;
    double lo[3] = {0, 0, 0}, hi[3] = {1, -1, 1}, x[3] = {1e300, 0, 0}, v;
    cr_expect_eq(nl_synth_sparse_point_alloc(m, 4, 1, NULL, NULL, &p), NL_EINVAL, "markov has no closed-form kernel");
    cr_expect_null(p);
    cr_expect_eq(nl_synth_sparse_point_alloc(g, 0, 1, NULL, NULL, &p), NL_EINVAL, "density 0");
    cr_expect_eq(nl_synth_sparse_point_alloc(g, 4, 1, lo, hi, &p), NL_EINVAL, "an empty box");
    cr_assert_eq(nl_synth_sparse_point_alloc(g, 4, 1, NULL, NULL, &p), NL_OK);
    cr_expect_eq(nl_synth_sparse_point_eval(p, 1, x, &v), NL_EINVAL, "a point at 1e300");
    x[0] = NAN;
    cr_expect_eq(nl_synth_sparse_point_eval(p, 1, x, &v), NL_EINVAL, "a NaN point");
    nl_synth_sparse_point_free(p), nl_model_free(m), nl_model_free(g);
}

/* The ACF at lags 0.5 and 1 (scale 1): r(d) = mean n(p) n(p + d e) over
 * M = 12000 seeded bases in a 40^3 box.  One product has variance at most
 * 1 + rho^2 + kappa (Isserlis, plus the shot noise's excess kurtosis
 * kappa = 1.52 / density); overlapping bases inflate it by at most
 * 1 + 2 (M / 40^3) (pi / 2)^1.5.  Tolerance: 4 standard errors plus the
 * kernel's truncation bound 4.4e-3. */
Test(cloud_primitive, point_noise_acf, .timeout = 60)
{
    enum { M = 12000 };
    const double density = 4, kappa = 1.524 / density, lag[3] = {0, 0.5, 1};
    nl_model *m = test_model("gauss:scale=1");
    nl_synth_sparse_point *p;
    double lo[3] = {0, 0, 0}, hi[3] = {41, 41, 41}, sum[3] = {0};
    cr_assert_eq(nl_synth_sparse_point_alloc(m, density, 29, lo, hi, &p), NL_OK, "%s", nl_errmsg());
    for (size_t b = 0; b < M; b++) {
        double x[9], v[3];
        for (int a = 0; a < 3; a++)
            x[a] = 40 * nl_rng_uniform(31, (uint32_t)a, b);
        for (int l = 1; l < 3; l++)
            memcpy(x + 3 * l, x, 3 * sizeof *x), x[3 * l + b % 3] += lag[l];
        nl_synth_sparse_point_eval(p, 3, x, v);
        for (int l = 0; l < 3; l++)
            sum[l] += v[0] * v[l];
    }
    double inflate = 1 + 2 * (M / 64000.0) * pow(M_PI / 2, 1.5);
    for (int l = 0; l < 3; l++) {
        double rho = exp(-lag[l] * lag[l]), tol = 4 * sqrt((1 + rho * rho + kappa) * inflate / M) + 4.4e-3;
        cr_expect_leq(fabs(sum[l] / M - rho), tol, "lag %g: %.4f, model %.4f, tolerance %.4f", lag[l], sum[l] / M, rho,
                      tol);
    }
    nl_synth_sparse_point_free(p), nl_model_free(m);
}

#define BASE                                                                                                        \
    "\"size\": [16, 12], \"box\": [[-1,-1,-1],[1,1,1]], \"points\": [[0.25,0,0,1.5],[0,0.5,0,0.4],[0.9,0.9,0.9,0]], " \
    "\"acf\": \"gauss:scale=0.6\", \"grid\": 8, \"camera\": {\"position\": [0,0,-4], \"look_at\": [0,0.125,0]}, "     \
    "\"sun\": [0.3,1,-0.5]"

/* The new keys parse into the scene; writing the defaults out changes no
 * bit of the picture (the defaults are the same code path). */
Test(cloud_primitive, scene_keys)
{
    nl_cloud_scene s, t;
    unsigned char a[16 * 12 * 3], b[16 * 12 * 3];
    cr_assert_eq(nl_cloud_scene_read(scratch_file("k1.json", "{" BASE ", \"noise\": {\"acf\": \"gauss:scale=0.2\", "
                                                 "\"grid\": 8}}"), &s), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(s.kriging, NL_CLOUD_ORDINARY);
    cr_expect_eq(s.noise_kind, NL_CLOUD_NOISE_GRID);
    cr_expect_eq(s.noise_density, 8);
    cr_assert_eq(nl_cloud_scene_read(scratch_file("k2.json", "{" BASE ", \"kriging\": \"ordinary\", \"rotation\": [0, 0, 0], "
                                                 "\"noise\": {\"acf\": \"gauss:scale=0.2\", \"grid\": 8, \"kind\": \"grid\"}}"),
                                     &t), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_render_cloud(&s, a, NULL, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_render_cloud(&t, b, NULL, NULL), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(memcmp(a, b, sizeof a), 0, "explicit defaults changed the picture");
    nl_cloud_scene_free(&s), nl_cloud_scene_free(&t);
    cr_assert_eq(nl_cloud_scene_read(scratch_file("k3.json", "{" BASE ", \"kriging\": \"simple\", \"rotation\": [10, -20.5, 300], "
                                                 "\"noise\": {\"acf\": \"gauss:scale=0.2\", \"kind\": \"point\", \"density\": 3}}"),
                                     &s), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(s.kriging, NL_CLOUD_SIMPLE);
    cr_expect_eq(s.rotation[1], -20.5);
    cr_expect_eq(s.noise_kind, NL_CLOUD_NOISE_POINT);
    cr_expect_eq(s.noise_density, 3);
    cr_assert_eq(nl_render_cloud(&s, a, NULL, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_render_cloud(&s, b, NULL, NULL), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(memcmp(a, b, sizeof a), 0, "point noise: two renders differ");
    nl_cloud_scene_free(&s);
    const char *bad[] = {"\"kriging\": \"universal\"", "\"kriging\": 1", "\"rotation\": [0, 0]", "\"rotation\": [0, 0, 400]",
                         "\"noise\": {\"acf\": \"gauss\", \"kind\": \"fft\"}", "\"noise\": {\"acf\": \"gauss\", \"density\": 0}"};
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char text[1024];
        snprintf(text, sizeof text, "{" BASE ", %s%s}", bad[i],
                 strstr(bad[i], "noise") ? "" : ", \"noise\": {\"acf\": \"gauss\"}");
        cr_expect_eq(nl_cloud_scene_read(scratch_file("bad.json", text), &s), NL_EINPUT, "%s", bad[i]);
        cr_expect_null(s.points);
    }
}
