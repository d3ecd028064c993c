/* Histogram and moments of a field's samples (GSL statistics).
 * Thread safety: reentrant (no shared state); the caller owns every array. */
#ifndef NL_HIST_H
#define NL_HIST_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

typedef struct {
    size_t n;         /* samples */
    double mean;      /* arithmetic mean */
    double variance;  /* unbiased sample variance (divisor n - 1) */
    double skewness;  /* third standardised moment (GSL: sample sd) */
    double kurtosis;  /* excess kurtosis: fourth standardised moment - 3 */
    double min, max;  /* range */
} nl_moments;

/* Moments and range of every sample of x (any dim; units of the samples).
 * A constant field (variance 0) has no skewness or kurtosis: both are NaN
 * then, and the caller reports them as undefined.  Returns NL_OK or
 * NL_EINVAL (fewer than 2 samples, max - min above DBL_MAX so that the
 * mean overflows, or a variance that overflows: it stays finite while every
 * |x - mean| is below sqrt(DBL_MAX / 2), about 9.5e153); *m is unspecified
 * on failure.  Use this, not loops by hand, for a field's mean and variance. */
int nl_moments_compute(const nl_field *x, nl_moments *m);

/* Histogram of `bins` equal bins over [min, max] of the samples (the maximum
 * falls in the last bin; a constant field spans [v, v + 1], or when
 * v + 1 rounds to v, |v| >= 2^53, a width of 2^-20 |v| toward 0): the caller's
 * edges[0..bins] and counts[0..bins-1] (counts as doubles).  Returns NL_OK,
 * NL_EINVAL (bins = 0, a sample is infinite or NaN, or max - min
 * overflows) or NL_ENOMEM. */
int nl_hist(const nl_field *x, size_t bins, double *edges, double *counts);

/* Counts of the samples of x in given bins: edges[0..bins] increasing (as
 * nl_hist makes them); a sample v goes to bin b when edges[b] <= v <
 * edges[b+1], below edges[0] to the first bin and from edges[bins] on to
 * the last, so that fields binned on common edges (an ensemble's) are
 * counted whole.  counts[0..bins-1] (doubles) are overwritten.  Returns
 * NL_OK or NL_EINVAL (bins = 0). */
int nl_hist_count(const nl_field *x, const double *edges, size_t bins, double *counts);

/* The histogram of nl_hist as a density against the Gaussian of the
 * moments mo (from nl_moments_compute): for each of the bins, its midpoint,
 * count / (N width) and the Gaussian density of mean mo->mean and variance
 * mo->variance at the midpoint (0 when the variance is 0; the caller's
 * arrays of bins entries).
 * Returns the codes of nl_hist, or NL_ENOMEM. */
int nl_hist_density(const nl_field *x, const nl_moments *mo, size_t bins, double *mid, double *density, double *gauss);

#ifdef __cplusplus
}
#endif

#endif
