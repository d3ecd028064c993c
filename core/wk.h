/* Models sampled on a periodic grid, and the Wiener-Khinchine conversion
 * between autocorrelation and spectrum on that grid (Lewis 1987, eq. (2)).
 *
 * Wrapped order: along an axis of n samples with spacing h, index j stands
 * for lag w(j) h and for frequency w(j) / (n h) (cycles per unit length),
 * where w(j) = j for j <= n/2 and j - n otherwise.  On an even axis the
 * sample at n/2 stands for both +n/2 and -n/2: models are sampled there as
 * the mean of the two, so sampled grids are exactly even.
 *
 * Scaling (FFTW is unnormalised; these are not):
 *     forward  S_k = (h_1 ... h_d) sum_j R_j exp(-2 pi i j.k / n)
 *     inverse  R_j = 1 / (n_1 h_1 ... n_d h_d) sum_k S_k exp(+2 pi i j.k / n)
 * so S is a two-sided spectral density in (variance) per (cycles per unit)^d
 * and R_0 is the Riemann sum of S over the grid frequencies.  The two are
 * exact inverses of each other.
 *
 * Statuses: NL_OK; NL_EINVAL (the model cannot be used in the field's
 * dimension, it is not finite at some sampled lag or frequency (named in the
 * message), it is not even (R(-t) != R(t) or S(-f) != S(f) beyond 1e-6 of
 * its largest value, on some 2048 points checked against their mirror
 * images: a half grid or a real part would silently keep only its even
 * part), the grids of input and output differ, or dim is not 1..3);
 * NL_ETOOBIG (a scratch grid does not fit: nl_field_alloc); NL_ENOMEM;
 * NL_EFAIL (FFTW could not plan; not seen in practice, FFTW_ESTIMATE plans
 * every size).  On failure the output's contents are unspecified.
 *
 * Thread safety: the conversions and the samplers that convert plan FFTW on
 * every call and so are not thread-safe (core/fftw_plan.h); sampling a
 * spectral model's spectrum or an R model's R plans nothing and is
 * thread-safe for reentrant models (nl_model_is_reentrant).  Models are
 * sampled on OpenMP threads when reentrant and the grid has more than 65536
 * values. */
#ifndef NL_WK_H
#define NL_WK_H

#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"
#include "model.h"

/* Wrapped index to signed offset. */
static inline long nl_wrap(size_t j, size_t n) { return j <= n / 2 ? (long)j : (long)j - (long)n; }

/* Fill R (whose dim, n and h are set) with the model's autocorrelation at the
 * wrapped lags.  Spectral models are sampled in frequency and converted
 * (plans FFTW). */
int nl_wk_sample_acf(const nl_model *m, nl_field *R);

/* Fill S with the model's spectrum at the wrapped frequencies of a space grid
 * of R's n and h: the closed form for spectral models, otherwise the forward
 * conversion of the sampled autocorrelation (plans FFTW). */
int nl_wk_sample_spectrum(const nl_model *m, nl_field *S);

/* The same on the half grid of a real-to-complex transform, in half the
 * memory: *out receives a malloc'ed array of (n0/2 + 1) n1 n2 values, entry
 * (k n1 + j) (n0/2 + 1) + i standing for the wrapped frequency (i, j, k)
 * (free it with nl_free, core/mem.h);
 * the rest of the grid follows from evenness, S(-f) = S(f).  n and h hold
 * dim entries (h NULL: unit spacing).  *out is NULL on failure.  Plans FFTW
 * for non-spectral models.  NL_EINVAL also for dim outside 1..3. */
int nl_wk_sample_spectrum_half(const nl_model *m, int dim, const size_t *n, const double *h, double **out);

/* One model value at the wrapped lag (freq 0) or frequency (freq 1) of
 * index idx[0..dim-1] of a grid of n samples at spacing h (NULL: unit),
 * bit for bit the value the whole-grid samplers above put there (a
 * distributed transform samples its own part of the grid: mpi/).  NaN or
 * an infinity when the model is not finite there (the caller names it).
 * Thread-safe for reentrant models. */
double nl_wk_value(const nl_model *m, int dim, const size_t *n, const double *h, const size_t *idx, int freq);

/* The same for whole rows r0 .. r1 - 1 of the grid (row r = j + n1 k, all
 * i < n[0]) into dst + (r - r0) stride.  NL_OK, or NL_EINVAL naming the
 * first sample where the model is not finite (as the whole-grid
 * samplers).  Models are sampled on OpenMP threads when reentrant. */
int nl_wk_sample_rows(const nl_model *m, int dim, const size_t *n, const double *h, size_t r0, size_t r1, int freq,
                      double *dst, size_t stride);

/* The checks the whole-grid samplers make before sampling: the model's
 * dimension, and for expressions (not reentrant) evenness on the grid.
 * NL_OK or NL_EINVAL naming the problem. */
int nl_wk_check_even(const nl_model *m, int dim, const size_t *n, const double *h, int freq);

/* Forward and inverse conversion of real, even (R_j = R_-j) fields; the
 * imaginary part, zero for even input up to rounding, is dropped.  R and S
 * must have the same dim and n (NL_EINVAL); the output's h is not read: the
 * input's spacing sets the scaling.  Plan FFTW: not thread-safe. */
int nl_wk_acf_to_spectrum(const nl_field *R, nl_field *S);
int nl_wk_spectrum_to_acf(const nl_field *S, nl_field *R);

#ifdef __cplusplus
}
#endif

#endif
