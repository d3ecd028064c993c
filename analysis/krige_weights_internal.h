/* Kriging weights on the data, for reuse: the estimate at x of values z
 * at the plan's data points is
 *     est(x) = c(x) + sum_k w_k(x) z_{idx_k(x)},
 * the weights depending only on the geometry, so that kriging any number
 * of value vectors at the same locations costs one multiply-add per
 * weight.  The estimator is nl_kl_point's (analysis/krige_local.h: the
 * nmax nearest data, or all; drift terms as the plan's), written as
 * weights (Cressie 1993, eq. (3.4.60) rearranged):
 *     lambda = C^-1 c0 + C^-1 X (X' C^-1 X)^-1 (x0 - X' C^-1 c0),
 * computed from chol(C) = L, Q = L^-1 X and chol(Q'Q) = M as
 *     lambda = L^-T (v + Q (M M')^-1 u),  v = L^-1 c0,  u = x0 - Q' v;
 * c(x) = m (1 - sum lambda) for simple kriging with the known mean m, else
 * 0 (the weights of a drift reproduce it).  Plans with a radius are not
 * supported (NL_EINVAL). */
#ifndef NL_KRIGE_WEIGHTS_INTERNAL_H
#define NL_KRIGE_WEIGHTS_INTERNAL_H

#include "krige_local.h"

#include <stddef.h>
#include <stdint.h>

/* Weights per location: nl_krige_weights_width(k) of them (the
 * neighbourhood's size, the same for every location), location t's at
 * w[t * width ..] with the data indices idx[t * width ..], and the
 * constant c[t].  The locations are count points x (count * dim
 * coordinates) when x is not NULL, else the cell centres of the grid g
 * from lo (sample i of axis a at lo[a] + (i + 0.5) g->h[a]; count must be
 * g->count).  Locations run in parallel (OpenMP) in fixed chunks; each
 * location's numbers do not depend on the thread count.
 * Errors: as nl_krige_local_eval; NL_EINVAL for a plan with a radius. */
size_t nl_krige_weights_width(const nl_krige_local *k);
int nl_krige_weights(const nl_krige_local *k, size_t count, const double *x, const double *lo, const nl_field *g,
                     uint32_t *idx, double *w, double *c);

#endif
