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
 * (NL_ENOTPD) unless NL_SYNTH_FFT_CLAMP is given.
 *
 * A nugget (core/model.h) is represented exactly: the sampled R holds it at
 * lag 0, so every eigenvalue gains it, the spectrum the constant nugget
 * h_1...h_d, and the field is the continuous part plus independent white
 * noise of variance nugget per sample. */
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

/* Plan synthesis of model m on a dim-D grid (1..3) of n[] samples, spacing
 * h[] (NULL: unit; the model's lag units).  The plan owns the amplitudes
 * sqrt(lambda_k) / N on the r2c half grid and two FFTW plans; free it with
 * nl_synth_fft_plan_free.  Plans FFTW and evaluates the model: NOT
 * thread-safe (call from one thread).  Returns NL_OK and *out, or
 * (*out = NULL)
 *   NL_EINVAL  a spacing refused by nl_synth_check_cell, a model that
 *              cannot be sampled in dim (nl_model_check_dim),
 *              or a size the spectrum sampling refuses;
 *   NL_ETOOBIG sizes overflow, exceed memory or FFTW's int sizes;
 *   NL_ENOTPD  negative eigenvalues beyond NL_SYNTH_FFT_CLAMP_TOL without
 *              NL_SYNTH_FFT_CLAMP, or no positive eigenvalue at all;
 *   NL_ENOMEM, NL_EFAIL  out of memory, FFTW could not plan. */
int nl_synth_fft_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                         nl_synth_fft_plan **out);

/* The same from a spectrum already sampled on the grid (wrapped order,
 * two-sided density, core/wk.h): S's dim, n and h define the grid; S is
 * read, not kept.  NL_ENOTPD, NL_ENOMEM, NL_EFAIL as above; not
 * thread-safe. */
int nl_synth_fft_plan_spectrum(const nl_field *S, unsigned flags, nl_synth_fft_plan **out);

/* Eigenvalue statistics of the plan (see nl_synth_fft_info). */
void nl_synth_fft_plan_info(const nl_synth_fft_plan *p, nl_synth_fft_info *info);

/* Synthesise the realization for `seed` into out (alloc'ed with the plan's
 * dim, n and h; row-major, x fastest; out->h is not changed).  Each call
 * allocates its own half-grid complex buffer and only reads the plan
 * (FFTW's new-array execute), so one plan may serve several threads.
 * Bit-identical for equal seeds.  NL_OK, NL_EINVAL (out does not match the
 * plan's grid), NL_ENOMEM. */
int nl_synth_fft_execute(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out);

/* Frees the plan and its FFTW plans (NULL: no-op); not thread-safe (FFTW). */
void nl_synth_fft_plan_free(nl_synth_fft_plan *p);

/* Check a grid spacing h[0..dim-1] (NULL: unit) for the spectral methods:
 * each positive and finite, and the cell volume h[0]...h[dim-1] a normal
 * double (the spectrum is divided by it).  NL_OK or NL_EINVAL naming the
 * value.  Thread-safe. */
int nl_synth_check_cell(int dim, const double *h);

#endif
