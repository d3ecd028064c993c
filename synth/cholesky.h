/* Direct simulation by the Cholesky factor of the covariance matrix (GSL,
 * level-3 BLAS):
 * x = L z, L L^T = C, C_ij = R(p_i - p_j) over the N grid samples, z_j =
 * nl_rng_gauss(seed, NL_SYNTH_CHOLESKY_STREAM, j).  Exact and non-periodic;
 * O(N^3) time and N^2 memory, so it is the ground truth for small grids.
 * A matrix that is not positive definite (Cholesky fails) is NL_ENOTPD; a
 * matrix that does not fit in memory (N^2 doubles) is refused before
 * allocation with NL_ETOOBIG.  A nugget (core/model.h) is represented
 * exactly: it is on C's diagonal, so the field is the continuous part plus
 * independent white noise of variance nugget per sample. */
#ifndef NL_SYNTH_CHOLESKY_H
#define NL_SYNTH_CHOLESKY_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stdint.h>

#define NL_SYNTH_CHOLESKY_STREAM 200u

/* Largest number of samples accepted (a 64 MiB-times-8 matrix). */
#define NL_SYNTH_CHOLESKY_MAX 8192

typedef struct nl_synth_cholesky_plan nl_synth_cholesky_plan;

/* Plan for model m on a dim-D grid (1..3) of n[] samples at spacing h[]
 * (NULL: unit; lag units of m), row-major with x fastest: C is count x
 * count, count = n[0] ... n[dim-1] <= NL_SYNTH_CHOLESKY_MAX.  The plan owns
 * the factor and a count-sample workspace; free with
 * nl_synth_cholesky_plan_free.  Not thread-safe (evaluates the model; GSL's
 * error handler).  Returns NL_OK and *out, or (*out = NULL)
 *   NL_EINVAL  dim outside 1..3, a zero size, a model unusable in dim, a
 *              covariance that is not finite at some lag of the grid;
 *   NL_ETOOBIG more than NL_SYNTH_CHOLESKY_MAX samples, or sizes overflow;
 *   NL_ENOTPD  the Cholesky factorisation fails;
 *   NL_ENOMEM  out of memory. */
int nl_synth_cholesky_plan_alloc(const nl_model *m, int dim, const size_t *n, const double *h,
                              nl_synth_cholesky_plan **out);

/* x = L z for `seed` into out (count samples, the plan's layout; out->n is
 * not checked beyond its count).  Bit-identical for equal seeds, whatever
 * the number of threads (the plan's factorisation runs on BLAS threads, the
 * product on one; tests/test_blas_threads.c).  Does not
 * allocate: z lives in the plan, so one plan serves ONE thread at a time
 * (give each thread its own plan).  NL_OK, or NL_EINVAL when out's count
 * differs from the plan's. */
int nl_synth_cholesky_execute(nl_synth_cholesky_plan *p, uint64_t seed, nl_field *out);

/* Frees the plan (NULL: no-op). */
void nl_synth_cholesky_plan_free(nl_synth_cholesky_plan *p);

#ifdef __cplusplus
}
#endif

#endif
