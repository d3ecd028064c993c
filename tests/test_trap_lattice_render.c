/* Error paths, after GSL's test_trap: every NL_E* code the headers of
 * rank1, ocean, lattice, krige, nonlin, creases, aliasing, io_obj and the
 * render modules list is triggered here, with the input that causes it.
 * NL_ENOMEM comes from starve.h (skipped where it cannot work). */
#include "starve.h"
#include "../analysis/aliasing.h"
#include "../analysis/creases.h"
#include "../analysis/krige.h"
#include "../analysis/nonlin.h"
#include "../core/io_obj.h"
#include "../core/io_points.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../render/cloud.h"
#include "../render/shade.h"
#include "../render/terrain.h"
#include "../synth/lattice.h"
#include "../synth/ocean.h"
#include "../synth/rank1_model.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static nl_field *field2(size_t nx, size_t ny)
{
    size_t n[2] = {nx, ny};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    cr_assert_not_null(f);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(0.37 * (double)i) + 0.25 * cos(1.91 * (double)i);
    return f;
}

/* Run `call` with the heap exhausted and expect NL_ENOMEM. */
#define EXPECT_ENOMEM(call)                                                                                    \
    do {                                                                                                       \
        if (!starve_begin())                                                                                   \
            cr_skip_test("allocation failure cannot be forced in this build");                                 \
        int st_ = (call);                                                                                      \
        starve_end();                                                                                          \
        cr_assert_eq(st_, NL_ENOMEM, "%s: got %d (%s)", #call, st_, nl_errmsg());                             \
    } while (0)

static double flat_spectrum(const long *k, int s, void *ctx)
{
    (void)s, (void)ctx;
    return k[0] == 3 ? -1 : 1;
}

Test(trap_rank1, einval)
{
    nl_rank1_lattice L;
    long g1[2] = {1, 5}, g2[2] = {2, 5};
    double c[2 * 89];
    cr_assert_eq(nl_rank1_fibonacci(2, &L), NL_EINVAL);
    cr_assert_eq(nl_rank1_fibonacci(35, &L), NL_EINVAL);
    cr_assert_eq(nl_rank1_generator(10, 0, g1, &L), NL_EINVAL);
    cr_assert_eq(nl_rank1_generator(10, NL_RANK1_MAX_DIM + 1, g1, &L), NL_EINVAL);
    cr_assert_eq(nl_rank1_generator(1, 2, g1, &L), NL_EINVAL);
    cr_assert_eq(nl_rank1_generator((1u << 24) + 1, 2, g1, &L), NL_EINVAL);
    cr_assert_eq(nl_rank1_generator(10, 2, g2, &L), NL_EINVAL);
    cr_assert_null(L.k, "a failed constructor leaves nothing to free");
    cr_assert_eq(nl_rank1_korobov(1, 2, 0, &L), NL_EINVAL);
    /* a negative variance at the wave vector of residue with k_0 = 3 */
    cr_assert_eq(nl_rank1_fibonacci(11, &L), NL_OK);
    cr_assert_eq(nl_rank1_coefficients(&L, flat_spectrum, NULL, 1, c), NL_EINVAL);
    nl_rank1_free(&L);
    /* the triangulation needs 2D and 3 points */
    long g3[1] = {1};
    size_t n1, n2;
    double v1[2], v2[2], img[4];
    cr_assert_eq(nl_rank1_generator(10, 1, g3, &L), NL_OK);
    cr_assert_eq(nl_rank1_delaunay(&L, &n1, &n2, v1, v2), NL_EINVAL);
    nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_generator(2, 2, g1, &L), NL_OK);
    cr_assert_eq(nl_rank1_delaunay(&L, &n1, &n2, v1, v2), NL_EINVAL);
    nl_rank1_free(&L);
    /* mesh and raster arguments */
    nl_rank1_mesh me;
    double f[13] = {0};
    cr_assert_eq(nl_rank1_fibonacci(7, &L), NL_OK);
    cr_assert_eq(nl_rank1_mesh_init(&L, 0, f, &me), NL_EINVAL);
    cr_assert_eq(nl_rank1_mesh_init(&L, INFINITY, f, &me), NL_EINVAL);
    cr_assert_eq(nl_rank1_rasterize(&L, f, NULL, 0, img, NULL, NULL), NL_EINVAL);
    cr_assert_eq(nl_rank1_rasterize(&L, NULL, NULL, 2, img, NULL, NULL), NL_EINVAL);
    nl_rank1_free(&L);
}

/* All points on one line (g = (1, 0)): no second basis vector. */
Test(trap_rank1, efail_degenerate_lattice)
{
    nl_rank1_lattice L;
    long g[2] = {1, 0};
    size_t n1, n2;
    double v1[2], v2[2];
    cr_assert_eq(nl_rank1_generator(10, 2, g, &L), NL_OK);
    cr_assert_eq(nl_rank1_delaunay(&L, &n1, &n2, v1, v2), NL_EFAIL);
    cr_expect(strstr(nl_errmsg(), "10 points of generator (1, 0) lie on one line") != NULL, "%s", nl_errmsg());
    nl_rank1_mesh me;
    cr_assert_eq(nl_rank1_mesh_init(&L, 1, NULL, &me), NL_EFAIL);
    nl_rank1_free(&L);
}

Test(trap_rank1, enomem)
{
    nl_rank1_lattice L;
    long g[4] = {1, 3, 9, 27};
    EXPECT_ENOMEM(nl_rank1_generator(1 << 16, 4, g, &L));
    cr_assert_null(L.k);
}

Test(trap_rank1_slow, enomem_synthesize)
{
    nl_rank1_lattice L;
    long g[1] = {1};
    size_t N = 1 << 16;
    cr_assert_eq(nl_rank1_generator(N, 1, g, &L), NL_OK);
    double *c = calloc(2 * N, sizeof *c), *f = malloc(N * sizeof *f);
    cr_assert(c && f);
    EXPECT_ENOMEM(nl_rank1_synthesize(&L, c, 1, f, NULL, NULL));
    free(c), free(f);
    nl_rank1_free(&L);
}

Test(trap_rank1, model)
{
    nl_rank1_lattice L2, L4;
    long g[4] = {1, 5, 25, 125};
    nl_model *sp = test_model("power:d=2.6,fmin=0.5,fmax=40"), *aniso = test_model("gauss:scale=0.2,ratio=2"),
             *iso = test_model("markov:scale=0.1");
    double f[89];
    cr_assert_eq(nl_rank1_fibonacci(11, &L2), NL_OK);
    cr_assert_eq(nl_rank1_generator(89, 4, g, &L4), NL_OK);
    cr_assert_eq(nl_rank1_model_check(sp, 4), NL_EINVAL, "spectra reach 3 dimensions");
    cr_assert_eq(nl_rank1_model_check(aniso, 2), NL_EINVAL, "an anisotropic R");
    cr_assert_eq(nl_rank1_model_synthesize(&L4, sp, 1, 1, f, NULL, NULL), NL_EINVAL);
    cr_assert_eq(nl_rank1_model_synthesize(&L2, iso, 0, 1, f, NULL, NULL), NL_EINVAL, "extent 0");
    cr_assert_eq(nl_rank1_model_synthesize(&L2, iso, 1, 1, f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    nl_rank1_free(&L2), nl_rank1_free(&L4);
    nl_model_free(sp), nl_model_free(aniso), nl_model_free(iso);
}

Test(trap_rank1, model_enomem)
{
    nl_rank1_lattice L;
    nl_model *iso = test_model("markov:scale=0.1");
    cr_assert_eq(nl_rank1_fibonacci(25, &L), NL_OK);
    double *f = malloc(L.N * sizeof *f);
    EXPECT_ENOMEM(nl_rank1_model_synthesize(&L, iso, 1, 1, f, NULL, NULL));
    free(f), nl_rank1_free(&L), nl_model_free(iso);
}

static const nl_ocean_params sea = {12.3, 0.4, 100, 1e-4};

Test(trap_ocean, einval)
{
    nl_rank1_lattice L1, L2;
    long g[1] = {1};
    double c[2 * 55], h[55], grid[16];
    nl_ocean_params bad[5] = {{0, 0.4, 100, 1e-4}, {12.3, 0.4, 0, 1e-4}, {12.3, 0.4, 100, 0},
                              {12.3, NAN, 100, 1e-4}, {INFINITY, 0.4, 100, 1e-4}};
    cr_assert_eq(nl_rank1_generator(55, 1, g, &L1), NL_OK);
    cr_assert_eq(nl_rank1_fibonacci(10, &L2), NL_OK);
    cr_assert_eq(nl_ocean_lattice_coefficients(&L1, &sea, 1, 0, c), NL_EINVAL, "a 1D lattice");
    cr_assert_eq(nl_ocean_lattice_frame(&L1, &sea, 1, 0, h, NULL), NL_EINVAL);
    for (int i = 0; i < 5; i++) {
        cr_assert_eq(nl_ocean_lattice_coefficients(&L2, &bad[i], 1, 0, c), NL_EINVAL, "parameters %d", i);
        cr_assert_eq(nl_ocean_grid(4, &bad[i], 1, 0, grid, NULL, NULL), NL_EINVAL, "parameters %d", i);
    }
    cr_assert_eq(nl_ocean_lattice_coefficients(&L2, &sea, 1, NAN, c), NL_EINVAL, "time");
    cr_assert_eq(nl_ocean_grid(1, &sea, 1, 0, grid, NULL, NULL), NL_EINVAL, "grid size");
    nl_rank1_free(&L1), nl_rank1_free(&L2);
}

Test(trap_ocean, enomem)
{
    nl_rank1_lattice L;
    cr_assert_eq(nl_rank1_fibonacci(20, &L), NL_OK);
    double *h = malloc(L.N * sizeof *h), *g = malloc(2 * L.N * sizeof *g), *grid = malloc(256 * 256 * sizeof *grid);
    cr_assert(h && g && grid);
    EXPECT_ENOMEM(nl_ocean_lattice_frame(&L, &sea, 1, 0.5, h, g));
    EXPECT_ENOMEM(nl_ocean_grid(256, &sea, 1, 0.5, grid, NULL, NULL));
    free(h), free(g), free(grid);
    nl_rank1_free(&L);
}

static void one_triangle(const void *ctx, size_t t, double xyz[9])
{
    (void)ctx, (void)t;
    for (int i = 0; i < 9; i++)
        xyz[i] = i;
}

Test(trap_obj, einval_and_eio)
{
    cr_assert_eq(nl_obj_write_triangles("/dev/null", NULL, 1, NULL, NULL), NL_EINVAL);
    cr_assert_eq(nl_obj_write_triangles("/nonexistent-dir/mesh.obj", NULL, 1, one_triangle, NULL), NL_EIO);
    cr_assert_eq(nl_obj_write_triangles("/dev/full", "full", 100000, one_triangle, NULL), NL_EIO,
                 "a write that fails is reported");
}

Test(trap_lattice, einval)
{
    nl_model *m = test_model("power:d=2.6,fmin=0.001"), *r = test_model("markov:scale=8");
    nl_synth_lattice_plan p;
    size_t n3[3] = {8, 8, 8};
    nl_field *f3 = nl_field_alloc(3, n3, NULL, NULL);
    cr_assert_eq(nl_synth_lattice_plan_init(m, 3, 16, 2, 0, &p), NL_EINVAL, "dimension");
    cr_assert_eq(nl_synth_lattice_plan_init(m, 1, 16, 0, 0, &p), NL_EINVAL, "no octave");
    cr_assert_eq(nl_synth_lattice_plan_init(m, 1, 16, NL_LATTICE_MAX_OCTAVES + 1, 0, &p), NL_EINVAL);
    cr_assert_eq(nl_synth_lattice_plan_init(m, 1, 16, 5, 0, &p), NL_EINVAL, "cells below 2 samples");
    cr_assert_eq(nl_synth_lattice_plan_init(r, 2, 16, 2, 0, &p), NL_EINVAL, "no closed-form 2D spectrum");
    cr_assert_eq(nl_synth_lattice_plan_init(m, 1, 16, 2, 0, &p), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_lattice_execute(&p, 1, f3), NL_EINVAL);
    nl_field_free(f3), nl_model_free(m), nl_model_free(r);
}

/* The first plan of a process measures the basis spectrum. */
Test(trap_lattice, enomem)
{
    nl_model *m = test_model("power:d=2.6,fmin=0.001");
    nl_synth_lattice_plan p;
    EXPECT_ENOMEM(nl_synth_lattice_plan_init(m, 2, 16, 2, 0, &p));
    nl_model_free(m);
}

static const double pts2[] = {0.1, 0.2, 0.7, 0.3, 0.4, 0.8}, val3[] = {1.5, -0.5, 0.25};

Test(trap_krige, einval)
{
    nl_model *m = test_model("gauss:scale=0.3"), *s = test_model("spectrum:exp(-f*f)"), *m1 = test_model("markov:scale=0.3");
    nl_krige_plan *p = (nl_krige_plan *)1;
    double dup[] = {0.1, 0.2, 0.1, 0.2, 0.4, 0.8}, nan_pts[] = {0.1, 0.2, NAN, 0.3, 0.4, 0.8};
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 0, pts2, val3, 0, 0, 0, &p), NL_EINVAL, "no points");
    cr_assert_null(p, "*out is NULL on failure");
    cr_assert_eq(nl_krige_plan_alloc(m, 4, 3, pts2, val3, 0, 0, 0, &p), NL_EINVAL, "dimension");
    cr_assert_eq(nl_krige_plan_alloc(s, 2, 3, pts2, val3, 0, 0, 0, &p), NL_EINVAL, "no R(lag)");
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 3, nan_pts, val3, 0, 0, 0, &p), NL_EINVAL, "not finite");
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 3, dup, val3, 0, 0, 1, &p), NL_EINVAL, "singular, strict");
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 3, dup, val3, 0, 0, 0, &p), NL_OK, "singular: pseudo-inverse");
    nl_krige_plan_free(p);
    /* a grid of another dimension */
    size_t n1 = 8;
    nl_field *g1 = nl_field_alloc(1, &n1, NULL, NULL);
    double lo[3] = {0, 0, 0};
    cr_assert_eq(nl_krige_plan_alloc(m1, 2, 3, pts2, val3, 0, 0, 0, &p), NL_OK);
    cr_assert_eq(nl_krige_eval_grid(p, lo, g1, NULL), NL_EINVAL);
    nl_field *g2 = field2(4, 4), *g3 = field2(4, 5);
    cr_assert_eq(nl_krige_eval_grid(p, lo, g2, g3), NL_EINVAL, "variance grid of another size");
    nl_krige_plan_free(p);
    nl_field_free(g1), nl_field_free(g2), nl_field_free(g3);
    nl_model_free(m), nl_model_free(s), nl_model_free(m1);
}

Test(trap_krige, enomem)
{
    nl_model *m = test_model("markov:scale=0.3");
    size_t n = 3000;
    double *pts = malloc(2 * n * sizeof *pts), *val = malloc(n * sizeof *val), x[2] = {0.5, 0.5}, e, v;
    cr_assert(pts && val);
    for (size_t i = 0; i < n; i++)
        pts[2 * i] = fmod(0.6180339887 * (double)i, 1), pts[2 * i + 1] = (double)i / (double)n, val[i] = sin((double)i);
    nl_krige_plan *p;
    EXPECT_ENOMEM(nl_krige_plan_alloc(m, 2, n, pts, val, 0, 0, 0, &p));
    cr_assert_eq(nl_krige_plan_alloc(m, 2, 100, pts, val, 0, 0, 0, &p), NL_OK);
    EXPECT_ENOMEM(nl_krige_eval(p, x, &e, &v, NULL));
    nl_field *g = field2(8, 8), *gv = field2(8, 8);
    double lo[2] = {0, 0};
    EXPECT_ENOMEM(nl_krige_eval_block(p, 4, pts, g->data, gv->data));
    /* libgomp allocates a little for every parallel region, even a serial
     * one: leave it 16 KiB while the 51 KiB block of variances fails */
    if (!starve_begin_leaving(16384))
        cr_skip_test("allocation failure cannot be forced in this build");
    int st = nl_krige_eval_grid(p, lo, g, gv);
    starve_end();
    cr_assert_eq(st, NL_ENOMEM, "got %d (%s)", st, nl_errmsg());
    nl_krige_plan_free(p);
    nl_field_free(g), nl_field_free(gv);
    free(pts), free(val);
    nl_model_free(m);
}

Test(trap_nonlin, einval)
{
    nl_dist *d;
    nl_hermite he;
    double t[4] = {0, 0.5, 0.2, 0.5}, rho[4], err, meas[8];
    size_t bad, n = 8;
    cr_assert_eq(nl_dist_parse("laplace", &d), NL_OK);
    cr_assert_eq(nl_hermite_expand(d, 1, &he), NL_EINVAL);
    cr_assert_eq(nl_hermite_expand(d, NL_HERMITE_MAX + 1, &he), NL_EINVAL);
    cr_assert_eq(nl_hermite_expand(d, 12, &he), NL_OK);
    cr_assert_eq(nl_nonlin_design(&he, t, 4, 1, rho, NULL, &err, &bad), NL_EINVAL, "target variance 0");
    t[0] = 1;
    cr_assert_eq(nl_nonlin_design(&he, t, 0, 1, rho, NULL, &err, &bad), NL_EINVAL, "no sample");
    cr_assert_eq(nl_nonlin_design(&he, t, 4, 0, rho, NULL, &err, &bad), NL_EINVAL, "spacing");
    nl_field *S = nl_field_alloc(1, &n, NULL, NULL), *S2 = field2(4, 2);
    for (size_t i = 0; i < n; i++)
        S->data[i] = 1;
    cr_assert_eq(nl_nonlin_verify(S2, d, 2, 4, meas), NL_EINVAL, "2D spectrum");
    cr_assert_eq(nl_nonlin_verify(S, d, 0, 4, meas), NL_EINVAL, "no realization");
    cr_assert_eq(nl_nonlin_verify(S, d, 2, 9, meas), NL_EINVAL, "more lags than samples");
    cr_assert_eq(nl_nonlin_verify(S, d, 2, 8, meas), NL_OK, "%s", nl_errmsg());
    nl_field_free(S), nl_field_free(S2), nl_dist_free(d);
}

Test(trap_nonlin, enomem)
{
    nl_dist *d;
    nl_hermite he;
    size_t n = 1 << 16;
    double *t = malloc(n * sizeof *t), *rho = malloc(n * sizeof *rho), err, meas[4];
    cr_assert(t && rho);
    for (size_t i = 0; i < n; i++)
        t[i] = exp(-(double)(i < n / 2 ? i : n - i) / 8);
    cr_assert_eq(nl_dist_parse("laplace", &d), NL_OK);
    EXPECT_ENOMEM(nl_hermite_expand(d, 12, &he));
    cr_assert_eq(nl_hermite_expand(d, 12, &he), NL_OK);
    EXPECT_ENOMEM(nl_nonlin_design(&he, t, n, 1, rho, NULL, &err, NULL));
    nl_field *S = nl_field_alloc(1, &n, NULL, NULL);
    cr_assert_not_null(S);
    EXPECT_ENOMEM(nl_nonlin_verify(S, d, 1, 4, meas));
    nl_field_free(S), nl_dist_free(d);
    free(t), free(rho);
}

Test(trap_creases, einval)
{
    nl_creases cr;
    size_t n1 = 64, n3[3] = {8, 8, 8};
    nl_field *f1 = nl_field_alloc(1, &n1, NULL, NULL), *f3 = nl_field_alloc(3, n3, NULL, NULL);
    cr_assert_eq(nl_creases_measure(f3, 2, &cr), NL_EINVAL, "3D");
    cr_assert_eq(nl_creases_measure(f1, 0, &cr), NL_EINVAL, "no level");
    cr_assert_eq(nl_creases_measure(f1, 41, &cr), NL_EINVAL, "too many levels");
    cr_assert_eq(nl_creases_measure(f1, 7, &cr), NL_EINVAL, "64 is not a multiple of 2^7");
    cr_assert_eq(nl_creases_measure(f1, 3, &cr), NL_EINVAL, "no middle level with 64 samples");
    nl_field_free(f1), nl_field_free(f3);
}

Test(trap_aliasing, codes)
{
    size_t n3[3] = {8, 8, 8};
    nl_field *f3 = nl_field_alloc(3, n3, NULL, NULL), *odd = field2(9, 8), *f = field2(512, 512);
    nl_model *m = test_model("markov:scale=4"), *bad = test_model("expr:1/abs(t)");
    double A;
    cr_assert_eq(nl_aliasing_measure(f3, &A), NL_EINVAL, "3D");
    cr_assert_eq(nl_aliasing_measure(odd, &A), NL_EINVAL, "odd size");
    cr_assert_eq(nl_aliasing_predict(bad, f, &A), NL_EINVAL, "not finite at lag 0");
    EXPECT_ENOMEM(nl_aliasing_measure(f, &A));
    EXPECT_ENOMEM(nl_aliasing_predict(m, f, &A));
    nl_field_free(f3), nl_field_free(odd), nl_field_free(f);
    nl_model_free(m), nl_model_free(bad);
}

Test(trap_render, shade)
{
    nl_field *x = field2(6, 5), *y = field2(5, 6), *one = field2(1, 1);
    size_t n1 = 30;
    nl_field *x1 = nl_field_alloc(1, &n1, NULL, NULL);
    double lo, hi;
    cr_assert_eq(nl_render_relief(x, 315, 30, 1, y), NL_EINVAL, "sizes differ");
    cr_assert_eq(nl_render_relief(x1, 315, 30, 1, x1), NL_EINVAL, "1D");
    cr_assert_eq(nl_render_relief(x, 315, 0, 1, x), NL_EINVAL, "elevation 0");
    cr_assert_eq(nl_render_relief(x, 315, 91, 1, x), NL_EINVAL, "elevation beyond the zenith");
    cr_assert_eq(nl_render_relief(x, 315, 30, 0, x), NL_EINVAL, "zscale 0");
    cr_assert_eq(nl_render_relief(x, NAN, 30, 1, x), NL_EINVAL, "azimuth");
    cr_assert_eq(nl_render_grey_range(one, &lo, &hi), NL_EINVAL, "one sample has no spread");
    nl_field_free(x), nl_field_free(y), nl_field_free(one), nl_field_free(x1);
}

Test(trap_render, terrain)
{
    nl_field *f = field2(32, 32), *small = field2(2, 32);
    nl_render_view v;
    uint8_t rgb[3 * 16];
    nl_render_view_default(f, &v);
    v.width = v.height = 4;
    cr_assert_eq(nl_render_terrain(small, &v, rgb), NL_EINVAL, "2 x 32");
    v.fov = 170;
    cr_assert_eq(nl_render_terrain(f, &v, rgb), NL_EINVAL, "fov");
    nl_render_view_default(f, &v);
    v.width = (size_t)1 << 62;
    cr_assert_eq(nl_render_terrain(f, &v, rgb), NL_ETOOBIG, "a picture that overflows");
    nl_render_view_default(f, &v);
    v.width = 4096, v.height = 4096;
    EXPECT_ENOMEM(nl_render_terrain(f, &v, NULL));
    nl_field_free(f), nl_field_free(small);
}

static double cloud_points[] = {0, 0.5, 0, 1.2, 0.3, 0.4, 0.2, 0.8};

static void scene(nl_cloud_scene *s)
{
    memset(s, 0, sizeof *s);
    s->width = 8, s->height = 6;
    for (int a = 0; a < 3; a++)
        s->lo[a] = -1, s->hi[a] = 1;
    s->npoints = 2, s->points = cloud_points;
    s->shape = test_model("gauss:scale=0.6");
    s->noise = test_model("gauss:scale=0.2");
    s->amplitude = 0.3, s->period = 1, s->noise_grid = 8, s->seed = 3;
    s->threshold = 0.2, s->extinction = 8, s->grid = 8;
    s->cam[2] = -4, s->fov = 40, s->sun[1] = 1;
}

Test(trap_render, cloud)
{
    nl_cloud_scene s;
    unsigned char rgb[3 * 48];
    double lum[48];
    scene(&s);
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_OK, "%s", nl_errmsg());
    s.grid = 1;
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_EINVAL, "grid of 1");
    s.grid = 8, s.npoints = 0;
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_EINVAL, "no data");
    s.npoints = 2, s.hi[1] = -1;
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_EINVAL, "empty box");
    s.hi[1] = 1, s.threshold = 1;
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_EINVAL, "threshold 1");
    s.threshold = 0.2, s.sun[1] = 0;
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_EINVAL, "no sun");
    s.sun[1] = 1;
    nl_model_free(s.noise);
    s.noise = test_model("expr:1-abs(t)/3");
    cr_assert_eq(nl_render_cloud(&s, rgb, lum, NULL), NL_ENOTPD, "a noise model that is not positive definite");
    EXPECT_ENOMEM(nl_render_cloud(&s, rgb, lum, NULL));
    nl_model_free(s.shape), nl_model_free(s.noise);
}

static const char *write_tmp(const char *name, const char *text)
{
    static char path[256];
    snprintf(path, sizeof path, "/tmp/noiselab-trap-%ld-%s", (long)getpid(), name);
    FILE *fp = fopen(path, "w");
    cr_assert_not_null(fp);
    fputs(text, fp);
    fclose(fp);
    return path;
}

Test(trap_points, einput_and_enomem)
{
    static const char *bad[] = {"", "# nothing\n", "x\n1\n", "a\tb\tc\td\te\n1\t2\t3\t4\t5\n", "x\tvalue\n",
                                "x\tvalue\n1\t2\n3\tnan\n", "x\ty\tvalue\n1\t2\n", "x\tvalue\n1\t2\t3\n"};
    nl_points *p = (nl_points *)1;
    cr_assert_eq(nl_points_read("/nonexistent-dir/p.tsv", &p), NL_EINPUT);
    cr_assert_null(p);
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        const char *path = write_tmp("bad.tsv", bad[i]);
        cr_assert_eq(nl_points_read(path, &p), NL_EINPUT, "case %zu: %s", i, nl_errmsg());
        unlink(path);
    }
    const char *path = write_tmp("ok.tsv", "x\ty\tvalue\n0.1\t0.2\t1.5\n");
    EXPECT_ENOMEM(nl_points_read(path, &p));
    unlink(path);
}

/* Rows read back exactly, comments and blank lines skipped, past the
 * first growth of the row buffer (256 rows). */
Test(trap_points, reads_back)
{
    char *text = malloc(300 * 64 + 64), *q = text;
    q += sprintf(q, "# made by hand\nx\ty\tz\tvalue\n\n");
    for (int i = 0; i < 300; i++)
        q += sprintf(q, "%d.25\t-%d.5\t2.385\t%d\n%s", i, i, 3 * i, i == 7 ? "# skipped\n" : "");
    const char *path = write_tmp("pts.tsv", text);
    nl_points *p;
    cr_assert_eq(nl_points_read(path, &p), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(p->dim, 3);
    cr_assert_eq(p->n, 300);
    for (size_t i = 0; i < 300; i++) {
        cr_assert_eq(p->pts[3 * i], (double)i + 0.25);
        cr_assert_eq(p->pts[3 * i + 1], -((double)i + 0.5));
        cr_assert_eq(p->pts[3 * i + 2], 2.385);
        cr_assert_eq(p->val[i], 3.0 * (double)i);
    }
    nl_points_free(p);
    unlink(path);
    free(text);
}

/* The hardening refusals: each with its code and the value named. */
Test(trap_rank1, hostile_inputs)
{
    nl_rank1_lattice L;
    long zero[2] = {1, 0}, same[3] = {1, 7, 7}, opposite[2] = {1, 609}, fine[2] = {1, 233};
    nl_model *neg = test_model("spectrum:cos(f)/(1+f*f)");
    nl_rank1_model_info info;
    double f[610];
    cr_assert_eq(nl_rank1_check_generator(610, 2, zero), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "degenerate"), "%s", nl_errmsg());
    cr_assert_eq(nl_rank1_check_generator(100, 3, same), NL_EINVAL);
    cr_assert_eq(nl_rank1_check_generator(610, 2, opposite), NL_EINVAL);
    cr_assert_eq(nl_rank1_check_generator(610, 2, fine), NL_OK);
    cr_assert_eq(nl_rank1_fibonacci(15, &L), NL_OK);
    cr_assert_eq(nl_rank1_model_synthesize(&L, neg, 1, 1, f, NULL, NULL), NL_ENOTPD, "a negative spectrum");
    cr_assert(strstr(nl_errmsg(), "not positive definite"), "%s", nl_errmsg());
    cr_assert_eq(nl_rank1_model_synthesize_info(&L, neg, 1, 1, NL_RANK1_CLAMP, f, NULL, NULL, &info), NL_OK, "%s",
                 nl_errmsg());
    cr_assert(info.negatives > 0 && info.clamp_error > 0 && isfinite(info.clamp_error));
    for (size_t n = 0; n < L.N; n++)
        cr_assert(isfinite(f[n]));
    nl_rank1_free(&L), nl_model_free(neg);
}

Test(trap_ocean, hostile_inputs)
{
    nl_rank1_lattice L;
    double c[2 * 55], grid[16];
    nl_ocean_params gale = {1e308, 0.4, 100, 1e-4}, speck = {12.3, 0.4, 1e-300, 1e-4}, loud = {12.3, 0.4, 100, 1e308};
    cr_assert_eq(nl_rank1_fibonacci(10, &L), NL_OK);
    cr_assert_eq(nl_ocean_lattice_coefficients(&L, &gale, 1, 0, c), NL_EINVAL, "a wind whose waves dwarf the patch");
    cr_assert(strstr(nl_errmsg(), "vanishes"), "%s", nl_errmsg());
    cr_assert_eq(nl_ocean_grid(4, &speck, 1, 0, grid, NULL, NULL), NL_EINVAL, "a patch of 1e-300 m");
    cr_assert_eq(nl_ocean_grid(4, &loud, 1, 0, grid, NULL, NULL), NL_EINVAL, "an amplitude that overflows");
    cr_assert(strstr(nl_errmsg(), "amplitude"), "%s", nl_errmsg());
    cr_assert_eq(nl_ocean_grid(4, &sea, 1, 1e308, grid, NULL, NULL), NL_EINVAL, "time 1e308");
    nl_rank1_free(&L);
}

Test(trap_lattice, not_positive_definite)
{
    nl_model *neg = test_model("spectrum:cos(20*f)/(1+f*f)");
    nl_synth_lattice_plan p;
    cr_assert_eq(nl_synth_lattice_plan_init(neg, 2, 16, 3, 0, &p), NL_ENOTPD);
    cr_assert(strstr(nl_errmsg(), "not positive definite"), "%s", nl_errmsg());
    cr_assert_eq(nl_synth_lattice_plan_init(neg, 2, 16, 3, NL_SYNTH_LATTICE_CLAMP, &p), NL_OK, "%s",
                 nl_errmsg());
    cr_assert(p.negatives > 0 && p.clamp_error > 0);
    nl_model_free(neg);
}

Test(trap_render, hostile_views)
{
    nl_field *f = field2(32, 32), *s = field2(32, 32);
    nl_render_view v;
    uint8_t rgb[3 * 16];
    cr_assert_eq(nl_render_relief(f, 30, 40, 1e308, s), NL_EINVAL, "slopes that overflow");
    cr_assert(strstr(nl_errmsg(), "zscale"), "%s", nl_errmsg());
    nl_render_view_default(f, &v);
    v.width = v.height = 4, v.tile = 1, v.haze = 1e300;
    cr_assert_eq(nl_render_terrain(f, &v, rgb), NL_EINVAL, "haze beyond reach");
    cr_assert(strstr(nl_errmsg(), "haze"), "%s", nl_errmsg());
    nl_render_view_default(f, &v);
    v.width = v.height = 4, v.cam[0] = 1e308;
    cr_assert_eq(nl_render_terrain(f, &v, rgb), NL_EINVAL, "camera far away");
    nl_render_view_default(f, &v);
    v.width = v.height = 4, v.azimuth = 1e308;
    cr_assert_eq(nl_render_terrain(f, &v, rgb), NL_EINVAL, "azimuth 1e308");
    nl_field_free(f), nl_field_free(s);
}

Test(trap_render, hostile_cloud_cameras)
{
    nl_cloud_scene s;
    unsigned char rgb[3 * 48];
    scene(&s);
    s.look[2] = -4;  /* the camera's own position */
    cr_assert_eq(nl_render_cloud(&s, rgb, NULL, NULL), NL_EINVAL, "looking at itself");
    cr_assert(strstr(nl_errmsg(), "look_at"), "%s", nl_errmsg());
    s.look[1] = -3;  /* straight down */
    cr_assert_eq(nl_render_cloud(&s, rgb, NULL, NULL), NL_EINVAL, "looking straight down");
    s.look[1] = 0, s.look[2] = 0, s.hi[0] = 1e308, s.lo[0] = -1e308;
    cr_assert_eq(nl_render_cloud(&s, rgb, NULL, NULL), NL_EINVAL, "a box of infinite size");
    cr_assert(strstr(nl_errmsg(), "box"), "%s", nl_errmsg());
    s.hi[0] = 1, s.lo[0] = -1;
    cr_assert_eq(nl_render_cloud(&s, rgb, NULL, NULL), NL_OK, "%s", nl_errmsg());
    nl_model_free(s.shape), nl_model_free(s.noise);
}
