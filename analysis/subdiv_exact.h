/* The exact covariance of a periodic subdivision field.
 *
 * Subdivision fields are linear in Gaussian numbers, so their covariance
 * follows exactly, level by level: with the coarse covariance C_0 (the
 * model's R wrapped on the coarse periodic grid, which periodic FFT
 * synthesis realises exactly) and the refinement x' = M x + u of eq. (3)/(9),
 *     C_{k+1} = M C_k M^T + diag(var u).
 * Lewis's construction estimates each new point from old points only, so
 * its residual is uncorrelated with them but not with its new neighbours:
 * C_k differs from R except for Markovian models.  This module computes
 * that difference: the expectation of the unbiased ACF estimate (known mean
 * 0) of the synthesised field, which a correct implementation's ensembles
 * must match and which measures the method's own error against the target.
 * Memory is (n_x n_y)^2 doubles: meant for fields up to about 64 x 64
 * (4096 samples) or 4096 samples in 1D. */
#ifndef NL_SUBDIV_EXACT_H
#define NL_SUBDIV_EXACT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"
#include "../synth/subdiv.h"

/* For each lag (lags[2i], lags[2i+1]) in samples (y ignored in 1D), the
 * mean of C(p, p + lag) over the positions p with p and p + lag inside the
 * nx x ny field (n = 1 in 1D), i.e. E of the unbiased estimate with known
 * mean 0.  m is the model the coefficients were made from.  out holds
 * nlags values (variance units of the model).  The subdivision must be
 * periodic with nx = cx 2^levels (and ny = cy 2^levels in 2D), cx, cy >= 2.
 * Random neighbourhoods (nl_subdiv_coeffs_randomize): the covariance
 * averaged over the random choice as well (each new point's alternative
 * uniform and independent of every other point's, as the synthesis draws
 * them): a new point enters every covariance with another point through
 * the mean of its alternatives' stencils, and its own variance is the mean
 * of a^T C a plus the displacement variance over its alternatives.  So the
 * result is the expected ACF of an ensemble over seeds.
 * Returns NL_OK, NL_EINVAL (neighbourhood half-widths above 4 in 2D or
 * 128 in 1D; random neighbourhoods with correlated displacements; a size
 * that is not the coarse size times 2^levels), NL_ETOOBIG (nx ny > 4096), NL_ENOMEM, or the codes
 * of nl_wk_sample_acf.  Reentrant (c and m are only read; as thread-safe as
 * the model). */
int nl_subdiv_exact_acf(const nl_subdiv_coeffs *c, const nl_model *m, size_t nx, size_t ny, size_t nlags,
                        const long *lags, double *out);

#ifdef __cplusplus
}
#endif

#endif
