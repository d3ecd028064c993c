/* The spectrum of an ensemble: each field's periodogram or Welch estimate,
 * their mean on the grid, and the mean and standard error of their
 * profiles (analysis/ensemble.h). */
#include "ensemble.h"
#include "ensemble_internal.h"
#include "psd.h"
#include "spectral.h"
#include "welch.h"
#include "../core/nl_error.h"

#include <stdlib.h>

static int estimate(const nl_field *x, const nl_ensemble_psd_opts *o, nl_field **P, size_t *segments)
{
    return o->welch ? nl_psd_welch(x, o->welch, o->mean, P, segments) : nl_psd_periodogram(x, o->mean, P);
}

/* Fields 1 .. K-1: each estimate's profile into its row of rows, its
 * values added to sum. */
static int add_rest(const nl_ensemble_source *src, const nl_ensemble_psd_opts *o, nl_field *first, nl_field *sum,
                    double *rows, double *freq, size_t *cnt, size_t *nf, size_t *segments, size_t *bad)
{
    for (size_t k = 1; k < src->K; k++) {
        const nl_field *x;
        nl_field *Pk = NULL;
        int st = nl_ensemble_get(src, k, first, &x);
        if (!st) {
            st = estimate(x, o, &Pk, segments);
            nl_ensemble_put(src, k, x);
        }
        if (!st)
            st = nl_psd_profile(Pk, freq, rows + k * *nf, cnt, nf);
        for (size_t i = 0; !st && i < Pk->count; i++)
            sum->data[i] += Pk->data[i];
        nl_field_free(Pk);
        if (st)
            return nl_ensemble_fail(st, k, bad);
    }
    return NL_OK;
}

int nl_ensemble_psd(const nl_ensemble_source *src, const nl_ensemble_psd_opts *o, nl_field **P, double *freq,
                    double *psd, double *se, size_t *nf, size_t *segments, size_t *bad)
{
    size_t K = src->K, *cnt = NULL, nseg = 1;
    double *rows = NULL;
    const nl_field *x;
    nl_field first, *sum = NULL;
    int st;
    *P = NULL;
    if (K < 2)
        return nl_ensemble_fail(NL_ERROR(NL_EINVAL, "ensemble psd: expected at least 2 fields, got %zu", K), K, bad);
    if ((st = nl_ensemble_get(src, 0, &first, &x)))
        return nl_ensemble_fail(st, 0, bad);
    st = estimate(x, o, &sum, &nseg);
    nl_ensemble_put(src, 0, x);
    if (st)
        return nl_ensemble_fail(st, 0, bad);
    *nf = nl_psd_profile_size(sum);
    if ((st = nl_ensemble_rows_alloc(K, *nf, &rows)) == NL_OK && !(cnt = malloc(*nf * sizeof *cnt)))
        st = NL_ERROR(NL_ENOMEM, "ensemble psd: out of memory");
    if (st)
        nl_ensemble_fail(st, K, bad);
    else if ((st = nl_psd_profile(sum, freq, rows, cnt, nf)))
        nl_ensemble_fail(st, 0, bad);
    else if ((st = add_rest(src, o, &first, sum, rows, freq, cnt, nf, &nseg, bad)) == NL_OK) {
        for (size_t i = 0; i < sum->count; i++)
            sum->data[i] /= (double)K;
        if ((st = nl_ensemble_mean_se(rows, K, *nf, psd, se)))
            nl_ensemble_fail(st, K, bad);
    }
    free(cnt), free(rows);
    if (st)
        nl_field_free(sum);
    else
        *P = sum;
    if (segments)
        *segments = nseg;
    return st;
}
