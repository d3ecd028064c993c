/* Direct simulation by the Cholesky factor of the covariance matrix (GSL):
 * x = L z, L L^T = C, C_ij = R(p_i - p_j) over the N grid samples, z_j =
 * nl_rng_gauss(seed, SYNTH_CHOLESKY_STREAM, j).  Exact and non-periodic;
 * O(N^3) time and N^2 memory, so it is the ground truth for small grids.
 * A matrix that is not positive definite (Cholesky fails) is NL_ENOTPD; a
 * matrix that does not fit in memory (N^2 doubles) is refused before
 * allocation with NL_ETOOBIG. */
#ifndef SYNTH_CHOLESKY_H
#define SYNTH_CHOLESKY_H

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

#define SYNTH_CHOLESKY_STREAM 200u

/* Largest number of samples accepted (a 64 MiB-times-8 matrix). */
#define SYNTH_CHOLESKY_MAX 8192

typedef struct synth_cholesky_plan synth_cholesky_plan;

int synth_cholesky_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                              synth_cholesky_plan **out);
int synth_cholesky_execute(const synth_cholesky_plan *p, uint64_t seed, nl_field *out);
void synth_cholesky_plan_free(synth_cholesky_plan *p);

#endif
