/* A height field in perspective: column ray marching with sun, shadows,
 * haze and sky (see terrain.h). */
#include "terrain.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { SS = 2, SHADOW_REACH = 256 };

static const double sky_horizon[3] = {0.80, 0.84, 0.88}, sky_zenith[3] = {0.33, 0.50, 0.76};
static const double water_rgb[3] = {0.10, 0.22, 0.33};

typedef struct {
    const nl_field *f;
    const nl_render_view *v;
    double *rgb;          /* lit colour per sample */
    double hmin, hmax;    /* heights after zscale */
} scene;

static double rad(double deg) { return deg * M_PI / 180; }

static void mix(double *c, const double *a, double t)
{
    for (int k = 0; k < 3; k++)
        c[k] += (a[k] - c[k]) * t;
}

/* Sample index along an axis of n, or -1 outside when not tiled. */
static long wrap(long i, long n, int tile)
{
    if (tile)
        return ((i % n) + n) % n;
    return i < 0 || i >= n ? -1 : i;
}

/* The cell of an nx x ny grid around (x, y) for bilinear interpolation:
 * its corners' sample indices q (x0y0, x1y0, x0y1, x1y1) and the weights
 * ax, ay; 0 when (x, y) is outside an untiled grid. */
typedef struct {
    size_t q[4];
    double ax, ay;
} cell;

static int cell_at(long nx, long ny, int tile, double x, double y, cell *c)
{
    double fx = floor(x), fy = floor(y);
    long i0 = wrap((long)fx, nx, tile), i1 = wrap((long)fx + 1, nx, tile);
    long j0 = wrap((long)fy, ny, tile), j1 = wrap((long)fy + 1, ny, tile);
    if (i0 < 0 || i1 < 0 || j0 < 0 || j1 < 0)
        return 0;
    c->q[0] = (size_t)(j0 * nx + i0), c->q[1] = (size_t)(j0 * nx + i1);
    c->q[2] = (size_t)(j1 * nx + i0), c->q[3] = (size_t)(j1 * nx + i1);
    c->ax = x - fx, c->ay = y - fy;
    return 1;
}

/* Bilinear value of d (stride values a sample) over cell c. */
static double lerp2(const double *d, size_t stride, const cell *c)
{
    return (1 - c->ay) * ((1 - c->ax) * d[stride * c->q[0]] + c->ax * d[stride * c->q[1]]) +
           c->ay * ((1 - c->ax) * d[stride * c->q[2]] + c->ax * d[stride * c->q[3]]);
}

/* Bilinear height (zscale applied) at (x, y); NAN outside an untiled field. */
static double height(const scene *s, double x, double y)
{
    cell c;
    if (!cell_at((long)s->f->n[0], (long)s->f->n[1], s->v->tile, x, y, &c))
        return NAN;
    return s->v->zscale * lerp2(s->f->data, 1, &c);
}

/* Ground colour by normalised height u and slope (rise per sample). */
static void ground(int palette, double u, double slope, double *c)
{
    static const double land[][4] = {{0.00, 0.20, 0.30, 0.14}, {0.35, 0.34, 0.45, 0.18}, {0.60, 0.47, 0.44, 0.27},
                                     {0.80, 0.52, 0.48, 0.43}, {0.88, 0.93, 0.93, 0.95}, {1.00, 0.97, 0.97, 0.99}};
    static const double sea[][4] = {{0.00, 0.04, 0.14, 0.28}, {0.60, 0.13, 0.33, 0.50}, {1.00, 0.62, 0.76, 0.86}};
    static const double rock[3] = {0.45, 0.41, 0.37};
    const double(*p)[4] = palette == NL_RENDER_SEA ? sea : land;
    int n = palette == NL_RENDER_SEA ? 3 : 6, k = 0;
    u = fmin(1, fmax(0, u));
    while (k + 2 < n && u > p[k + 1][0])
        k++;
    double t = (u - p[k][0]) / (p[k + 1][0] - p[k][0]);
    for (int q = 0; q < 3; q++)
        c[q] = p[k][q + 1] + t * (p[k + 1][q + 1] - p[k][q + 1]);
    if (palette == NL_RENDER_LAND) {
        double r = fmin(1, fmax(0, (slope - 1.0) / 0.8));
        mix(c, rock, r * r * (3 - 2 * r));
    }
}

/* Lit colour of every sample: ambient + Lambert toward the sun, zero where
 * the terrain toward the sun rises above the sun's ray. */
static void light(scene *s)
{
    const nl_render_view *v = s->v;
    long nx = (long)s->f->n[0], ny = (long)s->f->n[1];
    double L[3] = {cos(rad(v->sun[1])) * cos(rad(v->sun[0])), cos(rad(v->sun[1])) * sin(rad(v->sun[0])),
                   sin(rad(v->sun[1]))};
    double rise = tan(rad(v->sun[1])), hor = hypot(L[0], L[1]), span = s->hmax - s->hmin;
#pragma omp parallel for schedule(dynamic, 8)
    for (long j = 0; j < ny; j++)
        for (long i = 0; i < nx; i++) {
            double gx, gy, h = height(s, (double)i, (double)j), c[3], lit, slope;
            int shadow = 0;
            gx = (height(s, (double)wrap(i + 1, nx, 1), (double)j) - height(s, (double)wrap(i - 1, nx, 1), (double)j)) / 2;
            gy = (height(s, (double)i, (double)wrap(j + 1, ny, 1)) - height(s, (double)i, (double)wrap(j - 1, ny, 1))) / 2;
            if (!v->tile) { /* one-sided at the edges */
                if (i == 0 || i == nx - 1)
                    gx = i == 0 ? height(s, 1, (double)j) - h : h - height(s, (double)(nx - 2), (double)j);
                if (j == 0 || j == ny - 1)
                    gy = j == 0 ? height(s, (double)i, 1) - h : h - height(s, (double)i, (double)(ny - 2));
            }
            slope = hypot(gx, gy);
            lit = fmax(0, (-gx * L[0] - gy * L[1] + L[2]) / sqrt(gx * gx + gy * gy + 1));
            for (int k = 1; hor > 0 && k <= SHADOW_REACH && !shadow; k++) {
                double ray = h + k * rise, t;
                if (ray > s->hmax)
                    break;
                t = height(s, (double)i + k * L[0] / hor, (double)j + k * L[1] / hor);
                if (isnan(t))
                    break;
                shadow = t > ray;
            }
            ground(v->palette, span > 0 ? (h - s->hmin) / span : 0.5, slope, c);
            lit = 0.32 + 0.78 * (shadow ? 0 : lit);
            for (int k = 0; k < 3; k++)
                s->rgb[3 * (j * nx + i) + k] = c[k] * lit;
        }
}

static void colour_at(const scene *s, double x, double y, double *c)
{
    cell q;
    cell_at((long)s->f->n[0], (long)s->f->n[1], 1, x, y, &q);
    for (int k = 0; k < 3; k++)
        c[k] = lerp2(s->rgb + k, 3, &q);
}

static void sky(double elevation, double *c)
{
    double t = elevation > 0 ? 1 - exp(-elevation / rad(14)) : 0;
    memcpy(c, sky_horizon, sizeof sky_horizon);
    mix(c, sky_zenith, t);
}

/* Mean and standard deviation of the cloud field, for its threshold. */
static void cloud_stats(const nl_field *g, double *mean, double *sd)
{
    double s1 = 0, s2 = 0;
    for (size_t i = 0; i < g->count; i++)
        s1 += g->data[i], s2 += g->data[i] * g->data[i];
    *mean = s1 / (double)g->count;
    *sd = sqrt(fmax(0, s2 / (double)g->count - *mean * *mean));
}

/* Sky along the ray of horizontal direction (dx, dy) at this elevation,
 * with the cloud plane's cover mixed in (fading with distance). */
static void sky_at(const nl_render_view *v, double cmean, double csd, double dx, double dy, double elevation, double *c)
{
    sky(elevation, c);
    if (v->clouds && elevation > 0.01) {
        const nl_field *g = v->clouds;
        double dist = v->cloud_height / tan(elevation), val, cover, white[3] = {0.97, 0.97, 0.98};
        cell q;
        cell_at((long)g->n[0], (long)g->n[1], 1, (v->cam[0] + dist * dx) / v->cloud_scale,
                (v->cam[1] + dist * dy) / v->cloud_scale, &q);
        val = lerp2(g->data, 1, &q);
        cover = fmin(1, fmax(0, ((val - cmean) / (csd > 0 ? csd : 1) - 0.5) / 1.5));
        mix(c, white, cover * exp(-dist / (4 * v->haze)));
    }
}

void nl_render_view_default(const nl_field *f, nl_render_view *v)
{
    /* heights scaled so that the rms slope (differences between
     * neighbouring samples, wrapped) is 0.5: hills, not needles, whatever
     * the field's variance and correlation length */
    double g2 = 0;
    size_t nx = f->n[0], ny = f->dim > 1 ? f->n[1] : 1;
    for (size_t j = 0; j < ny; j++)
        for (size_t i = 0; i < nx; i++) {
            double c = f->data[j * nx + i], dx = f->data[j * nx + (i + 1) % nx] - c,
                   dy = f->data[((j + 1) % ny) * nx + i] - c;
            g2 += (dx * dx + dy * dy) / 2 / (double)(nx * ny);
        }
    memset(v, 0, sizeof *v);
    v->width = 960;
    v->height = 540;
    v->zscale = g2 > 0 ? 0.5 / sqrt(g2) : 1;
    v->cam[0] = 0.5 * (double)f->n[0];
    v->cam[1] = -0.05 * (double)f->n[1];
    v->cam[2] = 0.15 * (double)f->n[0];
    v->azimuth = 90;
    v->pitch = 10;
    v->fov = 60;
    v->sun[0] = 210;
    v->sun[1] = 35;
    v->haze = 2.5 * (double)f->n[1];
    v->water = NAN;
}

/* The view's numbers: each named with its value when out of range.  Far
 * bounds keep the ray marcher's trip count (its step grows with distance,
 * so about 250 log(8 haze) steps a column when tiled) and the cloud plane's
 * cell indices finite: camera and clouds within reach = 1000 (nx + ny),
 * haze within 1000 reach. */
static int check_view(const nl_field *f, const nl_render_view *v)
{
    double reach = 1000 * (double)(f->n[0] + f->n[1]), amax = 0;
    for (size_t i = 0; i < f->count; i++)
        amax = fmax(amax, fabs(f->data[i]));
    if (!(v->fov > 0 && v->fov < 170))
        return NL_ERROR(NL_EINVAL, "render: fov: expected 0 < fov < 170 degrees, got %g", v->fov);
    if (!(v->zscale > 0) || !isfinite(v->zscale * amax * (double)f->count))
        return NL_ERROR(NL_EINVAL, "render: zscale: expected a positive factor that keeps heights finite, got %g "
                        "(largest |value| %g)", v->zscale, amax);
    if (!(v->haze > 0 && v->haze <= 1000 * reach))
        return NL_ERROR(NL_EINVAL, "render: haze: expected 0 < haze <= %g samples, got %g", 1000 * reach, v->haze);
    if (!(fabs(v->pitch) <= 30) || !(fabs(v->azimuth) <= 360))
        return NL_ERROR(NL_EINVAL, "render: look: expected an azimuth within +-360 and |pitch| <= 30 degrees, got "
                        "%g,%g", v->azimuth, v->pitch);
    if (!(v->sun[1] > 0 && v->sun[1] <= 90) || !(fabs(v->sun[0]) <= 360))
        return NL_ERROR(NL_EINVAL, "render: sun: expected an azimuth within +-360 and 0 < elevation <= 90 degrees, "
                        "got %g,%g", v->sun[0], v->sun[1]);
    if (!(fabs(v->cam[0]) <= reach && fabs(v->cam[1]) <= reach && v->cam[2] > 0 && v->cam[2] <= reach))
        return NL_ERROR(NL_EINVAL, "render: camera: expected X, Y within +-%g and 0 < H <= %g samples, got %g,%g,%g",
                        reach, reach, v->cam[0], v->cam[1], v->cam[2]);
    if (!isnan(v->water) && !isfinite(v->zscale * v->water))
        return NL_ERROR(NL_EINVAL, "render: water: expected a finite level, got %g", v->water);
    if (v->clouds && (v->clouds->dim != 2 || !(v->cloud_height > 0 && v->cloud_height <= reach) ||
                      !(v->cloud_scale >= 1e-3 && v->cloud_scale <= reach)))
        return NL_ERROR(NL_EINVAL, "render: cloud plane: expected a 2D field, 0 < height <= %g and a scale from "
                        "0.001 to %g, got %g,%g", reach, reach, v->cloud_height, v->cloud_scale);
    return NL_OK;
}

/* The field and the view can be rendered, and the work arrays sized. */
static int check(const nl_field *f, const nl_render_view *v)
{
    if (f->dim != 2 || f->n[0] < 3 || f->n[1] < 3)
        return NL_ERROR(NL_EINVAL, "render: a perspective view needs a 2D field of at least 3 x 3 samples");
    const size_t W = v->width * SS, H = v->height * SS;
    if (v->width < 1 || v->height < 1)
        return NL_ERROR(NL_EINVAL, "render: size: expected at least 1 x 1 pixels, got %zu x %zu", v->width,
                        v->height);
    int st = check_view(f, v);
    if (st)
        return st;
    /* the supersampled picture (3 doubles a pixel) and the lit colours */
    size_t pic[2] = {3 * W, H}, col[2] = {3, f->count};
    st = nl_size_check(2, pic, sizeof(double), 1, NULL);
    if (st || (st = nl_size_check(2, col, sizeof(double), 1, NULL)))
        return st;
    return NL_OK;
}

/* The SS x SS supersampled picture averaged into 8-bit pixels. */
static void downsample(const nl_render_view *v, const double *img, uint8_t *rgb)
{
    const size_t W = v->width * SS;
    for (size_t y = 0; y < v->height; y++)
        for (size_t x = 0; x < v->width; x++)
            for (int k = 0; k < 3; k++) {
                double sum = 0;
                for (int q = 0; q < SS; q++)
                    for (int p = 0; p < SS; p++)
                        sum += img[3 * ((y * SS + q) * W + x * SS + p) + k];
                rgb[3 * (y * v->width + x) + k] = (uint8_t)lround(255 * fmin(1, fmax(0, sum / (SS * SS))));
            }
}

int nl_render_terrain(const nl_field *f, const nl_render_view *v, uint8_t *rgb)
{
    const size_t W = v->width * SS, H = v->height * SS;
    scene s = {f, v, NULL, INFINITY, -INFINITY};
    double focal, horizon, camz, tmax, mean = 0, cmean = 0, csd = 1, *img;
    int st = check(f, v);
    if (st)
        return st;
    for (size_t i = 0; i < f->count; i++) {
        s.hmin = fmin(s.hmin, v->zscale * f->data[i]), s.hmax = fmax(s.hmax, v->zscale * f->data[i]);
        mean += v->zscale * f->data[i] / (double)f->count;
    }
    s.rgb = malloc(3 * f->count * sizeof *s.rgb);
    img = malloc(3 * W * H * sizeof *img);
    if (!s.rgb || !img) {
        free(s.rgb), free(img);
        return NL_ERROR(NL_ENOMEM, "render: out of memory for a %zu x %zu picture", v->width, v->height);
    }
    light(&s);
    if (v->clouds)
        cloud_stats(v->clouds, &cmean, &csd);
    focal = 0.5 * (double)W / tan(rad(v->fov) / 2);
    horizon = 0.5 * (double)H - focal * tan(rad(v->pitch));
    camz = height(&s, v->cam[0], v->cam[1]);
    camz = (isnan(camz) ? mean : camz) + v->cam[2];
    tmax = v->tile ? 8 * v->haze : 2 * hypot((double)f->n[0], (double)f->n[1]) + hypot(v->cam[0], v->cam[1]);
#pragma omp parallel for schedule(dynamic, 16)
    for (size_t x = 0; x < W; x++) {
        /* columns to the right turn clockwise (toward smaller azimuths) */
        double a = atan(((double)x + 0.5 - 0.5 * (double)W) / focal), dx = cos(rad(v->azimuth) - a),
               dy = sin(rad(v->azimuth) - a), ca = cos(a), t = 0.5, dt = 0.2, c[3];
        long top = (long)H; /* rows >= top are drawn */
        int entered = 0;
        while (t < tmax && top > 0) {
            double px = v->cam[0] + t * dx, py = v->cam[1] + t * dy, h = height(&s, px, py), y;
            if (isnan(h)) {
                if (entered || t > 4 * tmax)
                    break; /* left the field */
            } else {
                int wet = !isnan(v->water) && h < v->zscale * v->water;
                entered = 1;
                if (wet)
                    h = v->zscale * v->water;
                y = horizon + (camz - h) / (t * ca) * focal;
                if (y < (double)top) {
                    long row = y < 0 ? 0 : (long)ceil(y);
                    if (wet) {
                        sky(atan((camz - h) / t), c); /* the sky it reflects, under the water's colour */
                        mix(c, water_rgb, 0.65);
                    } else {
                        colour_at(&s, px, py, c);
                    }
                    double hz[3];
                    sky(0, hz);
                    mix(c, hz, 1 - exp(-t / v->haze));
                    for (long r = row; r < top; r++)
                        memcpy(img + 3 * ((size_t)r * W + x), c, sizeof c);
                    top = row;
                }
            }
            t += dt;
            dt = 0.2 + 0.004 * t;
        }
        for (long r = 0; r < top; r++) {
            sky_at(v, cmean, csd, dx, dy, atan((horizon - (double)r) / focal), c);
            memcpy(img + 3 * ((size_t)r * W + x), c, sizeof c);
        }
    }
    downsample(v, img, rgb);
    free(s.rgb), free(img);
    return NL_OK;
}
