/* Slabs of sparse convolution along the slowest axis (Lewis GI '86, eq. 2):
 * the samples of slowest-axis indices s0..s0+ns-1, bit for bit those of the
 * whole grid.  A sample sums the impulses of the cells within the kernel's
 * reach in cell order (sparse.h), whatever the grid: a non-periodic slab is
 * the window at (0, s0).  A periodic slab draws the cells its samples reach
 * in unwrapped cell coordinates, each holding its canonical cell's impulses
 * (nl_sparse_impulses_make_periodic), and sums them in the order of the
 * periodic execute, shifted by the tile as there. */
#include "sparse.h"
#include "sparse_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdint.h>

static long kernel_reach(const nl_synth_sparse_plan *p)
{
    return p->angle ? (long)ceil(p->radius * M_SQRT2) + 1 : p->radius;
}

static long wrapl(long a, long n) { return ((a % n) + n) % n; }

/* The slab's checks: out is the field but along the slowest axis; with
 * wrap, the tile's checks of nl_synth_sparse_execute. */
static int slab_check(const nl_synth_sparse_plan *p, int wrap, const size_t *n, size_t s0, const nl_field *out)
{
    const int dim = p->dim, s = dim - 1;
    const long C = p->cell, reach = kernel_reach(p);
    if (out->dim != dim)
        return NL_ERROR(NL_EINVAL, "sparse: a %dD kernel cannot fill a %dD slab", dim, out->dim);
    if (dim == 2 && out->n[0] != n[0])
        return NL_ERROR(NL_EINVAL, "slab: expected rows of %zu samples, as the field's, got %zu", n[0], out->n[0]);
    if (out->n[s] < 1 || s0 > n[s] || out->n[s] > n[s] - s0 || n[s] > (size_t)NL_SPARSE_ORIGIN_MAX)
        return NL_ERROR(NL_EINVAL, "slab: %zu %s from %zu leave the field's %zu; expected at least one, within it",
                        out->n[s], dim == 2 ? "rows" : "samples", s0, n[s]);
    if (!wrap)
        return NL_OK;
    for (int a = 0; a < dim; a++) {
        if (n[a] % (size_t)C)
            return NL_ERROR(NL_EINVAL, "size: a periodic tile must be a multiple of the cell size %ld, got %zu "
                            "along axis %d", C, n[a], a);
        if ((size_t)(2 * reach + 1) > n[a])
            return NL_ERROR(NL_EINVAL, "radius: the kernel (%ld samples across) is larger than the tile",
                            2 * reach + 1);
    }
    return NL_OK;
}

/* One sample at (X, Y) of the periodic tile of ncx x ncy cells from the
 * cells drawn in im (unwrapped): the loops and sums of
 * nl_synth_sparse_execute's wrap path, in its order. */
static double sample_wrap(const nl_synth_sparse_plan *p, const nl_sparse_impulses *im, long X, long Y, long ncx,
                          long ncy)
{
    const int dim = p->dim, R = p->radius, C = p->cell, w = 2 * R + 1;
    const long reach = kernel_reach(p);
    long a0 = nl_sparse_floordiv(X - reach, C), a1 = nl_sparse_floordiv(X + reach, C);
    long b0 = dim == 2 ? nl_sparse_floordiv(Y - reach, C) : 0, b1 = dim == 2 ? nl_sparse_floordiv(Y + reach, C) : 0;
    double s = 0;
    for (long b = b0; b <= b1; b++)
        for (long a = a0; a <= a1; a++) {
            long ca = wrapl(a, ncx), cb = wrapl(b, ncy);
            size_t c = (size_t)((b - im->cy0) * im->ncx + (a - im->cx0));
            for (size_t k = im->start[c]; k < im->start[c + 1]; k++) {
                /* the image of the impulse in the cell a, b */
                long dx = X - (im->px[k] + (a - ca) * C), dy = dim == 2 ? Y - (im->py[k] + (b - cb) * C) : 0;
                if (!p->angle) {
                    if (dx < -R || dx > R || dy < -R || dy > R)
                        continue;
                    s += im->a[k] * p->h[(size_t)(dim == 2 ? (dy + R) * w + (dx + R) : dx + R)];
                } else {
                    s += im->a[k] * nl_sparse_table_at(p->h, R, im->c[k] * (double)dx + im->s[k] * (double)dy,
                                                       -im->s[k] * (double)dx + im->c[k] * (double)dy);
                }
            }
        }
    return s;
}

/* The cells a slab reaches per axis (unwrapped): x all the row's, the
 * slowest axis s0 - reach .. s0 + ns - 1 + reach. */
static void slab_cells(const nl_synth_sparse_plan *p, const size_t *n, size_t s0, size_t ns, long *c0, long *c1)
{
    const long C = p->cell, reach = kernel_reach(p);
    c0[0] = nl_sparse_floordiv(-reach, C), c1[0] = nl_sparse_floordiv((long)n[0] - 1 + reach, C);
    c0[1] = c1[1] = 0;
    c0[p->dim - 1] = nl_sparse_floordiv((long)s0 - reach, C);
    c1[p->dim - 1] = nl_sparse_floordiv((long)(s0 + ns) - 1 + reach, C);
}

int nl_synth_sparse_execute_slab(const nl_synth_sparse_plan *p, uint64_t seed, unsigned flags, const size_t *n_global,
                                 size_t s0, nl_field *out)
{
    const int dim = p->dim, wrap = (flags & NL_SYNTH_SPARSE_WRAP) != 0;
    const size_t ns = out->n[dim - 1], row = dim == 2 ? out->n[0] : 1;
    const long per[2] = {(long)n_global[0] / p->cell, dim == 2 ? (long)n_global[1] / p->cell : 1};
    long c0[2], c1[2];
    nl_sparse_impulses im;
    int st;
    if ((st = slab_check(p, wrap, n_global, s0, out)))
        return st;
    if (!wrap) {
        const long origin[2] = {dim == 2 ? 0 : (long)s0, (long)s0};
        return nl_synth_sparse_execute(p, seed, 0, origin, out);
    }
    if ((st = nl_synth_sparse_check_work(dim, out->n, p->radius, p->cell, p->density,
                                          p->angle ? NL_SYNTH_SPARSE_ANGLE : 0)))
        return st;
    slab_cells(p, n_global, s0, ns, c0, c1);
    if ((st = nl_sparse_impulses_make_periodic(p, seed, c0[0], c1[0], c0[1], c1[1], per, &im)))
        return st;
#pragma omp parallel for schedule(dynamic, 8) if (out->count > 65536)
    for (size_t j = 0; j < ns; j++)
        for (size_t i = 0; i < row; i++) {
            long X = dim == 2 ? (long)i : (long)(s0 + j), Y = dim == 2 ? (long)(s0 + j) : 0;
            out->data[j * row + i] = sample_wrap(p, &im, X, Y, per[0], per[1]);
        }
    nl_sparse_impulses_free(&im);
    for (size_t i = 0; p->info.mean != 0 && i < out->count; i++)
        out->data[i] += p->info.mean;
    return NL_OK;
}

size_t nl_synth_sparse_slab_bytes(const nl_synth_sparse_plan *p, unsigned flags, const size_t *n_global, size_t ns)
{
    const long C = p->cell, reach = kernel_reach(p);
    size_t n[2] = {n_global[0], p->dim == 2 ? n_global[1] : 1}, ncell = 1, cap;
    double want;
    long c0[2], c1[2];
    if (ns > (size_t)NL_SPARSE_ORIGIN_MAX || n[0] > (size_t)NL_SPARSE_ORIGIN_MAX)
        return SIZE_MAX;
    /* the cells of a slab from s0 = 0, and one more row of them along the
     * slowest axis for the worst alignment of s0 */
    slab_cells(p, n, 0, ns, c0, c1);
    (void)flags; /* a window reaches the same cells as a periodic slab */
    c1[p->dim - 1] = c0[p->dim - 1] + ((long)ns - 1 + 2 * reach) / C + 1;
    for (int a = 0; a < p->dim; a++)
        ncell *= (size_t)(c1[a] - c0[a] + 1);
    /* nl_sparse_impulses_make's first capacity: offsets per cell, and five
     * arrays of 1.5 times the expected impulses plus 64 */
    want = p->density * (double)ncell * 1.5;
    if (want > 1e18)
        return SIZE_MAX;
    cap = (size_t)want + 64;
    return (ncell + 1) * sizeof(size_t) + cap * (2 * sizeof(long) + 3 * sizeof(double));
}
