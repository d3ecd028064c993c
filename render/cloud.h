/* Clouds after Stam and Fiume 1991: a kriged global shape plus small-scale
 * noise, rendered by marching rays through the density.
 *
 * Density: rho(p) = max(0, K(p) (1 + a n(p)) - t) / (1 - t) where K > 0 and t
 * the threshold that makes the edges thin and translucent (the noise
 * modulates the shape, so empty sky stays empty).
 * K: kriging of the scene's data points (section 5, eqs. (19)-(22)) with the
 * covariance C(tau) = R(Rot^T tau), R the shape model (its own axes: x, y
 * and z stretched by ratio= and zratio=, after angle= about z) and Rot =
 * Rz(rotation[2]) Ry(rotation[1]) Rx(rotation[0]) (degrees; the ellipsoid's
 * principal axes are Rot's columns times the model's); ordinary kriging
 * (the paper's: weights summing to one, the mean estimated) or simple
 * kriging with mean 0.  Sampled on a G^3 grid over the scene box and
 * trilinearly interpolated.  Far from every datum ordinary kriging tends to
 * the estimated mean b (nl_krige_info.mean), simple kriging to 0: with
 * ordinary kriging a scene needs data of value 0 around the cloud (or b
 * below the threshold) to leave the sky empty.
 * n: unit-variance noise, either NL_CLOUD_NOISE_GRID, a periodic 3D FFT
 * field (synth/fft.h) of g^3 samples tiled with period P, trilinear, or
 * NL_CLOUD_NOISE_POINT, solid sparse-convolution noise evaluated at each
 * sample of each view ray (synth/sparse_point.h: a gauss: noise model,
 * `noise_density` impulses per scale^3, no grid and no period).
 * Light: a light volume holds the transmittance toward the sun, exp(-sigma
 * int rho ds) along the sun direction to the box, for every grid point
 * (precomputed once, then trilinear; with point noise the sun rays march
 * through the density sampled at the grid points).  View rays march with a
 * fixed step: L += T sigma rho ds (sun T_sun(p) phase + ambient), T *=
 * exp(-sigma rho ds), with the Henyey-Greenstein phase (g = 0.3); the
 * background is a vertical sky gradient attenuated by T.  Single
 * scattering only. */
#ifndef NL_RENDER_CLOUD_H
#define NL_RENDER_CLOUD_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../analysis/krige.h"
#include "../core/model.h"

#include <stddef.h>
#include <stdint.h>

typedef struct {
    size_t width, height;     /* image */
    double lo[3], hi[3];      /* scene box (y up) */
    size_t npoints;           /* data points */
    double *points;           /* npoints * 4: x y z value */
    nl_model *shape;          /* covariance of the global shape */
    nl_model *noise;          /* covariance of the noise */
    double amplitude;         /* a */
    double period;            /* P */
    size_t noise_grid;        /* g */
    uint64_t seed;            /* noise seed */
    double threshold;         /* t */
    double extinction;        /* sigma, per unit length at density 1 */
    double cam[3], look[3];   /* camera position and target */
    double fov;               /* vertical field of view, degrees */
    double sun[3];            /* direction toward the sun */
    size_t grid;              /* G */
    int kriging;              /* NL_CLOUD_ORDINARY (0) or NL_CLOUD_SIMPLE */
    double rotation[3];       /* degrees about x, y, z: the ellipsoid's orientation */
    int noise_kind;           /* NL_CLOUD_NOISE_GRID (0) or NL_CLOUD_NOISE_POINT */
    double noise_density;     /* point noise: impulses per noise scale^3 */
} nl_cloud_scene;

enum { NL_CLOUD_ORDINARY = 0, NL_CLOUD_SIMPLE = 1 };
enum { NL_CLOUD_NOISE_GRID = 0, NL_CLOUD_NOISE_POINT = 1 };

/* Render scene s into rgb (width * height * 3 bytes, rows top to bottom,
 * R G B per pixel) and lum (may be NULL: width * height doubles, the mean of
 * the tone-mapped R, G, B before quantisation, in [0, 1.6)).  Both buffers
 * are the caller's.  progress (may be NULL) is called with the fraction of
 * rows done, from inside an OpenMP critical section (one call at a time, in
 * any thread).  s, its points and models are only read.
 * Errors: NL_EINVAL for a scene without pixels, data points or models, a
 * grid or noise grid below 2 samples, an empty box, a threshold outside
 * [0, 1), a period <= 0, a fov outside (0, 180) degrees, or a zero sun
 * direction, rotation angles beyond +-360 degrees or not finite, more
 * than NL_KRIGE_LOCAL_MAX (2000) data points or a grid G with
 * G^3 (points + 7 G) above 1e9 (the work of the shape and light volumes
 * in covariance evaluations: about half a minute), and
 * those of the point noise (synth/sparse_point.h) and of the kriging plan of the shape covariance
 * (analysis/krige.h); NL_ENOTPD for a noise model that is not positive
 * definite on its grid (synth/fft.h); NL_ENOMEM.
 * Thread safety: reentrant for models that are thread-safe (not expr:);
 * runs its own OpenMP loops. */
int nl_render_cloud(const nl_cloud_scene *s, unsigned char *rgb, double *lum, void (*progress)(double));

/* nl_render_cloud, and *info (may be NULL) the shape's kriging plan
 * (analysis/krige.h): a singular system solved by the pseudo-inverse is
 * flagged there (info->pseudo_inverse, info->rcond). */
int nl_render_cloud_info(const nl_cloud_scene *s, unsigned char *rgb, double *lum, void (*progress)(double),
                         nl_krige_info *info);

/* The kriged shape K of scene s exactly as nl_render_cloud plans it (same
 * kriging, rotation and data), evaluated directly (no grid) at count points
 * x (count * 3 coordinates) into K (count); wsum (may be NULL, count) the
 * sum of the kriging weights at each point (1 for ordinary kriging).  Only
 * s->points, npoints, shape, kriging and rotation are read.  Errors: those
 * of the kriging plan (analysis/krige.h), NL_ENOMEM.  Thread-safe for
 * reentrant models. */
int nl_cloud_shape_eval(const nl_cloud_scene *s, size_t count, const double *x, double *K, double *wsum);

#ifdef __cplusplus
}
#endif

#endif
