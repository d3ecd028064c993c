/* Error paths of the synthesis modules (after GSL's fft/test_trap_source.c):
 * each NL_E* code that fft.h, circulant.h, cholesky.h, sparse.h,
 * faulting.h and shape.h list is triggered here (subdivision: in
 * test_subdiv_plan.c), with *out set to NULL by a failing _alloc.  Not
 * triggered: NL_ENOMEM, and NL_EFAIL from FFTW or a solver, which need a
 * failing allocator or library.  Then the plan properties: executing twice
 * with one seed is bit-identical, two seeds differ, and the circulant plan
 * is only read by execute, so two threads on one plan agree bit for bit
 * (exact equality: the same operations on the same numbers). */
#include "../core/dist.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/cholesky.h"
#include "../synth/circulant.h"
#include "../synth/faulting.h"
#include "../synth/fft.h"
#include "../synth/shape.h"
#include "../synth/sparse.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

static nl_field *field(int dim, size_t nx, size_t ny)
{
    size_t n[3] = {nx, ny, 1};
    nl_field *f = nl_field_alloc(dim, n, NULL, NULL);
    cr_assert_not_null(f);
    return f;
}

static int same(const nl_field *a, const nl_field *b)
{
    return a->count == b->count && memcmp(a->data, b->data, a->count * sizeof *a->data) == 0;
}

Test(synth_errors, fft)
{
    nl_model *m = test_model("markov:scale=3"), *osc = test_model("oscillatory:omega=2,scale=10"),
             *img = test_model("spectrum:exp(-k);ratio=0.5");
    size_t n[2] = {64, 64}, big[3] = {1000000, 1000000, 1000}, wide[1] = {(size_t)1 << 32};
    nl_synth_fft_plan *p = (nl_synth_fft_plan *)1;
    nl_field *f = field(2, 32, 64), *zero = field(1, 16, 1);
    cr_assert_eq(nl_synth_fft_plan_alloc(img, 2, n, NULL, 0, &p), NL_EINVAL, "%s", nl_errmsg());
    cr_assert_null(p);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 3, big, NULL, 0, &p), NL_ETOOBIG);
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 1, wide, NULL, 0, &p), NL_ETOOBIG, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_fft_plan_alloc(osc, 2, n, NULL, 0, &p), NL_ENOTPD);
    cr_assert(strstr(nl_errmsg(), "not positive definite"), "%s", nl_errmsg());
    memset(zero->data, 0, zero->count * sizeof *zero->data);
    cr_assert_eq(nl_synth_fft_plan_spectrum(zero, 0, &p), NL_ENOTPD, "no positive part");
    cr_assert_eq(nl_synth_fft_plan_alloc(m, 2, n, NULL, 0, &p), 0);
    cr_assert_eq(nl_synth_fft_execute(p, 1, f), NL_EINVAL, "32x64 field, 64x64 plan");
    nl_synth_fft_plan_free(p);
    nl_synth_fft_plan_free(NULL);
    nl_model_free(m), nl_model_free(osc), nl_model_free(img), nl_field_free(f), nl_field_free(zero);
}

Test(synth_errors, circulant)
{
    nl_model *m = test_model("markov:scale=3"), *bad = test_model("gauss-osc:omega=2,scale=3"),
             *img = test_model("spectrum:exp(-k);ratio=0.5");
    size_t n[3] = {64, 64, 1}, big[3] = {1000000, 1000000, 1000};
    nl_synth_circulant_plan *p = (nl_synth_circulant_plan *)1;
    nl_field *f = field(2, 64, 32);
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 4, n, NULL, 0, 16, &p), NL_EINVAL);
    cr_assert_null(p);
    cr_assert_eq(nl_synth_circulant_plan_alloc(img, 2, n, NULL, 0, 16, &p), NL_EINVAL, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 3, big, NULL, 0, 16, &p), NL_ETOOBIG);
    cr_assert_eq(nl_synth_circulant_plan_alloc(bad, 2, n, NULL, 0, 16, &p), NL_ENOTPD);
    cr_assert(strstr(nl_errmsg(), "cannot be embedded"), "%s", nl_errmsg());
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, n, NULL, 0, 16, &p), 0);
    cr_assert_eq(nl_synth_circulant_execute(p, 1, f), NL_EINVAL);
    nl_synth_circulant_plan_free(p);
    nl_synth_circulant_plan_free(NULL);
    nl_model_free(m), nl_model_free(bad), nl_model_free(img), nl_field_free(f);
}

Test(synth_errors, cholesky)
{
    /* the example: a triangle that is not positive definite on a
     * fine grid, found without touching GSL's error handler */
    nl_model *m = test_model("markov:scale=3"), *tri = test_model("expr:1-abs(t)/3"),
             *img = test_model("spectrum:exp(-k);ratio=0.5");
    size_t n[2] = {10, 10}, n0[1] = {0}, big[2] = {100, 100}, line[1] = {64};
    double h[1] = {0.1};
    nl_synth_cholesky_plan *p = (nl_synth_cholesky_plan *)1;
    nl_field *f = field(2, 10, 9);
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 1, n0, NULL, &p), NL_EINVAL, "a zero size: %s", nl_errmsg());
    cr_assert_null(p);
    cr_assert_eq(nl_synth_cholesky_plan_alloc(img, 2, n, NULL, &p), NL_EINVAL, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 2, big, NULL, &p), NL_ETOOBIG);
    cr_assert_eq(nl_synth_cholesky_plan_alloc(tri, 1, line, h, &p), NL_ENOTPD, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 2, n, NULL, &p), 0);
    cr_assert_eq(nl_synth_cholesky_execute(p, 1, f), NL_EINVAL);
    nl_synth_cholesky_plan_free(p);
    nl_synth_cholesky_plan_free(NULL);
    nl_model_free(m), nl_model_free(tri), nl_model_free(img), nl_field_free(f);
}

Test(synth_errors, sparse)
{
    nl_model *m = test_model("markov:scale=3");
    double h[2] = {1, 1};
    long origin[2] = {3, 4};
    nl_synth_sparse_plan *p = (nl_synth_sparse_plan *)1;
    nl_field *img = field(2, 16, 16), *flat = field(2, 16, 16), *one = field(1, 16, 1), *f = field(2, 60, 64),
             *f1 = field(1, 64, 1);
    for (size_t i = 0; i < img->count; i++)
        img->data[i] = sin(2.385 * (double)i), flat->data[i] = 1.5;
    cr_assert_eq(nl_synth_sparse_plan_model(m, 3, h, SPARSE_OPTS(0, 0, 1), &p), NL_EINVAL);
    cr_assert_null(p);
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(8, 0, -1), &p), NL_EINVAL, "density");
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(5000, 0, 1), &p), NL_EINVAL, "radius");
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(8, 5000, 1), &p), NL_EINVAL, "cell");
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-q)", 2, SPARSE_OPTS(8, 0, 1), &p), NL_EINVAL, "unknown variable");
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r", 2, SPARSE_OPTS(8, 0, 1), &p), NL_EINVAL, "malformed");
    cr_assert_eq(nl_synth_sparse_plan_expr("0*r", 2, SPARSE_OPTS(8, 0, 1), &p), NL_EINVAL, "zero kernel");
    cr_assert_eq(nl_synth_sparse_plan_expr("1/r", 2, SPARSE_OPTS(8, 0, 1), &p), NL_EINVAL, "not finite at 0");
    cr_assert_eq(nl_synth_sparse_plan_image(one, SPARSE_OPTS(0, 0, 1), &p), NL_EINVAL, "1D image");
    cr_assert_eq(nl_synth_sparse_plan_image(flat, SPARSE_OPTS(0, 0, 1), &p), NL_EINVAL, "constant image");
    cr_assert_eq(nl_synth_sparse_plan_exemplar(img, SPARSE_OPTS(9, 0, 1), &p), NL_EINVAL, "an 18x18 window of 16x16");
    cr_assert_eq(nl_synth_sparse_plan_exemplar(one, SPARSE_OPTS(0, 0, 1), &p), NL_EINVAL);
    cr_assert_null(p);

    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 1, SPARSE_OPTS(8, 0, 1), &p), 0);
    cr_assert_eq(nl_synth_sparse_set_angle(p, "x"), NL_EINVAL, "a 1D plan takes no angle");
    nl_synth_sparse_plan_free(p);
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(8, 0, 1), &p), 0);
    cr_assert_eq(nl_synth_sparse_set_angle(p, "x+"), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_set_angle(p, "z"), NL_EINVAL);
    cr_assert_eq(nl_synth_sparse_execute(p, 1, 0, NULL, f1), NL_EINVAL, "1D field, 2D plan");
    cr_assert_eq(nl_synth_sparse_execute(p, 1, NL_SYNTH_SPARSE_WRAP, origin, f), NL_EINVAL, "wrap with an origin");
    cr_assert_eq(nl_synth_sparse_execute(p, 1, NL_SYNTH_SPARSE_WRAP, NULL, f), NL_EINVAL,
                 "60 is not a multiple of the cell 8");
    nl_synth_sparse_plan_free(p);
    cr_assert_eq(nl_synth_sparse_plan_expr("exp(-r)", 2, SPARSE_OPTS(40, 8, 1), &p), 0);
    nl_field *tile = field(2, 64, 64);
    cr_assert_eq(nl_synth_sparse_execute(p, 1, NL_SYNTH_SPARSE_WRAP, NULL, tile), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "larger than the tile"), "%s", nl_errmsg());
    nl_field_free(tile);
    nl_synth_sparse_plan_free(p);
    nl_synth_sparse_plan_free(NULL);
    nl_model_free(m), nl_field_free(img), nl_field_free(flat), nl_field_free(one), nl_field_free(f);
    nl_field_free(f1);
}

Test(synth_errors, faulting_and_shape)
{
    nl_field *f3 = NULL, *f = field(2, 16, 16), *two = field(1, 1, 1);
    size_t n3[3] = {4, 4, 4}, K = 0;
    nl_dist *d;
    f3 = nl_field_alloc(3, n3, NULL, NULL);
    cr_assert_eq(nl_synth_faulting(1, 1, f3, &K), NL_EINVAL, "3D");
    cr_assert_eq(nl_synth_faulting(1, 0, f, &K), NL_EINVAL, "density 0");
    cr_assert_eq(nl_synth_faulting(1, 1e9, f, &K), NL_ETOOBIG, "1e9 * 32 faults");
    cr_assert_eq(nl_dist_parse("uniform", &d), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_shape(two, d, 0), NL_EINVAL, "one sample");
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = 2.385;
    cr_assert_eq(nl_synth_shape(f, d, 0), NL_EINVAL, "a constant field");
    nl_dist_free(d), nl_field_free(f3), nl_field_free(f), nl_field_free(two);
}

Test(synth_plans, execute_twice)
{
    nl_model *m = test_model("matern:nu=1.5,scale=3.7");
    size_t n[2] = {24, 20};
    nl_synth_cholesky_plan *ch;
    nl_synth_circulant_plan *ci;
    nl_field *a = field(2, 24, 20), *b = field(2, 24, 20), *c = field(2, 24, 20);
    cr_assert_eq(nl_synth_cholesky_plan_alloc(m, 2, n, NULL, &ch), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_cholesky_execute(ch, 4, a), 0);
    cr_assert_eq(nl_synth_cholesky_execute(ch, 4, b), 0);
    cr_assert_eq(nl_synth_cholesky_execute(ch, 5, c), 0);
    cr_assert(same(a, b) && !same(a, c));
    nl_synth_cholesky_plan_free(ch);
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, n, NULL, 0, 16, &ci), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_circulant_execute(ci, 4, a), 0);
    cr_assert_eq(nl_synth_circulant_execute(ci, 5, c), 0);
    cr_assert(!same(a, c));
    nl_synth_circulant_plan_free(ci);
    nl_model_free(m), nl_field_free(a), nl_field_free(b), nl_field_free(c);
}

/* Two threads on one const circulant plan, each execute with its own
 * workspace: every field equals the single-threaded one bit for bit.  The
 * grid is large enough (a 512 x 512 embedding) that the executions
 * overlap, so a shared workspace shows up as mismatches. */
Test(synth_plans, circulant_two_threads)
{
    nl_model *m = test_model("markov:scale=7.3");
    size_t n[2] = {256, 256};
    nl_synth_circulant_plan *ci;
    nl_field *a = field(2, 256, 256);
    int bad = 0;
    cr_assert_eq(nl_synth_circulant_plan_alloc(m, 2, n, NULL, 0, 16, &ci), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_synth_circulant_execute(ci, 4, a), 0);
#pragma omp parallel for num_threads(2) schedule(static, 1) reduction(+ : bad)
    for (int t = 0; t < 16; t++) {
        nl_field *g = nl_field_alloc(2, n, NULL, NULL);
        bad += !g || nl_synth_circulant_execute(ci, 4 + (uint64_t)(t % 2), g) != 0 || (t % 2 == 0 && !same(a, g));
        nl_field_free(g);
    }
    cr_assert_eq(bad, 0);
    nl_synth_circulant_plan_free(ci);
    nl_model_free(m), nl_field_free(a);
}
