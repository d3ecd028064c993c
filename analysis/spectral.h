/* Summaries of a spectrum on its wrapped frequency grid (core/wk.h): the
 * 1D half spectrum or the radial profile, the model's profile on the same
 * grid, and the angular-sector anisotropy of a 2D spectrum.
 *
 * Units: frequencies in cycles per unit length (f = w(k) / (n h)), except
 * nl_psd_sectors, whose band is in cycles per sample.  Values keep the
 * spectrum's own scaling (for nl_psd_periodogram, a two-sided density).
 * Thread safety: reentrant; nl_psd_model_profile evaluates the model, so it
 * is as thread-safe as the model (core/model.h). */
#ifndef NL_SPECTRAL_H
#define NL_SPECTRAL_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>

/* Number of points nl_psd_profile writes for a grid of P's size: n_0/2 + 1 in
 * 1D; in 2D/3D floor(fmax / step) + 1 radial bins with step = min_a 1/(n_a h_a)
 * and fmax = min_a 1/(2 h_a) (the smallest Nyquist frequency).  Never more
 * than n_0 + n_1 + n_2. */
size_t nl_psd_profile_size(const nl_field *P);

/* 1D: freq[i] = i / (n h), val[i] = P[i] for i = 0 .. n/2 (cnt untouched).
 * 2D/3D: the radial average (analysis/radial.h, NL_GRID_FREQ) in bins of
 * width step: freq = mean |f| of the bin, val = mean value, cnt = ordinates
 * (NAN and 0 for an empty bin).  Arrays hold nl_psd_profile_size(P) entries;
 * *nf receives that number.  Returns NL_OK. */
int nl_psd_profile(const nl_field *P, double *freq, double *val, size_t *cnt, size_t *nf);

/* The model's spectrum sampled on the grid of dim, n[0..dim-1] and h
 * (nl_wk_sample_spectrum: the sampled process, aliasing included), as the
 * profile of nl_psd_profile on that grid: val holds its
 * nl_psd_profile_size entries, *nf receives their number.  Returns NL_OK,
 * NL_ENOMEM / NL_ETOOBIG, or the codes of nl_wk_sample_spectrum. */
int nl_psd_model_profile(const nl_model *m, int dim, const size_t *n, const double *h, double *val, size_t *nf);

/* 2D: mean of P over nsec sectors of 180/nsec degrees from +x (direction
 * modulo 180: a real field's spectrum is even), over the ordinates with
 * fmin <= |f| <= fmax in cycles per sample; sector[b] = NAN when empty.
 * *aniso = largest / smallest sector mean.  Returns NL_OK or NL_EINVAL
 * (P not 2D, nsec = 0, or not 0 <= fmin <= fmax). */
int nl_psd_sectors(const nl_field *P, size_t nsec, double fmin, double fmax, double *sector, double *aniso);

#ifdef __cplusplus
}
#endif

#endif
