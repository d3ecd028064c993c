/* Slabs along the slowest axis (y in 2D, x in 1D), as a distributed
 * synthesis splits a field: for every split, the slabs computed on their
 * own, concatenated, equal the whole field bit for bit (memcmp, not a
 * tolerance: each sample must see the same operands in the same order).
 * The splits: the blocks FFTW-MPI gives P = 1, 2, 3, 4 ranks (ceil(n / P)
 * rows each, the last fewer) and P = 9, 12, whose last ranks get no rows
 * (skipped, as the caller does); uneven arbitrary cuts; and single rows,
 * including the first and the last, whose halos wrap round a periodic
 * field. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"
#include "slabs.h"
#include "util.h"

#include <criterion/criterion.h>
#include <string.h>

static size_t zero_rows_seen;

/* The slab s0 .. s0 + ns - 1 of `full` from fn, compared with full's rows. */
static void check_slab(const nl_field *full, slab_fn *fn, const void *ctx, size_t s0, size_t ns, const char *what)
{
    const int s = full->dim - 1;
    const size_t row = full->count / full->n[s];
    size_t n[3] = {full->n[0], full->n[1], full->n[2]};
    nl_field *f;
    int st;
    n[s] = ns;
    f = nl_field_alloc(full->dim, n, NULL, &st);
    cr_assert_not_null(f);
    st = fn(ctx, s0, f);
    cr_assert_eq(st, NL_OK, "%s: slab %zu + %zu: %s", what, s0, ns, nl_errmsg());
    cr_assert(memcmp(f->data, full->data + s0 * row, ns * row * sizeof *f->data) == 0,
              "%s: the slab of %zu rows from %zu differs from the whole field's", what, ns, s0);
    cr_assert_eq(f->h[0], full->h[0], "%s: spacing", what);
    nl_field_free(f);
}

/* The slabs between cuts c[0] = 0 < ... < c[k] = n, empty ones skipped. */
static void check_cuts(const nl_field *full, slab_fn *fn, const void *ctx, const size_t *c, size_t k, const char *what)
{
    size_t covered = 0;
    for (size_t r = 0; r < k; r++) {
        if (c[r + 1] == c[r]) {
            zero_rows_seen++;
            continue;
        }
        check_slab(full, fn, ctx, c[r], c[r + 1] - c[r], what);
        covered += c[r + 1] - c[r];
    }
    cr_assert_eq(covered, full->n[full->dim - 1], "%s: the slabs cover the field", what);
}

void check_slab_splits(const nl_field *full, slab_fn *fn, const void *ctx, const char *what)
{
    static const int ranks[] = {1, 2, 3, 4, 9, 12};
    const size_t n = full->n[full->dim - 1];
    size_t c[16];
    uint64_t x = 0x9e3779b97f4a7c15u;
    for (size_t t = 0; t < sizeof ranks / sizeof *ranks; t++) {
        /* FFTW-MPI's block split: ceil(n / P) rows, the last ranks fewer or none */
        size_t P = (size_t)ranks[t], b = (n + P - 1) / P;
        for (size_t r = 0; r <= P; r++)
            c[r] = r * b < n ? r * b : n;
        check_cuts(full, fn, ctx, c, P, what);
    }
    for (int rep = 0; rep < 2; rep++) {
        /* uneven cuts: 5 slabs at arbitrary (fixed) places */
        size_t k = 5;
        c[0] = 0, c[k] = n;
        for (size_t r = 1; r < k; r++) {
            x = x * 6364136223846793005u + 1442695040888963407u;
            c[r] = (size_t)(x >> 33) % (n + 1);
        }
        for (size_t r = 1; r < k; r++) /* sort */
            for (size_t q = r; q > 1 && c[q] < c[q - 1]; q--) {
                size_t tmp = c[q];
                c[q] = c[q - 1], c[q - 1] = tmp;
            }
        check_cuts(full, fn, ctx, c, k, what);
    }
    /* single rows: the first two, the middle, the last two */
    {
        size_t rows[] = {0, 1, n / 2, n - 2, n - 1};
        for (size_t r = 0; r < 5; r++)
            check_slab(full, fn, ctx, rows[r], 1, what);
    }
}

size_t slab_zero_rows_seen(void) { return zero_rows_seen; }

/* Subdivision: the plan's field, then its slabs. */
typedef struct {
    const nl_subdiv_plan *p;
    uint64_t seed;
    const nl_field *image;
} subdiv_ctx;

static int subdiv_slab(const void *ctx, size_t s0, nl_field *f)
{
    const subdiv_ctx *c = ctx;
    return c->image ? nl_subdiv_plan_execute_image_slab(c->p, c->image, c->seed, s0, f)
                    : nl_subdiv_plan_execute_slab(c->p, c->seed, s0, f);
}

static void check_subdiv(const char *model, int dim, size_t nx, size_t ny, const nl_subdiv_options *o,
                         const char *what)
{
    nl_model *m = test_model(model);
    size_t n[2] = {nx, ny};
    nl_subdiv_plan *p;
    nl_field *full = nl_field_alloc(dim, n, NULL, NULL);
    subdiv_ctx c = {NULL, 0x5eed1234abcdu, NULL};
    cr_assert_not_null(full);
    cr_assert_eq(nl_subdiv_plan_alloc(m, dim, n, 1.0, o, &p), NL_OK, "%s: %s", what, nl_errmsg());
    c.p = p;
    cr_assert_eq(nl_subdiv_plan_execute(p, c.seed, full), NL_OK, "%s: %s", what, nl_errmsg());
    check_slab_splits(full, subdiv_slab, &c, what);
    nl_subdiv_plan_free(p);
    nl_field_free(full);
    nl_model_free(m);
}

static nl_subdiv_options opts(void)
{
    nl_subdiv_options o;
    nl_subdiv_options_default(&o);
    return o;
}

Test(slabs, subdiv_periodic_default)
{
    nl_subdiv_options o = opts();
    check_subdiv("markaussian:alpha=1.4,scale=5.3", 2, 64, 64, &o, "64x64 N=2");
    check_subdiv("gauss:scale=3.7", 2, 96, 64, &o, "96x64 N=2");
    check_subdiv("markov:scale=9.1", 2, 64, 128, &o, "64x128 N=2");
    check_subdiv("markov:scale=9.1", 2, 256, 256, &o, "256x256 N=2 (5 levels)");
    cr_assert_gt(slab_zero_rows_seen(), 0, "some split left a rank without rows");
}

Test(slabs, subdiv_periodic_neighbourhoods)
{
    nl_subdiv_options o = opts();
    o.N = 3;
    check_subdiv("markov:scale=6.3", 2, 96, 64, &o, "96x64 N=3");
    o.N = 0;
    check_subdiv("markaussian:alpha=1.2,scale=4.4", 2, 64, 128, &o, "64x128 auto N");
    o.N = 1, o.levels = 2;
    check_subdiv("markov:scale=6.3", 2, 48, 40, &o, "48x40 N=1, 2 levels");
    o = opts();
    o.random_nb = 3;
    check_subdiv("markov:scale=6.3", 2, 64, 64, &o, "random neighbourhoods");
}

Test(slabs, subdiv_periodic_correlated_and_clamp)
{
    nl_subdiv_options o = opts();
    o.displacements = NL_SUBDIV_DISP_ERROR;
    check_subdiv("markov:scale=7.5", 2, 64, 64, &o, "correlated (error)");
    o.displacements = NL_SUBDIV_DISP_NEWNEW, o.taps = 3;
    check_subdiv("gauss:scale=4.2", 2, 96, 64, &o, "correlated (new-new), 3 taps");
    o = opts();
    o.allow_not_pd = 1, o.N = 3;
    check_subdiv("gauss:scale=7.9", 2, 64, 64, &o, "--clamp");
}

/* Large enough that refinement and displacements run on several threads
 * (above 65536 samples per level): the split among threads must not
 * matter either. */
Test(slabs_slow, subdiv_threaded)
{
    nl_subdiv_options o = opts();
    o.displacements = NL_SUBDIV_DISP_ERROR;
    check_subdiv("markov:scale=12.7", 2, 512, 384, &o, "512x384 correlated");
    check_subdiv("markov:scale=12.7", 1, 1 << 18, 1, &o, "1D 2^18 correlated");
}

Test(slabs, subdiv_1d)
{
    nl_subdiv_options o = opts();
    check_subdiv("markov:scale=11.3", 1, 256, 1, &o, "1D N=2");
    o.displacements = NL_SUBDIV_DISP_ERROR;
    check_subdiv("markov:scale=11.3", 1, 512, 1, &o, "1D correlated");
    o = opts();
    o.nonperiodic = 1;
    check_subdiv("markov:scale=11.3", 1, 300, 1, &o, "1D window");
}

Test(slabs, subdiv_nonperiodic_window)
{
    nl_subdiv_options o = opts();
    o.nonperiodic = 1;
    check_subdiv("markov:scale=4.1", 2, 96, 64, &o, "window 96x64");
    o.displacements = NL_SUBDIV_DISP_ERROR, o.levels = 4;
    check_subdiv("markov:scale=4.1", 2, 50, 37, &o, "window 50x37 correlated");
}

Test(slabs, subdiv_midpoint)
{
    size_t n[2] = {64, 64};
    nl_subdiv_plan *p;
    nl_field *full = nl_field_alloc(2, n, NULL, NULL);
    subdiv_ctx c = {NULL, 99, NULL};
    cr_assert_eq(nl_subdiv_plan_alloc_midpoint(2, n, 1.0, 0, 0.73, 1.0, 1.0, &p), NL_OK, "%s", nl_errmsg());
    c.p = p;
    cr_assert_eq(nl_subdiv_plan_execute(p, c.seed, full), NL_OK);
    check_slab_splits(full, subdiv_slab, &c, "midpoint");
    nl_subdiv_plan_free(p);
    nl_field_free(full);
}

Test(slabs, subdiv_seed_image)
{
    nl_model *m = test_model("markov:scale=5.5");
    size_t n[2] = {64, 32}, ni[2] = {16, 8};
    nl_subdiv_options o = opts();
    nl_subdiv_plan *p;
    nl_field *img = nl_field_alloc(2, ni, NULL, NULL), *full = nl_field_alloc(2, n, NULL, NULL);
    subdiv_ctx c = {NULL, 5, img};
    for (size_t i = 0; i < img->count; i++)
        img->data[i] = 3.25 + 0.37 * (double)((i * 7919) % 23);
    o.image = 1, o.levels = 2;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), NL_OK, "%s", nl_errmsg());
    c.p = p;
    cr_assert_eq(nl_subdiv_plan_execute_image(p, img, c.seed, full), NL_OK, "%s", nl_errmsg());
    check_slab_splits(full, subdiv_slab, &c, "seed image");
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 5, 0, full), NL_EINVAL, "an image plan needs its image");
    nl_subdiv_plan_free(p);
    nl_field_free(full), nl_field_free(img);
    nl_model_free(m);
}

Test(slabs, subdiv_seed_image_1d)
{
    nl_model *m = test_model("markov:scale=5.5");
    size_t n[1] = {256}, ni[1] = {32};
    nl_subdiv_options o = opts();
    nl_subdiv_plan *p;
    nl_field *img = nl_field_alloc(1, ni, NULL, NULL), *full = nl_field_alloc(1, n, NULL, NULL);
    subdiv_ctx c = {NULL, 6, img};
    for (size_t i = 0; i < img->count; i++)
        img->data[i] = -1.75 + 0.29 * (double)((i * 7919) % 13);
    o.image = 1, o.levels = 3;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 1, n, 1.0, &o, &p), NL_OK, "%s", nl_errmsg());
    c.p = p;
    cr_assert_eq(nl_subdiv_plan_execute_image(p, img, c.seed, full), NL_OK, "%s", nl_errmsg());
    check_slab_splits(full, subdiv_slab, &c, "1D seed image");
    nl_subdiv_plan_free(p);
    nl_field_free(full), nl_field_free(img);
    nl_model_free(m);
}

/* The contract's refusals: a slab outside the field, no rows, a row of the
 * wrong length, the wrong dimension. */
Test(slabs, subdiv_refusals)
{
    nl_model *m = test_model("markov:scale=5.5");
    size_t n[2] = {64, 64}, a[2] = {64, 8}, b[2] = {64, 0}, d[2] = {32, 8};
    nl_subdiv_options o = opts();
    nl_subdiv_plan *p;
    nl_field *f = nl_field_alloc(2, a, NULL, NULL), *g = nl_field_alloc(2, d, NULL, NULL);
    nl_field z = {.dim = 2, .n = {b[0], b[1], 1}, .count = 0};
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), NL_OK);
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 1, 57, f), NL_EINVAL, "rows 57..64 pass the field's 64");
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 1, 56, f), NL_OK, "rows 56..63");
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 1, (size_t)-1, f), NL_EINVAL, "s0 beyond everything");
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 1, 0, &z), NL_EINVAL, "no rows");
    cr_assert_eq(nl_subdiv_plan_execute_slab(p, 1, 0, g), NL_EINVAL, "rows of 32, not 64");
    nl_subdiv_plan_free(p);
    nl_field_free(f), nl_field_free(g);
    nl_model_free(m);
}

/* The byte estimate: a quarter slab needs well under the whole field's
 * levels (the halo and the coarse level are small beside it), and the
 * estimate grows with the slab. */
Test(slabs, subdiv_bytes_scale_with_the_slab)
{
    nl_model *m = test_model("markov:scale=9.1");
    size_t n[2] = {1024, 1024};
    nl_subdiv_options o = opts();
    nl_subdiv_plan *p;
    o.displacements = NL_SUBDIV_DISP_ERROR;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), NL_OK, "%s", nl_errmsg());
    size_t whole = nl_subdiv_plan_slab_bytes(p, 1024), quarter = nl_subdiv_plan_slab_bytes(p, 256),
           row = nl_subdiv_plan_slab_bytes(p, 1), field = 1024 * 1024 * sizeof(double);
    cr_assert_gt(whole, field / 2, "the whole field's levels: its last but one level and more (%zu)", whole);
    cr_assert_lt(quarter, whole * 2 / 5, "a quarter slab: %zu bytes, the whole %zu", quarter, whole);
    cr_assert_lt(row, field / 20, "one row: %zu bytes", row);
    cr_assert_lt(row, quarter);
    nl_subdiv_plan_free(p);
    nl_model_free(m);
}
