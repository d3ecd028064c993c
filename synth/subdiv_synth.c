/* Generalized stochastic subdivision: refinement of a grid level by level,
 * periodic (Lewis 1987, "Boundary Conditions": wrapped indices) or as a
 * window of an infinite, spatially consistent field. */
#include "subdiv_simd_internal.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef nl_subdiv_grid grid;

int nl_subdiv_grid_alloc(grid *g, long x0, long y0, long nx, long ny)
{
    size_t n[2] = {(size_t)nx, (size_t)ny};
    int st = nl_size_check(2, n, sizeof(double), 1, NULL);
    if (st)
        return st;
    g->x0 = x0, g->y0 = y0, g->nx = nx, g->ny = ny, g->stride = nx;
    g->v = nl_alloc((size_t)nx * (size_t)ny * sizeof *g->v);
    return g->v ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory for a %ld x %ld level", nx, ny);
}

static inline double at(const grid *g, long i, long j) { return g->v[(j - g->y0) * g->nx + (i - g->x0)]; }

/* Correlated displacements of one level, per class and cell (subdiv.h). */
typedef struct {
    double *v;     /* v[(a ny + y) nx + x] for the cell (c0 + x, c1 + y) */
    long c0, c1;   /* first cell */
    long nx, ny;   /* cells (ny = 1 in 1D) */
} disp;

/* The displacements for the cells of dst; per = the periodic level's cells
 * (NULL: an infinite level).  d->v NULL when the level is independent. */
static int disp_alloc(int dim, const nl_subdiv_level *l, const grid *dst, const long *per, uint64_t seed,
                      unsigned lv, disp *d)
{
    long c0[2], n[2], none[2] = {0, 0};
    size_t sz[3] = {(size_t)l->nclass, 0, 0};
    int st;
    d->v = NULL;
    if (!l->filt)
        return NL_OK;
    c0[0] = fdiv2(dst->x0), c0[1] = dim == 2 ? fdiv2(dst->y0) : 0;
    n[0] = fdiv2(dst->x0 + dst->nx - 1) - c0[0] + 1;
    n[1] = dim == 2 ? fdiv2(dst->y0 + dst->ny - 1) - c0[1] + 1 : 1;
    sz[1] = (size_t)n[0], sz[2] = (size_t)n[1];
    if ((st = nl_size_check(3, sz, sizeof(double), 1, NULL)))
        return st;
    if (!(d->v = nl_alloc(sz[0] * sz[1] * sz[2] * sizeof *d->v)))
        return NL_ERROR(NL_ENOMEM, "out of memory for the displacements of level %u", lv);
    d->c0 = c0[0], d->c1 = c0[1], d->nx = n[0], d->ny = n[1];
    if ((st = nl_subdiv_disp_fill(l, dim, seed, lv, c0, n, per ? per : none, d->v))) {
        nl_free(d->v);
        d->v = NULL;
    }
    return st;
}

static inline double disp_at(const disp *d, int a, long i, long j)
{
    return d->v[(a * d->ny + (j - d->c1)) * d->nx + (i - d->c0)];
}

/* The pairs of keys k0..k1-1 on row J into g[2 (k - k0) + branch]: runs of
 * consecutive counters, split where the key's low word wraps (at k = 0). */
#define ROW_CHUNK 256
static void row_gauss(const row_job *r, long k0, long k1, double *g)
{
    const uint32_t st = NL_SUBDIV_STREAM + r->lv + 1;
    long mid = k0 < 0 && k1 > 0 ? 0 : k1;
    nl_rng_gauss_fill(r->seed, st, rng_index(2, k0, r->J), 2 * (size_t)(mid - k0), g);
    if (mid < k1)
        nl_rng_gauss_fill(r->seed, st, rng_index(2, mid, r->J), 2 * (size_t)(k1 - mid), g + 2 * (mid - k0));
}

/* The stencil path: the fastest this CPU has, or the one NOISELAB_SIMD
 * lowers the Gaussian fill to (core/rng.h); all give the same bits. */
static nl_subdiv_pairs_fn *pairs_path(void)
{
    const char *s = nl_rng_simd();
    return !strcmp(s, "avx512") ? nl_subdiv_pairs_avx512 : !strcmp(s, "avx2") ? nl_subdiv_pairs_avx2
                                                                              : nl_subdiv_pairs_scalar;
}

/* Whole pairs (2i, 2i + 1), i = i0..i1-1, in chunks of ROW_CHUNK, by the
 * vectorised stencils (subdiv_simd_internal.h): the sums, their order and
 * the random numbers are those of row_any (odd rows: the pair of key i;
 * even rows: key i / 2 for both odd points 4k + 1, 4k + 3). */
static void row_pairs(const row_job *r, long i0, long i1)
{
    nl_subdiv_pairs_fn *fn = pairs_path();
    double g[2 * ROW_CHUNK + 2];
    for (long c0 = i0; c0 < i1; c0 += ROW_CHUNK) {
        long c1 = i1 - c0 < ROW_CHUNK ? i1 : c0 + ROW_CHUNK, k0 = r->oy ? c0 : fdiv2(c0);
        if (!r->dodd)
            row_gauss(r, k0, r->oy ? c1 : fdiv2(c1 - 1) + 1, g);
        fn(r, c0, c1, r->dodd ? NULL : g, k0);
    }
}

/* Any N, samples I = I0..I1-1, in chunks of 2 ROW_CHUNK. */
static void row_any(const row_job *r, long I0, long I1)
{
    const int w = 2 * r->N;
    double g[2 * (ROW_CHUNK + 2)];
    for (long C0 = I0; C0 < I1; C0 += 2 * ROW_CHUNK) {
        long C1 = I1 - C0 < 2 * ROW_CHUNK ? I1 : C0 + 2 * ROW_CHUNK;
        /* odd rows draw at every I: samples 2i and 2i + 1 share the pair of
         * key i; even rows at odd I: samples 4k + 1 and 4k + 3 share key k */
        long k0 = r->oy ? fdiv2(C0) : fdiv2(fdiv2(C0)), k1 = r->oy ? fdiv2(C1 - 1) : fdiv2(fdiv2(C1 - 1));
        if (!r->dodd)
            row_gauss(r, k0, k1 + 1, g);
        for (long I = C0; I < C1; I++) {
            long i = fdiv2(I), key;
            const nl_subdiv_class *cl;
            double s = 0;
            if (I == 2 * i) {
                if (!r->oy) {
                    r->out[I] = r->rows[r->N - 1][i + r->N - 1];
                    continue;
                }
                cl = r->even;
            } else {
                cl = r->odd;
            }
            for (int k = 0; k < w; k++) {
                const double *a = cl->a + k * w, *x = r->rows[k] + i;
                for (int q = 0; q < w; q++)
                    s += a[q] * x[q];
            }
            if (r->dodd) {
                r->out[I] = s + (cl == r->odd ? r->dodd[i] : r->deven[i]);
                continue;
            }
            key = r->oy ? i : fdiv2(i);
            r->out[I] = s + (cl == r->odd ? r->sd_odd : r->sd_even) * g[2 * (key - k0) + (r->oy ? I - 2 * i : i - 2 * key)];
        }
    }
}

/* One row J of a 2D level with the standard 2N x 2N neighbourhoods: the
 * same arithmetic as the general loop in refine() (coefficients in the
 * same order), with the class fixed by the parities of I and J and the
 * source rows looked up once. */
static void refine_row_2d(const nl_subdiv_level *l, const grid *src, grid *dst, long J, long Jr, uint64_t seed,
                          unsigned lv, const disp *dp)
{
    const long j = fdiv2(J);
    row_job r;
    r.N = l->N, r.J = Jr, r.oy = J - 2 * j, r.seed = seed, r.lv = lv;
    r.out = dst->v + (J - dst->y0) * dst->stride - dst->x0;
    r.odd = &l->cls[r.oy ? 0 : 1], r.even = &l->cls[2];
    r.sd_odd = sqrt(r.odd->variance), r.sd_even = sqrt(r.even->variance);
    for (int k = 0; k < 2 * r.N; k++)
        r.rows[k] = src->v + (j + 1 - r.N + k - src->y0) * src->nx - src->x0 + 1 - r.N;
    /* correlated: this row's displacements by cell, odd I (face on odd
     * rows, edge-x on even ones) and even I (edge-y) */
    r.dodd = r.deven = NULL;
    if (dp->v) {
        r.dodd = dp->v + ((r.oy ? 0 : 1) * dp->ny + (j - dp->c1)) * dp->nx - dp->c0;
        r.deven = dp->v + (2 * dp->ny + (j - dp->c1)) * dp->nx - dp->c0;
    }
    /* an odd first or last sample on its own, whole pairs between */
    const long I0 = dst->x0, I1 = dst->x0 + dst->nx, p0 = fdiv2(I0 + 1), p1 = fdiv2(I1);
    if (I0 != 2 * fdiv2(I0))
        row_any(&r, I0, I0 + 1);
    if (p0 < p1)
        row_pairs(&r, p0, p1);
    if (I1 != 2 * p1)
        row_any(&r, I1 - 1, I1);
}

/* Fill dst (range set) at level `lv` + 1 from src at level lv.  Point I of
 * the finer grid is old point I/2 when I is even, else the midpoint of old
 * points (I-1)/2 and (I+1)/2.  Eq. (3) in 1D, eq. (9) in 2D.  The random
 * numbers are drawn at (I mod rp[0], J mod rp[1]) (rp[a] = 0: I, J): a
 * periodic level's canonical point (Jr below), while the stencil reads src
 * around the unwrapped (I, J). */
static void refine(int dim, const nl_subdiv_level *l, const grid *src, grid *dst, uint64_t seed, unsigned lv,
                   const disp *dp, const long *rp)
{
    const int N = l->N, w = 2 * N;
    const int standard = dim == 2 && !l->cls[0].nalt && !l->cls[1].nalt && !l->cls[2].nalt;
#pragma omp parallel for schedule(static) if (dst->nx * dst->ny > 65536)
    for (long J = dst->y0; J < dst->y0 + dst->ny; J++) {
        double *row = dst->v + (J - dst->y0) * dst->stride;
        const long Jr = nl_subdiv_wrap(J, rp[1]);
        if (standard) {
            refine_row_2d(l, src, dst, J, Jr, seed, lv, dp);
            continue;
        }
        for (long I = dst->x0; I < dst->x0 + dst->nx; I++) {
            long i = fdiv2(I), j = fdiv2(J), Ir = nl_subdiv_wrap(I, rp[0]);
            int ox = (int)(I - 2 * i), oy = dim == 2 ? (int)(J - 2 * j) : 0;
            const nl_subdiv_class *cl;
            double s = 0;
            if (!ox && !oy) {
                row[I - dst->x0] = at(src, i, dim == 2 ? j : src->y0);
                continue;
            }
            int c = dim == 1 ? 0 : ox && oy ? 0 : ox ? 1 : 2;  /* mid; face, edge-x, edge-y */
            if (dim == 1) {
                cl = &l->cls[0];
                for (int k = 0; k < w; k++)
                    s += cl->a[k] * at(src, i + 1 - N + k, src->y0);
            } else {
                cl = &l->cls[c];
                if (cl->nalt) {
                    /* a random quadrilateral neighbourhood */
                    size_t n = cl->n, alt = (size_t)(nl_rng_uniform(seed, NL_SUBDIV_STREAM + 64 + lv,
                                                                    rng_index(dim, Ir, Jr)) * cl->nalt);
                    const int *ofx = cl->offx + alt * n, *ofy = cl->offy + alt * n;
                    const double *a = cl->alt_a + alt * n;
                    for (size_t p = 0; p < n; p++)
                        s += a[p] * at(src, i + ofx[p], j + ofy[p]);
                    s += sqrt(cl->alt_var[alt]) * nl_rng_gauss(seed, NL_SUBDIV_STREAM + lv + 1, rng_index(dim, Ir, Jr));
                    row[I - dst->x0] = s;
                    continue;
                }
                for (int r = 0; r < w; r++)
                    for (int q = 0; q < w; q++)
                        s += cl->a[r * w + q] * at(src, i + 1 - N + q, j + 1 - N + r);
            }
            if (dp->v)
                s += disp_at(dp, c, i, dim == 2 ? j : 0);
            else
                s += sqrt(cl->variance) * nl_rng_gauss(seed, NL_SUBDIV_STREAM + lv + 1, rng_index(dim, Ir, Jr));
            row[I - dst->x0] = s;
        }
    }
}

int nl_subdiv_refine_level(int dim, const nl_subdiv_level *l, const grid *src, grid *dst, uint64_t seed, unsigned lv,
                           const long *per)
{
    const long none[2] = {0, 0}, rp[2] = {per ? 2 * per[0] : 0, per && dim == 2 ? 2 * per[1] : 0};
    disp dp = {NULL, 0, 0, 0, 0};
    int st = disp_alloc(dim, l, dst, per, seed, lv, &dp);
    if (st)
        return st;
    refine(dim, l, src, dst, seed, lv, &dp, per ? rp : none);
    nl_free(dp.v);
    return NL_OK;
}

size_t nl_subdiv_disp_bytes(int dim, const nl_subdiv_level *l, const grid *dst)
{
    const long M = l->taps, yM = dim == 2 ? M : 0;
    long nx, ny;
    if (!l->filt)
        return 0;
    nx = fdiv2(dst->x0 + dst->nx - 1) - fdiv2(dst->x0) + 1;
    ny = dim == 2 ? fdiv2(dst->y0 + dst->ny - 1) - fdiv2(dst->y0) + 1 : 1;
    /* the table, and disp_fill's white numbers over the cells +- M */
    return (size_t)l->nclass * sizeof(double) *
           ((size_t)nx * (size_t)ny + (size_t)(nx + 2 * M) * (size_t)(ny + 2 * yM));
}

int nl_subdiv_check_levels(const nl_subdiv_coeffs *c, int allow_not_pd)
{
    if (!allow_not_pd && (c->flags & NL_SUBDIV_NOT_PD)) {
        for (int k = 0; k < c->levels; k++)
            for (int j = 0; j < c->level[k].nclass; j++)
                if (c->level[k].cls[j].flags & NL_SUBDIV_NOT_PD)
                    return NL_ERROR(NL_ENOTPD,
                                    "subdivision: the model is not positive definite at level %d (%s, spacing %g, "
                                    "min eigenvalue %.3g); use --clamp to synthesise it anyway",
                                    k, nl_subdiv_class_name(c->level[k].cls[j].cls), c->level[k].spacing,
                                    c->level[k].cls[j].min_eigenvalue);
    }
    return NL_OK;
}

int nl_subdiv_check_periodic_levels(const nl_subdiv_coeffs *c, long cx, long cy)
{
    for (int k = 0; k < c->levels; k++) {
        long nk = c->dim == 2 && cy < cx ? cy << k : cx << k;
        if (nk < 2L * c->level[k].reach)
            return NL_ERROR(NL_EINVAL, "size: level %d has %ld samples per axis, fewer than its neighbourhood "
                            "of %d; use fewer --levels or a larger --size", k, nk, 2 * c->level[k].reach);
    }
    return NL_OK;
}

/* Copy a periodic level (indices 0..n-1) into a grid padded by `pad` wrapped
 * samples on each side. */
static int pad_periodic(int dim, const double *v, long nx, long ny, long pad, grid *g)
{
    long py = dim == 2 ? pad : 0;
    int st = nl_subdiv_grid_alloc(g, -pad, -py, nx + 2 * pad, ny + 2 * py);
    if (st)
        return st;
#pragma omp parallel for schedule(static) if (nx * ny > 65536)
    for (long j = -py; j < ny + py; j++) {
        const double *s = v + ((j % ny) + ny) % ny * nx;
        double *d = g->v + (j + py) * g->nx + pad;
        memcpy(d, s, (size_t)nx * sizeof *d);
        for (long i = 1; i <= pad; i++) {
            d[-i] = s[((-i % nx) + nx) % nx];
            d[nx - 1 + i] = s[(nx - 1 + i) % nx];
        }
    }
    return NL_OK;
}

/* A padded grid g (from -pad) whose interior 0..nx-1, 0..ny-1 is set: its
 * border wrapped in place, the same values as pad_periodic of the interior. */
static void wrap_border(int dim, grid *g, long nx, long ny, long pad)
{
    long py = dim == 2 ? pad : 0;
#pragma omp parallel for schedule(static) if (nx * ny > 65536)
    for (long j = 0; j < ny; j++) {
        double *d = g->v + (j + py) * g->nx + pad;
        for (long i = 1; i <= pad; i++) {
            d[-i] = d[((-i % nx) + nx) % nx];
            d[nx - 1 + i] = d[(nx - 1 + i) % nx];
        }
    }
    for (long j = -py; j < ny + py; j++)
        if (j < 0 || j >= ny)
            memcpy(g->v + (j + py) * g->nx, g->v + (((j % ny) + ny) % ny + py) * g->nx, (size_t)g->nx * sizeof *g->v);
}

int nl_subdiv_refine_periodic(const nl_subdiv_coeffs *c, const nl_field *coarse, uint64_t seed, int allow_not_pd,
                           nl_field *f)
{
    const int dim = c->dim;
    long nx = (long)f->n[0], ny = dim == 2 ? (long)f->n[1] : 1;
    long cx = (long)coarse->n[0], cy = dim == 2 ? (long)coarse->n[1] : 1;
    int st;

    if (f->dim != dim || coarse->dim != dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD plan cannot fill a %dD field", dim, f->dim);
    if ((cx << c->levels) != nx || (cy << (dim == 2 ? c->levels : 0)) != ny)
        return NL_ERROR(NL_EINVAL, "size: expected %ld%s%.0ld samples (the %ld%s%.0ld coarse grid refined %d times), "
                        "got %ld%s%.0ld", cx << c->levels, dim == 2 ? "x" : "", dim == 2 ? cy << c->levels : 0L,
                        cx, dim == 2 ? "x" : "", dim == 2 ? cy : 0L, c->levels, nx, dim == 2 ? "x" : "",
                        dim == 2 ? ny : 0L);
    if ((st = nl_subdiv_check_periodic_levels(c, cx, cy)) || (st = nl_subdiv_check_levels(c, allow_not_pd)))
        return st;
    /* src: the current level, padded for its refinement (the coarse field
     * copied; then each refined level, refined straight into the interior
     * of a padded grid; the last one is refined straight into f) */
    grid src = {NULL, 0, 0, 0, 0, 0};
    if (c->levels && (st = pad_periodic(dim, coarse->data, cx, cy, c->levels ? c->level[0].reach : 0, &src)))
        return st;
    for (int k = 0; k < c->levels && !st; k++) {
        grid next = {NULL, 0, 0, 0, 0, 0}, dst = {f->data, 0, 0, 2 * cx, dim == 2 ? 2 * cy : 1, 2 * cx};
        long per[2] = {cx, cy}, pad = k + 1 < c->levels ? c->level[k + 1].reach : 0, py = dim == 2 ? pad : 0;
        if (k + 1 < c->levels && !(st = nl_subdiv_grid_alloc(&next, -pad, -py, 2 * cx + 2 * pad, dst.ny + 2 * py)))
            dst.v = next.v + py * next.nx + pad, dst.stride = next.nx;
        if (!st && (st = nl_subdiv_refine_level(dim, &c->level[k], &src, &dst, seed, (unsigned)k, per)))
            nl_free(next.v);
        if (!st) {
            nl_free(src.v);
            src = next;
            cx *= 2;
            if (dim == 2)
                cy *= 2;
            if (src.v)
                wrap_border(dim, &src, cx, cy, pad);
        }
    }
    if (!st && c->levels == 0)
        memcpy(f->data, coarse->data, f->count * sizeof *f->data);
    if (!st)
        for (int a = 0; a < dim; a++)
            f->h[a] = ldexp(c->spacing0, -c->levels);
    nl_free(src.v);
    return st;
}

int nl_subdiv_synth_window(const nl_subdiv_coeffs *c, uint64_t seed, const long *origin, nl_field *f)
{
    const int dim = c->dim, L = c->levels;
    long (*rx)[2], (*ry)[2];
    grid g;
    int st;

    if (f->dim != dim)
        return NL_ERROR(NL_EINVAL, "subdivision: a %dD plan cannot fill a %dD field", dim, f->dim);
    if ((st = nl_subdiv_check_levels(c, 0)))
        return st;
    for (int a = 0; a < dim; a++)
        if (origin[a] < -NL_SUBDIV_ORIGIN_MAX || origin[a] > NL_SUBDIV_ORIGIN_MAX - (long)f->n[a])
            return NL_ERROR(NL_EINVAL, "origin: the window from %ld with %zu samples along axis %d leaves +-%ld",
                            origin[a], f->n[a], a, NL_SUBDIV_ORIGIN_MAX);
    rx = malloc((size_t)(L + 1) * sizeof *rx);
    ry = malloc((size_t)(L + 1) * sizeof *ry);
    if (!rx || !ry) {
        free(rx), free(ry);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    /* index ranges needed at each level, finest first */
    rx[L][0] = origin[0], rx[L][1] = origin[0] + (long)f->n[0] - 1;
    ry[L][0] = dim == 2 ? origin[1] : 0, ry[L][1] = dim == 2 ? origin[1] + (long)f->n[1] - 1 : 0;
    for (int k = L - 1; k >= 0; k--) {
        int N = c->level[k].reach;
        rx[k][0] = fdiv2(rx[k + 1][0]) - N, rx[k][1] = fdiv2(rx[k + 1][1]) + N;
        ry[k][0] = dim == 2 ? fdiv2(ry[k + 1][0]) - N : 0, ry[k][1] = dim == 2 ? fdiv2(ry[k + 1][1]) + N : 0;
    }
    /* level 0: independent samples of variance R(0) */
    st = nl_subdiv_grid_alloc(&g, rx[0][0], ry[0][0], rx[0][1] - rx[0][0] + 1, ry[0][1] - ry[0][0] + 1);
    for (long j = 0; !st && j < g.ny; j++)
        for (long i = 0; i < g.nx; i++)
            g.v[j * g.nx + i] = sqrt(c->r0) * nl_rng_gauss(seed, NL_SUBDIV_STREAM, rng_index(dim, g.x0 + i, g.y0 + j));
    for (int k = 0; k < L && !st; k++) {
        grid dst;
        st = nl_subdiv_grid_alloc(&dst, rx[k + 1][0], ry[k + 1][0], rx[k + 1][1] - rx[k + 1][0] + 1,
                                  ry[k + 1][1] - ry[k + 1][0] + 1);
        if (!st && (st = nl_subdiv_refine_level(dim, &c->level[k], &g, &dst, seed, (unsigned)k, NULL)))
            nl_free(dst.v);
        if (!st) {
            nl_free(g.v);
            g = dst;
        }
    }
    if (!st) {
        memcpy(f->data, g.v, f->count * sizeof *g.v);
        for (int a = 0; a < dim; a++)
            f->h[a] = ldexp(c->spacing0, -L);
    }
    nl_free(g.v);
    free(rx);
    free(ry);
    return st;
}
