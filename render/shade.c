/* Lambert relief, resampling and grey ranges for pictures of fields. */
#include "shade.h"
#include "../analysis/hist.h"
#include "../core/nl_error.h"

#include <math.h>

/* n . l times |n| (n unnormalised) for gradient (gx, gy) */
static double facing(double gx, double gy, const double *l) { return -gx * l[0] - gy * l[1] + l[2]; }

int nl_render_relief(const nl_field *x, double az, double el, double zscale, nl_field *out)
{
    if (x->dim != 2 || out->dim != 2 || x->n[0] != out->n[0] || x->n[1] != out->n[1])
        return NL_ERROR(NL_EINVAL, "relief: expected a 2D field and an output of the same size");
    if (!(zscale > 0) || !isfinite(zscale) || !(el > 0 && el <= 90) || !isfinite(az))
        return NL_ERROR(NL_EINVAL, "relief: expected zscale > 0, a finite azimuth and 0 < elevation <= 90, got "
                        "%g, %g, %g", zscale, az, el);
    size_t nx = x->n[0], ny = x->n[1];
    double l[3] = {cos(el * M_PI / 180) * cos(az * M_PI / 180), cos(el * M_PI / 180) * sin(az * M_PI / 180),
                   sin(el * M_PI / 180)};
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            size_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i, j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
            double gx = zscale * (x->data[j * nx + i1] - x->data[j * nx + i0]) / ((double)(i1 - i0) * x->h[0]);
            double gy = zscale * (x->data[j1 * nx + i] - x->data[j0 * nx + i]) / ((double)(j1 - j0) * x->h[1]);
            double n = sqrt(gx * gx + gy * gy + 1);
            if (!isfinite(n))
                return NL_ERROR(NL_EINVAL, "relief: zscale: %g makes the slope at (%zu, %zu) %s; expected heights "
                                "whose slopes stay finite", zscale, i, j, isnan(n) ? "not a number" : "overflow");
            out->data[j * nx + i] = fmax(0, facing(gx, gy, l) / n);
        }
    return NL_OK;
}

void nl_render_shade_gradients(size_t count, const double *gx, const double *gy, const double light[3],
                               double ambient, double *out)
{
    double ln = sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
    for (size_t q = 0; q < count; q++) {
        double n = sqrt(gx[q] * gx[q] + gy[q] * gy[q] + 1);
        out[q] = ambient + (1 - ambient) * fmax(0, facing(gx[q], gy[q], light) / (n * ln));
    }
}

void nl_render_nearest(size_t M, const double *src, size_t W, double *dst)
{
    for (size_t y = 0; y < W; y++)
        for (size_t x = 0; x < W; x++)
            dst[y * W + x] = src[(y * M / W) * M + x * M / W];
}

int nl_render_grey_range(const nl_field *x, double *lo, double *hi)
{
    nl_moments m;
    int st = nl_moments_compute(x, &m);
    if (st)
        return st;
    *lo = m.mean - 3 * sqrt(m.variance), *hi = m.mean + 3 * sqrt(m.variance);
    if (!(*hi > *lo))
        *hi = *lo + 1;
    if (!isfinite(*lo) || !isfinite(*hi) || !isfinite(*hi - *lo))
        return NL_ERROR(NL_EINVAL, "grey range: mean %g +- 3 sd %g is not finite; expected finite values (or give "
                        "--range)", m.mean, sqrt(m.variance));
    return NL_OK;
}
