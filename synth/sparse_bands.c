/* Sparse convolution: band-limited kernels chosen by footprint, and the
 * field at arbitrary points (Lewis GI '86, sec. 3.1, anti-aliasing by depth). */
#include "sparse.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "sparse_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void nl_sparse_bands_clear(nl_synth_sparse_plan *p)
{
    for (int l = 1; l <= p->nbands; l++) {
        free(p->band[l]);
        p->band[l] = NULL;
    }
    p->nbands = 0;
}

static int sigma_taps(int l) { return 4 << (l - 1); } /* 4 sigma_l, sigma_l = 2^(l-1) */

/* h (half-width R) convolved with the separable Gaussian of level l into
 * out (half-width R + 4 sigma_l); tmp holds (2R + 1) rows of that width. */
static void blur(const double *h, int R, int l, double *g, double *tmp, double *out)
{
    int G = sigma_taps(l), Rl = R + G, w = 2 * R + 1, wl = 2 * Rl + 1;
    double sigma = ldexp(1, l - 1), sum = 0;
    for (int q = -G; q <= G; q++)
        sum += g[q + G] = exp(-0.5 * q * q / (sigma * sigma));
    for (int q = -G; q <= G; q++)
        g[q + G] /= sum;
    for (int j = 0; j < w; j++) /* along x: rows of h */
        for (int i = -Rl; i <= Rl; i++) {
            double s = 0;
            for (int q = -G; q <= G; q++)
                if (i - q >= -R && i - q <= R)
                    s += g[q + G] * h[(size_t)j * w + (size_t)(i - q + R)];
            tmp[(size_t)j * wl + (size_t)(i + Rl)] = s;
        }
    for (int j = -Rl; j <= Rl; j++) /* along y */
        for (int i = 0; i < wl; i++) {
            double s = 0;
            for (int q = -G; q <= G; q++)
                if (j - q >= -R && j - q <= R)
                    s += g[q + G] * tmp[(size_t)(j - q + R) * wl + (size_t)i];
            out[(size_t)(j + Rl) * wl + (size_t)i] = s;
        }
}

int nl_synth_sparse_set_bands(nl_synth_sparse_plan *p, int levels)
{
    size_t cells = 0, rows;
    double *g, *tmp;
    int st;
    if (p->dim != 2)
        return NL_ERROR(NL_EINVAL, "bands: band-limited kernels need a 2D plan, got %dD", p->dim);
    if (levels < 0 || levels > NL_SPARSE_BANDS_MAX)
        return NL_ERROR(NL_EINVAL, "bands: expected 0 to %d levels, got %d", NL_SPARSE_BANDS_MAX, levels);
    nl_sparse_bands_clear(p);
    for (int l = 1; l <= levels; l++) {
        size_t wl = 2 * (size_t)(p->radius + sigma_taps(l)) + 1;
        cells += wl * wl;
    }
    rows = (2 * (size_t)p->radius + 1) * (2 * (size_t)(p->radius + sigma_taps(levels > 0 ? levels : 1)) + 1);
    {
        size_t need = cells + rows;
        if ((st = nl_size_check(1, &need, sizeof(double), 1, NULL)))
            return st;
    }
    g = malloc((size_t)(2 * sigma_taps(NL_SPARSE_BANDS_MAX) + 1) * sizeof *g);
    tmp = malloc(rows * sizeof *tmp);
    for (int l = 1; l <= levels && g && tmp; l++) {
        size_t wl = 2 * (size_t)(p->radius + sigma_taps(l)) + 1;
        if (!(p->band[l] = malloc(wl * wl * sizeof(double))))
            break;
        p->band_radius[l] = p->radius + sigma_taps(l);
        blur(p->h, p->radius, l, g, tmp, p->band[l]);
        p->nbands = l;
    }
    free(g), free(tmp);
    if (p->nbands != levels) {
        nl_sparse_bands_clear(p);
        return NL_ERROR(NL_ENOMEM, "out of memory for %d band-limited kernels", levels);
    }
    return NL_OK;
}

double nl_synth_sparse_band_variance(const nl_synth_sparse_plan *p, int level)
{
    double s2 = 0;
    size_t wl;
    if (level == 0)
        return p->info.variance;
    if (level < 0 || level > p->nbands)
        return NAN;
    wl = 2 * (size_t)p->band_radius[level] + 1;
    for (size_t i = 0; i < wl * wl; i++)
        s2 += p->band[level][i] * p->band[level][i];
    return p->density / ((double)p->cell * p->cell) * s2;
}

/* The level pair and weight of a footprint: value = (1 - t) x_l0 + t x_l0+1. */
static int level_of(const nl_synth_sparse_plan *p, const double *footprint, size_t i, double *t)
{
    double lam = footprint && footprint[i] > 1 ? fmin(log2(footprint[i]), p->nbands) : 0;
    int l0 = (int)floor(lam);
    if (l0 >= p->nbands)
        l0 = p->nbands, lam = l0;
    *t = lam - l0;
    return l0;
}

static long reach_of(const nl_synth_sparse_plan *p, int l)
{
    int R = l ? p->band_radius[l] : p->radius;
    return p->angle ? (long)ceil(R * M_SQRT2) + 1 : R;
}

/* Checks the points and footprints; their bounding box in *box (x0, x1, y0, y1). */
static int check_points(const nl_synth_sparse_plan *p, size_t n, const double *xy, const double *footprint,
                        double *box)
{
    const double lim = (double)NL_SPARSE_ORIGIN_MAX;
    box[0] = box[2] = INFINITY, box[1] = box[3] = -INFINITY;
    if (p->dim != 2)
        return NL_ERROR(NL_EINVAL, "sparse: evaluation at points needs a 2D plan, got %dD", p->dim);
    for (size_t i = 0; i < n; i++) {
        double x = xy[2 * i], y = xy[2 * i + 1];
        if (!(fabs(x) <= lim) || !(fabs(y) <= lim))
            return NL_ERROR(NL_EINVAL, "points: point %zu (%g, %g) is not finite or beyond +-%ld samples", i, x, y,
                            NL_SPARSE_ORIGIN_MAX);
        if (footprint && !(footprint[i] >= 0 && isfinite(footprint[i])))
            return NL_ERROR(NL_EINVAL, "footprint: point %zu: expected a finite value >= 0, got %g", i, footprint[i]);
        box[0] = fmin(box[0], x), box[1] = fmax(box[1], x);
        box[2] = fmin(box[2], y), box[3] = fmax(box[3], y);
    }
    return NL_OK;
}

/* The field at one point from tables l0 (and l0 + 1 with weight t). */
static double point_value(const nl_synth_sparse_plan *p, const nl_sparse_impulses *im, double x, double y, int l0,
                          double t)
{
    const long C = p->cell, reach = reach_of(p, t > 0 ? l0 + 1 : l0);
    const double *h0 = l0 ? p->band[l0] : p->h, *h1 = t > 0 ? p->band[l0 + 1] : NULL;
    const int R0 = l0 ? p->band_radius[l0] : p->radius, R1 = t > 0 ? p->band_radius[l0 + 1] : 0;
    long a0 = nl_sparse_floordiv((long)floor(x) - reach, C), a1 = nl_sparse_floordiv((long)ceil(x) + reach, C);
    long b0 = nl_sparse_floordiv((long)floor(y) - reach, C), b1 = nl_sparse_floordiv((long)ceil(y) + reach, C);
    double s0 = 0, s1 = 0;
    for (long b = b0; b <= b1; b++)
        for (long a = a0; a <= a1; a++) {
            size_t c = (size_t)((b - im->cy0) * im->ncx + (a - im->cx0));
            for (size_t k = im->start[c]; k < im->start[c + 1]; k++) {
                double dx = x - (double)im->px[k], dy = y - (double)im->py[k], u = dx, v = dy;
                if (p->angle)
                    u = im->c[k] * dx + im->s[k] * dy, v = -im->s[k] * dx + im->c[k] * dy;
                s0 += im->a[k] * nl_sparse_table_at(h0, R0, u, v);
                if (h1)
                    s1 += im->a[k] * nl_sparse_table_at(h1, R1, u, v);
            }
        }
    return h1 ? (1 - t) * s0 + t * s1 : s0;
}

int nl_synth_sparse_execute_points(const nl_synth_sparse_plan *p, uint64_t seed, size_t n, const double *xy,
                                   const double *footprint, double *out)
{
    double box[4], t, cells, per, work;
    long reach = 0, C = p->cell;
    nl_sparse_impulses im;
    int st, top = 0;
    if ((st = check_points(p, n, xy, footprint, box)) || n == 0)
        return st;
    for (size_t i = 0; i < n; i++) {
        int l = level_of(p, footprint, i, &t);
        top = l + (t > 0) > top ? l + (t > 0) : top;
    }
    reach = reach_of(p, top);
    cells = ((box[1] - box[0] + 2.0 * reach) / C + 3) * ((box[3] - box[2] + 2.0 * reach) / C + 3);
    per = 2.0 * reach / C + 3;
    work = cells * p->density + (double)n * per * per * (p->density + 1);
    if (work > NL_SPARSE_WORK_MAX)
        return NL_ERROR(NL_ETOOBIG, "sparse: about %.2g impulse evaluations for %zu points (box %gx%g samples, reach "
                        "%ld), above %.0e; expected fewer or closer points", work, n, box[1] - box[0],
                        box[3] - box[2], reach, NL_SPARSE_WORK_MAX);
    if ((st = nl_sparse_impulses_make(p, seed, nl_sparse_floordiv((long)floor(box[0]) - reach, C),
                                      nl_sparse_floordiv((long)ceil(box[1]) + reach, C),
                                      nl_sparse_floordiv((long)floor(box[2]) - reach, C),
                                      nl_sparse_floordiv((long)ceil(box[3]) + reach, C), &im)))
        return st;
#pragma omp parallel for schedule(dynamic, 256) if (n > 16384)
    for (size_t i = 0; i < n; i++) {
        double w;
        int l = level_of(p, footprint, i, &w);
        out[i] = point_value(p, &im, xy[2 * i], xy[2 * i + 1], l, w);
    }
    nl_sparse_impulses_free(&im);
    for (size_t i = 0; p->info.mean != 0 && i < n; i++)
        out[i] += p->info.mean;
    return NL_OK;
}
