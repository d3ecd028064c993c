/* Validation of a model's synthesis: does each method reproduce the target?
 *
 * For each method (periodic FFT, circulant embedding, periodic generalized
 * subdivision, sparse convolution) the model is planned once and M
 * realizations (seeds 1..M) are synthesised on an n[0] x n[1] grid of unit
 * spacing (lags in samples).  Their unbiased ACF with known mean 0 along x at
 * the NL_VALIDATE_LAGS lags 0..32 is averaged, with the standard error from
 * the ensemble's spread, and the verdict is the ensemble verdict of
 * analysis/verdict.h: max |z| = |mean - R| / se against the Bonferroni
 * threshold of Student's t(M - 1) for a family-wise false-alarm rate alpha
 * over the NL_VALIDATE_LAGS lags (nl_verdict_threshold).
 *
 * The plans: FFT (synth/fft.h) and circulant embedding up to 16 n per axis
 * (synth/circulant.h) without clamping; subdivision (synth/subdiv.h) with
 * N = 2 and nl_subdiv_default_levels(dim, n, 16) levels (a coarse grid of at
 * least 16 samples per axis); sparse convolution (synth/sparse.h) of the
 * model's kernel at its default radius and cell, density 32, wrapped.
 *
 * Subdivision (Lewis 1987) estimates new points from earlier levels only, so
 * its covariance differs from R except for Markovian models in 1D; on small
 * grids (1D up to 2048 samples, 2D up to 64 x 64) the result also holds its
 * exact expected ACF (analysis/subdiv_exact.h), computed whenever its
 * coefficients exist and are positive definite, even when the model or the
 * coarse FFT is refused.
 *
 * A method that cannot run (its plan fails, a realization fails, or the
 * caller says the model is not positive definite) is "refused": a result
 * (status and message in its nl_validate_method_result), not an error.
 *
 * Thread safety: none of these functions is thread-safe (they plan FFTW and
 * evaluate the model, which is not thread-safe for expression models). */
#ifndef NL_VALIDATE_H
#define NL_VALIDATE_H

#include "../core/model.h"

#include <stddef.h>

/* Lags 0..NL_VALIDATE_LAGS - 1 along x. */
#define NL_VALIDATE_LAGS 33

/* The methods, in the order nl_validate_model runs them. */
enum { NL_VALIDATE_FFT, NL_VALIDATE_CIRCULANT, NL_VALIDATE_SUBDIV, NL_VALIDATE_SPARSE, NL_VALIDATE_METHODS };

/* "fft", "circulant", "subdiv", "sparse"; NULL outside 0..NL_VALIDATE_METHODS - 1. */
const char *nl_validate_method_name(int method);

typedef struct {
    size_t realizations;  /* M >= 2: seeds 1..M */
    double alpha;         /* family-wise false-alarm rate of the verdict, in (0, 1) */
    /* NULL, or called before each realization: `done` of `total` realizations
     * of `method` are finished */
    void (*progress)(void *ctx, int method, size_t done, size_t total);
    void *progress_ctx;   /* passed to progress */
} nl_validate_options;

/* The defaults: 32 realizations, alpha = 1e-3, no progress. */
void nl_validate_options_default(nl_validate_options *o);

/* One method's ensemble against the target. */
typedef struct {
    const char *name;               /* nl_validate_method_name (static storage) */
    int ran;                        /* 1: the ensemble ran and the numbers below are set; 0: refused */
    int status;                     /* the NL_E* code of a refusal; NL_OK when ran or not run yet */
    char why[256];                  /* the refusal's one-line message ("" when ran, "not run" before) */
    double mean[NL_VALIDATE_LAGS];  /* ensemble mean ACF, variance units of the model */
    double se[NL_VALIDATE_LAGS];    /* its standard error, sd / sqrt(M) */
    double zmax;                    /* max |z| over the lags */
    int pass;                       /* zmax <= threshold */
} nl_validate_method_result;

/* Everything validation found; caller-owned, nothing to free. */
typedef struct {
    int dim;                        /* 1 or 2 */
    size_t n[2];                    /* grid (n[1] = 1 in 1D) */
    size_t realizations;            /* M */
    int positive_definite;          /* as given to nl_validate_init */
    double target[NL_VALIDATE_LAGS];/* R(i, 0) */
    double threshold;               /* Bonferroni threshold of t(M - 1) */
    int have_exact;                 /* exact[] is set */
    double exact[NL_VALIDATE_LAGS]; /* subdivision's exact expected ACF */
    nl_validate_method_result method[NL_VALIDATE_METHODS]; /* by NL_VALIDATE_* */
} nl_validate_result;

/* Prepare *out for model m in dim (1 or 2) on an n[0..dim-1] grid, each
 * n[a] > NL_VALIDATE_LAGS - 1 (n[1] ignored in 1D): the target, the
 * threshold, every method not yet run.  positive_definite is the caller's
 * verdict on the model (nl_check_model, analysis/check.h): 0 refuses every
 * method (NL_ENOTPD).  m is read, not kept.  Returns NL_OK or NL_EINVAL
 * (dim, a size, realizations or alpha out of range; *out is then
 * unspecified). */
int nl_validate_init(const nl_model *m, int dim, const size_t *n, int positive_definite,
                     const nl_validate_options *o, nl_validate_result *out);

/* Plan `method` for m (the model given to nl_validate_init), synthesise the
 * ensemble and fill out->method[method] (subdivision also sets have_exact
 * and exact).  The verdict is against out->target, which the caller may
 * replace after nl_validate_init (e.g. to judge against another model).  o must give the realizations given to nl_validate_init
 * (its alpha is not read here).  Returns NL_OK (ran or refused: see ran and status), or
 * NL_EINVAL (method out of range, realizations differing from out's; out
 * untouched). */
int nl_validate_method(const nl_model *m, int method, const nl_validate_options *o, nl_validate_result *out);

/* nl_validate_init, then nl_validate_method for every method in order.
 * Returns NL_OK or NL_EINVAL as nl_validate_init. */
int nl_validate_model(const nl_model *m, int dim, const size_t *n, int positive_definite,
                      const nl_validate_options *o, nl_validate_result *out);

#endif
