/* Circulant embedding (Dietrich and Newsam 1993; Wood and Chan 1994): an
 * exact stationary Gaussian field on a NON-periodic grid.
 *
 * The n_a-sample grid is embedded in a periodic grid of m_a >= 2 (n_a - 1)
 * samples (m_a even and 2, 3, 5-smooth for FFTW), on which the wrapped R is
 * a circulant covariance whose eigenvalues are the DFT of its first row.
 * When all are non-negative (the clamping rule of synth/fft.h), periodic
 * FFT synthesis on the m grid cropped to the first n_a samples per axis has
 * covariance exactly R(lag) for every pair of the n grid.  A negative
 * eigenvalue beyond that rule doubles m (up to max_factor * n per axis);
 * a model whose embedding never becomes non-negative is refused
 * (NL_ENOTPD) unless clamping is accepted.
 *
 * A spectral model (power:, spectrum:) is sampled in frequency on the
 * embedding, not in lag: the covariance is then the Riemann sum of S over
 * the embedding's frequencies, which misses the power below 1/(m h).  The
 * plan measures that loss against R(0) (variance_loss; the caller flags it
 * above NL_SYNTH_CIRCULANT_LOSS_TOL): a steep power law whose fmin is far
 * below 1/(m h) keeps only a fraction of its variance (power:d=2.424 on 64
 * samples, embedding 128: 0.10 of it).
 *
 * A nugget (core/model.h) is represented exactly, as by synth/fft.h: the
 * wrapped R holds it at lag 0, which adds it to every eigenvalue. */
#ifndef NL_SYNTH_CIRCULANT_H
#define NL_SYNTH_CIRCULANT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "fft.h"

typedef struct {
    size_t m[3];          /* embedding size per axis */
    double min_eigenvalue;/* smallest eigenvalue of the embedding covariance matrix */
    double max_eigenvalue;/* largest */
    double clamp_error;   /* covariance change from zeroing negatives, / R(0) */
    int doublings;        /* times the embedding was doubled */
    double variance_loss; /* spectral models: 1 - (variance of the synthesised field) / R(0), negative
                           * for a gain; NaN when R(0) is not known (spectrum:); lag models: 0 */
} nl_synth_circulant_info;

/* |variance_loss| above which a plan's field is flagged: a
 * spectral model is sampled at the embedding's frequencies, so the power
 * below its lowest frequency 1/(m h) (and above the Nyquist frequency) is
 * not synthesised; the model's R(0) is then not the field's variance. */
#define NL_SYNTH_CIRCULANT_LOSS_TOL 1e-3

typedef struct nl_synth_circulant_plan nl_synth_circulant_plan;

/* Plan for model m on a dim-D grid (1..3) of n[] samples at spacing h[]
 * (NULL: unit), flags 0 or NL_SYNTH_FFT_CLAMP (accept a clamped embedding
 * at max_factor), max_factor >= 2 the largest embedding per axis in units
 * of n.  The plan owns its FFT plan (synth/fft.h); free with
 * nl_synth_circulant_plan_free.  Plans FFTW and evaluates the model: not
 * thread-safe.  Returns NL_OK and *out, or (*out = NULL)
 *   NL_EINVAL  dim outside 1..3, a zero size, a model unusable in dim;
 *   NL_ETOOBIG the embedding does not fit in memory or FFTW's int sizes;
 *   NL_ENOTPD  the embedding is not non-negative at max_factor (no clamp);
 *   NL_ENOMEM, NL_EFAIL  out of memory, FFTW could not plan. */
int nl_synth_circulant_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h, unsigned flags,
                               int max_factor, nl_synth_circulant_plan **out);

/* The embedding and its eigenvalue range (eigenvalues of the covariance
 * matrix, i.e. spectrum densities over the cell volume). */
void nl_synth_circulant_plan_info(const nl_synth_circulant_plan *p, nl_synth_circulant_info *info);

/* The field for `seed` into out (the plan's dim and n, row-major, x
 * fastest): the first n_a samples per axis of the periodic synthesis on the
 * embedding.  Each call allocates its own embedding-size workspace and only
 * reads the plan, so one plan may serve several threads.  Bit-identical for
 * equal seeds.  NL_OK, NL_EINVAL (out does not match), NL_ENOMEM. */
int nl_synth_circulant_execute(const nl_synth_circulant_plan *p, uint64_t seed, nl_field *out);

/* The embedding size of an axis of n samples before doublings: the
 * smallest even 2,3,5-smooth number >= 2 (n - 1).  Pure. */
size_t nl_synth_circulant_size(size_t n);

/* Frees the plan (NULL: no-op). */
void nl_synth_circulant_plan_free(nl_synth_circulant_plan *p);

#ifdef __cplusplus
}
#endif

#endif
