/* Slabs of a subdivided field: the samples of slowest-axis indices
 * s0..s0+ns-1 (2D: rows; 1D: samples along x), bit for bit those of the
 * whole field, from grids of O(slab + halo) samples per level.
 *
 * Refinement is local (Lewis 1987, eq. (3), (9)): a fine row J reads the
 * rows fdiv2(J) - reach .. fdiv2(J) + reach of the level above, so the rows
 * a slab needs at each level follow from the finest up, as for a window of
 * the infinite field.  A periodic level keeps those rows in unwrapped
 * coordinates (they may run below 0 or past the level's rows): stored row t
 * holds the level's row t mod n.  Its random numbers and displacements are
 * drawn at the canonical row (nl_subdiv_refine_level with per), the stencils
 * read the unwrapped neighbours: each sample sees the same operands in the
 * same order as in nl_subdiv_refine_periodic. */
#include "subdiv_internal.h"
#include "../core/mem.h"
#include "../core/nl_error.h"

#include <math.h>
#include <string.h>

/* Levels are at most 40 (nl_subdiv_coeffs_alloc). */
#define SLAB_LEVELS 41

/* The slowest-axis range lo[k]..hi[k] each level k = 0..L must hold for the
 * finest rows s0..s0+ns-1 (as nl_subdiv_synth_window computes). */
static void slab_ranges(const nl_subdiv_coeffs *c, long s0, long ns, long *lo, long *hi)
{
    const int L = c->levels;
    lo[L] = s0, hi[L] = s0 + ns - 1;
    for (int k = L - 1; k >= 0; k--) {
        lo[k] = fdiv2(lo[k + 1]) - c->level[k].reach;
        hi[k] = fdiv2(hi[k + 1]) + c->level[k].reach;
    }
}

/* Level 0 of the slab from the whole periodic coarse level (cx x cy): 2D
 * rows lo..hi (unwrapped) of columns -pad..cx+pad-1; 1D samples lo..hi. */
static int slab_level0(int dim, const double *v, long cx, long cy, long lo, long hi, long pad, nl_subdiv_grid *g)
{
    int st = dim == 2 ? nl_subdiv_grid_alloc(g, -pad, lo, cx + 2 * pad, hi - lo + 1)
                      : nl_subdiv_grid_alloc(g, lo, 0, hi - lo + 1, 1);
    if (st)
        return st;
    for (long j = 0; j < g->ny; j++) {
        const double *s = v + (dim == 2 ? nl_subdiv_wrap(g->y0 + j, cy) * cx : 0);
        for (long i = 0; i < g->nx; i++)
            g->v[j * g->nx + i] = s[nl_subdiv_wrap(g->x0 + i, cx)];
    }
    return NL_OK;
}

/* The padding columns of a 2D level whose columns 0..nx-1 are set: wrapped
 * copies, as wrap_border in subdiv_synth.c. */
static void wrap_columns(nl_subdiv_grid *g, long nx, long pad)
{
    for (long j = 0; j < g->ny; j++) {
        double *d = g->v + j * g->nx + pad;
        for (long i = 1; i <= pad; i++) {
            d[-i] = d[nl_subdiv_wrap(-i, nx)];
            d[nx - 1 + i] = d[(nx - 1 + i) % nx];
        }
    }
}

/* The destination of level k + 1: a padded grid `next` (returned in *next,
 * its interior in *dst), or f itself for the finest level. */
static int slab_dst(int dim, const nl_subdiv_coeffs *c, int k, long nx, const long *lo, const long *hi, nl_field *f,
                    nl_subdiv_grid *next, nl_subdiv_grid *dst)
{
    const long ny = hi[k + 1] - lo[k + 1] + 1, pad = k + 1 < c->levels ? c->level[k + 1].reach : 0;
    int st;
    next->v = NULL;
    if (k + 1 == c->levels) {
        *dst = dim == 2 ? (nl_subdiv_grid){f->data, 0, lo[k + 1], nx, ny, nx}
                        : (nl_subdiv_grid){f->data, lo[k + 1], 0, ny, 1, ny};
        return NL_OK;
    }
    if (dim == 1) {
        st = nl_subdiv_grid_alloc(next, lo[k + 1], 0, ny, 1);
        *dst = *next;
        return st;
    }
    if ((st = nl_subdiv_grid_alloc(next, -pad, lo[k + 1], nx + 2 * pad, ny)))
        return st;
    *dst = (nl_subdiv_grid){next->v + pad, 0, lo[k + 1], nx, ny, next->nx};
    return NL_OK;
}

static int slab_check(const nl_subdiv_coeffs *c, long cx, long cy, size_t s0, const nl_field *f)
{
    const int dim = c->dim, L = c->levels;
    const long n = (dim == 2 ? cy : cx) << L, ns = (long)f->n[dim - 1];
    if (f->dim != dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD plan cannot fill a %dD slab", dim, f->dim);
    if (dim == 2 && (long)f->n[0] != cx << L)
        return NL_ERROR(NL_EINVAL, "slab: expected rows of %ld samples (the %ld coarse columns refined %d times), "
                        "got %zu", cx << L, cx, L, f->n[0]);
    if (ns < 1 || s0 > (size_t)n || (long)s0 > n - ns)
        return NL_ERROR(NL_EINVAL, "slab: %zu %s from %zu leave the field's %ld; expected at least one, within it",
                        f->n[dim - 1], dim == 2 ? "rows" : "samples", s0, n);
    return NL_OK;
}

int nl_subdiv_refine_slab(const nl_subdiv_coeffs *c, const nl_field *coarse, uint64_t seed, int allow_not_pd,
                          size_t s0, nl_field *f)
{
    const int dim = c->dim, L = c->levels;
    long cx = (long)coarse->n[0], cy = dim == 2 ? (long)coarse->n[1] : 1, lo[SLAB_LEVELS], hi[SLAB_LEVELS];
    nl_subdiv_grid src = {NULL, 0, 0, 0, 0, 0};
    int st;
    if (coarse->dim != dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD coarse level for a %dD plan", coarse->dim, dim);
    if ((st = slab_check(c, cx, cy, s0, f)) || (st = nl_subdiv_check_periodic_levels(c, cx, cy)) ||
        (st = nl_subdiv_check_levels(c, allow_not_pd)))
        return st;
    slab_ranges(c, (long)s0, (long)f->n[dim - 1], lo, hi);
    if (L == 0) {
        for (size_t j = 0; j < f->count / f->n[0]; j++)
            memcpy(f->data + j * f->n[0], coarse->data + (dim == 2 ? (s0 + j) * coarse->n[0] : s0),
                   f->n[0] * sizeof *f->data);
    } else {
        st = slab_level0(dim, coarse->data, cx, cy, lo[0], hi[0], dim == 2 ? c->level[0].reach : 0, &src);
    }
    for (int k = 0; k < L && !st; k++) {
        nl_subdiv_grid next, dst;
        const long per[2] = {cx, cy};
        if ((st = slab_dst(dim, c, k, 2 * cx, lo, hi, f, &next, &dst)))
            break;
        if ((st = nl_subdiv_refine_level(dim, &c->level[k], &src, &dst, seed, (unsigned)k, per))) {
            nl_free(next.v);
            break;
        }
        nl_free(src.v);
        src = next;
        cx *= 2;
        if (dim == 2) {
            cy *= 2;
            if (src.v)
                wrap_columns(&src, cx, -src.x0);
        }
    }
    nl_free(src.v);
    if (!st)
        for (int a = 0; a < dim; a++)
            f->h[a] = ldexp(c->spacing0, -L);
    return st;
}

/* a + b, saturating at SIZE_MAX (an estimate that overflows is "too much"). */
static size_t add_sat(size_t a, size_t b) { return a > SIZE_MAX - b ? SIZE_MAX : a + b; }

static size_t grid_bytes(long nx, long ny)
{
    if (nx <= 0 || ny <= 0)
        return 0;
    if ((size_t)nx > SIZE_MAX / sizeof(double) / (size_t)ny)
        return SIZE_MAX;
    return (size_t)nx * (size_t)ny * sizeof(double);
}

/* The extent of level k along x: 2D periodic slabs the level's columns
 * plus its padding; windows (origin 0) the range they compute; 1D the
 * slab's range len. */
static long level_nx(const nl_subdiv_coeffs *c, int k, long nx, const long *len, const long *xlo, const long *xhi,
                     int window)
{
    if (c->dim == 1)
        return len[k];
    if (window)
        return xhi[k] - xlo[k] + 1;
    return (nx >> (c->levels - k)) + (k < c->levels ? 2L * c->level[k].reach : 0);
}

size_t nl_subdiv_slab_bytes(const nl_subdiv_coeffs *c, long nx, long ns, int window)
{
    const int dim = c->dim, L = c->levels;
    long len[SLAB_LEVELS], xlo[SLAB_LEVELS], xhi[SLAB_LEVELS];
    size_t peak = 0;
    /* the rows (1D: samples) of each level for the worst alignment of s0:
     * len rows from any start reach at most len / 2 + 1 rows of the level
     * above; a window's columns exactly, from origin 0 */
    len[L] = ns, xlo[L] = 0, xhi[L] = nx - 1;
    for (int k = L - 1; k >= 0; k--) {
        len[k] = len[k + 1] / 2 + 1 + 2L * c->level[k].reach;
        xlo[k] = fdiv2(xlo[k + 1]) - c->level[k].reach, xhi[k] = fdiv2(xhi[k + 1]) + c->level[k].reach;
    }
    for (int k = 0; k < L; k++) {
        long sx = level_nx(c, k, nx, len, xlo, xhi, window), dx = level_nx(c, k + 1, nx, len, xlo, xhi, window);
        long sy = dim == 2 ? len[k] : 1, dy = dim == 2 ? len[k + 1] : 1;
        /* the displacements' cells: x as refined (windows and 2D slabs from
         * a known column, 1D from the worst, odd, one), rows from an odd one */
        nl_subdiv_grid d = {NULL, dim == 1 ? 1 : window ? xlo[k + 1] : 0, dim == 2, 0, dy, 0};
        d.nx = dim == 1 ? len[k + 1] : window ? dx : nx >> (L - k - 1);
        /* the source, the destination (the finest one is f, except for a
         * window, which copies into f at the end) and the displacements */
        size_t b = add_sat(grid_bytes(sx, sy), k + 1 < L || window ? grid_bytes(dx, dy) : 0);
        b = add_sat(b, nl_subdiv_disp_bytes(dim, &c->level[k], &d));
        peak = b > peak ? b : peak;
    }
    return peak;
}
