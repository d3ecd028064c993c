/* Autocorrelation estimators.
 *
 * For a field x of n_a samples per axis and a mean m (the sample mean, or a
 * known mean when the process mean is known), with
 *     c(l) = sum over the overlap of (x_j - m)(x_{j+l} - m)   (core/autocorr.h)
 * the estimates at lag l (in length units: lag l_a h_a) are
 *     biased    c(l) / N,                         E = (1 - |l|/n) R(l) for a known mean
 *     unbiased  c(l) / prod_a (n_a - |l_a|),      E = R(l) for a known mean
 * (with the sample mean both carry an extra O(1/N) bias).  The biased
 * estimate is a positive definite sequence (Lewis 1987, eq. (15)); the
 * unbiased one has lower bias and higher variance at large lags.
 *
 * Layout: the full estimate lives on the wrapped grid of core/autocorr.h,
 * m_a = 2 n_a samples per axis (1 beyond dim), row-major with x fastest:
 * index i of axis a is lag i for i < n_a, lag i - m_a for i > n_a, and index
 * n_a (lag -n_a) is 0.  Its spacing is x's; lag arrays below are in the
 * field's length units (lag index times h_axis) unless said otherwise.
 * analysis/fftshift.h turns it into lags -(n-1)..n-1 with 0 at the centre.
 *
 * Thread safety: nl_acf_plan_alloc, nl_acf_plan_free and nl_acf_full call
 * the FFTW planner, which is not thread-safe: call them from one thread at
 * a time.  nl_acf_plan_execute on distinct plans may run concurrently (one
 * plan owns scratch: not two threads on one plan).  The other functions are
 * reentrant, except nl_acf_model_values, which is as thread-safe as the
 * model (core/model.h). */
#ifndef NL_ACF_H
#define NL_ACF_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>

enum { NL_ACF_BIASED = 0, NL_ACF_UNBIASED = 1 };

/* A plan for fields of one size: the FFTW plans and scratch of the lag sums,
 * made once (core/autocorr_plan.h).  Executing it gives bit-identical
 * results to nl_acf_full. */
typedef struct nl_acf_plan nl_acf_plan;

/* Plan for dim (1..3) axes of n[0..dim-1] >= 1 samples; *out is released by
 * nl_acf_plan_free (NULL on failure).  Returns NL_OK, NL_EINVAL (dim out of
 * range), NL_ETOOBIG (the 2n grid overflows or exceeds memory), NL_ENOMEM,
 * NL_EFAIL (FFTW could not plan). */
int nl_acf_plan_alloc(int dim, const size_t *n, nl_acf_plan **out);

/* A zeroed field of the plan's output grid (2 n_a per axis) with spacing h
 * (NULL: unit); released by nl_field_free.  NULL on failure, with *status
 * NL_EINVAL, NL_ETOOBIG or NL_ENOMEM (as nl_field_alloc). */
nl_field *nl_acf_plan_output_alloc(const nl_acf_plan *p, const double *h, int *status);

/* The full estimate of x (the plan's dim and n) into out (the plan's output
 * grid, e.g. from nl_acf_plan_output_alloc).  mean: NAN for the sample mean,
 * else the known mean; unbiased: NL_ACF_BIASED or NL_ACF_UNBIASED.  Returns
 * NL_OK or NL_EINVAL (x or out does not match the plan). */
int nl_acf_plan_execute(nl_acf_plan *p, const nl_field *x, double mean, int unbiased, nl_field *out);

/* NULL is a no-op. */
void nl_acf_plan_free(nl_acf_plan *p);

/* One shot: plan, execute, free.  *out (released by nl_field_free) is the
 * full estimate on the wrapped grid, spacing x's.  Returns the codes of
 * nl_acf_plan_alloc and nl_acf_plan_output_alloc; *out is NULL on failure. */
int nl_acf_full(const nl_field *x, double mean, int unbiased, nl_field **out);

/* Lags 0..maxlag along axis (0 = x, 1 = y, 2 = z) of a full estimate:
 * lag[i] = i h_axis (length units), val[i] = estimate; maxlag + 1 entries
 * each.  Returns NL_OK or NL_EINVAL (axis not an axis of full, or
 * maxlag >= n_axis, i.e. half the full grid). */
int nl_acf_axis(const nl_field *full, int axis, size_t maxlag, double *lag, double *val);

/* The radial average of a full estimate (analysis/radial.h, NL_GRID_LAG) in
 * nbins bins one sample spacing wide (the smallest h_a): lag = mean
 * distance of the bin in length units, val = mean estimate, cnt = lags
 * averaged (NAN and 0 when empty); nbins entries each.  Returns NL_OK. */
int nl_acf_radial(const nl_field *full, size_t nbins, double *lag, double *val, size_t *cnt);

/* The direct sum of eq. (15) for lags 0..maxlag (in samples) along `axis`
 * (O(N maxlag)), with the same divisors and mean as nl_acf_full; agrees with
 * the FFT estimate to rounding.  val holds maxlag + 1 entries.  Returns
 * NL_OK or NL_EINVAL (axis not an axis of x, or maxlag >= n_axis). */
int nl_acf_direct(const nl_field *x, double mean, int unbiased, int axis, size_t maxlag, double *val);

/* Whether the second-order estimates of x (acf, periodogram, Welch) stay
 * finite: with m = mean (the sample mean when mean is NaN), N = count and D
 * the largest |x - m|, requires m finite and D <= sqrt(DBL_MAX / 16) / N
 * (the transforms' squared moduli and the padded autocorrelation sums, at
 * most 8 N^2 D^2, with a factor 2 to spare) and, when spacing is set, that
 * D^2 N^2 times the cell h[0] h[1] h[2] be finite too.  Every estimator of
 * this module and of psd.h calls it before it runs.  Returns NL_OK or
 * NL_EINVAL naming the mean, the deviation and the bound. */
int nl_estimate_check_range(const nl_field *x, double mean, int spacing);

/* Bartlett's approximation (1946) to the variance of the biased
 * autocovariance estimate of a 1D Gaussian series at lag k:
 *     Var c_k ~ (1/N) sum_{|v| < N} [c_v^2 + c_{v+k} c_{v-k}],
 * with the estimate c (lags 0..nc-1, in samples) in place of R (its plug-in
 * form), summed over |v| <= nc - 1.  var[k] for k = 0..maxlag.  Returns
 * NL_OK or NL_EINVAL (nc < 2 maxlag + 1). */
int nl_acf_bartlett(const double *c, size_t nc, size_t N, size_t maxlag, double *var);

/* A 95% band val[k] -+ 1.959964 sqrt(Var c_k) around the biased estimate
 * val[0..maxlag] of a 1D field of N samples, with Var from nl_acf_bartlett
 * on the estimate full (nl_acf_full, biased) up to lag min(4 maxlag, n - 1).
 * lo and hi hold maxlag + 1 entries.  Returns NL_OK, NL_EINVAL (full not
 * 1D, or n < 2 maxlag + 1 samples) or NL_ENOMEM. */
int nl_acf_bartlett_band(const nl_field *full, size_t N, size_t maxlag, const double *val, double *lo, double *hi);

/* The model's band: what the biased estimate (sample mean removed, as
 * nl_acf_full with mean NAN) of a dim-D field of n[0..dim-1] samples of
 * spacing h (NULL: unit) gives at lags k = 0..maxlag samples along axis
 * when the field is a Gaussian realisation of the model.  With N = prod n_a,
 * R(k) the model's R at k h_axis along axis, V = Var(sample mean) =
 * (1/N^2) sum_v prod_a (n_a - |v_a|) R(v) and g(j) = Cov(x_j, sample mean):
 *     mean[k] = E c(k) = (1 - k/n_axis)(R(k) + V) - (2/N) sum_{j in O_k} g(j)
 * exactly (O_k: the N (1 - k/n_axis) samples with a partner at +k), i.e.
 * (1 - k/n_axis) R(k) less O(V) (white noise: -(1 - k/n) var / N, k > 0);
 * lo, hi = mean -+ 1.959964 sd with Bartlett's variance (1946) summed over
 * lag vectors r with the model's R less V (the covariance of the deviations
 * from the sample mean, taken as stationary) and the finite field's pair
 * counts,
 *     Var c(k) = (1/N^2) sum_r (n_axis - k - |r_axis|)+ prod_{a != axis}
 *                (n_a - |r_a|) [(R(r) - V)^2 + (R(r + k e) - V)(R(r - k e) - V)],
 * (with V = 0, the exact variance for a known mean); exact for white noise
 * at k = 0 (2 var^2 (N - 1) / N^2).  Against the exact variance (the deviations'
 * covariance near the edges) it is within 0.5% on a field 16 correlation
 * lengths long, 12% at 4; against 8000 fields of markov:scale=8, 64 x 64
 * (circulant embedding) the mean agrees within the Monte-Carlo error and
 * the sd within 1.7% (its error 0.8%).  The band is the estimate's
 * expected spread around the model, not around the estimate
 * (nl_acf_bartlett_band).
 * Units: those of R (variance).  Costs O(2^dim N maxlag) evaluations and
 * a grid of 2^dim N doubles.  Spectral models are sampled as R on the
 * periodic grid of 2 n_a per axis (core/wk.h).  mean, lo and hi hold
 * maxlag + 1 entries.  Returns NL_OK, NL_EINVAL (dim not 1..3, axis out
 * of range, maxlag >= n_axis, the model not defined in dim or not
 * stationary), NL_ETOOBIG / NL_ENOMEM, or the codes of nl_wk_sample_acf. */
int nl_acf_model_band(const nl_model *m, int dim, const size_t *n, const double *h, int axis, size_t maxlag,
                      double *mean, double *lo, double *hi);

/* The model's R at lag[i] (length units) along axis of a dim-D field of
 * n[0..dim-1] samples with spacing h[0..dim-1], for the nl values of lag.
 * R models are evaluated at the lag (NAN for a non-finite lag); spectral
 * models are transformed on a periodic grid of 2 n_a samples per axis
 * (core/wk.h) and read at the nearest grid lag, NAN from lag n_axis h on.
 * Returns NL_OK, NL_EINVAL (axis out of range, or the model is not defined
 * in dim, nl_model_check_dim), NL_ENOMEM / NL_ETOOBIG, or the codes of
 * nl_wk_sample_acf. */
int nl_acf_model_values(const nl_model *m, int dim, const size_t *n, const double *h, int axis, const double *lag,
                        size_t nl, double *out);

#ifdef __cplusplus
}
#endif

#endif
