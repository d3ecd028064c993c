/* Experiment: sparse convolution noise on a plane seen in perspective,
 * point-sampled against band-limited by depth (Lewis GI '86, sec. 3.1).
 *
 * usage: sparse_depth KERNEL RADIUS CELL DENSITY WxH SEED PREFIX
 * The camera stands HC = 20 samples above the plane z = 0 at the origin,
 * looks along +y 6 degrees down, 60 degrees across.  Each pixel's plane point
 * comes from its centre's ray; its footprint is the longer edge of its quad
 * of corner rays on the plane (the depth direction: the footprint of
 * mip-mapping, Williams 1983).  Three pictures of the same noise (seed SEED):
 *   PREFIX-plain.png      the noise at the pixel centre (point sampling);
 *   PREFIX-band.png       the noise with the band-limited kernel chosen by
 *                         footprint (nl_synth_sparse_set_bands, 5 levels);
 *   PREFIX-ref.png        the reference: the mean of S x S point samples over
 *                         the pixel, S = clamp(ceil(footprint / 2), 2, 16)
 *                         (sub-samples at most 2 samples apart on the plane
 *                         up to footprint 32);
 *   PREFIX-level.png      the band level, 0 (black) .. 5 (white).
 * Plane points beyond DMAX = 600 samples (footprint about 60) and the sky
 * are left at the mean, in all pictures, and outside the measures.  On
 * stdout, for the pixels of footprint 8..64: their number, the reference's
 * rms, and the rms differences plain - reference and band - reference, all
 * in units of the noise's standard deviation. */
#include "../core/field.h"
#include "../core/io.h"
#include "../core/nl_error.h"
#include "../synth/sparse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define HC 20.0
#define PITCH (6 * M_PI / 180)
#define FOV (60 * M_PI / 180)
#define DMAX 600.0

typedef struct {
    size_t w, h; /* picture size */
    double f;    /* focal length, pixels */
} camera;

/* The plane point of screen position (u, v) (pixels from the top left):
 * 1 and the point, or 0 for the sky and beyond DMAX. */
static int hit(const camera *c, double u, double v, double *x, double *y)
{
    double sx = u - (double)c->w / 2, sy = (double)c->h / 2 - v;
    double rx = sx, ry = c->f * cos(PITCH) + sy * sin(PITCH), rz = -c->f * sin(PITCH) + sy * cos(PITCH), t;
    if (rz >= 0)
        return 0;
    t = HC / -rz;
    *x = t * rx, *y = t * ry;
    return hypot(*x, *y) <= DMAX;
}

static int save(const char *prefix, const char *name, const camera *c, const double *v, double lo, double hi)
{
    char path[1024];
    size_t n[2] = {c->w, c->h};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL);
    int st;
    if (!f)
        return 1;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = v[i];
    snprintf(path, sizeof path, "%s-%s.png", prefix, name);
    st = nl_png_write_field(path, f, lo, hi);
    nl_field_free(f);
    return st;
}

/* The reference: S x S sub-samples per pixel, averaged. */
static int reference(const nl_synth_sparse_plan *p, uint64_t seed, const camera *c, const double *fp,
                     const int *ok, double *ref)
{
    size_t np = 0, k = 0, npix = c->w * c->h;
    double *xy, *val;
    int st;
    for (size_t i = 0; i < npix; i++)
        if (ok[i]) {
            int S = (int)fmin(16, fmax(2, ceil(fp[i] / 2)));
            np += (size_t)S * (size_t)S;
        }
    xy = malloc(2 * np * sizeof *xy), val = malloc(np * sizeof *val);
    if (!xy || !val) {
        free(xy), free(val);
        return 1;
    }
    for (size_t i = 0; i < npix; i++) {
        int S = (int)fmin(16, fmax(2, ceil(fp[i] / 2)));
        for (int b = 0; ok[i] && b < S; b++)
            for (int a = 0; a < S; a++, k++)
                if (!hit(c, (double)(i % c->w) + (a + 0.5) / S, (double)(i / c->w) + (b + 0.5) / S, &xy[2 * k],
                         &xy[2 * k + 1]))
                    xy[2 * k] = xy[2 * k + 1] = 0; /* a sub-sample past DMAX: the mean's point, rare */
    }
    st = nl_synth_sparse_execute_points(p, seed, np, xy, NULL, val);
    k = 0;
    for (size_t i = 0; !st && i < npix; i++) {
        int S = (int)fmin(16, fmax(2, ceil(fp[i] / 2)));
        double s = 0;
        for (int q = 0; ok[i] && q < S * S; q++)
            s += val[k++];
        ref[i] = ok[i] ? s / (S * S) : 0;
    }
    free(xy), free(val);
    return st;
}

int main(int argc, char **argv)
{
    camera c;
    size_t npix, far = 0;
    int radius, cell, *ok, st;
    double density, *xy, *fp, *plain, *band, *ref, *lev, sd, e_plain = 0, e_band = 0, r_ref = 0;
    unsigned long long seed;
    nl_synth_sparse_plan *p;
    if (argc != 8 || sscanf(argv[5], "%zux%zu", &c.w, &c.h) != 2 || sscanf(argv[6], "%llu", &seed) != 1 ||
        c.w < 16 || c.h < 16 || c.w > 4096 || c.h > 4096) {
        fprintf(stderr, "usage: sparse_depth KERNEL RADIUS CELL DENSITY WxH SEED PREFIX\n");
        return 2;
    }
    radius = atoi(argv[2]), cell = atoi(argv[3]), density = atof(argv[4]);
    c.f = (double)c.w / 2 / tan(FOV / 2);
    if ((st = nl_synth_sparse_plan_expr(argv[1], 2, &(nl_synth_sparse_options){radius, cell, density, 0}, &p)) ||
        (st = nl_synth_sparse_set_bands(p, 5))) {
        fprintf(stderr, "sparse_depth: %s\n", nl_errmsg());
        return 1;
    }
    sd = sqrt(nl_synth_sparse_band_variance(p, 0));
    npix = c.w * c.h;
    ok = calloc(npix, sizeof *ok);
    xy = calloc(2 * npix, sizeof *xy), fp = calloc(npix, sizeof *fp);
    plain = calloc(npix, sizeof *plain), band = calloc(npix, sizeof *band), ref = calloc(npix, sizeof *ref);
    lev = calloc(npix, sizeof *lev);
    if (!ok || !xy || !fp || !plain || !band || !ref || !lev)
        return 1;
    for (size_t i = 0; i < npix; i++) {
        double u = (double)(i % c.w), v = (double)(i / c.w), x0, y0, x1, y1, x2, y2, x3, y3;
        ok[i] = hit(&c, u + 0.5, v + 0.5, &xy[2 * i], &xy[2 * i + 1]) && hit(&c, u, v, &x0, &y0) &&
                hit(&c, u + 1, v, &x1, &y1) && hit(&c, u, v + 1, &x2, &y2) && hit(&c, u + 1, v + 1, &x3, &y3);
        if (ok[i])
            fp[i] = fmax(fmax(hypot(x1 - x0, y1 - y0), hypot(x3 - x2, y3 - y2)),
                         fmax(hypot(x2 - x0, y2 - y0), hypot(x3 - x1, y3 - y1)));
        else
            xy[2 * i] = xy[2 * i + 1] = 0;
        lev[i] = ok[i] ? fmin(5, fmax(0, log2(fmax(fp[i], 1)))) : 5;
    }
    if ((st = nl_synth_sparse_execute_points(p, seed, npix, xy, NULL, plain)) ||
        (st = nl_synth_sparse_execute_points(p, seed, npix, xy, fp, band)) ||
        (st = reference(p, seed, &c, fp, ok, ref))) {
        fprintf(stderr, "sparse_depth: %s\n", nl_errmsg());
        return 1;
    }
    for (size_t i = 0; i < npix; i++) {
        if (!ok[i]) {
            plain[i] = band[i] = ref[i] = 0;
            continue;
        }
        if (fp[i] >= 8 && fp[i] <= 64) {
            far++;
            e_plain += (plain[i] - ref[i]) * (plain[i] - ref[i]);
            e_band += (band[i] - ref[i]) * (band[i] - ref[i]);
            r_ref += ref[i] * ref[i];
        }
    }
    if (save(argv[7], "plain", &c, plain, -3 * sd, 3 * sd) || save(argv[7], "band", &c, band, -3 * sd, 3 * sd) ||
        save(argv[7], "ref", &c, ref, -3 * sd, 3 * sd) || save(argv[7], "level", &c, lev, 0, 5)) {
        fprintf(stderr, "sparse_depth: %s\n", nl_errmsg());
        return 1;
    }
    printf("%zu %.4f %.4f %.4f\n", far, sqrt(r_ref / (double)far) / sd, sqrt(e_plain / (double)far) / sd,
           sqrt(e_band / (double)far) / sd);
    free(ok), free(xy), free(fp), free(plain), free(band), free(ref), free(lev);
    nl_synth_sparse_plan_free(p);
    return 0;
}
