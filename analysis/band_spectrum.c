/* The chi-square band of a spectrum estimate and Welch's equivalent
 * degrees of freedom (analysis/bands.h). */
#include "bands.h"
#include "../core/nl_error.h"

#include <gsl/gsl_cdf.h>
#include <math.h>

int nl_band_chisq(double nu, double *lo, double *hi)
{
    if (!(nu > 0) || !isfinite(nu))
        return NL_ERROR(NL_EINVAL, "band: expected positive degrees of freedom, got %g", nu);
    *lo = gsl_cdf_chisq_Pinv(0.025, nu) / nu;
    *hi = gsl_cdf_chisq_Pinv(0.975, nu) / nu;
    return NL_OK;
}

/* rho(d) of segments d half-segments apart along one axis: the squared
 * overlap sum of the window (welch.c's Hann) over its sum of squares. */
static double overlap_corr(size_t S, size_t d)
{
    double s = 0, s2 = 0, w[2];
    size_t shift = d * (S / 2);
    if (shift >= S)
        return 0;
    for (size_t t = 0; t < S; t++) {
        w[0] = 0.5 * (1 - cos(2 * M_PI * ((double)t + 0.5) / (double)S));
        s2 += w[0] * w[0];
        if (t + shift < S) {
            w[1] = 0.5 * (1 - cos(2 * M_PI * ((double)(t + shift) + 0.5) / (double)S));
            s += w[0] * w[1];
        }
    }
    return (s / s2) * (s / s2);
}

/* sum_{i,j} rho(i - j) over K segments along one axis. */
static double pair_sum(size_t S, size_t K)
{
    double s = (double)K;
    for (size_t d = 1; d < K; d++) {
        double r = overlap_corr(S, d);
        if (r == 0)
            break;
        s += 2 * (double)(K - d) * r;
    }
    return s;
}

int nl_welch_edf(int dim, const size_t *n, size_t S, double *nu)
{
    double K = 1, sum = 1;
    if (dim < 1 || dim > 2)
        return NL_ERROR(NL_EINVAL, "welch: expected a 1D or 2D field, got %dD", dim);
    for (int a = 0; a < dim; a++) {
        if (S < 4 || S > n[a])
            return NL_ERROR(NL_EINVAL, "welch: expected a segment of 4 samples up to the field's size, got %zu", S);
        size_t Ka = (n[a] - S) / (S / 2) + 1;
        K *= (double)Ka;
        sum *= pair_sum(S, Ka);
    }
    *nu = 2 * K * K / sum;
    return NL_OK;
}
