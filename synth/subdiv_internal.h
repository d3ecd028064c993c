/* Shared between the subdivision sources; not installed. */
#ifndef NL_SYNTH_SUBDIV_INTERNAL_H
#define NL_SYNTH_SUBDIV_INTERNAL_H

#include "subdiv.h"

#include <stdint.h>

/* The counter of the random number at integer position (i, j): see
 * NL_SUBDIV_STREAM in subdiv.h. */
static inline uint64_t rng_index(int dim, long i, long j)
{
    if (dim == 1)
        return (uint64_t)i;
    return ((uint64_t)(uint32_t)j << 32) | (uint32_t)i;
}

/* NL_ENOTPD naming the first class flagged not positive definite, unless
 * allow_not_pd; NL_OK otherwise. */
int nl_subdiv_check_levels(const nl_subdiv_coeffs *c, int allow_not_pd);

/* The correlated displacements of level lv (l->filt set) for the cells
 * c0[a] .. c0[a] + n[a] - 1: out[(a n[1] + y) n[0] + x] for class a (n[1] = 1
 * in 1D).  per[a] > 0: a periodic level of per[a] cells (white numbers
 * wrap); 0: an infinite one.  NL_OK or NL_ENOMEM. */
int nl_subdiv_disp_fill(const nl_subdiv_level *l, int dim, uint64_t seed, unsigned lv, const long *c0,
                        const long *n, const long *per, double *out);

/* Floor division by 2, and i modulo n into 0..n-1 (n = 0: i itself). */
static inline long fdiv2(long a) { return a >= 0 ? a / 2 : -((-a + 1) / 2); }
static inline long nl_subdiv_wrap(long i, long n) { return !n || (i >= 0 && i < n) ? i : ((i % n) + n) % n; }

/* Samples of one level at integer indices x0..x0+nx-1, y0..y0+ny-1. */
typedef struct {
    double *v;     /* row-major, x fastest */
    long x0, y0;   /* index of v[0] */
    long nx, ny;   /* extent (ny = 1 in 1D) */
    long stride;   /* between rows of v (nx, or more for a view into a padded level) */
} nl_subdiv_grid;

/* g covering x0..x0+nx-1, y0..y0+ny-1 (stride nx), from nl_alloc.  NL_OK,
 * NL_ETOOBIG, NL_ENOMEM. */
int nl_subdiv_grid_alloc(nl_subdiv_grid *g, long x0, long y0, long nx, long ny);

/* Refine the range of dst (level lv + 1) from src (level lv, covering every
 * index dst's stencils read).  per NULL: an infinite level; else per[a] the
 * cells of the periodic level lv (its sample count per axis; per[1] = 1 in
 * 1D): the random numbers and displacements of a fine point I are those of
 * its canonical index I mod 2 per[a], so dst may hold rows (1D: samples)
 * outside 0..2 per[a] - 1 whose values are those of the canonical ones,
 * while the stencils read src at the unwrapped indices.  NL_OK, NL_ETOOBIG,
 * NL_ENOMEM.  Thread-safe. */
int nl_subdiv_refine_level(int dim, const nl_subdiv_level *l, const nl_subdiv_grid *src, nl_subdiv_grid *dst,
                           uint64_t seed, unsigned lv, const long *per);

/* NL_EINVAL when a periodic level of the coarse cx x cy grid (cy = 1 in 1D)
 * is smaller than its neighbourhood, as nl_subdiv_refine_periodic reports. */
int nl_subdiv_check_periodic_levels(const nl_subdiv_coeffs *c, long cx, long cy);

/* The peak bytes the displacements of level l take for cells covering
 * dst's range (the table and nl_subdiv_disp_fill's white numbers); 0 when
 * the level is independent. */
size_t nl_subdiv_disp_bytes(int dim, const nl_subdiv_level *l, const nl_subdiv_grid *dst);

/* nl_subdiv_refine_periodic's samples of slowest-axis indices s0 .. s0 +
 * ns - 1 (2D rows, 1D samples; ns = f->n[dim - 1]) into f, whose other
 * axes are the whole field's (subdiv_slab.c).  Same codes, and NL_EINVAL
 * for a slab not within the field. */
int nl_subdiv_refine_slab(const nl_subdiv_coeffs *c, const nl_field *coarse, uint64_t seed, int allow_not_pd,
                          size_t s0, nl_field *f);

/* The peak bytes of level grids and displacements nl_subdiv_refine_slab
 * (window 0; nx the field's row length, 2D) or nl_subdiv_synth_window at
 * origin (0, s0) (window 1, nx its row length) allocate for a slab of ns
 * rows (1D: samples), for any s0; not f. */
size_t nl_subdiv_slab_bytes(const nl_subdiv_coeffs *c, long nx, long ns, int window);

#endif
