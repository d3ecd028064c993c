/* Shared between the cloud renderer's files: sampled volumes and the
 * kriged global shape. */
#ifndef NL_RENDER_CLOUD_INTERNAL_H
#define NL_RENDER_CLOUD_INTERNAL_H

#include "cloud.h"
#include "../analysis/krige.h"

typedef struct {
    size_t n[3];       /* samples per axis */
    double lo[3], d[3];/* origin and step */
    double *v;         /* values, x fastest */
    int periodic;      /* wrap instead of clamp */
} nl_cloud_vol;

/* Trilinear value of g at p (clamped, or wrapped when periodic). */
double nl_cloud_vol_at(const nl_cloud_vol *g, const double *p);

/* The kriged shape of scene s: plan over the data points, rotated into the
 * ellipsoid's frame. */
typedef struct {
    nl_krige_plan *kp;  /* kriging plan (ordinary or simple) */
    double rot[9];      /* R, row-major: the ellipsoid's axes are its columns */
    int rotated;        /* 0 when every angle is 0 (coordinates used as given) */
} nl_cloud_shape;

int nl_cloud_shape_plan(const nl_cloud_scene *s, nl_cloud_shape *sh);
/* K at p (3 coordinates); lambda (may be NULL) the n weights. */
int nl_cloud_shape_at(const nl_cloud_shape *sh, const double *p, double *K, double *lambda);
void nl_cloud_shape_free(nl_cloud_shape *sh);

/* The shape sampled on a G^3 grid over the box; *step the smallest grid
 * step; *info (may be NULL) the kriging plan's (a pseudo-inverse flagged). */
int nl_cloud_shape_volume(const nl_cloud_scene *s, nl_cloud_vol *v, double *step, nl_krige_info *info);

#endif
