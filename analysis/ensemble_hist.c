/* Moments and histograms of an ensemble (analysis/ensemble.h). */
#include "ensemble.h"
#include "ensemble_internal.h"
#include "hist.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

/* Each field's four moments into row k of v (4 per field); the overall
 * n, min and max into *all. */
static int each_field(const nl_ensemble_source *src, double *v, nl_moments *all, nl_moments *one, size_t *bad)
{
    all->n = 0, all->min = INFINITY, all->max = -INFINITY;
    for (size_t k = 0; k < src->K; k++) {
        const nl_field *x;
        nl_moments m;
        int st = nl_ensemble_get(src, k, NULL, &x);
        if (!st) {
            st = nl_moments_compute(x, &m);
            nl_ensemble_put(src, k, x);
        }
        if (st)
            return nl_ensemble_fail(st, k, bad);
        if (k == 0)
            *one = m;
        v[4 * k] = m.mean, v[4 * k + 1] = m.variance, v[4 * k + 2] = m.skewness, v[4 * k + 3] = m.kurtosis;
        all->n += m.n;
        all->min = fmin(all->min, m.min), all->max = fmax(all->max, m.max);
    }
    return NL_OK;
}

int nl_ensemble_moments(const nl_ensemble_source *src, nl_moments *mean, nl_moments *se, size_t *bad)
{
    size_t K = src->K;
    double *v, mu[4], s[4] = {NAN, NAN, NAN, NAN};
    nl_moments all, one;
    int st;
    if (K < 1)
        return nl_ensemble_fail(NL_ERROR(NL_EINVAL, "ensemble moments: expected at least 1 field, got 0"), K, bad);
    if ((st = nl_ensemble_rows_alloc(K, 4, &v)))
        return nl_ensemble_fail(st, K, bad);
    if ((st = each_field(src, v, &all, &one, bad)) == NL_OK && K > 1 && (st = nl_ensemble_mean_se(v, K, 4, mu, s)))
        nl_ensemble_fail(st, K, bad);
    free(v);
    if (st)
        return st;
    if (K == 1) /* the field's own, as nl_moments_compute gives them */
        *mean = one;
    else
        *mean = (nl_moments){.n = all.n, .mean = mu[0], .variance = mu[1], .skewness = mu[2], .kurtosis = mu[3],
                             .min = all.min, .max = all.max};
    if (se)
        *se = (nl_moments){.n = 0, .mean = s[0], .variance = s[1], .skewness = s[2], .kurtosis = s[3], .min = NAN,
                           .max = NAN};
    return NL_OK;
}

/* The edges of a field spanning [lo, hi]: what nl_hist makes of its range. */
static int span_edges(double lo, double hi, size_t bins, double *edges, double *counts)
{
    size_t two = 2;
    int st;
    nl_field *span = nl_field_alloc(1, &two, NULL, &st);
    if (!span)
        return st;
    span->data[0] = lo, span->data[1] = hi;
    st = nl_hist(span, bins, edges, counts);
    nl_field_free(span);
    return st;
}

int nl_ensemble_hist(const nl_ensemble_source *src, size_t bins, double lo, double hi, double *edges,
                     double *counts, double *se, size_t *bad)
{
    size_t K = src->K;
    double *c;
    int st;
    if (K < 2)
        return nl_ensemble_fail(NL_ERROR(NL_EINVAL, "ensemble hist: expected at least 2 fields, got %zu", K), K, bad);
    if ((st = span_edges(lo, hi, bins, edges, counts)) || (st = nl_ensemble_rows_alloc(K, bins, &c)))
        return nl_ensemble_fail(st, K, bad);
    for (size_t k = 0; k < K; k++) {
        const nl_field *x;
        if ((st = nl_ensemble_get(src, k, NULL, &x)) == NL_OK) {
            st = nl_hist_count(x, edges, bins, c + k * bins);
            nl_ensemble_put(src, k, x);
        }
        if (st) {
            free(c);
            return nl_ensemble_fail(st, k, bad);
        }
    }
    st = nl_ensemble_mean_se(c, K, bins, counts, se);
    free(c);
    return st ? nl_ensemble_fail(st, K, bad) : NL_OK;
}
