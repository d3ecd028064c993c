/* Miller's square-square subdivision (G. S. P. Miller, "The definition and
 * rendering of terrain maps", SIGGRAPH '86), the "higher quality
 * interpolant" Lewis 1987 ("Comparison of Stochastic Synthesis Methods")
 * credits with alleviating the creases of midpoint displacement.
 *
 * Each level replaces a periodic grid of spacing s by one of spacing s/2:
 * every parent square (corners P00, P10, P01, P11) gives four new points,
 * at a quarter of the diagonal from each corner, each the weighted mean of
 * the four corners, 9/16 for the nearest, 3/16 for the two beside it and
 * 1/16 for the opposite one (the refinement mask of the biquadratic
 * B-spline; in 1D, Chaikin's 3/4, 1/4), plus an independent Gaussian
 * displacement.  The old points are not kept: the scheme approximates
 * rather than interpolates, and its noise-free limit is a C1 biquadratic
 * spline instead of the bilinear surface with slope breaks along the grid
 * lines that midpoint displacement leaves.  New point 2i + a (a = 0, 1) of
 * the level lies in parent cell i at a quarter (a = 0) or three quarters
 * (a = 1) of it; in 2D the product of the two axes.
 *
 * Variances (the convention of midpoint displacement in synth/subdiv.h):
 * for fBm with variogram gamma(h) = sigma2 |h|^(2H) / 2, the displacement
 * of level k has the variance of the interpolant's error,
 *     v_k = 2 sum_i a_i gamma(t - p_i) - sum_i sum_q a_i a_q gamma(p_i - p_q),
 * (a_i the mask, p_i the corners, t the new point, at spacing s_k =
 * s_0 / 2^k), times an extra vscale^k (Haruyama-Barsky-style altered
 * variances); the coarse values are independent with variance
 * sigma2 s_0^(2H) / 2.  v_k falls by 2^(-2H) per level.
 *
 * Random numbers: coarse value i (2D: (i, j)) is
 * nl_rng_gauss(seed, NL_MILLER_STREAM, j 2^32 + i); the displacement of
 * point (i, j) of level k (from 0) is
 * nl_rng_gauss(seed, NL_MILLER_STREAM + 1 + k, j 2^32 + i). */
#ifndef NL_SYNTH_MIDPOINT_H
#define NL_SYNTH_MIDPOINT_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stdint.h>

#define NL_MILLER_STREAM 820u
#define NL_MILLER_MAX_LEVELS 30

/* The mask of new point (a, b) = (0, 0) of a parent square, over the
 * corners in the order P00, P10, P01, P11 (2D: 9/16, 3/16, 3/16, 1/16) or
 * P0, P1 (1D: 3/4, 1/4); the other new points take it mirrored.  w holds 4
 * doubles (dim 2) or 2 (dim 1); dim is 1 or 2 (other values: w untouched).
 * Pure; thread-safe. */
void nl_synth_midpoint_miller_mask(int dim, double *w);

/* The coarse variance (*r0) and the displacement variances v[0..levels-1]
 * of fBm (0 < H < 1, sigma2 > 0, vscale > 0) refined from coarse spacing
 * spacing0 > 0 (module comment).  NL_EINVAL for arguments out of range or a
 * variance that is not finite.  Pure; thread-safe. */
int nl_synth_midpoint_miller_variances(int dim, int levels, double spacing0, double H, double sigma2, double vscale,
                                       double *r0, double *v);

/* One level: in (n[0] x n[1] samples, n[1] = 1 in 1D, periodic) to out
 * (2 n[0] x 2 n[1] in 2D, 2 n[0] in 1D), each new point the mask applied
 * to its parent square plus sd times its Gaussian of level `level` (sd = 0:
 * the interpolant alone).  Arrays row-major, x fastest; in and out must
 * not overlap.  Pure; thread-safe. */
void nl_synth_midpoint_miller_refine(int dim, const size_t *n, const double *in, double sd, uint64_t seed, int level,
                                     double *out);

/* The default levels for n[0..dim-1] samples: the most that leave a coarse
 * grid of 2 samples per axis (0 when none does).  Pure; thread-safe. */
int nl_synth_midpoint_miller_default_levels(int dim, const size_t *n);

/* Square-square synthesis of fBm into out (1D or 2D, unit spacing in
 * samples; out->h is not read): levels L (0: the most that leave a coarse
 * grid of 2 samples per axis) with each out->n[a] a multiple of 2^L of at
 * least 2 coarse samples.  Errors: NL_EINVAL (out 3D, sizes, levels outside
 * 0..NL_MILLER_MAX_LEVELS, and those of nl_synth_midpoint_miller_variances),
 * NL_ETOOBIG (the scratch grid exceeds the memory available), NL_ENOMEM.
 * Pure in its arguments (bit-identical for equal ones); thread-safe. */
int nl_synth_midpoint_miller(int levels, double H, double sigma2, double vscale, uint64_t seed, nl_field *out);

/* What the midpoint method's plan holds (nl_method_plan_impl of a
 * "midpoint" plan, synth/method.h; owned by that plan). */
typedef struct {
    double H;                   /* the Hurst exponent: given, or from a power:d=D model */
    int levels;                 /* levels of refinement (the default resolved) */
    int miller;                 /* 1: Miller's square-square interpolant; 0: Fournier's midpoints */
    double vscale;              /* the variance-scale factor per level */
    struct nl_subdiv_plan *plan;/* Fournier: the subdivision plan; Miller: NULL */
} nl_midpoint_method_plan;

#ifdef __cplusplus
}
#endif

#endif
