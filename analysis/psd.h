/* Power spectral density estimates.
 *
 * Periodogram of a field x with mean m (NAN: sample mean) on its own grid:
 *     P_k = (h_1 ... h_d) / N |sum_j (x_j - m) exp(-2 pi i j.k / n)|^2
 * at the wrapped frequencies f_k = w(k) / (n h) (core/wk.h), in cycles per
 * unit length.  P is a TWO-SIDED density: Parseval holds as
 *     sum_k P_k / (n_1 h_1 ... n_d h_d) = (1/N) sum_j (x_j - m)^2,
 * and, for a known mean, E[P_k] is the transform of the triangle-weighted
 * ACF (1 - |l|/n) R(l): the sampled spectrum smoothed by the Fejer kernel
 * (biased: leakage from strong frequencies into weak ones), exactly the
 * spectrum at f_k only for a periodic field (FFT synthesis), whose
 * circular ACF it transforms.  With the sample mean P_0 = 0.
 * Layout: the full grid (both halves, P(-k) = P(k)), x's n and h, row-major
 * with x fastest, wrapped order (analysis/fftshift.h centres it).
 *
 * Thread safety: nl_psd_plan_alloc, nl_psd_plan_free and
 * nl_psd_periodogram call the FFTW planner, which is not thread-safe: call
 * them from one thread at a time.  nl_psd_plan_execute on distinct plans may
 * run concurrently (a plan owns scratch: not two threads on one plan). */
#ifndef NL_PSD_H
#define NL_PSD_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

/* FFTW plan and scratch for periodograms of fields of one size. */
typedef struct nl_psd_plan nl_psd_plan;

/* Plan for dim (1..3) axes of n[0..dim-1] >= 1 samples; *out is released by
 * nl_psd_plan_free (NULL on failure).  Returns NL_OK, NL_EINVAL (dim out of
 * range, n[a] = 0), NL_ETOOBIG, NL_ENOMEM (including FFTW failing to plan). */
int nl_psd_plan_alloc(int dim, const size_t *n, nl_psd_plan **out);

/* The periodogram of x (the plan's dim and n) into P (same dim and n; its
 * spacing is left as it is).  Bit-identical to nl_psd_periodogram.  Returns
 * NL_OK or NL_EINVAL (x or P does not match the plan; nothing written). */
int nl_psd_plan_execute(nl_psd_plan *p, const nl_field *x, double mean, nl_field *P);

/* NULL is a no-op. */
void nl_psd_plan_free(nl_psd_plan *p);

/* One shot: *out (released by nl_field_free) is the periodogram of x.
 * Returns the codes of nl_psd_plan_alloc and nl_field_alloc; *out is NULL
 * on failure. */
int nl_psd_periodogram(const nl_field *x, double mean, nl_field **out);

#ifdef __cplusplus
}
#endif

#endif
