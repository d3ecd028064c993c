/* Rank-1 lattice fields of a noiselab model (Keller 2001 with the model
 * layer of core/model.h): the variance per wave vector on a torus of side
 * `extent`, and the whole synthesis in one call.
 *
 * Variance per wave vector: S(k / extent) / extent^s, with S the closed-form
 * spectrum of a spectral model (s <= 3) or the Hankel transform (Keller's
 * eq. 13) of an isotropic R; rounding-level negatives of the quadrature
 * (below 1e-12 of S(0)) become 0. */
#ifndef NL_SYNTH_RANK1_MODEL_H
#define NL_SYNTH_RANK1_MODEL_H

#include "rank1.h"
#include "../core/model.h"

typedef struct {
    const nl_model *m;  /* the model (borrowed) */
    int s;              /* dimension */
    double extent;      /* torus side */
} nl_rank1_model_ctx;

/* The variance at integer wave vector k (s values) for ctx (an
 * nl_rank1_model_ctx *); an nl_rank1_spectrum.  Thread-safe for models
 * that are (every kind but expr:). */
double nl_rank1_model_spectrum(const long *k, int s, void *ctx);

/* NL_OK when the model gives a spectrum in s dimensions; NL_EINVAL for a
 * spectral model in s > 3 or a model that is neither spectral nor
 * isotropic. */
int nl_rank1_model_check(const nl_model *m, int s);

/* The field of model m on lattice L (torus of side extent > 0): f (N
 * values), grad (N * s, may be NULL) and *imag (may be NULL) as
 * nl_rank1_synthesize, coefficients from seed as nl_rank1_coefficients.
 * Errors: those of nl_rank1_model_check, NL_EINVAL for an extent that is
 * not positive and finite or a spectrum value that is negative or not
 * finite, NL_ENOMEM.  Not thread-safe (plans FFTW). */
int nl_rank1_model_synthesize(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed, double *f,
                              double *grad, double *imag);

#endif
