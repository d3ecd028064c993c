/* A field's values at points (core/field_sample.h) and noiselab sample. */
#include "../core/field_sample.h"
#include "../core/io_coords.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An affine function of the coordinates, filled into f (spacing h, first sample x0). */
static double affine(const double *x, int dim)
{
    static const double c[3] = {0.731, -1.385, 2.113};
    double v = 0.417;
    for (int a = 0; a < dim; a++)
        v += c[a] * x[a];
    return v;
}

static nl_field *affine_field(int dim, const size_t *n, const double *h, const double *x0)
{
    nl_field *f = nl_field_alloc(dim, n, h, NULL);
    cr_assert_not_null(f);
    for (size_t k = 0; k < f->n[2]; k++)
        for (size_t j = 0; j < f->n[1]; j++)
            for (size_t i = 0; i < f->n[0]; i++) {
                size_t id[3] = {i, j, k};
                double x[3];
                for (int a = 0; a < dim; a++)
                    x[a] = x0[a] + (double)id[a] * f->h[a];
                f->data[(k * f->n[1] + j) * f->n[0] + i] = affine(x, dim);
            }
    return f;
}

/* Property: multilinear interpolation reproduces affine functions exactly
 * (each axis's linear weights sum to 1 and reproduce the coordinate), so at
 * random points of the hull the error is rounding only: the values are
 * O(10), the weights' and coordinates' rounding a few ulps, so 1e-12. */
Test(sample, linear_reproduces_affine_functions)
{
    static const size_t sizes[3][3] = {{17, 1, 1}, {9, 13, 1}, {5, 6, 7}};
    const double h[3] = {0.37, 1.9, 0.61}, x0[3] = {-2.385, 4.2, 0.5};
    for (int dim = 1; dim <= 3; dim++) {
        nl_field *f = affine_field(dim, sizes[dim - 1], h, x0);
        double pts[3 * 200], val[200];
        nl_field_random_points(f, x0, 11, 200, pts);
        cr_assert_eq(nl_field_sample(f, x0, NL_INTERP_LINEAR, 200, pts, val), 0, "%s", nl_errmsg());
        for (int i = 0; i < 200; i++)
            cr_expect(fabs(val[i] - affine(pts + i * dim, dim)) < 1e-12, "%dD point %d: %.17g vs %.17g", dim, i,
                      val[i], affine(pts + i * dim, dim));
        nl_field_free(f);
    }
}

/* Property: nearest interpolation returns the value of the sample closest
 * on every axis (checked against a brute-force search over all samples,
 * exact equality), and both interpolations return samples exactly at
 * the samples' own coordinates. */
Test(sample, nearest_is_the_closest_sample)
{
    const size_t n[2] = {11, 7};
    const double h[2] = {0.5, 1.25}, x0[2] = {1, -3};
    nl_field *f = nl_field_alloc(2, n, h, NULL);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = nl_rng_gauss(5, 0, i);
    double pts[2 * 100], val[100], lin[100];
    nl_field_random_points(f, x0, 3, 100, pts);
    cr_assert_eq(nl_field_sample(f, x0, NL_INTERP_NEAREST, 100, pts, val), 0);
    for (int p = 0; p < 100; p++) {
        double best = INFINITY, v = NAN;
        for (size_t j = 0; j < n[1]; j++)
            for (size_t i = 0; i < n[0]; i++) {
                double dx = pts[2 * p] - (x0[0] + (double)i * h[0]), dy = pts[2 * p + 1] - (x0[1] + (double)j * h[1]);
                if (dx * dx + dy * dy < best)
                    best = dx * dx + dy * dy, v = f->data[j * n[0] + i];
            }
        cr_expect_eq(val[p], v, "point %d", p);
    }
    for (size_t j = 0; j < n[1]; j++)
        for (size_t i = 0; i < n[0]; i++) {
            double x[2] = {x0[0] + (double)i * h[0], x0[1] + (double)j * h[1]};
            cr_assert_eq(nl_field_sample(f, x0, NL_INTERP_NEAREST, 1, x, val), 0);
            cr_assert_eq(nl_field_sample(f, x0, NL_INTERP_LINEAR, 1, x, lin), 0);
            cr_expect_eq(val[0], f->data[j * n[0] + i]);
            cr_expect_eq(lin[0], f->data[j * n[0] + i]);
        }
    nl_field_free(f);
}

Test(sample, refuses_points_outside_and_non_finite)
{
    const size_t n[2] = {8, 8};
    const double x0[2] = {0, 0};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    double pts[6] = {1, 1, 7, 7.5, 2, 2}, val[3];
    cr_expect_eq(nl_field_sample(f, x0, NL_INTERP_LINEAR, 3, pts, val), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "point 2 (7, 7.5)"), "%s", nl_errmsg());
    pts[3] = NAN;
    cr_expect_eq(nl_field_sample(f, x0, NL_INTERP_LINEAR, 3, pts, val), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "point 2") && !strstr(nl_errmsg(), "nan"), "%s", nl_errmsg());
    pts[3] = 7;
    cr_expect_eq(nl_field_sample(f, x0, 5, 3, pts, val), NL_EINVAL);
    cr_expect_eq(nl_field_sample(f, x0, NL_INTERP_LINEAR, 3, pts, val), 0);
    nl_field_free(f);
}

/* The command: random points lie in the field's coordinates (a window's
 * recorded origin times the spacing), and sampling the table it wrote
 * again gives the same values (its coordinates are the printed ones). */
Test(sample, cli_round_trip_and_origin)
{
    char cmd[1024], out[65536], err[1024], out2[65536];
    const char *d = scratch_dir();
    snprintf(cmd, sizeof cmd, "synth subdiv --acf markov:scale=6 --size 32x32 --nonperiodic --origin 8,4 "
             "--spacing 0.5 --seed 4 -o %s/w.exr", d);
    cr_assert_eq(run_noiselab(cmd, out, sizeof out, err, sizeof err), 0, "%s", err);
    snprintf(cmd, sizeof cmd, "sample %s/w.exr --random 50 --seed 9 -o %s/p.tsv", d, d);
    cr_assert_eq(run_noiselab(cmd, out, sizeof out, err, sizeof err), 0, "%s", err);
    int dim;
    size_t n;
    double *pts;
    snprintf(cmd, sizeof cmd, "%s/p.tsv", d);
    cr_assert_eq(nl_coords_read(cmd, &dim, &n, &pts), 0, "%s", nl_errmsg());
    cr_assert(dim == 2 && n == 50);
    for (size_t i = 0; i < n; i++) /* x in 8 * 0.5 .. (8 + 31) 0.5, y in 4 * 0.5 .. (4 + 31) 0.5 */
        cr_expect(pts[2 * i] >= 4 && pts[2 * i] <= 19.5 && pts[2 * i + 1] >= 2 && pts[2 * i + 1] <= 17.5,
                  "point %zu (%g, %g)", i, pts[2 * i], pts[2 * i + 1]);
    free(pts);
    snprintf(cmd, sizeof cmd, "sample %s/w.exr --points %s/p.tsv", d, d);
    cr_assert_eq(run_noiselab(cmd, out2, sizeof out2, err, sizeof err), 0, "%s", err);
    snprintf(cmd, sizeof cmd, "%s/p.tsv", d);
    FILE *fp = fopen(cmd, "r");
    size_t len = fread(out, 1, sizeof out - 1, fp);
    out[len] = 0;
    fclose(fp);
    cr_expect_str_eq(out, out2);
}

Test(sample, cli_refuses_a_point_outside)
{
    char cmd[1024], out[4096], err[1024], path[512];
    const char *d = scratch_dir();
    snprintf(cmd, sizeof cmd, "synth fft --acf gauss:scale=2 --size 16x16 -o %s/g.exr", d);
    cr_assert_eq(run_noiselab(cmd, out, sizeof out, err, sizeof err), 0, "%s", err);
    snprintf(path, sizeof path, "%s/out.tsv", d);
    FILE *fp = fopen(path, "w");
    fputs("x\ty\n1\t2\n15\t15\n15.5\t3\n", fp);
    fclose(fp);
    snprintf(cmd, sizeof cmd, "sample %s/g.exr --points %s -o %s/res.tsv", d, path, d);
    cr_assert_eq(run_noiselab(cmd, out, sizeof out, err, sizeof err), 2);
    cr_expect(strstr(err, "point 3 (15.5, 3)") && count_lines(err) == 1, "%s", err);
    snprintf(path, sizeof path, "%s/res.tsv", d);
    cr_expect(!file_exists(path));
}
