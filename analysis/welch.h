/* Welch's averaged periodogram (Bartlett with overlap and a window).
 *
 * The field is cut into segments of S samples per axis overlapping by half,
 * each multiplied by a Hann window w (separable in 2D), and the periodograms
 *     P_k = (h_1..h_d) / (S^d U) |sum_j w_j (x_j - m) exp(-2 pi i j.k / S)|^2,
 *     U = mean of w^2 (so that a white input keeps its level),
 * are averaged.  The result is a two-sided density on the S-sample
 * frequency grid (wrapped order, core/wk.h), with about 1/(number of
 * segments) of a single periodogram's variance, at the price of the window's
 * resolution (a main lobe of 4/S cycles per sample). */
#ifndef NL_WELCH_H
#define NL_WELCH_H

#include "../core/field.h"

#include <stddef.h>

/* mean: NAN for the sample mean.  *segments receives the count averaged. */
int nl_psd_welch(const nl_field *x, size_t S, double mean, nl_field **out, size_t *segments);

#endif
