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

/* Phillips spectrum at integer wave vector k (2D). */
double nl_ocean_phillips(const nl_ocean_params *o, double kx, double ky);

/* Lattice: coefficients c (2N, re/im) at time t; heights and gradients
 * (per metre) by nl_rank1_synthesize with extent = patch. */
int nl_ocean_lattice_coefficients(const nl_rank1_lattice *L, const nl_ocean_params *o, uint64_t seed, double t, double *c);

/* Grid M x M (x fastest): heights h and gradients gx, gy (may be NULL) at
 * time t by 2D FFTs. */
int nl_ocean_grid(size_t M, const nl_ocean_params *o, uint64_t seed, double t, double *h, double *gx, double *gy);

#endif
