/* Welch's averaged periodogram (Bartlett with overlap and a window).
 *
 * The field is cut into segments of S samples per axis overlapping by half,
 * each multiplied by a Hann window w (separable in 2D), and the periodograms
 *     P_k = (h_1..h_d) / (S^d U) |sum_j w_j (x_j - m) exp(-2 pi i j.k / S)|^2,
 *     U = mean of w^2 (so that a white input keeps its level),
 * are averaged.  The result is a two-sided density on the S-sample
 * frequency grid (S per axis, x's spacing, wrapped order, core/wk.h;
 * frequencies w(k) / (S h) in cycles per unit length), with about
 * 1/(number of segments) of a single periodogram's variance, at the price of
 * the window's resolution (a main lobe of 4/S cycles per sample).  In 1D
 * the segments start every S/2 samples; in 2D on a grid of S/2.
 *
 * Thread safety: nl_welch_plan_alloc, nl_welch_plan_free and nl_psd_welch
 * call the FFTW planner, which is not thread-safe: call them from one thread
 * at a time.  nl_welch_plan_execute on distinct plans may run concurrently
 * (a plan owns scratch: not two threads on one plan). */
#ifndef NL_WELCH_H
#define NL_WELCH_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

/* The window, the segment scratch and the FFTW plan for segments of S. */
typedef struct nl_welch_plan nl_welch_plan;

/* Plan for dim (1 or 2) and segments of S (4 <= S <= INT_MAX) samples per
 * axis; *out is released by nl_welch_plan_free (NULL on failure).  Returns
 * NL_OK, NL_EINVAL (dim or S out of range), NL_ENOMEM, NL_EFAIL (FFTW could
 * not plan). */
int nl_welch_plan_alloc(int dim, size_t S, nl_welch_plan **out);

/* Welch's estimate of x (the plan's dim, at least S samples per axis) into
 * P (the plan's dim, S samples per axis; overwritten, spacing left as it
 * is).  mean: NAN for the sample mean.  *segments (may be NULL) receives the
 * count averaged.  Bit-identical to nl_psd_welch.  Returns NL_OK or
 * NL_EINVAL (x or P does not match the plan; nothing written). */
int nl_welch_plan_execute(nl_welch_plan *p, const nl_field *x, double mean, nl_field *P, size_t *segments);

/* NULL is a no-op. */
void nl_welch_plan_free(nl_welch_plan *p);

/* One shot.  *out (released by nl_field_free) has x's spacing; *segments
 * (may be NULL) receives the count averaged.  Returns NL_OK, NL_EINVAL
 * (x more than 2D, S < 4 or larger than an axis of x), NL_ENOMEM, NL_EFAIL;
 * *out is NULL on failure. */
int nl_psd_welch(const nl_field *x, size_t S, double mean, nl_field **out, size_t *segments);

#ifdef __cplusplus
}
#endif

#endif
