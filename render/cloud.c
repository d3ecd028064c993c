/* Clouds (Stam and Fiume 1991): kriged shape + noise density, light volume,
 * ray marching. */
#include "cloud_internal.h"
#include "../analysis/krige_local.h"
#include "../core/nl_error.h"
#include "../synth/fft.h"
#include "../synth/sparse_point.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const nl_cloud_scene *s;
    nl_cloud_vol shape, noise, light;
    nl_synth_sparse_point *pn; /* point noise, or NULL: the noise volume */
} ctx;

static double density(const ctx *c, const double *p)
{
    const nl_cloud_scene *s = c->s;
    for (int a = 0; a < 3; a++)
        if (p[a] < s->lo[a] || p[a] > s->hi[a])
            return 0;
    double k = nl_cloud_vol_at(&c->shape, p);
    if (k <= 0)
        return 0;
    double n;
    if (c->pn)
        nl_synth_sparse_point_eval(c->pn, 1, p, &n);  /* p is inside the box: cannot fail */
    else
        n = nl_cloud_vol_at(&c->noise, p);
    double v = k * (1 + s->amplitude * n) - s->threshold;
    return v > 0 ? v / (1 - s->threshold) : 0;
}

/* ray-box intersection: [t0, t1] inside, or 0 */
static int box_hit(const nl_cloud_scene *s, const double *o, const double *d, double *t0, double *t1)
{
    double a = 0, b = INFINITY;
    for (int k = 0; k < 3; k++) {
        if (fabs(d[k]) < 1e-15) {
            if (o[k] < s->lo[k] || o[k] > s->hi[k])
                return 0;
            continue;
        }
        double u = (s->lo[k] - o[k]) / d[k], v = (s->hi[k] - o[k]) / d[k];
        a = fmax(a, fmin(u, v)), b = fmin(b, fmax(u, v));
    }
    *t0 = a, *t1 = b;
    return b > a;
}

static void normalize(double *v)
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int a = 0; a < 3; a++)
        v[a] /= n;
}

/* The small-scale noise: a periodic FFT field of unit variance, g^3 samples
 * over one period. */
static int noise_volume(const nl_cloud_scene *s, nl_cloud_vol *v)
{
    size_t g = s->noise_grid, n[3] = {g, g, g};
    double h[3] = {s->period / (double)g, s->period / (double)g, s->period / (double)g}, zero[3] = {0, 0, 0};
    nl_synth_fft_plan *fp;
    int st;
    nl_field *f = nl_field_alloc(3, n, h, &st);
    if (!f || (st = nl_synth_fft_plan_alloc(s->noise, 3, n, h, 0, &fp))) {
        nl_field_free(f);
        return st;
    }
    nl_synth_fft_execute(fp, s->seed, f);
    nl_synth_fft_plan_free(fp);
    double sd = sqrt(nl_model_acf(s->noise, 3, zero));
    for (size_t i = 0; i < f->count; i++)
        f->data[i] /= sd;
    for (int a = 0; a < 3; a++)
        v->n[a] = g, v->lo[a] = 0, v->d[a] = h[a];
    v->periodic = 1;
    v->v = malloc(f->count * sizeof(double));
    if (!v->v) {
        nl_field_free(f);
        return NL_ERROR(NL_ENOMEM, "out of memory for the noise volume");
    }
    memcpy(v->v, f->data, f->count * sizeof(double));
    nl_field_free(f);
    return NL_OK;
}

/* The density toward the sun: computed at x, or, with point noise, from
 * its samples at the grid points (dens) so that the G^3 sun rays do not
 * evaluate the noise at every step. */
static double sun_density(const ctx *c, const nl_cloud_vol *dens, const double *x)
{
    if (!dens->v)
        return density(c, x);
    for (int a = 0; a < 3; a++)
        if (x[a] < c->s->lo[a] || x[a] > c->s->hi[a])
            return 0;
    return nl_cloud_vol_at(dens, x);
}

static void grid_point(const ctx *c, size_t q, double *p)
{
    size_t G = c->s->grid;
    p[0] = c->s->lo[0] + (double)(q % G) * c->shape.d[0], p[1] = c->s->lo[1] + (double)((q / G) % G) * c->shape.d[1];
    p[2] = c->s->lo[2] + (double)(q / (G * G)) * c->shape.d[2];
}

/* The light volume: transmittance toward the sun from every shape grid
 * point, marched with `step`. */
static int light_volume(ctx *c, const double *sun, double step)
{
    const nl_cloud_scene *s = c->s;
    size_t G = s->grid;
    nl_cloud_vol dens = c->shape;
    dens.v = NULL;
    c->light = c->shape;
    c->light.v = malloc(G * G * G * sizeof(double));
    if (c->pn && (dens.v = malloc(G * G * G * sizeof(double))))
#pragma omp parallel for schedule(dynamic, 256)
        for (size_t q = 0; q < G * G * G; q++) {
            double p[3];
            grid_point(c, q, p);
            dens.v[q] = density(c, p);
        }
    if (!c->light.v || (c->pn && !dens.v)) {
        free(dens.v);
        return NL_ERROR(NL_ENOMEM, "out of memory for the light volume");
    }
#pragma omp parallel for schedule(dynamic, 16)
    for (size_t q = 0; q < G * G * G; q++) {
        double p[3], t0, t1, tau = 0;
        grid_point(c, q, p);
        if (box_hit(s, p, sun, &t0, &t1))
            for (double t = step * 0.5; t < t1; t += step) {
                double x[3] = {p[0] + t * sun[0], p[1] + t * sun[1], p[2] + t * sun[2]};
                tau += sun_density(c, &dens, x) * step;
            }
        c->light.v[q] = exp(-s->extinction * tau);
    }
    free(dens.v);
    return NL_OK;
}

typedef struct {
    double f[3], r[3], u[3];  /* forward, right, up (unit) */
    double tanh_, aspect;     /* tan(fov / 2), width / height */
    double sun[3];            /* unit direction toward the sun */
    double step;              /* march step */
} camera;

/* One pixel: march the view ray, add single scattering, then the sky;
 * rgb[3] bytes, *lu the luminance. */
static void pixel(const ctx *c, const camera *cm, size_t x, size_t y, unsigned char *rgb, double *lu)
{
    const nl_cloud_scene *s = c->s;
    const double g_hg = 0.3, sunc[3] = {1.0, 0.96, 0.88}, amb[3] = {0.35, 0.42, 0.55}, step = cm->step;
    const double *f = cm->f, *r = cm->r, *u = cm->u, *sun = cm->sun;
    double sx = (2 * ((double)x + 0.5) / (double)s->width - 1) * cm->tanh_ * cm->aspect;
    double sy = (1 - 2 * ((double)y + 0.5) / (double)s->height) * cm->tanh_, d[3], t0, t1, T = 1, L[3] = {0, 0, 0};
    for (int a = 0; a < 3; a++)
        d[a] = f[a] + sx * r[a] + sy * u[a];
    normalize(d);
    double mu = d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2];
    double phase = (1 - g_hg * g_hg) / pow(1 + g_hg * g_hg - 2 * g_hg * mu, 1.5);
    if (box_hit(s, s->cam, d, &t0, &t1))
        for (double t = t0 + step * 0.5; t < t1 && T > 1e-3; t += step) {
            double p[3] = {s->cam[0] + t * d[0], s->cam[1] + t * d[1], s->cam[2] + t * d[2]};
            double rho = density(c, p);
            if (rho <= 0)
                continue;
            double a = s->extinction * rho * step, ls = nl_cloud_vol_at(&c->light, p);
            for (int k = 0; k < 3; k++)
                L[k] += T * a * (sunc[k] * ls * phase * 1.4 + amb[k]);
            T *= exp(-a);
        }
    /* sky: deeper blue upward */
    double h = fmax(0, fmin(1, 0.5 + d[1]));
    double sky[3] = {0.55 - 0.3 * h, 0.7 - 0.25 * h, 0.95 - 0.1 * h};
    *lu = 0;
    for (int k = 0; k < 3; k++) {
        double v = L[k] + T * sky[k];
        v = v / (1 + v) * 1.6;  /* soft tone map */
        rgb[k] = (unsigned char)lrint(255 * fmin(1, fmax(0, v)));
        *lu += v / 3;
    }
}

static void camera_setup(const nl_cloud_scene *s, camera *cm)
{
    double *f = cm->f, *r = cm->r, *u = cm->u;
    f[0] = s->look[0] - s->cam[0], f[1] = s->look[1] - s->cam[1], f[2] = s->look[2] - s->cam[2];
    normalize(f);
    r[0] = -f[2], r[1] = 0, r[2] = f[0];  /* forward x (0, 1, 0) */
    normalize(r);
    u[0] = r[1] * f[2] - r[2] * f[1], u[1] = r[2] * f[0] - r[0] * f[2], u[2] = r[0] * f[1] - r[1] * f[0];
    cm->tanh_ = tan(s->fov * M_PI / 360), cm->aspect = (double)s->width / (double)s->height;
}

/* The camera: finite, within reach of the box, not looking at its own
 * position, not straight up or down (the picture's up is +y). */
static int check_camera(const nl_cloud_scene *s, double size)
{
    double f[3], fl, fh;
    for (int a = 0; a < 3; a++)
        if (!(fabs(s->cam[a]) <= 1e6 * size) || !(fabs(s->look[a]) <= 1e6 * size))
            return NL_ERROR(NL_EINVAL, "cloud: camera: expected \"position\" and \"look_at\" within 1e6 box sizes "
                            "(%g) of the origin, got %g and %g on axis %d", size, s->cam[a], s->look[a], a + 1);
    for (int a = 0; a < 3; a++)
        f[a] = s->look[a] - s->cam[a];
    fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]), fh = hypot(f[0], f[2]);
    if (!(fl > 1e-9 * size))
        return NL_ERROR(NL_EINVAL, "cloud: camera: \"look_at\" (%g, %g, %g) is the camera's position: expected a "
                        "point to look at", s->look[0], s->look[1], s->look[2]);
    if (!(fh > 1e-6 * fl))
        return NL_ERROR(NL_EINVAL, "cloud: camera: looking straight %s (from %g, %g, %g to %g, %g, %g): expected a "
                        "direction off the vertical (up is +y)", f[1] > 0 ? "up" : "down", s->cam[0], s->cam[1],
                        s->cam[2], s->look[0], s->look[1], s->look[2]);
    return NL_OK;
}

/* The work of the volumes, in covariance evaluations (about 3e7 a second):
 * the shape kriges every grid sample from all n points (G^3 n, after an
 * O(n^3) factorisation), and the light marches from every grid sample
 * toward the sun (about G steps of some 7 evaluations each).  Refused: more
 * points than krige takes in one neighbourhood (NL_KRIGE_LOCAL_MAX), and
 * over CLOUD_MAX_WORK (about half a minute). */
#define CLOUD_MAX_WORK 1e9
static int check_work(const nl_cloud_scene *s)
{
    double G = (double)s->grid, work = G * G * G * ((double)s->npoints + 7 * G);
    if (s->npoints > NL_KRIGE_LOCAL_MAX)
        return NL_ERROR(NL_EINVAL, "cloud: \"points\": the shape kriges with all %zu points at once; expected at most "
                        "%d (as krige's neighbourhoods; O(n^3))", s->npoints, NL_KRIGE_LOCAL_MAX);
    if (work > CLOUD_MAX_WORK)
        return NL_ERROR(NL_EINVAL, "cloud: \"grid\" %zu with %zu points: about %.3g covariance evaluations for the "
                        "shape and light volumes (grid^3 (points + 7 grid)); expected at most %.0e (about half a "
                        "minute): a smaller grid or fewer points", s->grid, s->npoints, work, CLOUD_MAX_WORK);
    return NL_OK;
}

static int check_scene(const nl_cloud_scene *s)
{
    double size = 0;
    int st;
    if (!s->width || !s->height || s->grid < 2 || s->noise_grid < 2 || !s->npoints || !s->points || !s->shape ||
        !s->noise)
        return NL_ERROR(NL_EINVAL, "cloud: expected a picture, grids of at least 2 samples, data points and two "
                        "models");
    for (int a = 0; a < 3; a++) {
        if (!(s->hi[a] > s->lo[a]) || !isfinite(s->hi[a] - s->lo[a]) || !(fabs(s->lo[a]) <= 1e12) ||
            !(fabs(s->hi[a]) <= 1e12))
            return NL_ERROR(NL_EINVAL, "cloud: box: expected lower < upper within +-1e12 on every axis, got %g to "
                            "%g on axis %d", s->lo[a], s->hi[a], a + 1);
        if (!((s->hi[a] - s->lo[a]) * 1e6 >= fmax(fabs(s->lo[a]), fabs(s->hi[a]))))
            return NL_ERROR(NL_EINVAL, "cloud: box: %g to %g on axis %d is too thin for its position (below 1e-6 "
                            "of it)", s->lo[a], s->hi[a], a + 1);
        size = fmax(size, s->hi[a] - s->lo[a]);
    }
    for (size_t i = 0; i < s->npoints; i++)
        for (int a = 0; a < 4; a++)
            if (!isfinite(s->points[4 * i + a]) || fabs(s->points[4 * i + a]) > 1e12)
                return NL_ERROR(NL_EINVAL, "cloud: points[%zu]: expected values within +-1e12, got %g", i,
                                s->points[4 * i + a]);
    if (!(s->threshold >= 0 && s->threshold < 1) || !(s->period > 0) || !(s->fov > 0 && s->fov < 180) ||
        (s->sun[0] == 0 && s->sun[1] == 0 && s->sun[2] == 0))
        return NL_ERROR(NL_EINVAL, "cloud: expected 0 <= threshold < 1, a positive period, 0 < fov < 180 and a "
                        "non-zero sun direction, got %g, %g, %g, (%g, %g, %g)", s->threshold, s->period, s->fov,
                        s->sun[0], s->sun[1], s->sun[2]);
    if (!isfinite(s->sun[0] * s->sun[0] + s->sun[1] * s->sun[1] + s->sun[2] * s->sun[2]))
        return NL_ERROR(NL_EINVAL, "cloud: sun: expected a direction of finite length, got (%g, %g, %g)", s->sun[0],
                        s->sun[1], s->sun[2]);
    if ((st = check_camera(s, size)))
        return st;
    for (int a = 0; a < 3; a++)
        if (!(fabs(s->rotation[a]) <= 360))
            return NL_ERROR(NL_EINVAL, "cloud: rotation: expected angles within +-360 degrees, got %g about axis %d",
                            s->rotation[a], a + 1);
    if ((s->kriging != NL_CLOUD_ORDINARY && s->kriging != NL_CLOUD_SIMPLE) ||
        (s->noise_kind != NL_CLOUD_NOISE_GRID && s->noise_kind != NL_CLOUD_NOISE_POINT))
        return NL_ERROR(NL_EINVAL, "cloud: expected ordinary or simple kriging and grid or point noise, got %d and %d",
                        s->kriging, s->noise_kind);
    /* the shape, light and noise volumes */
    size_t vs[3] = {s->grid, s->grid, s->grid}, vn[3] = {s->noise_grid, s->noise_grid, s->noise_grid};
    /* shape and light, and with point noise the density sampled for the light */
    if ((st = nl_size_check(3, vs, (s->noise_kind == NL_CLOUD_NOISE_POINT ? 3 : 2) * sizeof(double), 1, NULL)) ||
        (st = nl_size_check(3, vn, 2 * sizeof(double), 1, NULL)))
        return st;
    return check_work(s);
}

int nl_render_cloud(const nl_cloud_scene *s, unsigned char *rgb, double *lum, void (*progress)(double))
{
    return nl_render_cloud_info(s, rgb, lum, progress, NULL);
}

int nl_render_cloud_info(const nl_cloud_scene *s, unsigned char *rgb, double *lum, void (*progress)(double),
                         nl_krige_info *info)
{
    ctx c;
    camera cm;
    int st;
    if (info)
        memset(info, 0, sizeof *info);
    if ((st = check_scene(s)))
        return st;
    memset(&c, 0, sizeof c);
    c.s = s;
    memcpy(cm.sun, s->sun, sizeof cm.sun);
    normalize(cm.sun);
    if ((st = nl_cloud_shape_volume(s, &c.shape, &cm.step, info)) ||
        (st = s->noise_kind == NL_CLOUD_NOISE_POINT
                  ? nl_synth_sparse_point_alloc(s->noise, s->noise_density, s->seed, s->lo, s->hi, &c.pn)
                  : noise_volume(s, &c.noise)) ||
        (cm.step *= 0.5, st = light_volume(&c, cm.sun, cm.step))) {
        free(c.shape.v), free(c.noise.v), free(c.light.v), nl_synth_sparse_point_free(c.pn);
        return st;
    }
    camera_setup(s, &cm);
    size_t done = 0;
#pragma omp parallel for schedule(dynamic, 4)
    for (size_t y = 0; y < s->height; y++) {
        for (size_t x = 0; x < s->width; x++) {
            double lu;
            pixel(&c, &cm, x, y, rgb + 3 * (y * s->width + x), &lu);
            if (lum)
                lum[y * s->width + x] = lu;
        }
        if (progress) {
#pragma omp atomic
            done++;
#pragma omp critical
            progress((double)done / (double)s->height);
        }
    }
    free(c.shape.v), free(c.noise.v), free(c.light.v), nl_synth_sparse_point_free(c.pn);
    return NL_OK;
}
