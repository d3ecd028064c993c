/* Solid sparse-convolution noise evaluated at any point of R^3 (the shot
 * noise of Lewis GI '86, eq. 2, in continuous space): the noise Stam and
 * Fiume 1991 ask for in section 4, "each value of the random field can be
 * computed independently", with no grid.
 *
 *     n(p) = c sum_i a_i h(p - p_i),  h(x) = exp(-|x|^2 / (2 s^2)) for |x| < r
 * impulses p_i of a Poisson process of intensity lambda = density / L^3 per
 * unit volume, amplitudes a_i ~ N(0, 1); s = L / 2 for the model
 * gauss:scale=L,var=V, so that the untruncated kernel's autocorrelation is
 * the model's (GI '86, eq. 1: R is lambda times the kernel's autocorrelation):
 *     (h * h)(d) = (pi s^2)^(3/2) exp(-|d|^2 / (4 s^2)) = (pi s^2)^(3/2) exp(-(|d| / L)^2).
 * The kernel is cut at r = 3.5 s = 1.75 L; the energy of h^2 beyond r is
 * NL_SPARSE_POINT_TAIL (a 3D normal of standard deviation s / sqrt(2) beyond
 * 4.95 of them), so by Cauchy-Schwarz the ACF differs from V exp(-(d/L)^2) by
 * at most sqrt(tail) = 4.4e-3 V.  c makes the variance exactly V with the
 * truncated kernel.  Excess kurtosis 3 int h^4 / (lambda (int h^2)^2) =
 * 1.52 / density (untruncated): the noise tends to a Gaussian as the density
 * grows.
 *
 * How the seed maps to the impulses: space is cut into cubes of side w =
 * r / 2; cube (i, j, k) (|i|, |j|, |k| < 2^20) has id ((i + 2^20) << 42 |
 * (j + 2^20) << 21 | (k + 2^20)); its count is nl_rng_poisson(seed,
 * NL_SPARSE_POINT_STREAM, id, 0, lambda w^3), impulse q's position (i + u) w,
 * u = nl_rng_uniform2(seed, NL_SPARSE_POINT_STREAM + 1..3, id, q) per axis,
 * its amplitude nl_rng_gauss2(seed, NL_SPARSE_POINT_STREAM + 4, id, q).  A
 * value sums the cubes that come within r of p in the order of i, then j,
 * then k (k fastest), impulses in order: a pure function of
 * (seed, p), bit-identical whether the cubes come from the plan's cache or
 * are drawn on the fly. */
#ifndef NL_SYNTH_SPARSE_POINT_H
#define NL_SYNTH_SPARSE_POINT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/model.h"

#include <stddef.h>
#include <stdint.h>

#define NL_SPARSE_POINT_STREAM 420u
#define NL_SPARSE_POINT_TAIL 2.0e-5
/* Cube coordinates stay below 2^20 in magnitude: points within 2^20 w of the origin. */
#define NL_SPARSE_POINT_CELLS_MAX (1L << 20)

typedef struct nl_synth_sparse_point nl_synth_sparse_point;

typedef struct {
    double scale;     /* L */
    double variance;  /* V */
    double radius;    /* r = 1.75 L */
    double lambda;    /* impulses per unit volume */
    double kurtosis;  /* predicted excess kurtosis (untruncated kernel) */
    size_t cached;    /* impulses held by the plan's cache */
} nl_synth_sparse_point_stats;

/* Plan the noise of model m (gauss:scale=L[,var=V], isotropic, no nugget)
 * with `density` impulses per volume L^3, seeded by seed; the impulses of
 * the cubes meeting the box [lo, hi] (3 doubles each; lo = hi = NULL: no
 * cache; either NULL: the same) grown by r are drawn once and kept (O(density * box volume / L^3)
 * memory); values elsewhere are drawn on the fly (slower, same bits).
 * *out (NULL on failure) is released by nl_synth_sparse_point_free.
 * Errors: NL_EINVAL for a model that is not an isotropic gauss: without a
 * nugget, a density outside [0.01, 1e4], a box that is not finite, with lo
 * above hi, or beyond NL_SPARSE_POINT_CELLS_MAX cubes of the origin;
 * NL_ETOOBIG when the cache would exceed the memory available
 * (core/field.h) or 1e8 impulses; NL_ENOMEM.  The model is only read
 * during the call (not kept).  Thread-safe. */
int nl_synth_sparse_point_alloc(const nl_model *m, double density, uint64_t seed, const double *lo, const double *hi,
                                nl_synth_sparse_point **out);

/* n at count points x (count * 3 coordinates, x y z) into out (count).
 * Errors: NL_EINVAL for a coordinate that is not finite or beyond
 * NL_SPARSE_POINT_CELLS_MAX - 2 cubes (of side w) of the origin (out is then partly
 * written).  The plan is only read: thread-safe. */
int nl_synth_sparse_point_eval(const nl_synth_sparse_point *p, size_t count, const double *x, double *out);

void nl_synth_sparse_point_info(const nl_synth_sparse_point *p, nl_synth_sparse_point_stats *info);

/* NULL is a no-op. */
void nl_synth_sparse_point_free(nl_synth_sparse_point *p);

#ifdef __cplusplus
}
#endif

#endif
