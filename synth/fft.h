/* Periodic Fourier (FFT) synthesis of a stationary Gaussian field.
 *
 * The model is sampled on the periodic grid (wrapped lags, see core/wk.h)
 * and its covariance matrix, which is circulant, is diagonalised by the DFT:
 * eigenvalues lambda_k = S_k / (h_1 ... h_d).  A realization is
 *     x = (1/N) IDFT( sqrt(lambda) . DFT(w) ),
 * with w the white noise on the N grid samples in row-major order, w_2k and
 * w_2k+1 the pair nl_rng_gauss_pair(seed, NL_STREAM_WHITE, k).  Its covariance is exactly the sampled, wrapped R: the field
 * is Gaussian, periodic, ensemble mean 0 and variance R(0) (for spectral
 * models, the Riemann sum of S over the grid frequencies).  The same seed and
 * size give the same w for every model (common random numbers).
 *
 * Negative eigenvalues (a model that is not positive definite on this grid,
 * or one truncated by the period) cannot be synthesised.  Setting them to
 * zero changes every covariance entry by at most E = sum|lambda_neg| / N;
 * when E <= 1e-6 R(0), a change no estimator on fewer than 1e12 samples can
 * resolve, they are set to zero silently; above that the plan is refused
 * (NL_ENOTPD) unless NL_SYNTH_FFT_CLAMP is given. */
#ifndef NL_SYNTH_FFT_H
#define NL_SYNTH_FFT_H

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

enum { NL_SYNTH_FFT_CLAMP = 1 };

/* Relative covariance error below which negative eigenvalues are dropped. */
#define NL_SYNTH_FFT_CLAMP_TOL 1e-6

typedef struct nl_synth_fft_plan nl_synth_fft_plan;

typedef struct {
    double variance;    /* R(0) of the synthesised field: mean of lambda after clamping */
    double min_lambda;  /* most negative (or smallest) eigenvalue, as a density S */
    double max_lambda;  /* largest eigenvalue, as a density S */
    size_t negatives;   /* eigenvalues set to zero */
    double clamp_error; /* bound on the covariance change from clamping, relative to R(0) */
} nl_synth_fft_info;

/* Plan synthesis of model m on a dim-D grid of n[] samples, spacing h[]
 * (NULL: unit).  Returns NL_OK, or NL_EINVAL/NL_ETOOBIG/NL_ENOTPD with a
 * message. */
int nl_synth_fft_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                         nl_synth_fft_plan **out);

/* The same from a spectrum already sampled on the grid (wrapped order,
 * two-sided density, core/wk.h): S's dim, n and h define the grid. */
int nl_synth_fft_plan_spectrum(const nl_field *S, unsigned flags, nl_synth_fft_plan **out);

void nl_synth_fft_plan_info(const nl_synth_fft_plan *p, nl_synth_fft_info *info);

/* Synthesise the realization for `seed` into out (alloc'ed with the plan's
 * dim, n and h).  Thread-safe: one plan may serve several threads. */
int nl_synth_fft_execute(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out);

void nl_synth_fft_plan_free(nl_synth_fft_plan *p);

#endif
