/* Direct simulation by the Cholesky factor of the covariance matrix (GSL):
 * x = L z, L L^T = C, C_ij = R(p_i - p_j) over the N grid samples, z_j =
 * nl_rng_gauss(seed, NL_SYNTH_CHOLESKY_STREAM, j).  Exact and non-periodic;
 * O(N^3) time and N^2 memory, so it is the ground truth for small grids.
 * A matrix that is not positive definite (Cholesky fails) is NL_ENOTPD; a
 * matrix that does not fit in memory (N^2 doubles) is refused before
 * allocation with NL_ETOOBIG. */
#ifndef NL_SYNTH_CHOLESKY_H
#define NL_SYNTH_CHOLESKY_H

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

#define NL_SYNTH_CHOLESKY_STREAM 200u

/* Largest number of samples accepted (a 64 MiB-times-8 matrix). */
#define NL_SYNTH_CHOLESKY_MAX 8192

typedef struct nl_synth_cholesky_plan nl_synth_cholesky_plan;

int nl_synth_cholesky_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                              nl_synth_cholesky_plan **out);
int nl_synth_cholesky_execute(const nl_synth_cholesky_plan *p, uint64_t seed, nl_field *out);
void nl_synth_cholesky_plan_free(nl_synth_cholesky_plan *p);

#endif
