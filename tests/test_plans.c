/* Plans of the estimators: executing an acf, periodogram or Welch plan gives
 * the same bits as the one-shot function (same FFTW plan flags, same order
 * of operations), for every dim, on several fields in a row (the scratch is
 * reset), and on input whose samples are not SIMD-aligned (the plans copy
 * into their own aligned scratch, so FFTW never sees the caller's alignment).
 * Equality is exact (memcmp): any tolerance would hide a changed operation. */
#include "../analysis/acf.h"
#include "../analysis/psd.h"
#include "../analysis/welch.h"
#include "../core/rng.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static nl_field *noise(int dim, const size_t *n, uint64_t seed)
{
    double h[3] = {0.5, 0.75, 1.25};
    nl_field *f = nl_field_alloc(dim, n, h, NULL);
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = 2.385 + nl_rng_gauss(seed, 5, i) + 0.3 * sin(0.1 * (double)i);
    return f;
}

/* A view of f whose samples sit one double past an aligned address. */
static nl_field misaligned(const nl_field *f, double **buf)
{
    nl_field v = *f;
    *buf = malloc((f->count + 1) * sizeof **buf);
    memcpy(*buf + 1, f->data, f->count * sizeof **buf);
    v.data = *buf + 1;
    return v;
}

static void same(const nl_field *a, const nl_field *b, const char *what)
{
    cr_assert_eq(a->count, b->count, "%s: sizes differ", what);
    cr_assert(memcmp(a->data, b->data, a->count * sizeof *a->data) == 0, "%s: results differ", what);
}

static void acf_case(int dim, const size_t *n)
{
    nl_acf_plan *p;
    cr_assert_eq(nl_acf_plan_alloc(dim, n, &p), 0);
    nl_field *out = nl_acf_plan_output_alloc(p, NULL, NULL);
    cr_assert_not_null(out);
    for (uint64_t s = 1; s <= 3; s++)
        for (int ub = 0; ub < 2; ub++) {
            nl_field *x = noise(dim, n, s), *ref, v;
            double *buf, mean = s == 2 ? 2.5 : NAN;
            cr_assert_eq(nl_acf_full(x, mean, ub, &ref), 0);
            cr_assert_eq(nl_acf_plan_execute(p, x, mean, ub, out), 0);
            same(ref, out, "acf plan");
            v = misaligned(x, &buf);
            cr_assert_eq(nl_acf_plan_execute(p, &v, mean, ub, out), 0);
            same(ref, out, "acf plan, misaligned input");
            free(buf);
            nl_field_free(ref), nl_field_free(x);
        }
    nl_field_free(out);
    nl_acf_plan_free(p);
}

Test(plans, acf_equals_one_shot)
{
    acf_case(1, (size_t[]){37});
    acf_case(2, (size_t[]){24, 17});
    acf_case(3, (size_t[]){6, 5, 4});
}

static void psd_case(int dim, const size_t *n)
{
    nl_psd_plan *p;
    cr_assert_eq(nl_psd_plan_alloc(dim, n, &p), 0);
    for (uint64_t s = 1; s <= 3; s++) {
        nl_field *x = noise(dim, n, s), *ref, *P = nl_field_alloc(dim, n, x->h, NULL), v;
        double *buf, mean = s == 2 ? 2.5 : NAN;
        cr_assert_eq(nl_psd_periodogram(x, mean, &ref), 0);
        cr_assert_eq(nl_psd_plan_execute(p, x, mean, P), 0);
        same(ref, P, "periodogram plan");
        v = misaligned(x, &buf);
        cr_assert_eq(nl_psd_plan_execute(p, &v, mean, P), 0);
        same(ref, P, "periodogram plan, misaligned input");
        free(buf);
        nl_field_free(ref), nl_field_free(P), nl_field_free(x);
    }
    nl_psd_plan_free(p);
}

Test(plans, periodogram_equals_one_shot)
{
    psd_case(1, (size_t[]){37});
    psd_case(2, (size_t[]){24, 17});
    psd_case(3, (size_t[]){6, 5, 4});
}

static void welch_case(int dim, const size_t *n, size_t S)
{
    nl_welch_plan *p;
    size_t nseg, nref;
    cr_assert_eq(nl_welch_plan_alloc(dim, S, &p), 0);
    nl_field *P = nl_field_alloc(dim, (size_t[]){S, S}, NULL, NULL);
    for (uint64_t s = 1; s <= 3; s++) {
        nl_field *x = noise(dim, n, s), *ref, v;
        double *buf, mean = s == 2 ? 2.5 : NAN;
        cr_assert_eq(nl_psd_welch(x, S, mean, &ref, &nref), 0);
        cr_assert_eq(nl_welch_plan_execute(p, x, mean, P, &nseg), 0);
        cr_assert_eq(nseg, nref);
        same(ref, P, "welch plan");
        v = misaligned(x, &buf);
        cr_assert_eq(nl_welch_plan_execute(p, &v, mean, P, NULL), 0);
        same(ref, P, "welch plan, misaligned input");
        free(buf);
        nl_field_free(ref), nl_field_free(x);
    }
    nl_field_free(P);
    nl_welch_plan_free(p);
}

Test(plans, welch_equals_one_shot)
{
    welch_case(1, (size_t[]){300}, 64);
    welch_case(1, (size_t[]){97}, 10);
    welch_case(2, (size_t[]){40, 33}, 16);
}

/* One plan serves fields of other spacings: h only scales the result. */
Test(plans, periodogram_spacing_taken_from_the_field)
{
    size_t n[1] = {64};
    nl_psd_plan *p;
    nl_field *x = noise(1, n, 4), *P = nl_field_alloc(1, n, NULL, NULL), *ref;
    cr_assert_eq(nl_psd_plan_alloc(1, n, &p), 0);
    x->h[0] = 3.5;
    cr_assert_eq(nl_psd_periodogram(x, NAN, &ref), 0);
    cr_assert_eq(nl_psd_plan_execute(p, x, NAN, P), 0);
    same(ref, P, "periodogram plan, other spacing");
    nl_field_free(ref), nl_field_free(P), nl_field_free(x);
    nl_psd_plan_free(p);
}

/* The headers' thread-safety claim: plans made one after the other, then
 * executed at once from several threads (one plan each), give the one-shot
 * bits.  (Run under a thread sanitizer to check for races beyond results.) */
Test(plans, distinct_plans_execute_concurrently)
{
    enum { T = 4 };
    size_t n[2] = {48, 40};
    nl_field *x[T], *ra[T], *rp[T], *rw[T], *oa[T], *op[T], *ow[T];
    nl_acf_plan *pa[T];
    nl_psd_plan *pp[T];
    nl_welch_plan *pw[T];
    int st[T];
    for (int t = 0; t < T; t++) {
        x[t] = noise(2, n, (uint64_t)t + 10);
        cr_assert_eq(nl_acf_full(x[t], NAN, 1, &ra[t]), 0);
        cr_assert_eq(nl_psd_periodogram(x[t], NAN, &rp[t]), 0);
        cr_assert_eq(nl_psd_welch(x[t], 16, NAN, &rw[t], NULL), 0);
        cr_assert_eq(nl_acf_plan_alloc(2, n, &pa[t]), 0);
        cr_assert_eq(nl_psd_plan_alloc(2, n, &pp[t]), 0);
        cr_assert_eq(nl_welch_plan_alloc(2, 16, &pw[t]), 0);
        oa[t] = nl_acf_plan_output_alloc(pa[t], NULL, NULL);
        op[t] = nl_field_alloc(2, n, NULL, NULL);
        ow[t] = nl_field_alloc(2, (size_t[]){16, 16}, NULL, NULL);
    }
#pragma omp parallel for num_threads(T)
    for (int t = 0; t < T; t++)
        st[t] = nl_acf_plan_execute(pa[t], x[t], NAN, 1, oa[t]) | nl_psd_plan_execute(pp[t], x[t], NAN, op[t]) |
                nl_welch_plan_execute(pw[t], x[t], NAN, ow[t], NULL);
    for (int t = 0; t < T; t++) {
        cr_assert_eq(st[t], 0);
        same(ra[t], oa[t], "acf plan in a thread");
        same(rp[t], op[t], "periodogram plan in a thread");
        same(rw[t], ow[t], "welch plan in a thread");
        nl_acf_plan_free(pa[t]), nl_psd_plan_free(pp[t]), nl_welch_plan_free(pw[t]);
        nl_field_free(x[t]), nl_field_free(ra[t]), nl_field_free(rp[t]), nl_field_free(rw[t]);
        nl_field_free(oa[t]), nl_field_free(op[t]), nl_field_free(ow[t]);
    }
}
