/* Periodic Fourier (FFT) synthesis of a stationary Gaussian field.
 *
 * The model is sampled on the periodic grid (wrapped lags, see core/wk.h)
 * and its covariance matrix, which is circulant, is diagonalised by the DFT:
 * eigenvalues lambda_k = S_k / (h_1 ... h_d).  A realization is
 *     x = IDFT( sqrt(lambda / (2 N)) . G )    (unnormalised inverse DFT, FFTW c2r)
 * with G the complex white spectrum on the r2c half grid (k0 = 0..n0/2,
 * then k1, k2; row-major): G_k = g_2k + i g_2k+1 with g_2k, g_2k+1 the
 * pair nl_rng_gauss_pair(seed, NL_STREAM_WHITE, k), made Hermitian in the
 * columns k0 = 0 and n0/2 (the later of k and -k in row order is the
 * conjugate of the earlier; a self-conjugate k, every component 0 or
 * n_a/2, is sqrt(2) Re G_k).  sqrt(N/2) G is distributed as the DFT of N
 * independent N(0, 1) samples, so the field is that white noise filtered by
 * sqrt(lambda): its covariance is exactly the sampled, wrapped R: the field
 * is Gaussian, periodic, ensemble mean 0 and variance R(0) (for spectral
 * models, the Riemann sum of S over the grid frequencies).  The same seed
 * and size give the same G for every model (common random numbers: the
 * DFT of any field is sqrt(lambda / (2 N)) G, the ratio of two models'
 * DFTs is real and non-negative).  Since version 0.2.0 the white noise is
 * drawn in the frequency domain (one transform instead of two); before,
 * w = (g_0, g_1, ...) was drawn in space and transformed: fields of a seed
 * differ from those of 0.1.x, their statistics do not.
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

#ifdef __cplusplus
extern "C" {
#endif

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
 * sqrt(lambda_k / (2 N)) on the r2c half grid and its FFTW plans; free it with
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
 * dim, n and h; row-major, x fastest; out->h is not changed).  For even
 * n[0] the transform runs in out itself (the half grid's columns 0..n0/2-1
 * in place of the rows, column n0/2 in a side buffer of N / n0 complex
 * numbers, the rows' c2r through a buffer of 8 rows per thread): peak
 * memory the field and the plan's amplitudes (half the field); for odd
 * n[0] a half-grid complex buffer (about the field's size) is allocated per
 * call.  The call only reads the plan (FFTW's new-array execute), so one
 * plan may serve several threads.  Bit-identical for equal seeds.  NL_OK,
 * NL_EINVAL (out does not match the plan's grid), NL_ENOMEM. */
int nl_synth_fft_execute(const nl_synth_fft_plan *p, uint64_t seed, nl_field *out);

/* Frees the plan and its FFTW plans (NULL: no-op); not thread-safe (FFTW). */
void nl_synth_fft_plan_free(nl_synth_fft_plan *p);

/* Check a grid spacing h[0..dim-1] (NULL: unit) for the spectral methods:
 * each positive and finite, and the cell volume h[0]...h[dim-1] a normal
 * double (the spectrum is divided by it).  NL_OK or NL_EINVAL naming the
 * value.  Thread-safe. */
int nl_synth_check_cell(int dim, const double *h);

#ifdef __cplusplus
}
#endif

#endif
