/* Clouds after Stam and Fiume 1991: a kriged global shape plus small-scale
 * noise, rendered by marching rays through the density.
 *
 * Density: rho(p) = max(0, K(p) (1 + a n(p)) - t) / (1 - t) where K > 0, K simple
 * kriging (mean 0) of the scene's data points with an ellipsoidal
 * covariance, sampled on a G^3 grid over the scene box and trilinearly
 * interpolated; n is a periodic 3D FFT field (unit variance) of g^3 samples
 * tiled with period P, trilinear (the noise modulates the shape, so empty
 * sky stays empty); t the threshold that makes the edges thin and
 * translucent.
 * Light: a light volume holds the transmittance toward the sun, exp(-sigma
 * int rho ds) along the sun direction to the box, for every grid point
 * (precomputed once, then trilinear).  View rays march with a fixed step:
 * L += T sigma rho ds (sun T_sun(p) phase + ambient), T *= exp(-sigma rho ds),
 * with the Henyey-Greenstein phase (g = 0.3); the background is a vertical
 * sky gradient attenuated by T.  Single scattering only. */
#ifndef NL_RENDER_CLOUD_H
#define NL_RENDER_CLOUD_H

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
} nl_cloud_scene;

/* Render scene s into rgb (width * height * 3 bytes, rows top to bottom,
 * R G B per pixel) and lum (may be NULL: width * height doubles, the mean of
 * the tone-mapped R, G, B before quantisation, in [0, 1.6)).  Both buffers
 * are the caller's.  progress (may be NULL) is called with the fraction of
 * rows done, from inside an OpenMP critical section (one call at a time, in
 * any thread).  s, its points and models are only read.
 * Errors: NL_EINVAL for a scene without pixels, data points or models, a
 * grid or noise grid below 2 samples, an empty box, a threshold outside
 * [0, 1), a period <= 0, a fov outside (0, 180) degrees, or a zero sun
 * direction, and those of the kriging plan of the shape covariance
 * (analysis/krige.h); NL_ENOTPD for a noise model that is not positive
 * definite on its grid (synth/fft.h); NL_ENOMEM.
 * Thread safety: reentrant for models that are thread-safe (not expr:);
 * runs its own OpenMP loops. */
int nl_render_cloud(const nl_cloud_scene *s, unsigned char *rgb, double *lum, void (*progress)(double));

#endif
