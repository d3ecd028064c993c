/* Stam and Fiume 1991: the verdicts of the cloud primitive, measured on the
 * library the renderer uses.
 *
 * usage: cloud_checks weights SCENE.json
 *   the scene's kriged shape (nl_cloud_shape_eval: the renderer's kriging,
 *   rotation and data): the largest |K - d_i| at the data (bound 1e-9 of the
 *   largest |d|: an exact interpolator, eq. (19)) and, for ordinary
 *   kriging, the largest |sum_i lambda_i - 1| at the data and at 2000
 *   seeded points of the box (bound 1e-12: the unbiasedness constraint of
 *   eq. (22)), and the estimated mean b (the value far from every datum).
 *   Prints "points N max_error E max_wsum_error W mean B".
 * usage: cloud_checks axes AX AY AZ
 *   one datum of value 1 at the origin, simple kriging, shape
 *   gauss:scale=1,ratio=0.5,zratio=0.25 rotated by (AX, AY, AZ) degrees:
 *   K(p) = exp(-|D^-1 R^T p|^2), whose second moments are R diag(1, 1/4,
 *   1/16) R^T / 2.  The moments are summed on a grid of spacing 0.08 over
 *   [-4, 4]^3 and their eigenvectors compared with R's columns: prints the
 *   angle (degrees) between each measured principal axis and the one asked
 *   for, and the measured axis ratios (0.5 and 0.25 expected).  Bounds: 0.05
 *   degrees and 1e-3 on the ratios (the grid sum of a Gaussian of standard
 *   deviation >= 0.177 at spacing 0.08 is exact to far below that: the
 *   aliasing error of the sum is exp(-2 pi^2 sigma^2 / h^2) ~ 1e-42).
 * usage: cloud_checks acf DENSITY
 *   point-evaluated sparse-convolution noise of gauss:scale=1 with DENSITY
 *   impulses per scale^3 (seed 7): at M = 30000 seeded base points p of a
 *   56^3 box and axis e (cycling x, y, z), r(d) = mean n(p) n(p + d e) for d
 *   = 0, 0.25, ..., 2 against exp(-d^2).  Tolerance, per lag: 4 standard
 *   errors plus the truncation bound 4.4e-3 (sparse_point.h).  The
 *   variance of one product is 1 + rho^2 + kappa (Isserlis plus the excess
 *   kurtosis kappa of shot noise, an upper bound for its fourth-cumulant
 *   term); the M bases are not independent (a base within a correlation
 *   length of another): inflating by 1 + 2 (M / volume) int rho^2 dx, int
 *   rho^2 = (pi / 2)^1.5, bounds it.  Prints a TSV (lag, measured, model,
 *   tolerance).
 * Every mode exits 1 when a bound fails, 2 on bad input. */
#include "../render/cloud_scene.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/sparse_point.h"

#include <gsl/gsl_eigen.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int weights(const char *path)
{
    nl_cloud_scene s;
    if (nl_cloud_scene_read(path, &s)) {
        fprintf(stderr, "cloud_checks: %s\n", nl_errmsg());
        return 2;
    }
    size_t n = s.npoints, m = n + 2000;
    double *x = malloc(3 * m * sizeof *x), *K = malloc(m * sizeof *K), *w = malloc(m * sizeof *w), err = 0, werr = 0,
           top = 0;
    for (size_t i = 0; i < n; i++) {
        memcpy(x + 3 * i, s.points + 4 * i, 3 * sizeof *x);
        top = fmax(top, fabs(s.points[4 * i + 3]));
    }
    for (size_t i = n; i < m; i++)
        for (int a = 0; a < 3; a++)
            x[3 * i + a] = s.lo[a] + (s.hi[a] - s.lo[a]) * nl_rng_uniform(19, (uint32_t)a, i);
    if (nl_cloud_shape_eval(&s, m, x, K, w)) {
        fprintf(stderr, "cloud_checks: %s\n", nl_errmsg());
        return 2;
    }
    for (size_t i = 0; i < m; i++) {
        if (i < n)
            err = fmax(err, fabs(K[i] - s.points[4 * i + 3]));
        if (s.kriging == NL_CLOUD_ORDINARY)
            werr = fmax(werr, fabs(w[i] - 1));
    }
    /* the value far from every datum is the estimated mean */
    double far[3] = {1e6, 1e6, 1e6}, b;
    nl_cloud_shape_eval(&s, 1, far, &b, NULL);
    printf("points %zu max_error %.1e max_wsum_error %.1e mean %.3f\n", n, err, werr, b);
    int ok = err <= 1e-9 * top && werr <= 1e-12;
    free(x), free(K), free(w), nl_cloud_scene_free(&s);
    return ok ? 0 : 1;
}

/* R's column a (as in render/cloud_shape.c: Rz(az) Ry(ay) Rx(ax)). */
static void column(const double *deg, int a, double *v)
{
    double e[3] = {0, 0, 0}, t;
    e[a] = 1;
    for (int k = 0; k < 3; k++) {
        double c = cos(deg[k] * M_PI / 180), s = sin(deg[k] * M_PI / 180);
        int i = (k + 1) % 3, j = (k + 2) % 3;  /* the plane rotated about axis k */
        t = c * e[i] - s * e[j], e[j] = s * e[i] + c * e[j], e[i] = t;
    }
    memcpy(v, e, sizeof e);
}

static int axes(const double *deg)
{
    static double pt[4] = {0, 0, 0, 1};
    nl_cloud_scene s = {0};
    s.npoints = 1, s.points = pt, s.kriging = NL_CLOUD_SIMPLE;
    memcpy(s.rotation, deg, sizeof s.rotation);
    if (nl_model_parse("gauss:scale=1,ratio=0.5,zratio=0.25", &s.shape))
        return 2;
    const int G = 101;
    const double h = 0.08;
    double M[9] = {0}, tot = 0, *x = malloc(3 * (size_t)G * G * sizeof *x), *K = malloc((size_t)G * G * sizeof *K);
    for (int k = 0; k < G; k++) {
        for (int q = 0; q < G * G; q++)
            x[3 * q] = (q % G - G / 2) * h, x[3 * q + 1] = (q / G - G / 2) * h, x[3 * q + 2] = (k - G / 2) * h;
        if (nl_cloud_shape_eval(&s, (size_t)G * G, x, K, NULL))
            return 2;
        for (int q = 0; q < G * G; q++) {
            tot += K[q];
            for (int i = 0; i < 9; i++)
                M[i] += K[q] * x[3 * q + i / 3] * x[3 * q + i % 3];
        }
    }
    for (int i = 0; i < 9; i++)
        M[i] /= tot;
    gsl_matrix_view mv = gsl_matrix_view_array(M, 3, 3);
    gsl_vector *ev = gsl_vector_alloc(3);
    gsl_matrix *V = gsl_matrix_alloc(3, 3);
    gsl_eigen_symmv_workspace *ws = gsl_eigen_symmv_alloc(3);
    gsl_eigen_symmv(&mv.matrix, ev, V, ws);
    gsl_eigen_symmv_sort(ev, V, GSL_EIGEN_SORT_VAL_DESC);
    double worst = 0;
    printf("axis\tangle_error_deg\tlength_ratio\texpected\n");
    for (int a = 0; a < 3; a++) {
        double c[3], v[3], dot = 0, cr[3];
        column(deg, a, c);
        for (int i = 0; i < 3; i++)
            v[i] = gsl_matrix_get(V, (size_t)i, (size_t)a), dot += c[i] * v[i];
        for (int i = 0; i < 3; i++)
            cr[i] = c[(i + 1) % 3] * v[(i + 2) % 3] - c[(i + 2) % 3] * v[(i + 1) % 3];
        /* the angle from |cross| and |dot|: accurate near 0, where acos is not */
        double ang = atan2(sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]), fabs(dot)) * 180 / M_PI, ratio = sqrt(gsl_vector_get(ev, (size_t)a) /
                                                                          gsl_vector_get(ev, 0));
        double want = a == 0 ? 1 : a == 1 ? 0.5 : 0.25;
        printf("%c\t%.2e\t%.6f\t%g\n", "xyz"[a], ang, ratio, want);
        worst = fmax(worst, ang);
        if (fabs(ratio - want) > 1e-3)
            worst = INFINITY;
    }
    gsl_eigen_symmv_free(ws), gsl_matrix_free(V), gsl_vector_free(ev);
    free(x), free(K), nl_model_free(s.shape);
    return worst <= 0.05 ? 0 : 1;
}

static int acf(double density)
{
    enum { M = 30000, LAGS = 9 };
    const double box = 56, kappa = 6 * M_SQRT2 / (density * pow(M_PI, 1.5));
    double lo[3] = {0, 0, 0}, hi[3] = {box + 2, box + 2, box + 2}, sum[LAGS] = {0};
    nl_model *m;
    nl_synth_sparse_point *p;
    if (nl_model_parse("gauss:scale=1", &m) || nl_synth_sparse_point_alloc(m, density, 7, lo, hi, &p)) {
        fprintf(stderr, "cloud_checks: %s\n", nl_errmsg());
        return 2;
    }
    for (size_t b = 0; b < M; b++) {
        double x[3 * LAGS], v[LAGS];
        int e = (int)(b % 3);
        for (int a = 0; a < 3; a++)
            x[a] = box * nl_rng_uniform(23, (uint32_t)a, b);
        for (int l = 1; l < LAGS; l++)
            memcpy(x + 3 * l, x, 3 * sizeof *x), x[3 * l + e] += 0.25 * l;
        nl_synth_sparse_point_eval(p, LAGS, x, v);
        for (int l = 0; l < LAGS; l++)
            sum[l] += v[0] * v[l];
    }
    int ok = 1;
    double inflate = 1 + 2 * (M / pow(box, 3)) * pow(M_PI / 2, 1.5);
    printf("lag\tmeasured\tmodel\ttolerance\n");
    for (int l = 0; l < LAGS; l++) {
        double d = 0.25 * l, rho = exp(-d * d), r = sum[l] / M;
        double tol = 4 * sqrt((1 + rho * rho + kappa) * inflate / M) + 4.4e-3;
        printf("%g\t%.4f\t%.4f\t%.4f\n", d, r, rho, tol);
        ok = ok && fabs(r - rho) <= tol;
    }
    nl_synth_sparse_point_free(p), nl_model_free(m);
    return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
    double deg[3];
    if (argc == 3 && !strcmp(argv[1], "weights"))
        return weights(argv[2]);
    if (argc == 5 && !strcmp(argv[1], "axes")) {
        for (int a = 0; a < 3; a++)
            deg[a] = atof(argv[2 + a]);
        return axes(deg);
    }
    if (argc == 3 && !strcmp(argv[1], "acf"))
        return acf(atof(argv[2]));
    fprintf(stderr, "usage: cloud_checks weights SCENE.json | axes AX AY AZ | acf DENSITY\n");
    return 2;
}
