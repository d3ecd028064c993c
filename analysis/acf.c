/* Autocorrelation estimates from the FFT lag sums (Lewis 1987, eq. (15)). */
#include "acf.h"
#include "radial.h"
#include "../core/autocorr.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

int nl_acf_axis(const nl_field *full, int axis, size_t maxlag, double *lag, double *val)
{
    size_t stride = 1;
    if (axis < 0 || axis >= full->dim)
        return NL_ERROR(NL_EINVAL, "axis: expected an axis of the %d-D field, got %d", full->dim, axis);
    if (maxlag >= full->n[axis] / 2)
        return NL_ERROR(NL_EINVAL, "max-lag: expected at most %zu samples, got %zu", full->n[axis] / 2 - 1, maxlag);
    for (int a = 0; a < axis; a++)
        stride *= full->n[a];
    for (size_t i = 0; i <= maxlag; i++) {
        lag[i] = (double)i * full->h[axis];
        val[i] = full->data[i * stride];
    }
    return NL_OK;
}

int nl_acf_radial(const nl_field *full, size_t nbins, double *lag, double *val, size_t *cnt)
{
    double step = full->h[0];
    for (int a = 1; a < full->dim; a++)
        step = fmin(step, full->h[a]);
    return nl_radial(full, NL_GRID_LAG, step, nbins, lag, val, cnt);
}

int nl_acf_direct(const nl_field *x, double mean, int unbiased, int axis, size_t maxlag, double *val)
{
    double m;
    size_t stride = 1, n;
    int st = nl_estimate_check_range(x, mean, 0);
    if (st)
        return st;
    if (axis < 0 || axis >= x->dim)
        return NL_ERROR(NL_EINVAL, "axis: expected an axis of the %d-D field, got %d", x->dim, axis);
    m = isnan(mean) ? nl_field_mean(x) : mean, n = x->n[axis];
    if (maxlag >= n)
        return NL_ERROR(NL_EINVAL, "max-lag: expected at most %zu samples, got %zu", n - 1, maxlag);
    for (int a = 0; a < axis; a++)
        stride *= x->n[a];
    for (size_t l = 0; l <= maxlag; l++) {
        double s = 0;
        /* every pair (p, p + l e_axis) inside the grid (eq. 15) */
        for (size_t q = 0; q < x->count; q++) {
            size_t pos = (q / stride) % n;
            if (pos + l < n)
                s += (x->data[q] - m) * (x->data[q + l * stride] - m);
        }
        double pairs = (double)x->count / (double)n * (double)(n - l);
        val[l] = s / (unbiased ? pairs : (double)x->count);
    }
    return NL_OK;
}

int nl_acf_bartlett(const double *c, size_t nc, size_t N, size_t maxlag, double *var)
{
    if (nc < 2 * maxlag + 1)
        return NL_ERROR(NL_EINVAL, "bartlett: expected the autocovariance to lag %zu at least", 2 * maxlag);
    for (size_t k = 0; k <= maxlag; k++) {
        double s = 0;
        long K = (long)(nc - 1) - (long)k;
        for (long v = -K; v <= K; v++) {
            size_t av = (size_t)labs(v), p = (size_t)labs(v + (long)k), q = (size_t)labs(v - (long)k);
            s += c[av] * c[av] + (p < nc && q < nc ? c[p] * c[q] : 0);
        }
        var[k] = s / (double)N;
    }
    return NL_OK;
}

/* The deviation D from the mean up to which the second-order sums of N
 * samples stay finite: the transform of the deviations is at most N D in
 * modulus, its squared modulus at most N^2 D^2 (the periodogram, a Welch
 * segment), and the inverse transform of the autocorrelation sums the
 * squared moduli over the 2^dim N <= 8 N cells of its padded grid: at most
 * 8 N^2 D^2 (Parseval).  With a factor 2 for rounding, all stay finite for
 * D <= sqrt(DBL_MAX / 16) / N (about 3.4e153 / N).  With the spacing, the
 * density's N^2 D^2 cell must be finite too: D below sqrt(DBL_MAX / cell) / N. */
int nl_estimate_check_range(const nl_field *x, double mean, int spacing)
{
    double m = isnan(mean) ? nl_field_mean(x) : mean, d = 0, cell = x->h[0] * x->h[1] * x->h[2];
    double N = (double)x->count, bound = sqrt(DBL_MAX / 16.0) / N;
    for (size_t i = 0; i < x->count; i++)
        d = fmax(d, fabs(x->data[i] - m));
    if (!isfinite(m) || !(d <= bound))
        return NL_ERROR(NL_EINVAL,
                        "the samples deviate from their mean %g by up to %g: the sums of squares of the estimate "
                        "overflow; expected deviations below %.3g (sqrt(DBL_MAX / 16) / %zu samples)",
                        m, d, bound, x->count);
    if (spacing && !isfinite(d * d * N * N * cell))
        return NL_ERROR(NL_EINVAL,
                        "the samples deviate from their mean %g by up to %g: the spectral density overflows at the "
                        "cell %g; expected deviations below %.3g (sqrt(DBL_MAX / cell) / %zu samples)",
                        m, d, cell, sqrt(DBL_MAX / cell) / N, x->count);
    return NL_OK;
}
