/* Does an ensemble of synthesised fields have the target autocorrelation?
 *
 * M realizations x of a zero-mean process are added one by one; each gives
 * the unbiased ACF estimate with the known mean 0 (analysis/acf.h)
 *     r(l) = (1/P) sum_j x_j x_{j+l}    (P pairs),   E r(l) = C(l),
 * read at L chosen lags.  The ensemble mean at each lag is compared with
 * the target R(l) through z(l) = |mean - R(l)| / se(l), and the verdict is
 * max_l z(l) against a Bonferroni threshold for a family-wise false-alarm
 * rate alpha over the ntests lags tested:
 *   - se from the ensemble's own spread (nl_verdict_stats): sd / sqrt(M)
 *     with sd the sample standard deviation (divisor M - 1); z then follows
 *     Student's t with M - 1 degrees of freedom, and the threshold is
 *     nl_verdict_threshold(alpha, ntests, M - 1);
 *   - se from the estimator's exact variance (nl_verdict_isserlis_var, by
 *     Isserlis' theorem for a Gaussian field of covariance C):
 *     sqrt(Var r(l) / M); z is close to N(0, 1) (CLT) and the threshold is
 *     nl_verdict_threshold(alpha, ntests, 0).
 * noiselab validate, experiments/fft_acf.c and the statistical tests use
 * this module.
 *
 * Lags are in samples, (lx, ly) with ly = 0 in 1D, or (lx, ly, lz) with
 * nl_verdict_alloc3; negative lags are read at their wrapped index of the
 * full estimate (core/autocorr.h).
 * Thread safety: nl_verdict_alloc and nl_verdict_free plan FFTW (not
 * thread-safe: one thread at a time); nl_verdict_add on distinct
 * accumulators may run concurrently; the rest is reentrant. */
#ifndef NL_VERDICT_H
#define NL_VERDICT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

/* Ensemble accumulator: sums and sums of squares of r at the lags. */
typedef struct nl_verdict nl_verdict;

/* For fields of dim (1..3) axes of n[0..dim-1] samples and nlags >= 1 lags
 * (copied), each |l_a| < n_a.  *out is released by nl_verdict_free (NULL on
 * failure).  Returns NL_OK, NL_EINVAL (dim, nlags or a lag out of range),
 * NL_ETOOBIG, NL_ENOMEM, NL_EFAIL (FFTW could not plan). */
int nl_verdict_alloc(int dim, const size_t *n, size_t nlags, const long (*lags)[2], nl_verdict **out);

/* The same with lags (lx, ly, lz) (ly = 0 in 1D, lz = 0 below 3D). */
int nl_verdict_alloc3(int dim, const size_t *n, size_t nlags, const long (*lags)[3], nl_verdict **out);

/* Add one realization (the dim and n of the accumulator).  Returns NL_OK or
 * NL_EINVAL (x does not match; nothing added). */
int nl_verdict_add(nl_verdict *v, const nl_field *x);

/* Realizations added so far. */
size_t nl_verdict_count(const nl_verdict *v);

/* Ensemble mean and (when se is not NULL) its standard error from the
 * ensemble's spread, nlags entries each:
 *     mean = s1 / M,  se = sqrt(max(0, (s2 - M mean^2) / (M - 1))) / sqrt(M).
 * Returns NL_OK or NL_EINVAL (fewer than 1 realization, or 2 with se). */
int nl_verdict_stats(const nl_verdict *v, double *mean, double *se);

/* NULL is a no-op. */
void nl_verdict_free(nl_verdict *v);

/* max over i < L of |mean[i] - target[i]| / max(se[i], 1e-300); *worst (may
 * be NULL) receives the first i attaining it (0 when every z is NaN). */
double nl_verdict_zmax(size_t L, const double *mean, const double *se, const double *target, size_t *worst);

/* Bonferroni threshold for ntests two-sided tests at family-wise rate alpha:
 * the upper alpha / (2 ntests) quantile of Student's t with dof degrees of
 * freedom, or of the standard normal when dof = 0.  NAN when alpha is not
 * in (0, 1) or ntests = 0. */
double nl_verdict_threshold(double alpha, size_t ntests, size_t dof);

/* Covariance of the process at offset (dx, dy) in samples. */
typedef double (*nl_verdict_cov)(long dx, long dy, void *ctx);

/* Exact variance of one realization's unbiased estimate r(lx, ly) (known
 * mean 0) on an n[0] x n[1] grid (n[1] = 1 in 1D) of a Gaussian field of
 * covariance C, by Isserlis' theorem, grouping products by offset d:
 *     Var r(l) = (1/P^2) sum_d prod_a (n_a - l_a - |d_a|) [C(d)^2 + C(d+l) C(d-l)],
 * P = prod_a (n_a - l_a); 0 <= l_a < n_a.  O(n_0 n_1) calls of C. */
double nl_verdict_isserlis_var(nl_verdict_cov C, void *ctx, const size_t *n, long lx, long ly);

#ifdef __cplusplus
}
#endif

#endif
