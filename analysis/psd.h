/* Power spectral density estimates.
 *
 * Periodogram of a field x with mean m (NAN: sample mean) on its own grid:
 *     P_k = (h_1 ... h_d) / N |sum_j (x_j - m) exp(-2 pi i j.k / n)|^2
 * at the wrapped frequencies f_k = w(k) / (n h) (core/wk.h), in cycles per
 * unit length.  P is a TWO-SIDED density: Parseval holds as
 *     sum_k P_k / (n_1 h_1 ... n_d h_d) = (1/N) sum_j (x_j - m)^2,
 * and E[P_k] is the spectrum S(f_k) smoothed by the Fejer kernel. */
#ifndef NL_PSD_H
#define NL_PSD_H

#include "../core/field.h"

int nl_psd_periodogram(const nl_field *x, double mean, nl_field **out);

#endif
