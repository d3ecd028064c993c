/* A spatial index over points in 1 to 3 dimensions: a balanced k-d tree
 * (Bentley 1975; Friedman, Bentley and Finkel 1977) with buckets of at most
 * NL_SPINDEX_LEAF points, split at the median of the axis of largest spread.
 *
 * Plan/execute: nl_spindex_alloc builds the tree once (O(n log n) time,
 * O(n) memory: a copy of the coordinates in tree order, a permutation and
 * about n / 4 nodes); the queries are read-only and may run concurrently on
 * one index.  Distances are Euclidean, in the units of the coordinates;
 * queries return squared distances to spare the square roots. */
#ifndef NL_SPINDEX_H
#define NL_SPINDEX_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

#define NL_SPINDEX_LEAF 8

typedef struct nl_spindex nl_spindex;

/* Index n >= 1 points of dim (1..3) coordinates (pts: n * dim, point i at
 * pts[i * dim]; copied).  *out (NULL on failure) is released by
 * nl_spindex_free.  Errors: NL_EINVAL for dim outside 1..3, n = 0 or a
 * coordinate that is not finite (the message names the point);
 * NL_ETOOBIG when the index exceeds the memory available (core/field.h);
 * NL_ENOMEM.  Thread-safe. */
int nl_spindex_alloc(int dim, size_t n, const double *pts, nl_spindex **out);

/* Release the index (NULL is a no-op). */
void nl_spindex_free(nl_spindex *s);

/* Points and dimension indexed. */
size_t nl_spindex_size(const nl_spindex *s);
int nl_spindex_dim(const nl_spindex *s);

/* The k nearest points to x (dim coordinates): min(k, n) indices (into the
 * caller's original order) in idx and their squared distances in d2, in
 * increasing distance, ties broken by the lower index.  Returns the number
 * found.  idx and d2 hold k entries.  No allocation; never fails. */
size_t nl_spindex_knn(const nl_spindex *s, const double *x, size_t k, size_t *idx, double *d2);

/* The points within distance r of x (|x - p| <= r): up to cap indices in
 * idx (ascending distance, ties by index) and squared distances in d2 (may
 * be NULL).  Returns the number of points within r, which may exceed cap
 * (then only the nearest cap are stored). No allocation; never fails. */
size_t nl_spindex_within(const nl_spindex *s, const double *x, double r, size_t cap, size_t *idx, double *d2);

/* Call fn(ctx, i, j, d2) once for every pair i < j (original indices) with
 * squared distance d2 < cutoff^2, in no particular order; memory O(1)
 * beyond the index, time O(n log n + pairs).  Stops at the first non-zero
 * return of fn and returns it; 0 when every pair was visited (NL_EFAIL
 * if the tree were deeper than 64 levels, which a balanced tree of size_t
 * points is not). */
typedef int (*nl_spindex_pair_fn)(void *ctx, size_t i, size_t j, double d2);
int nl_spindex_pairs(const nl_spindex *s, double cutoff, nl_spindex_pair_fn fn, void *ctx);

/* The share of nl_spindex_pairs that belongs to position a (0 <= a < n, in
 * the index's own order): the pairs of that point with the points after it
 * in that order.  Calling it for every a visits every pair once; distinct a
 * may run concurrently (to split the work among threads). */
int nl_spindex_pairs_at(const nl_spindex *s, size_t a, double cutoff, nl_spindex_pair_fn fn, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
