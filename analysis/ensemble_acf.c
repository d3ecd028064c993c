/* The autocorrelation of an ensemble: each field's estimate, then their
 * mean and standard error (analysis/ensemble.h). */
#include "acf.h"
#include "ensemble.h"
#include "ensemble_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>

/* Field x's estimate at lags 0 .. nlag - 1, as noiselab acf makes it. */
static int estimate(const nl_field *x, const nl_ensemble_acf_opts *o, double *lag, double *val, size_t *cnt)
{
    nl_field *full;
    int st;
    if (o->direct) {
        for (size_t i = 0; i < o->nlag; i++)
            lag[i] = (double)i * x->h[o->axis];
        return nl_acf_direct(x, o->mean, o->unbiased, o->axis, o->nlag - 1, val);
    }
    if ((st = nl_acf_full(x, o->mean, o->unbiased, &full)))
        return st;
    st = o->radial ? nl_acf_radial(full, o->nlag, lag, val, cnt) : nl_acf_axis(full, o->axis, o->nlag - 1, lag, val);
    nl_field_free(full);
    return st;
}

int nl_ensemble_acf(const nl_ensemble_source *src, const nl_ensemble_acf_opts *o, double *lag, double *acf,
                    double *se, size_t *bad)
{
    size_t K = src->K, *cnt;
    double *rows;
    nl_field first;
    int st;
    if (K < 2 || !o->nlag || o->axis < 0 || o->axis > 2 || (o->radial && o->direct))
        return nl_ensemble_fail(NL_ERROR(NL_EINVAL, "ensemble acf: expected at least 2 fields, 1 lag, an axis 0 to "
                                         "2 and not both radial and direct; got %zu, %zu, %d, %d and %d", K,
                                         o->nlag, o->axis, o->radial, o->direct), K, bad);
    if ((st = nl_ensemble_rows_alloc(K, o->nlag, &rows)))
        return nl_ensemble_fail(st, K, bad);
    if (!(cnt = malloc(o->nlag * sizeof *cnt))) {
        free(rows);
        return nl_ensemble_fail(NL_ERROR(NL_ENOMEM, "ensemble acf: out of memory"), K, bad);
    }
    for (size_t k = 0; k < K; k++) {
        const nl_field *x;
        if ((st = nl_ensemble_get(src, k, &first, &x)) == NL_OK) {
            st = estimate(x, o, lag, rows + k * o->nlag, cnt);
            nl_ensemble_put(src, k, x);
        }
        if (st) {
            free(rows), free(cnt);
            return nl_ensemble_fail(st, k, bad);
        }
    }
    st = nl_ensemble_mean_se(rows, K, o->nlag, acf, se);
    free(rows), free(cnt);
    return st ? nl_ensemble_fail(st, K, bad) : NL_OK;
}
