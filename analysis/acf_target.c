/* The model's R at the lags of an estimate, and Bartlett's band around it. */
#include "acf.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <math.h>
#include <stdlib.h>

/* R of a spectral model: the inverse transform on a grid twice the data's
 * (core/wk.h), read at the nearest grid lag; NAN beyond half that grid. */
static int spectral_values(const nl_model *m, int dim, const size_t *n, const double *h, int axis,
                           const double *lag, size_t nl, double *out)
{
    size_t n2[3], stride = 1;
    int st;
    nl_field *R;
    for (int a = 0; a < 3; a++)
        n2[a] = a < dim ? 2 * n[a] : 1;
    R = nl_field_alloc(dim, n2, h, &st);
    if (!R)
        return st;
    if ((st = nl_wk_sample_acf(m, R))) {
        nl_field_free(R);
        return st;
    }
    for (int a = 0; a < axis; a++)
        stride *= R->n[a];
    for (size_t i = 0; i < nl; i++) {
        size_t idx = (size_t)lrint(lag[i] / R->h[axis]);
        out[i] = idx < n2[axis] / 2 ? R->data[idx * stride] : NAN;
    }
    nl_field_free(R);
    return NL_OK;
}

int nl_acf_model_values(const nl_model *m, int dim, const size_t *n, const double *h, int axis, const double *lag,
                        size_t nl, double *out)
{
    int st;
    if (axis < 0 || axis >= dim)
        return NL_ERROR(NL_EINVAL, "axis: expected an axis of the %d-D field, got %d", dim, axis);
    if ((st = nl_model_check_dim(m, dim)) || (st = nl_model_check_stationary(m, "an ACF target")))
        return st;
    if (nl_model_is_spectral(m))
        return spectral_values(m, dim, n, h, axis, lag, nl, out);
    for (size_t i = 0; i < nl; i++) {
        double v[3] = {0, 0, 0};
        v[axis] = lag[i];
        out[i] = isfinite(lag[i]) ? nl_model_acf(m, dim, v) : NAN;
    }
    return NL_OK;
}

int nl_acf_bartlett_band(const nl_field *full, size_t N, size_t maxlag, const double *val, double *lo, double *hi)
{
    size_t nc, n0 = full->n[0] / 2;
    double *var;
    int st;
    if (full->dim != 1)
        return NL_ERROR(NL_EINVAL, "bands: expected the estimate of a 1D field, got %dD", full->dim);
    nc = 4 * maxlag + 1 < n0 ? 4 * maxlag + 1 : n0;
    if (nc < 2 * maxlag + 1)
        return NL_ERROR(NL_EINVAL, "bands: expected a field of at least %zu samples for max-lag %zu",
                        2 * maxlag + 1, maxlag);
    if (!(var = malloc((maxlag + 1) * sizeof *var)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the band");
    if ((st = nl_acf_bartlett(full->data, nc, N, maxlag, var))) {
        free(var);
        return st;
    }
    for (size_t i = 0; i <= maxlag; i++)
        lo[i] = val[i] - 1.959964 * sqrt(var[i]), hi[i] = val[i] + 1.959964 * sqrt(var[i]);
    free(var);
    return NL_OK;
}
