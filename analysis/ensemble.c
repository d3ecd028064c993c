/* Mean and standard error over realizations, column by column; the
 * drivers' common steps. */
#include "ensemble.h"
#include "ensemble_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int nl_ensemble_mean_se(const double *v, size_t K, size_t m, double *mean, double *se)
{
    if (K < 2 || m == 0)
        return NL_ERROR(NL_EINVAL, "ensemble: expected at least 2 realizations of at least 1 value, got %zu of %zu",
                        K, m);
    for (size_t i = 0; i < m; i++) {
        double s = 0, ss = 0;
        for (size_t r = 0; r < K; r++)
            s += v[r * m + i];
        s /= (double)K;
        for (size_t r = 0; r < K; r++)
            ss += (v[r * m + i] - s) * (v[r * m + i] - s);
        mean[i] = isfinite(s) ? s : NAN;
        if (se)
            se[i] = isfinite(s) && isfinite(ss) ? sqrt(ss / ((double)(K - 1) * (double)K)) : NAN;
    }
    return NL_OK;
}

int nl_ensemble_fail(int st, size_t k, size_t *bad)
{
    if (bad)
        *bad = k;
    return st;
}

int nl_ensemble_get(const nl_ensemble_source *s, size_t k, nl_field *first, const nl_field **f)
{
    int st;
    *f = NULL;
    if (s->fields)
        *f = s->fields[k];
    else if (!s->get)
        return NL_ERROR(NL_EINVAL, "ensemble: expected fields or a get callback, got neither");
    else if ((st = s->get(s->ctx, k, f)))
        return st;
    if (!*f)
        return NL_ERROR(NL_EINVAL, "ensemble: field %zu of %zu is missing", k + 1, s->K);
    if (!first)
        return NL_OK;
    if (k == 0) {
        memset(first, 0, sizeof *first);
        first->dim = (*f)->dim, first->count = (*f)->count;
        memcpy(first->n, (*f)->n, sizeof first->n), memcpy(first->h, (*f)->h, sizeof first->h);
        return NL_OK;
    }
    int same = (*f)->dim == first->dim;
    for (int a = 0; a < 3 && same; a++) /* the spacing of the axes the fields have */
        same = (*f)->n[a] == first->n[a] && (a >= first->dim || (*f)->h[a] == first->h[a]);
    if (!same) {
        nl_ensemble_put(s, k, *f);
        *f = NULL;
        return NL_ERROR(NL_EINVAL, "ensemble: field %zu differs from the first in its size or spacing", k + 1);
    }
    return NL_OK;
}

void nl_ensemble_put(const nl_ensemble_source *s, size_t k, const nl_field *f)
{
    if (!s->fields && s->put && f)
        s->put(s->ctx, k, f);
}

int nl_ensemble_rows_alloc(size_t K, size_t m, double **rows)
{
    size_t dims[2] = {m, K};
    int st;
    *rows = NULL;
    if ((st = nl_size_check(2, dims, sizeof **rows, 1, NULL)))
        return st;
    *rows = malloc(K * m * sizeof **rows);
    return *rows ? NL_OK : NL_ERROR(NL_ENOMEM, "ensemble: out of memory for %zu estimates of %zu values", K, m);
}
