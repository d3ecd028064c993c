/* A field's values at arbitrary points (nearest sample or multilinear). */
#include "field_sample.h"
#include "nl_error.h"
#include "rng.h"

#include <math.h>
#include <stdio.h>

/* Along one axis of m samples: the lower sample i0 and the weight t of the
 * upper one (t = 0 and i0 the nearest with nearest interpolation). */
static void axis_pos(double u, size_t m, int interp, size_t *i0, double *t)
{
    double top = (double)(m - 1);
    u = u < 0 ? 0 : u > top ? top : u;
    if (interp == NL_INTERP_NEAREST || m == 1) {
        double r = floor(u + 0.5);
        *i0 = (size_t)(r > top ? top : r), *t = 0;
        return;
    }
    double f = floor(u);
    if (f >= top) /* the last sample: the segment below it, at its end */
        f = top - 1;
    *i0 = (size_t)f, *t = u - f;
}

size_t nl_field_stencil(const nl_field *f, const double *u, int interp, size_t *idx, double *w)
{
    size_t i0[3] = {0, 0, 0}, k = 0;
    double t[3] = {0, 0, 0};
    for (int a = 0; a < f->dim; a++)
        axis_pos(u[a], f->n[a], interp, &i0[a], &t[a]);
    /* corner c: bit a set takes the upper sample of axis a; weightless corners are skipped */
    for (unsigned c = 0; c < (1u << f->dim); c++) {
        double wc = 1;
        size_t j[3] = {i0[0], i0[1], i0[2]};
        for (int a = 0; a < f->dim; a++) {
            int up = (c >> a) & 1;
            wc *= up ? t[a] : 1 - t[a];
            j[a] += (size_t)up;
        }
        if (wc == 0)
            continue;
        idx[k] = (j[2] * f->n[1] + j[1]) * f->n[0] + j[0];
        w[k++] = wc;
    }
    return k;
}

/* The message for point i (coordinates x) outside the hull on axis a. */
static int outside(const nl_field *f, const double *x0, size_t i, const double *x, int a)
{
    char c[96];
    int k = 0;
    for (int b = 0; b < f->dim; b++)
        k += snprintf(c + k, sizeof c - (size_t)k, "%s%.10g", b ? ", " : "", x[b]);
    return NL_ERROR(NL_EINVAL, "point %zu (%s) lies outside the field, whose samples span %.10g to %.10g on axis %d",
                    i + 1, c, x0[a], x0[a] + (double)(f->n[a] - 1) * f->h[a], a + 1);
}

int nl_field_sample(const nl_field *f, const double *x0, int interp, size_t n, const double *pts, double *vals)
{
    int d = f->dim;
    if (interp != NL_INTERP_NEAREST && interp != NL_INTERP_LINEAR)
        return NL_ERROR(NL_EINVAL, "interpolation %d: expected nearest (%d) or linear (%d)", interp,
                        NL_INTERP_NEAREST, NL_INTERP_LINEAR);
    for (int a = 0; a < d; a++)
        if (!isfinite(x0[a]))
            return NL_ERROR(NL_EINVAL, "the field's first sample: expected finite coordinates, got %g on axis %d",
                            x0[a], a + 1);
    for (size_t i = 0; i < n; i++) {
        const double *x = pts + i * (size_t)d;
        double u[3];
        size_t idx[NL_STENCIL_MAX];
        double w[NL_STENCIL_MAX], v = 0;
        for (int a = 0; a < d; a++) {
            u[a] = (x[a] - x0[a]) / f->h[a];
            if (!isfinite(x[a]))
                return NL_ERROR(NL_EINVAL, "point %zu: expected finite coordinates, got a non-finite one on axis %d",
                                i + 1, a + 1);
            if (!(u[a] >= -1e-9 && u[a] <= (double)(f->n[a] - 1) + 1e-9))
                return outside(f, x0, i, x, a);
        }
        size_t k = nl_field_stencil(f, u, interp, idx, w);
        for (size_t j = 0; j < k; j++)
            v += w[j] * f->data[idx[j]];
        vals[i] = v;
    }
    return NL_OK;
}

void nl_field_random_points(const nl_field *f, const double *x0, uint64_t seed, size_t n, double *pts)
{
    size_t d = (size_t)f->dim;
    for (size_t i = 0; i < n; i++)
        for (size_t a = 0; a < d; a++)
            pts[i * d + a] = x0[a] + nl_rng_uniform(seed, NL_STREAM_POINTS, i * d + a) * (double)(f->n[a] - 1) *
                                         f->h[a];
}
