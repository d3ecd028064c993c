/* Shaded relief of height fields (Lambert's cosine law) and the small
 * image operations the pictures around it need.
 *
 * A height field z(x, y) with gradient (gx, gy) has the upward normal
 * (-gx, -gy, 1) / sqrt(gx^2 + gy^2 + 1); lit from the direction l, a
 * Lambertian surface returns max(0, n . l / |l|).  No shadows are cast. */
#ifndef NL_RENDER_SHADE_H
#define NL_RENDER_SHADE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>

/* Relief of the 2D field x into out (a 2D field of the same n, caller's):
 * light from azimuth az (degrees from +x toward +y) and elevation el
 * (degrees above the horizon); heights times zscale in units of the grid
 * spacing x->h.  Gradients by central differences, one-sided at the edges.
 * Values in [0, 1].
 * Errors: NL_EINVAL for x or out not 2D, sizes that differ, zscale not
 * positive and finite, or el outside (0, 90], or a slope that overflows
 * (zscale times a height difference); out is then partly written.
 * Thread-safe. */
int nl_render_relief(const nl_field *x, double az, double el, double zscale, nl_field *out);

/* Relief from given gradients: out[q] = ambient + (1 - ambient)
 * max(0, n_q . l / |l|) for q < count, with n_q the normal of gradient
 * (gx[q], gy[q]); light l (3 values, need not be unit, not zero).
 * Thread-safe. */
void nl_render_shade_gradients(size_t count, const double *gx, const double *gy, const double light[3],
                               double ambient, double *out);

/* Nearest-sample resampling of an M x M image (row-major) onto W x W:
 * dst[y W + x] = src[(y M / W) M + x M / W] (integer division).  Thread-safe. */
void nl_render_nearest(size_t M, const double *src, size_t W, double *dst);

/* The default grey range of a field: mean -+ 3 standard deviations (hi =
 * lo + 1 when that is empty).  Errors: those of nl_moments_compute, NL_EINVAL
 * when the range is not finite
 * (analysis/hist.h).  Thread-safe. */
int nl_render_grey_range(const nl_field *x, double *lo, double *hi);

#ifdef __cplusplus
}
#endif

#endif
