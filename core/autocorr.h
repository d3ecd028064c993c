/* Lag-product sums of a field by FFT (the shared primitive under the
 * empirical autocorrelation of eq. (15), Lewis 1987, and the ACF estimators).
 *
 * c(l) = sum over j with j and j + l inside the grid of
 *        (x_j - mean)(x_{j+l} - mean),  for every lag |l_a| < n_a.
 * The result is a field of m_a = 2 n_a samples per axis (1 beyond dim), in
 * wrapped order: index i holds lag i for i < n_a and lag i - m_a for
 * i > n_a (index n_a is lag -n_a, which is 0).  Zero padding to 2 n_a makes
 * the circular correlation equal to the linear one. */
#ifndef NL_AUTOCORR_H
#define NL_AUTOCORR_H

#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"

/* Units: the sums are of squared field units, not divided by any count
 * (the estimators divide).  *out receives a new field of 2 n_a samples per
 * axis with x's spacing h, released by nl_field_free; NULL on failure.
 * Returns NL_OK, NL_ETOOBIG (two arrays of the padded size do not fit:
 * nl_size_check), NL_ENOMEM (allocation failed), NL_EFAIL (FFTW could not
 * plan; not seen in practice, FFTW_ESTIMATE plans every size).  Plans FFTW
 * on every call, so it is not thread-safe (core/fftw_plan.h); x is only
 * read. */
int nl_autocorr_sums(const nl_field *x, double mean, nl_field **out);

/* Arithmetic mean of the count samples (sum / count, in order).  No status;
 * thread-safe. */
double nl_field_mean(const nl_field *x);

#ifdef __cplusplus
}
#endif

#endif
