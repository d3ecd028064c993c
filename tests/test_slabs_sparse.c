/* Slabs of sparse convolution (nl_synth_sparse_execute_slab): concatenated
 * slabs equal the whole grid bit for bit, periodic (the impulses of cells
 * wrapped round the tile, summed in the periodic execute's order) and not
 * (the window at (0, s0)), for the splits of tests/test_slabs.c. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/sparse.h"
#include "slabs.h"
#include "util.h"

#include <criterion/criterion.h>

typedef struct {
    const nl_synth_sparse_plan *p;
    uint64_t seed;
    int wrap;
    const size_t *n;
} sparse_ctx;

static int sparse_slab(const void *ctx, size_t s0, nl_field *f)
{
    const sparse_ctx *c = ctx;
    return nl_synth_sparse_execute_slab(c->p, c->seed, c->wrap ? NL_SYNTH_SPARSE_WRAP : 0, c->n, s0, f);
}

/* The whole grid of p, then its slabs, with and without wrap. */
static void check_sparse(const nl_synth_sparse_plan *p, int dim, size_t nx, size_t ny, const char *what)
{
    size_t n[2] = {nx, ny};
    for (int wrap = 0; wrap <= 1; wrap++) {
        nl_field *full = nl_field_alloc(dim, n, NULL, NULL);
        sparse_ctx c = {p, 0xabcdef12345u + (uint64_t)wrap, wrap, n};
        cr_assert_not_null(full);
        cr_assert_eq(nl_synth_sparse_execute(p, c.seed, wrap ? NL_SYNTH_SPARSE_WRAP : 0, NULL, full), NL_OK,
                     "%s: %s", what, nl_errmsg());
        check_slab_splits(full, sparse_slab, &c, what);
        nl_field_free(full);
    }
}

static nl_synth_sparse_plan *model_plan(const char *spec, int dim, int radius, int cell, double density)
{
    nl_model *m = test_model(spec);
    nl_synth_sparse_plan *p;
    cr_assert_eq(nl_synth_sparse_plan_model(m, dim, NULL, SPARSE_OPTS(radius, cell, density), &p), NL_OK, "%s",
                 nl_errmsg());
    nl_model_free(m);
    return p;
}

Test(slabs, sparse_2d)
{
    nl_synth_sparse_plan *p = model_plan("gauss:scale=3.3", 2, 0, 0, 4.7);
    check_sparse(p, 2, 64, 64, "sparse 64x64, auto radius");
    check_sparse(p, 2, 96, 64, "sparse 96x64");
    check_sparse(p, 2, 64, 128, "sparse 64x128");
    nl_synth_sparse_plan_free(p);
    /* a kernel as wide as the tile allows: halos wrap more than one cell */
    p = model_plan("markov:scale=2.1", 2, 15, 8, 2.3);
    check_sparse(p, 2, 32, 48, "sparse radius 15, cell 8, 32x48");
    nl_synth_sparse_plan_free(p);
}

/* Above 65536 samples: several threads share the gather. */
Test(slabs, sparse_threaded)
{
    nl_synth_sparse_plan *p = model_plan("markov:scale=4.4", 2, 12, 0, 1.7);
    check_sparse(p, 2, 512, 384, "sparse 512x384");
    nl_synth_sparse_plan_free(p);
}

Test(slabs, sparse_angle_and_expression)
{
    nl_synth_sparse_plan *p;
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-(x*x/30+y*y/4))", 2, SPARSE_OPTS(9, 0, 3.1), &p), NL_OK, "%s",
                 nl_errmsg());
    check_sparse(p, 2, 64, 48, "expression kernel");
    cr_assert_eq(nl_synth_sparse_set_angle(p, "x/17+y/29"), NL_OK, "%s", nl_errmsg());
    check_sparse(p, 2, 64, 48, "rotated kernel");
    cr_assert_eq(nl_synth_sparse_set_bands(p, 2), NL_OK, "%s", nl_errmsg());
    check_sparse(p, 2, 64, 48, "with bands");
    nl_synth_sparse_plan_free(p);
}

Test(slabs, sparse_1d)
{
    nl_synth_sparse_plan *p = model_plan("markov:scale=5.9", 1, 0, 0, 3.3);
    check_sparse(p, 1, 512, 1, "sparse 1D");
    nl_synth_sparse_plan_free(p);
}

/* An exemplar plan adds its mean to every sample: the slabs too. */
Test(slabs, sparse_exemplar_mean)
{
    size_t ni[2] = {24, 24};
    nl_field *img = nl_field_alloc(2, ni, NULL, NULL);
    nl_synth_sparse_plan *p;
    for (size_t i = 0; i < img->count; i++)
        img->data[i] = 7.5 + 0.41 * (double)((i * 7919) % 31) - 0.13 * (double)(i % 5);
    cr_assert_eq(nl_synth_sparse_plan_exemplar(img, SPARSE_OPTS(0, 8, 2.9), &p), NL_OK, "%s", nl_errmsg());
    check_sparse(p, 2, 64, 48, "exemplar");
    nl_synth_sparse_plan_free(p);
    nl_field_free(img);
}

Test(slabs, sparse_refusals)
{
    nl_synth_sparse_plan *p = model_plan("gauss:scale=3.3", 2, 6, 8, 2.0);
    size_t n[2] = {64, 64}, a[2] = {64, 8}, d[2] = {32, 8}, odd[2] = {64, 60};
    nl_field *f = nl_field_alloc(2, a, NULL, NULL), *g = nl_field_alloc(2, d, NULL, NULL);
    cr_assert_eq(nl_synth_sparse_execute_slab(p, 1, NL_SYNTH_SPARSE_WRAP, n, 57, f), NL_EINVAL,
                 "rows 57..64 pass the field's 64");
    cr_assert_eq(nl_synth_sparse_execute_slab(p, 1, NL_SYNTH_SPARSE_WRAP, n, 56, f), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_sparse_execute_slab(p, 1, 0, n, 0, g), NL_EINVAL, "rows of 32, not 64");
    cr_assert_eq(nl_synth_sparse_execute_slab(p, 1, NL_SYNTH_SPARSE_WRAP, odd, 0,
                 f), NL_EINVAL, "60 rows: not a multiple of the cell");
    cr_assert_eq(nl_synth_sparse_execute_slab(p, 1, 0, odd, 0, f), NL_OK, "a window needs no whole cells");
    nl_synth_sparse_plan_free(p);
    nl_field_free(f), nl_field_free(g);
}

/* The bytes: a quarter of the rows needs well under the whole grid's
 * impulses (the halo is two reaches, small beside 256 rows). */
Test(slabs, sparse_bytes_scale_with_the_slab)
{
    nl_synth_sparse_plan *p = model_plan("gauss:scale=3.3", 2, 0, 0, 8.0);
    size_t n[2] = {1024, 1024};
    size_t whole = nl_synth_sparse_slab_bytes(p, NL_SYNTH_SPARSE_WRAP, n, 1024),
           quarter = nl_synth_sparse_slab_bytes(p, NL_SYNTH_SPARSE_WRAP, n, 256);
    cr_assert_lt(quarter, whole * 3 / 10, "a quarter slab: %zu bytes, the whole grid %zu", quarter, whole);
    cr_assert_gt(quarter, whole / 5);
    nl_synth_sparse_plan_free(p);
}
