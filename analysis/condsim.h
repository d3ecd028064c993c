/* Conditional simulation by kriging (Journel 1974; Journel and Huijbregts
 * 1978, section VI.A.2): a field with the model's covariance that honours
 * data d_i at points t_i.  From an unconditional realization U of the
 * model (any exact method: fft, circulant, subdivision) on a grid,
 *     Z(x) = U(x) + K[d - U(t)](x),
 * where K[v](x) is the kriging estimate (analysis/krige.h) at x from values
 * v_i at the t_i.  Over realizations of U, Z has the kriging estimate
 * K[d](x) as its mean and the kriging variance as its variance (the
 * estimation error U(x) - K[U(t)](x) is that of kriging and, for Gaussian
 * U, independent of the data's values), with ordinary kriging (unknown
 * mean) or simple kriging with a known mean.
 *
 * Grid.  Sample i of axis a sits at the cell centre lo[a] + (i + 0.5) h[a]
 * (as nl_krige_eval_grid), so the grid covers [lo[a], lo[a] + n[a] h[a]].
 * U(t_i) is read from the grid by nl_field_stencil (core/field_sample.h):
 * exact for data on samples (within NL_CONDSIM_ON_SAMPLE spacings of one
 * on every axis: taken as on it), which are then honoured to rounding
 * (Z(t_i) = d_i: kriging interpolates); between samples, the stencil's
 * value differs from U(t_i) by an error whose standard deviation
 *     s_i^2 = R(0) - 2 sum_k w_k R(t_i - x_k) + sum_kl w_k w_l R(x_k - x_l)
 * is known from the model; the plan reports the largest s_i / sqrt(R(0)).
 * Z then honours d_i only to about that error, and its covariance near
 * such data is perturbed by it.
 *
 * Ownership and threads: the plan copies the data and borrows the model,
 * which must outlive it; nl_condsim_plan_free releases it (NULL is a
 * no-op).  nl_condsim_execute may run concurrently on one plan (with
 * different fields) for models that are thread-safe (every kind but
 * expr:). */
#ifndef NL_CONDSIM_H
#define NL_CONDSIM_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"
#include "../core/model.h"

#include <stddef.h>

#define NL_CONDSIM_ON_SAMPLE 1e-9

typedef struct nl_condsim_plan nl_condsim_plan;

typedef struct {
    size_t n;         /* data */
    size_t on_samples;/* data read from one grid sample (honoured exactly) */
    double max_error; /* largest s_i / sqrt(R(0)) (0 when every datum is on a sample) */
    size_t worst;     /* the datum (from 0) with it */
    double max_move;  /* largest distance from a datum to its nearest sample, in units of the
                       * coordinates (the nearest-sample interpolation's move) */
} nl_condsim_info;

/* The plan for data pts (n points of grid->dim coordinates, row-major) and
 * values val, on a grid of grid->n samples of spacing grid->h (grid->data
 * is not read) whose cell centres start at lo + h / 2; interp: NL_INTERP_*
 * (core/field_sample.h) for reading U at the data; simple: simple kriging
 * with the known mean `mean`, else ordinary; nmax > 0: local kriging from
 * the nmax nearest data (analysis/krige_local.h; the ensemble's mean and
 * variance are then that kriging's), 0: every datum (analysis/krige.h).
 * *out is NULL on failure.
 * Errors: NL_EINVAL for n = 0, interp unknown, a datum outside
 * [lo, lo + n h] (the message names the first: its row from 1 and
 * coordinates), a non-finite lo or datum, or what nl_krige_plan_alloc
 * refuses in the model or data (checked here, once, on the data's values);
 * NL_ETOOBIG, NL_ENOMEM. */
int nl_condsim_plan_alloc(const nl_model *m, size_t n, const double *pts, const double *val, const double *lo,
                          const nl_field *grid, int interp, int simple, double mean, size_t nmax,
                          nl_condsim_plan **out);

/* Replace the unconditional realization in f (the plan's grid: same dim, n
 * and h) by the conditional one, Z = U + K[d - U(t)].  Cost: one kriging
 * set-up (O(n^3)) and one kriging of the grid (O(n) per sample).
 * Errors: NL_EINVAL for a field of another shape or non-finite samples at
 * the data; NL_ETOOBIG, NL_ENOMEM; those of nl_krige_plan_alloc. */
int nl_condsim_execute(const nl_condsim_plan *p, nl_field *f);

void nl_condsim_plan_info(const nl_condsim_plan *p, nl_condsim_info *info);
void nl_condsim_plan_free(nl_condsim_plan *p);

#ifdef __cplusplus
}
#endif

#endif
