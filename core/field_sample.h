/* A field's values at arbitrary points: nearest-sample or multilinear
 * (bilinear in 2D, trilinear in 3D) interpolation between its samples.
 *
 * Coordinates.  Sample i of axis a sits at x0[a] + i h[a] (x0: the caller's
 * coordinate of sample 0, e.g. (origin) h for a window of a synthesised
 * field, or a + h/2 for a grid of cell centres on [a, b]).  A point's index
 * position is u[a] = (x[a] - x0[a]) / h[a].
 *
 * Every function here is thread-safe and allocates nothing. */
#ifndef NL_FIELD_SAMPLE_H
#define NL_FIELD_SAMPLE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"

#include <stddef.h>
#include <stdint.h>

enum {
    NL_INTERP_NEAREST = 0, /* the value of the nearest sample (ties round half up) */
    NL_INTERP_LINEAR = 1   /* multilinear in the 2^dim samples around the point */
};

#define NL_STENCIL_MAX 8 /* samples in a 3D multilinear stencil */

/* The samples and weights giving f's interpolated value at index position
 * u (f->dim entries): idx[0..k-1] (flat indices into f->data) and w[0..k-1]
 * (non-negative, summing to 1), k returned (1 .. 2^dim; arrays of
 * NL_STENCIL_MAX).  u is clamped to [0, n[a] - 1] on each axis first (a
 * point beyond the last sample takes the edge's value).  The value is
 * sum_j w[j] f->data[idx[j]].  u must be finite; interp not one of
 * NL_INTERP_* is taken as NL_INTERP_LINEAR. */
size_t nl_field_stencil(const nl_field *f, const double *u, int interp, size_t *idx, double *w);

/* vals[i] = f interpolated at point i of pts (n points of f->dim
 * coordinates each, row-major).  Points must lie within the samples' hull,
 * x0[a] <= x[a] <= x0[a] + (n[a] - 1) h[a] (to 1e-9 of a spacing).
 * Errors (nothing is guaranteed in vals then): NL_EINVAL for interp not one
 * of NL_INTERP_*, x0 not finite, or a point with a coordinate not finite or
 * outside the hull (the message names the first: its row, counting from 1,
 * and coordinates). */
int nl_field_sample(const nl_field *f, const double *x0, int interp, size_t n, const double *pts, double *vals);

/* n points drawn uniformly in the samples' hull (see nl_field_sample) into
 * pts (n * f->dim coordinates): coordinate a of point i is
 * x0[a] + U (n[a] - 1) h[a] with U = nl_rng_uniform(seed, NL_STREAM_POINTS,
 * i dim + a) (core/rng.h).  Pure function of its arguments. */
#define NL_STREAM_POINTS 0x504f4e54u
void nl_field_random_points(const nl_field *f, const double *x0, uint64_t seed, size_t n, double *pts);

#ifdef __cplusplus
}
#endif

#endif
