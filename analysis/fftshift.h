/* Wrapped grids (core/wk.h: index j stands for offset w(j)) to centred ones,
 * for pictures and EXR output.  Layout everywhere: row-major, x fastest,
 * index (k n_1 + j) n_0 + i.
 *
 * Thread safety: every function here is reentrant (no shared state). */
#ifndef NL_FFTSHIFT_H
#define NL_FFTSHIFT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

/* The spectrum P (any dim, wrapped order) with zero frequency moved to index
 * floor(n_a / 2) of each axis: C(i + floor(n_a/2) mod n_a) = P(i), same n and
 * h.  *out is released by nl_field_free.  Returns NL_OK or NL_ENOMEM /
 * NL_ETOOBIG (from nl_field_alloc); *out is NULL on failure. */
int nl_fftshift_alloc(const nl_field *P, nl_field **out);

/* The full ACF estimate of nl_acf_full (2 n_a per axis, wrapped) as lags
 * -(n_a - 1) .. n_a - 1 per axis with lag 0 at the centre, index n_a - 1:
 * 2 n_a - 1 samples per axis, spacing h (lags in length units: index times h).  The unused
 * wrapped index n_a (lag -n_a, always 0) is dropped.  *out is released by
 * nl_field_free.  Returns NL_OK, NL_EINVAL (an axis of full is odd, so not
 * the output of nl_acf_full) or NL_ENOMEM / NL_ETOOBIG; *out is NULL on
 * failure. */
int nl_acf_centred_alloc(const nl_field *full, nl_field **out);

/* In place: v <- log10(max(v, rel * vmax)) with vmax the largest value of f
 * before the call, which is returned (the floor keeps log10 finite for a
 * zero ordinate; rel > 0, e.g. 1e-12).  For log-scale pictures of spectra. */
double nl_fftshift_log10_floor(nl_field *f, double rel);

#ifdef __cplusplus
}
#endif

#endif
