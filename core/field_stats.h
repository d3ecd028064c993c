/* Sample mean, variance and root mean square of a field's samples, in the
 * plain forms the synthesis reports use for their preview ranges. */
#ifndef NL_FIELD_STATS_H
#define NL_FIELD_STATS_H

#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"

/* Mean m = sum x_i / N (each term divided by N before it is added) and
 * population variance v = sum (x_i - m)^2 / N (likewise), over the
 * f->count samples in storage order.  A field without samples gives 0, 0.
 * Cannot fail; thread-safe.  (For the unbiased variance, skewness and
 * kurtosis see nl_moments_compute in analysis/hist.h.) */
void nl_field_mean_var(const nl_field *f, double *mean, double *var);

/* sqrt(sum x_i^2 / N), each term divided by N before it is added; 0 for a
 * field without samples.  Cannot fail; thread-safe. */
double nl_field_rms(const nl_field *f);

#ifdef __cplusplus
}
#endif

#endif
