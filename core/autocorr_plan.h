/* A plan for the lag-product sums of core/autocorr.h: FFTW plans and scratch
 * made once for fields of one size, then executed on many fields.
 *
 * For a field of n_a samples per axis (dim 1..3) the result is the field c
 * of m_a = 2 n_a samples per axis (1 beyond dim), wrapped order, holding
 *     c(l) = sum over j with j and j + l inside the grid of (x_j - mean)(x_{j+l} - mean)
 * exactly as nl_autocorr_sums makes it (same transforms, same planner
 * flags, same order of operations: bit-identical results).
 *
 * Thread safety: nl_autocorr_plan_alloc and nl_autocorr_plan_free call the
 * FFTW planner, which is not thread-safe: call them from one thread at a
 * time.  nl_autocorr_plan_execute on distinct plans may run concurrently;
 * one plan must not be executed by two threads at once (it owns scratch). */
#ifndef NL_AUTOCORR_PLAN_H
#define NL_AUTOCORR_PLAN_H

#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"

#include <stddef.h>

typedef struct nl_autocorr_plan nl_autocorr_plan;

/* Plan for fields of dim (1..3) axes of n[0..dim-1] >= 1 samples.  *out is
 * released by nl_autocorr_plan_free.  Returns NL_OK, NL_EINVAL (dim out of
 * range, n[a] = 0), NL_ETOOBIG (the 2n grid overflows or exceeds memory),
 * NL_ENOMEM or NL_EFAIL (FFTW could not plan); *out is NULL on failure. */
int nl_autocorr_plan_alloc(int dim, const size_t *n, nl_autocorr_plan **out);

/* Lag sums of x (same dim and n as the plan) about `mean` into c (dim and
 * 2 n_a samples per axis; its spacing is left as it is).  Returns NL_OK or
 * NL_EINVAL when x or c does not match the plan (nothing is written). */
int nl_autocorr_plan_execute(nl_autocorr_plan *p, const nl_field *x, double mean, nl_field *c);

/* Grid of the result: dim and m[0..2] (2 n_a per axis, 1 beyond dim). */
void nl_autocorr_plan_grid(const nl_autocorr_plan *p, int *dim, size_t *m);

/* NULL is a no-op. */
void nl_autocorr_plan_free(nl_autocorr_plan *p);

#ifdef __cplusplus
}
#endif

#endif
