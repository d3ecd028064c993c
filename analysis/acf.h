/* Autocorrelation estimators.
 *
 * For a field x of n_a samples per axis and a mean m (the sample mean, or a
 * known mean when the process mean is known), with
 *     c(l) = sum over the overlap of (x_j - m)(x_{j+l} - m)   (core/autocorr.h)
 * the estimates at lag l (spacing units: lag l_a h_a) are
 *     biased    c(l) / N,                         E = (1 - |l|/n) R(l) for a known mean
 *     unbiased  c(l) / prod_a (n_a - |l_a|),      E = R(l) for a known mean
 * (with the sample mean both carry an extra O(1/N) bias).  The biased
 * estimate is a positive definite sequence (Lewis 1987, eq. (15)); the
 * unbiased one has lower bias and higher variance at large lags. */
#ifndef NL_ACF_H
#define NL_ACF_H

#include "../core/field.h"

#include <stddef.h>

enum { NL_ACF_BIASED = 0, NL_ACF_UNBIASED = 1 };

/* The full estimate on the wrapped grid of core/autocorr.h (2 n_a per axis).
 * mean: NAN for the sample mean, else the known mean. */
int nl_acf_full(const nl_field *x, double mean, int unbiased, nl_field **out);

/* Lags 0..maxlag along axis (0 = x, 1 = y, 2 = z) of a full estimate:
 * lag[i] = i h_axis, val[i] = estimate.  maxlag must be < n_axis. */
int nl_acf_axis(const nl_field *full, int axis, size_t maxlag, double *lag, double *val);

/* The direct sum of eq. (15) for lags 0..maxlag along `axis` (O(N maxlag)),
 * with the same divisors and mean as nl_acf_full; agrees with the FFT
 * estimate to rounding. */
int nl_acf_direct(const nl_field *x, double mean, int unbiased, int axis, size_t maxlag, double *val);

/* Bartlett's approximation (1946) to the variance of the biased
 * autocovariance estimate of a 1D Gaussian series at lag k:
 *     Var c_k ~ (1/N) sum_{|v| < N} [c_v^2 + c_{v+k} c_{v-k}],
 * with the estimate c in place of R (its plug-in form), summed over
 * |v| <= vmax.  var[k] for k = 0..maxlag. */
int nl_acf_bartlett(const double *c, size_t nc, size_t N, size_t maxlag, double *var);

#endif
