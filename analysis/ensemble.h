/* Ensemble averages of estimates: the mean of K realizations of an
 * estimate (a periodogram profile, an autocorrelation, a histogram, a
 * moment) and its standard error, so that the scatter of one estimate and
 * the gain of averaging can be read off the numbers.
 *
 * For realizations v_r[i], r = 0..K-1, of an estimate of m values,
 *     mean[i] = (1/K) sum_r v_r[i],
 *     se[i]   = sqrt( sum_r (v_r[i] - mean[i])^2 / ((K - 1) K) ),
 * the standard error of the mean of K independent realizations (the
 * sample standard deviation, divisor K - 1, over sqrt K).  Two passes, so
 * no cancellation.
 * Thread safety: reentrant; the caller owns every array. */
#ifndef NL_ENSEMBLE_H
#define NL_ENSEMBLE_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

/* v: K rows of m values, row r at v + r m.  mean and se: m values each (se
 * may be NULL).  A column holding a non-finite value gives NAN in mean and
 * se.  Returns NL_OK or NL_EINVAL (K < 2 or m = 0: one realization has no
 * standard error). */
int nl_ensemble_mean_se(const double *v, size_t K, size_t m, double *mean, double *se);

#ifdef __cplusplus
}
#endif

#endif
