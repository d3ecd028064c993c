/* Rank-1 lattice fields of a noiselab model (Keller 2001 with the model
 * layer of core/model.h): the variance per wave vector on a torus of side
 * `extent`, and the whole synthesis in one call.
 *
 * Variance per wave vector: S(k / extent) / extent^s, with S the closed-form
 * spectrum of a spectral model (s <= 3) or the Hankel transform (Keller's
 * eq. 13) of an isotropic R; rounding-level negatives of the quadrature
 * (below 1e-12 of S(0)) become 0.
 *
 * Synthesis evaluates the Hankel transform once per distinct |k|^2 when
 * there are at most NL_RANK1_EXACT_RADII of them (the same values as one
 * evaluation per wave vector), else on a radial table: nodes uniform in
 * u = log(1 + w / w1), w1 = max |k| / extent / 1024, up to 1.05 max |k| /
 * extent, from 129 doubling to at most 1025 until the cubic (four-point
 * Lagrange in u) interpolation of the half table misses the new nodes by
 * at most 1e-6 of S(0); that measured miss, a bound for the full table, is
 * reported.  Negative values beyond the quadrature's
 * relative tolerance (1e-9 of S(0)) mean the model is not positive
 * definite on the lattice: refused, or zeroed under NL_RANK1_CLAMP. */
#ifndef NL_SYNTH_RANK1_MODEL_H
#define NL_SYNTH_RANK1_MODEL_H

#ifdef __cplusplus
extern "C" {
#endif

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
 * spectral model in s > 3, a model that is neither spectral nor
 * isotropic, a model with a nugget (the Hankel transform of R has no
 * white-noise part) or a spherical model in s > 3 (not positive definite
 * there). */
int nl_rank1_model_check(const nl_model *m, int s);

/* The field of model m on lattice L (torus of side extent > 0): f (N
 * values), grad (N * s, may be NULL) and *imag (may be NULL) as
 * nl_rank1_synthesize, coefficients from seed as nl_rank1_coefficients.
 * Errors: those of nl_rank1_model_check, NL_EINVAL for an extent that is
 * not positive and finite or a spectrum value that is not finite,
 * NL_ENOTPD for a negative one, NL_ETOOBIG, NL_ENOMEM.  Not thread-safe (plans FFTW). */
#define NL_RANK1_EXACT_RADII 1024
#define NL_RANK1_CLAMP 1u  /* flag: zero negative spectrum values, report the change */

/* What a synthesis did: radial table nodes (0: exact per radius) and the
 * measured interpolation error relative to S(0); negative spectrum values
 * zeroed (counting both of a pair) and their weight relative to the
 * positive variance (the bound on the change of the variance). */
typedef struct {
    size_t nodes;
    double interp_error;
    size_t negatives;
    double clamp_error;
} nl_rank1_model_info;

/* As nl_rank1_model_synthesize, with flags (0 or NL_RANK1_CLAMP) and info
 * (may be NULL).  Further errors: NL_ENOTPD for negative spectrum values
 * beyond rounding without NL_RANK1_CLAMP (or with no positive part),
 * NL_ETOOBIG when the lattice's buffers exceed the memory available
 * (nl_mem_available), NL_EINVAL when the Hankel transform fails. */
int nl_rank1_model_synthesize_info(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed,
                                   unsigned flags, double *f, double *grad, double *imag, nl_rank1_model_info *info);

/* The coefficients c (2N doubles, re/im, as nl_rank1_coefficients) that
 * nl_rank1_model_synthesize_info transforms: the field's trigonometric
 * series, for nl_rank1_eval and nl_rank1_grid (synth/rank1.h).  Same
 * arguments, flags, info and errors (no FFT: thread-safe for reentrant
 * models). */
int nl_rank1_model_coefficients(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed,
                                unsigned flags, double *coef, nl_rank1_model_info *info);

int nl_rank1_model_synthesize(const nl_rank1_lattice *L, const nl_model *m, double extent, uint64_t seed, double *f,
                              double *grad, double *imag);

#ifdef __cplusplus
}
#endif

#endif
