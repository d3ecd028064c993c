/* The rank-1 field between the lattice points (synth/rank1.h: nl_rank1_eval,
 * nl_rank1_grid, and the ocean's picture nl_ocean_lattice_image): the series
 * equals the one-FFT synthesis at the lattice points and its gradient the
 * synthesised gradient; the W x W FFT equals the series at every pixel
 * centre, in 2D and on a slice of a 3D lattice, aliased or not; the field is
 * real, also for even N (the N/2 term).
 *
 * Tolerances: both sides sum the same N terms c_m e^{i phi} in another
 * order (or through an FFT), so they differ by rounding, at most some
 * log2(N) eps sum_m |c_m| for the FFTs and N eps sum |c_m| for the direct
 * sum (phases reduced mod 1 first); 1e-12 sum_m |c_m| bounds both for N
 * below 10^4 (N eps = 2e-12 at the worst, the errors being random-signed
 * far below it). */
#include "../core/nl_error.h"
#include "../synth/ocean.h"
#include "../synth/rank1.h"
#include "../synth/rank1_model.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double sum_abs(const double *c, size_t N)
{
    double s = 0;
    for (size_t m = 0; m < N; m++)
        s += hypot(c[2 * m], c[2 * m + 1]);
    return s;
}

/* A lattice and a field's coefficients (model m on a unit torus, seed 5). */
static double *field(nl_rank1_lattice *L, const char *spec)
{
    nl_model *m = test_model(spec);
    nl_rank1_model_ctx ctx = {m, L->s, 1.0};
    double *c = malloc(2 * L->N * sizeof *c);
    cr_assert_eq(nl_rank1_coefficients(L, nl_rank1_model_spectrum, &ctx, 5, c), NL_OK, "%s", nl_errmsg());
    nl_model_free(m);
    return c;
}

/* The series at the lattice points x_n is the synthesis: f and gradient. */
static void at_lattice_points(nl_rank1_lattice *L, const char *spec)
{
    size_t N = L->N, s = (size_t)L->s;
    double *c = field(L, spec), *f = malloc(N * sizeof *f), *g = malloc(N * s * sizeof *g), *x = malloc(N * s * sizeof *x),
           *v = malloc(N * sizeof *v), *gv = malloc(N * s * sizeof *gv), imag, extent = 2.385;
    cr_assert_eq(nl_rank1_synthesize(L, c, extent, f, g, NULL), NL_OK);
    for (size_t n = 0; n < N; n++)
        nl_rank1_point(L, n, x + n * s);
    cr_assert_eq(nl_rank1_eval(L, c, extent, N, x, v, gv, &imag), NL_OK, "%s", nl_errmsg());
    double tol = 1e-12 * sum_abs(c, N), gmax = 0, gerr = 0;
    cr_expect_leq(imag, tol, "imaginary part %g", imag);
    for (size_t n = 0; n < N; n++)
        cr_expect_leq(fabs(v[n] - f[n]), tol, "N %zu, point %zu: series %.17g, synthesis %.17g", N, n, v[n], f[n]);
    for (size_t q = 0; q < N * s; q++)
        gmax = fmax(gmax, fabs(g[q])), gerr = fmax(gerr, fabs(gv[q] - g[q]));
    /* the gradient's terms carry 2 pi |k| / extent: scale the bound by the largest */
    double kmax = 0;
    for (size_t m = 0; m < N; m++)
        kmax = fmax(kmax, nl_rank1_wave_norm(L, m));
    cr_expect_leq(gerr, tol * 2 * M_PI * kmax / extent, "N %zu: gradient differs by %g (largest %g)", N, gerr, gmax);
    free(c), free(f), free(g), free(x), free(v), free(gv);
}

Test(rank1_eval_slow, series_at_lattice_points)
{
    nl_rank1_lattice L;
    cr_assert_eq(nl_rank1_fibonacci(15, &L), NL_OK);  /* N = 610, even: the N/2 term */
    at_lattice_points(&L, "gauss:scale=0.1");
    nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_fibonacci(17, &L), NL_OK);  /* N = 1597, odd */
    at_lattice_points(&L, "markov:scale=0.2");
    nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_korobov(1000, 3, 0, &L), NL_OK);
    at_lattice_points(&L, "gauss:scale=0.15");
    nl_rank1_free(&L);
}

/* Every pixel of the W x W FFT is the series at its centre. */
static void grid_is_series(nl_rank1_lattice *L, size_t W, const double *at)
{
    double *c = field(L, "gauss:scale=0.12"), *img = malloc(W * W * sizeof *img), *gx = malloc(W * W * sizeof *gx),
           *gy = malloc(W * W * sizeof *gy), imag;
    size_t s = (size_t)L->s;
    cr_assert_eq(nl_rank1_grid(L, c, 1.0, W, at, img, gx, gy, &imag), NL_OK, "%s", nl_errmsg());
    double tol = 1e-12 * sum_abs(c, L->N);
    cr_expect_leq(imag, tol, "imaginary part %g", imag);
    for (size_t q = 0; q < W * W; q += 7) {
        double x[4] = {((double)(q % W) + 0.5) / (double)W, ((double)(q / W) + 0.5) / (double)W, 0, 0}, v, g[4];
        for (size_t a = 2; a < s; a++)
            x[a] = at[a - 2];
        cr_assert_eq(nl_rank1_eval(L, c, 1.0, 1, x, &v, g, NULL), NL_OK);
        cr_expect_leq(fabs(img[q] - v), tol, "W %zu, pixel %zu: %.17g, series %.17g", W, q, img[q], v);
        cr_expect_leq(fabs(gx[q] - g[0]) + fabs(gy[q] - g[1]), tol * 2 * M_PI * 2 * (double)W, "gradient at %zu", q);
    }
    free(c), free(img), free(gx), free(gy);
}

Test(rank1_eval, grid_equals_series)
{
    nl_rank1_lattice L;
    double at[2] = {0.3141, -7.25};
    cr_assert_eq(nl_rank1_fibonacci(15, &L), NL_OK);
    grid_is_series(&L, 64, NULL);  /* alias-free: max |k_a| < 32 */
    grid_is_series(&L, 10, NULL);  /* aliased pixels are still the series' values */
    nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_korobov(2048, 3, 0, &L), NL_OK);
    grid_is_series(&L, 48, at);
    nl_rank1_free(&L);
    cr_assert_eq(nl_rank1_korobov(4096, 4, 0, &L), NL_OK);
    grid_is_series(&L, 40, at);
    nl_rank1_free(&L);
}

/* The ocean's picture is the series of its coefficients; refusals. */
Test(rank1_eval, ocean_image_and_refusals)
{
    nl_rank1_lattice L;
    nl_ocean_params o = {20, 0.5, 1000, 2e-7};
    size_t W = 32;
    double h[32 * 32], *c, x[3] = {1e10, 0, 0}, v;
    cr_assert_eq(nl_rank1_fibonacci(12, &L), NL_OK);
    c = malloc(2 * L.N * sizeof *c);
    cr_assert_eq(nl_ocean_lattice_image(&L, &o, 3, 1.5, W, h, NULL, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_ocean_lattice_coefficients(&L, &o, 3, 1.5, c), NL_OK);
    for (size_t q = 0; q < W * W; q += 13) {
        double p[2] = {((double)(q % W) + 0.5) / (double)W, ((double)(q / W) + 0.5) / (double)W};
        cr_assert_eq(nl_rank1_eval(&L, c, o.patch, 1, p, &v, NULL, NULL), NL_OK);
        cr_expect_leq(fabs(v - h[q]), 1e-12 * sum_abs(c, L.N), "pixel %zu", q);
    }
    cr_expect_eq(nl_rank1_eval(&L, c, 1.0, 1, x, &v, NULL, NULL), NL_EINVAL, "a point at 1e10");
    cr_expect_eq(nl_rank1_eval(&L, c, 0, 1, x + 1, &v, NULL, NULL), NL_EINVAL, "extent 0");
    cr_expect_eq(nl_rank1_grid(&L, c, 1.0, 1, NULL, h, NULL, NULL, NULL), NL_EINVAL, "W = 1");
    cr_expect_eq(nl_rank1_grid(&L, c, -1, 8, NULL, h, NULL, NULL, NULL), NL_EINVAL, "extent -1");
    nl_rank1_free(&L), free(c);
    cr_assert_eq(nl_rank1_korobov(64, 3, 0, &L), NL_OK);
    c = calloc(2 * L.N, sizeof *c);
    double bad = NAN;
    cr_expect_eq(nl_rank1_grid(&L, c, 1.0, 8, &bad, h, NULL, NULL, NULL), NL_EINVAL, "a NaN slice");
    nl_rank1_free(&L), free(c);
    cr_assert_eq(nl_rank1_korobov(64, 1, 0, &L), NL_OK);
    c = calloc(2 * L.N, sizeof *c);
    cr_expect_eq(nl_rank1_grid(&L, c, 1.0, 8, NULL, h, NULL, NULL, NULL), NL_EINVAL, "a 1D lattice");
    nl_rank1_free(&L), free(c);
}

/* The model's coefficients, transformed, are exactly the one-call synthesis
 * (the same operations in the same order: bit-identical). */
Test(rank1_eval, model_coefficients_are_the_synthesis)
{
    nl_rank1_lattice L;
    nl_model *m = test_model("matern:nu=1.5,scale=0.1");
    cr_assert_eq(nl_rank1_korobov(3001, 3, 0, &L), NL_OK);
    double *c = malloc(2 * L.N * sizeof *c), *f = malloc(L.N * sizeof *f), *g = malloc(L.N * sizeof *g);
    cr_assert_eq(nl_rank1_model_coefficients(&L, m, 2.385, 9, 0, c, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_rank1_synthesize(&L, c, 2.385, f, NULL, NULL), NL_OK);
    cr_assert_eq(nl_rank1_model_synthesize(&L, m, 2.385, 9, g, NULL, NULL), NL_OK);
    cr_expect_eq(memcmp(f, g, L.N * sizeof *f), 0, "two steps differ from one");
    free(c), free(f), free(g), nl_model_free(m), nl_rank1_free(&L);
}
