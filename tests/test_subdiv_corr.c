/* Subdivision with correlated displacements (synth/subdiv_disp.c): the
 * consistency properties of independent displacements hold unchanged
 * (windows agree on overlaps, another level keeps every sample, a given
 * coarse level is kept, threads do not change a bit), the filter realises
 * the covariance it was made for, and the options are checked.  The
 * statistics (ensembles against the exact covariance, the error factors)
 * are in test_subdiv_stat.c. */
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/subdiv.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <omp.h>
#include <string.h>

static nl_subdiv_coeffs *corr(const char *spec, int dim, int levels, double s0, int N, int taps)
{
    nl_model *m = test_model(spec);
    nl_subdiv_coeffs *c;
    cr_assert_eq(nl_subdiv_coeffs_alloc(m, dim, levels, s0, N, 1e-4, 16, &c), 0, "%s: %s", spec, nl_errmsg());
    cr_assert_eq(nl_subdiv_coeffs_correlate(c, m, taps, NL_SUBDIV_DISP_ERROR), 0, "%s: %s", spec, nl_errmsg());
    nl_model_free(m);
    return c;
}

static nl_field *window(const nl_subdiv_coeffs *c, int dim, long ox, long oy, size_t nx, size_t ny)
{
    size_t n[2] = {nx, ny};
    long o[2] = {ox, oy};
    nl_field *f = nl_field_alloc(dim, n, NULL, NULL);
    cr_assert_eq(nl_subdiv_synth_window(c, 77, o, f), 0, "%s", nl_errmsg());
    return f;
}

Test(subdiv_corr, windows_agree_on_overlaps)
{
    nl_subdiv_coeffs *c1 = corr("markaussian:alpha=1.4,scale=6", 1, 6, 64.0, 4, 4);
    nl_subdiv_coeffs *c2 = corr("markaussian:alpha=1.4,scale=6", 2, 5, 32.0, 2, 2);
    nl_field *a = window(c1, 1, -37, 0, 200, 1), *b = window(c1, 1, 50, 0, 300, 1);
    for (long i = 50; i < 163; i++)
        cr_assert_eq(a->data[i + 37], b->data[i - 50], "1D sample %ld", i);
    nl_field_free(a), nl_field_free(b);
    a = window(c2, 2, -20, 7, 64, 48);
    b = window(c2, 2, 11, -5, 90, 70);
    for (long y = 7; y < 55; y++)
        for (long x = 11; x < 44; x++)
            cr_assert_eq(a->data[(y - 7) * 64 + (x + 20)], b->data[(y + 5) * 90 + (x - 11)], "2D (%ld, %ld)", x, y);
    nl_field_free(a), nl_field_free(b);
    nl_subdiv_coeffs_free(c1), nl_subdiv_coeffs_free(c2);
}

Test(subdiv_corr, refining_keeps_existing_samples)
{
    nl_subdiv_coeffs *c5 = corr("markaussian:alpha=1.4,scale=6", 2, 5, 32.0, 2, 2);
    nl_subdiv_coeffs *c6 = corr("markaussian:alpha=1.4,scale=6", 2, 6, 32.0, 2, 2);
    nl_field *a = window(c5, 2, -8, 3, 40, 30), *b = window(c6, 2, -16, 6, 80, 60);
    for (size_t y = 0; y < 30; y++)
        for (size_t x = 0; x < 40; x++)
            cr_assert_eq(a->data[y * 40 + x], b->data[(2 * y) * 80 + 2 * x], "(%zu, %zu)", x, y);
    nl_field_free(a), nl_field_free(b);
    nl_subdiv_coeffs_free(c5), nl_subdiv_coeffs_free(c6);
}

/* 512 x 256 periodic: the finest levels run on several threads. */
Test(subdiv_corr, periodic_is_bit_reproducible_across_threads)
{
    nl_model *m = test_model("markaussian:alpha=1.4,scale=5");
    nl_subdiv_coeffs *c = corr("markaussian:alpha=1.4,scale=5", 2, 4, 16.0, 2, 2);
    size_t n[2] = {512, 256};
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    omp_set_num_threads(1);
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 5, 0, a), 0, "%s", nl_errmsg());
    omp_set_num_threads(2);
    cr_assert_eq(nl_subdiv_synth_periodic(c, m, 5, 0, b), 0);
    cr_assert_eq(memcmp(a->data, b->data, a->count * sizeof(double)), 0);
    nl_field_free(a), nl_field_free(b), nl_model_free(m), nl_subdiv_coeffs_free(c);
}

Test(subdiv_corr, seed_level_is_kept)
{
    nl_subdiv_coeffs *c = corr("markaussian:alpha=1.4,scale=3", 2, 3, 8.0, 2, 2);
    size_t nc[2] = {8, 6}, n[2] = {64, 48};
    nl_field *coarse = nl_field_alloc(2, nc, NULL, NULL), *f = nl_field_alloc(2, n, NULL, NULL);
    for (size_t i = 0; i < coarse->count; i++)
        coarse->data[i] = sin(2.385 * (double)i);
    cr_assert_eq(nl_subdiv_refine_periodic(c, coarse, 9, 0, f), 0, "%s", nl_errmsg());
    for (size_t y = 0; y < 6; y++)
        for (size_t x = 0; x < 8; x++)
            cr_assert_eq(f->data[8 * y * 64 + 8 * x], coarse->data[y * 8 + x]);
    nl_field_free(coarse), nl_field_free(f), nl_subdiv_coeffs_free(c);
}

/* The filter's covariance is the target's: the variance exactly (rows are
 * scaled to it), the rest within the filt_error the level reports, which
 * for these models and 4 taps is small. */
Test(subdiv_corr, filter_realises_the_error_covariance)
{
    nl_subdiv_coeffs *c = corr("markaussian:alpha=1.4,scale=8", 1, 6, 64.0, 4, 4);
    for (int k = 0; k < c->levels; k++) {
        const nl_subdiv_level *l = &c->level[k];
        double v = nl_subdiv_disp_realised(l, 1, 0, 0, 0, 0);
        cr_assert_float_eq(v, l->cls[0].variance, 1e-12 * c->r0, "level %d variance %g, eq. (7) %g", k, v,
                           l->cls[0].variance);
        cr_assert_lt(l->filt_error, 1e-3, "level %d filter error %g", k, l->filt_error);
        cr_assert_eq(nl_subdiv_disp_realised(l, 1, 0, 0, 2 * l->taps + 1, 0), 0.0, "beyond the filter's reach");
    }
    nl_subdiv_coeffs_free(c);
    c = corr("markaussian:alpha=1.4,scale=6", 2, 4, 16.0, 2, 2);
    for (int k = 0; k < c->levels; k++)
        for (int a = 0; a < 3; a++)
            cr_assert_float_eq(nl_subdiv_disp_realised(&c->level[k], 2, a, a, 0, 0), c->level[k].cls[a].variance,
                               1e-12 * c->r0, "level %d class %d", k, a);
    nl_subdiv_coeffs_free(c);
}

/* Options: the default is independent (bit for bit the same field as
 * before), taps are range-checked, random neighbourhoods are refused. */
Test(subdiv_corr, plan_options)
{
    nl_model *m = test_model("markaussian:alpha=1.4,scale=4");
    size_t n[2] = {64, 64};
    nl_subdiv_options o;
    nl_subdiv_plan *p, *q;
    nl_field *a = nl_field_alloc(2, n, NULL, NULL), *b = nl_field_alloc(2, n, NULL, NULL);
    nl_subdiv_options_default(&o);
    cr_assert_eq(o.displacements, NL_SUBDIV_DISP_INDEPENDENT);
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), 0, "%s", nl_errmsg());
    o.displacements = NL_SUBDIV_DISP_ERROR;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &q), 0, "%s", nl_errmsg());
    cr_assert_eq(nl_subdiv_plan_coeffs(q)->level[0].taps, 2, "2D default taps");
    cr_assert_eq(nl_subdiv_plan_execute(p, 3, a), 0);
    cr_assert_eq(nl_subdiv_plan_execute(q, 3, b), 0);
    cr_assert_neq(memcmp(a->data, b->data, a->count * sizeof(double)), 0, "correlated differs");
    for (size_t i = 0; i < a->count; i += 8 * 64 + 8)
        cr_assert_eq(a->data[i], b->data[i], "the coarse level is the same (sample %zu)", i);
    nl_subdiv_plan_free(p), nl_subdiv_plan_free(q);
    o.taps = NL_SUBDIV_MAX_TAPS + 1;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "--taps"), "%s", nl_errmsg());
    o.taps = 2, o.random_nb = 4;
    cr_assert_eq(nl_subdiv_plan_alloc(m, 2, n, 1.0, &o, &p), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "random neighbourhoods"), "%s", nl_errmsg());
    nl_field_free(a), nl_field_free(b), nl_model_free(m);
}
