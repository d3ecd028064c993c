/* Welford's running mean and variance of realizations (analysis/ensemble.h). */
#include "ensemble.h"
#include "../core/nl_error.h"

#include <stdlib.h>
#include <string.h>

struct nl_welford {
    nl_field *mean; /* the running mean */
    nl_field *m2;   /* the running sum of squared deviations */
    size_t count;   /* realizations added */
};

int nl_welford_alloc(int dim, const size_t *n, const double *h, nl_welford **out)
{
    nl_welford *w;
    int st = NL_OK;
    *out = NULL;
    if (!(w = calloc(1, sizeof *w)))
        return NL_ERROR(NL_ENOMEM, "welford: out of memory");
    if (!(w->mean = nl_field_alloc(dim, n, h, &st)) || !(w->m2 = nl_field_alloc(dim, n, h, &st))) {
        nl_welford_free(w);
        return st;
    }
    *out = w;
    return NL_OK;
}

void nl_welford_free(nl_welford *w)
{
    if (!w)
        return;
    nl_field_free(w->mean), nl_field_free(w->m2);
    free(w);
}

int nl_welford_add(nl_welford *w, const nl_field *f)
{
    double *s1 = w->mean->data, *s2 = w->m2->data, k1 = (double)(w->count + 1);
    if (f->dim != w->mean->dim || memcmp(f->n, w->mean->n, sizeof f->n))
        return NL_ERROR(NL_EINVAL, "welford: expected a field of the accumulator's size, got a %dD field of %zu "
                        "samples", f->dim, f->count);
    for (size_t i = 0; i < f->count; i++) {
        double d = f->data[i] - s1[i];
        s1[i] += d / k1;
        s2[i] += d * (f->data[i] - s1[i]);
    }
    w->count++;
    return NL_OK;
}

size_t nl_welford_count(const nl_welford *w) { return w->count; }

const nl_field *nl_welford_mean(const nl_welford *w) { return w->mean; }

int nl_welford_variance(const nl_welford *w, nl_field **out)
{
    int st;
    nl_field *v = nl_field_alloc(w->m2->dim, w->m2->n, w->m2->h, &st);
    *out = NULL;
    if (!v)
        return st;
    for (size_t i = 0; i < v->count; i++) /* the unbiased variance, divisor count - 1 */
        v->data[i] = w->count > 1 ? w->m2->data[i] / (double)(w->count - 1) : 0;
    *out = v;
    return NL_OK;
}
