/* Ocean waves after Tessendorf ("Simulating Ocean Water", SIGGRAPH 2000
 * course notes), on a rank-1 lattice (Keller 2001, section 4) or a regular
 * grid.  Patch of side P metres, wave vector K = 2 pi k / P (rad/m):
 *     Phillips P(K) = A exp(-1 / (K L)^2) / K^4 |K^ . w^|^2 exp(-K^2 l^2),
 *     L = V^2 / g, l = L / 1000 (suppresses waves much shorter than L),
 *     h0(k) = (xi + i eta) sqrt(P(K) / 2), xi, eta ~ N(0, 1) from
 *             (seed, NL_OCEAN_STREAM, index of k),
 *     h(k, t) = h0(k) e^{i w t} + conj(h0(-k)) e^{-i w t},  w^2 = g |K|,
 * so h(-k, t) = conj(h(k, t)) and the field is real (on the grid the
 * Nyquist row and column, which have no distinct partner, are left out). *
 * A sets the units of height (the CLI's --amplitude). */
#ifndef NL_SYNTH_OCEAN_H
#define NL_SYNTH_OCEAN_H

#ifdef __cplusplus
extern "C" {
#endif

#include "rank1.h"

#include <stdint.h>

#define NL_OCEAN_STREAM 700u
#define NL_OCEAN_G 9.81

typedef struct {
    double wind;      /* V, m/s */
    double angle;     /* wind direction, radians from +x */
    double patch;     /* P, metres */
    double amplitude; /* A */
} nl_ocean_params;

/* Every function is reentrant: parameters and lattices are only read and
 * the caller owns every array.  The FFT functions plan FFTW, which is not
 * thread-safe (core/fftw_plan.h).  Parameters are checked where a status
 * is returned: NL_EINVAL unless wind, patch and amplitude are positive and
 * finite, the angle within 1e6 radians and |t| <= 1e9 s; NL_EINVAL too
 * when the spectrum vanishes on every wave vector used (a wind whose waves
 * dwarf the patch, a patch too small for the wind) or the heights or
 * gradients overflow (amplitude). */

/* Phillips spectrum P(K) at integer wave vector (kx, ky) (2D), K = 2 pi k /
 * patch; 0 at k = 0. */
double nl_ocean_phillips(const nl_ocean_params *o, double kx, double ky);

/* Lattice: coefficients c (2N doubles, re/im) at time t seconds; heights
 * and gradients (per metre) by nl_rank1_synthesize with extent = patch.
 * NL_EINVAL: a lattice that is not 2D, or bad parameters. */
int nl_ocean_lattice_coefficients(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, double *c);

/* One frame on the lattice: heights h (N) and gradients grad (2N: dh/dx,
 * dh/dy per point, per metre; may be NULL) at time t.  Errors: those of
 * nl_ocean_lattice_coefficients and nl_rank1_synthesize, NL_ENOMEM. */
int nl_ocean_lattice_frame(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, double *h,
                           double *grad);

/* One lattice frame as a picture: the field itself, the trigonometric
 * polynomial of the lattice's coefficients at time t evaluated on a W x W
 * grid of the patch (nl_rank1_grid: pixel centres, row-major; heights and
 * gradients per metre, W * W doubles each, gx and gy may be NULL, both or
 * neither).  Errors: those of nl_ocean_lattice_coefficients and
 * nl_rank1_grid, heights or gradients that overflow, NL_ENOMEM. */
int nl_ocean_lattice_image(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, size_t W,
                           double *h, double *gx, double *gy);

/* Unit upward normals (3 per point: nx ny nz) of a height field from its
 * gradients (2 per point), n = (-gx, -gy, 1) / sqrt(gx^2 + gy^2 + 1). */
void nl_ocean_normals(size_t count, const double *grad, double *nrm);

/* Grid M x M (x fastest, spacing patch / M): heights h and gradients gx,
 * gy (per metre; each may be NULL), M * M doubles each, at time t by 2D
 * FFTs.  NL_EINVAL: M outside 2..65536 or bad parameters; NL_ENOMEM. */
int nl_ocean_grid(size_t M, const nl_ocean_params *o, uint64_t seed, double t, double *h, double *gx, double *gy);

#ifdef __cplusplus
}
#endif

#endif
