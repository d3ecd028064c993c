/* Histogram and moments of a field's samples (GSL statistics). */
#ifndef NL_HIST_H
#define NL_HIST_H

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

int nl_moments_compute(const nl_field *x, nl_moments *m);

/* Histogram of `bins` equal bins over [min, max] of the samples (the maximum
 * falls in the last bin): edges[0..bins], counts[0..bins-1]. */
int nl_hist(const nl_field *x, size_t bins, double *edges, double *counts);

#endif
