/* The global shape of a cloud (Stam and Fiume 1991, section 5): kriging of
 * the scene's data with an ellipsoidal covariance, fully oriented. */
#include "cloud_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

double nl_cloud_vol_at(const nl_cloud_vol *g, const double *p)
{
    double s = 0, t[3];
    long i0[3];
    for (int a = 0; a < 3; a++) {
        double u = (p[a] - g->lo[a]) / g->d[a];
        if (!g->periodic)
            u = fmin(fmax(u, 0), (double)g->n[a] - 1.000001);
        i0[a] = (long)floor(u);
        t[a] = u - (double)i0[a];
    }
    for (int c = 0; c < 8; c++) {
        double w = 1;
        size_t idx[3];
        for (int a = 0; a < 3; a++) {
            long i = i0[a] + ((c >> a) & 1);
            if (g->periodic)
                i = ((i % (long)g->n[a]) + (long)g->n[a]) % (long)g->n[a];
            idx[a] = (size_t)i;
            w *= (c >> a) & 1 ? t[a] : 1 - t[a];
        }
        s += w * g->v[(idx[2] * g->n[1] + idx[1]) * g->n[0] + idx[0]];
    }
    return s;
}

/* R = Rz(c) Ry(b) Rx(a) from the scene's angles (degrees). */
static void rotation(const double *deg, double *R)
{
    double a = deg[0] * M_PI / 180, b = deg[1] * M_PI / 180, c = deg[2] * M_PI / 180;
    double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b), cc = cos(c), sc = sin(c);
    double r[9] = {cc * cb, cc * sb * sa - sc * ca, cc * sb * ca + sc * sa,
                   sc * cb, sc * sb * sa + cc * ca, sc * sb * ca - cc * sa,
                   -sb,     cb * sa,                cb * ca};
    memcpy(R, r, sizeof r);
}

/* q = R^T p: the point in the ellipsoid's frame, where the model's own axes
 * (x; y and z stretched by ratio and zratio) apply. */
static void to_frame(const nl_cloud_shape *sh, const double *p, double *q)
{
    if (!sh->rotated) {
        memcpy(q, p, 3 * sizeof *q);
        return;
    }
    for (int a = 0; a < 3; a++)
        q[a] = sh->rot[a] * p[0] + sh->rot[3 + a] * p[1] + sh->rot[6 + a] * p[2];
}

/* Stam and Fiume, eqs. (19)-(22): L(t) = sum_i lambda_i d_i, minimum
 * variance and unbiased; ordinary kriging (the paper's: unknown mean, the
 * weights summing to one through the Lagrange multiplier nu) or simple
 * kriging with mean 0 (analysis/krige.h solves both). */
int nl_cloud_shape_plan(const nl_cloud_scene *s, nl_cloud_shape *sh)
{
    double *pts = malloc(s->npoints * 3 * sizeof *pts), *val = malloc(s->npoints * sizeof *val);
    int st;
    memset(sh, 0, sizeof *sh);
    if (!pts || !val) {
        free(pts), free(val);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    sh->rotated = s->rotation[0] != 0 || s->rotation[1] != 0 || s->rotation[2] != 0;
    rotation(s->rotation, sh->rot);
    for (size_t i = 0; i < s->npoints; i++)
        to_frame(sh, s->points + 4 * i, pts + 3 * i), val[i] = s->points[4 * i + 3];
    st = nl_krige_plan_alloc(s->shape, 3, s->npoints, pts, val, s->kriging == NL_CLOUD_SIMPLE, 0, 0, &sh->kp);
    free(pts), free(val);
    return st;
}

int nl_cloud_shape_at(const nl_cloud_shape *sh, const double *p, double *K, double *lambda)
{
    double q[3];
    to_frame(sh, p, q);
    return nl_krige_eval(sh->kp, q, K, NULL, lambda);
}

void nl_cloud_shape_free(nl_cloud_shape *sh)
{
    nl_krige_plan_free(sh->kp);
    sh->kp = NULL;
}

int nl_cloud_shape_volume(const nl_cloud_scene *s, nl_cloud_vol *v, double *step, nl_krige_info *info)
{
    nl_cloud_shape sh;
    size_t G = s->grid;
    int st;
    if ((st = nl_cloud_shape_plan(s, &sh)))
        return st;
    if (info)
        nl_krige_plan_info(sh.kp, info);
    *step = 1e300;
    for (int a = 0; a < 3; a++) {
        v->n[a] = G, v->lo[a] = s->lo[a], v->d[a] = (s->hi[a] - s->lo[a]) / (double)(G - 1);
        *step = fmin(*step, v->d[a]);
    }
    v->v = malloc(G * G * G * sizeof(double));
    if (!v->v) {
        nl_cloud_shape_free(&sh);
        return NL_ERROR(NL_ENOMEM, "out of memory for the shape grid");
    }
    for (size_t q = 0; q < G * G * G; q++) {
        double p[3] = {s->lo[0] + (double)(q % G) * v->d[0], s->lo[1] + (double)((q / G) % G) * v->d[1],
                       s->lo[2] + (double)(q / (G * G)) * v->d[2]};
        nl_cloud_shape_at(&sh, p, &v->v[q], NULL);
    }
    nl_cloud_shape_free(&sh);
    return NL_OK;
}

int nl_cloud_shape_eval(const nl_cloud_scene *s, size_t count, const double *x, double *K, double *wsum)
{
    nl_cloud_shape sh;
    int st;
    double *lam = NULL;
    if ((st = nl_cloud_shape_plan(s, &sh)))
        return st;
    if (wsum && !(lam = malloc(s->npoints * sizeof *lam))) {
        nl_cloud_shape_free(&sh);
        return NL_ERROR(NL_ENOMEM, "out of memory for the kriging weights");
    }
    for (size_t q = 0; q < count && !st; q++) {
        st = nl_cloud_shape_at(&sh, x + 3 * q, &K[q], lam);
        if (wsum) {
            wsum[q] = 0;
            for (size_t i = 0; i < s->npoints; i++)
                wsum[q] += lam[i];
        }
    }
    free(lam);
    nl_cloud_shape_free(&sh);
    return st;
}
