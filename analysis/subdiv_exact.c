/* Exact covariance propagation through periodic subdivision levels. */
#include "subdiv_exact.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <stdlib.h>
#include <string.h>

/* New point I of a level: the old points and weights it is made of, and the
 * variance of its own displacement.  With random neighbourhoods, the mean
 * over the alternatives (each drawn with probability 1/nalt). */
typedef struct {
    int n, cap;     /* stencil size (1 for a kept point); capacity of idx, w */
    long *idx;      /* old flat indices */
    double *w;      /* weights */
    double var;     /* displacement variance */
    int cls;        /* class index into the level's cls[] (-1: a kept point) */
    long ci, cj;    /* its cell */
} stencil;

static long wrap(long i, long n) { return ((i % n) + n) % n; }

/* Adds weight v of old point idx to the stencil, merging a repeated point. */
static void add_point(stencil *s, long idx, double v)
{
    for (int q = 0; q < s->n; q++)
        if (s->idx[q] == idx) {
            s->w[q] += v;
            return;
        }
    s->idx[s->n] = idx, s->w[s->n++] = v;
}

/* The old flat index of point p of alternative a of class cl, for the new
 * point of cell (i, j). */
static long alt_index(const nl_subdiv_class *cl, int a, size_t p, long i, long j, long cx, long cy)
{
    size_t k = (size_t)a * cl->n + p;
    return wrap(j + cl->offy[k], cy) * cx + wrap(i + cl->offx[k], cx);
}

/* The mean stencil of a class with random neighbourhoods: the new point of
 * an independent, uniform choice among the alternatives is, on average,
 * their mean (its covariance with any other point is the mean's, the
 * choices of two points being independent; its own variance is not:
 * second_moment). */
static void mean_stencil(const nl_subdiv_class *cl, long i, long j, long cx, long cy, stencil *s)
{
    s->var = 0;
    for (int a = 0; a < cl->nalt; a++) {
        for (size_t p = 0; p < cl->n; p++)
            add_point(s, alt_index(cl, a, p, i, j, cx, cy), cl->alt_a[(size_t)a * cl->n + p] / cl->nalt);
        s->var += cl->alt_var[a] / cl->nalt;
    }
}

/* The variance of a new point of cell (i, j) of a class with random
 * neighbourhoods: the mean over the alternatives of a^T C a plus their
 * displacement variance (C the old level's n1 x n1 covariance). */
static double second_moment(const nl_subdiv_class *cl, long i, long j, long cx, long cy, const double *C)
{
    const long n1 = cx * cy;
    double v = 0;
    for (int a = 0; a < cl->nalt; a++) {
        const double *w = cl->alt_a + (size_t)a * cl->n;
        double q = 0;
        for (size_t p = 0; p < cl->n; p++)
            for (size_t r = 0; r < cl->n; r++)
                q += w[p] * w[r] * C[alt_index(cl, a, p, i, j, cx, cy) * n1 + alt_index(cl, a, r, i, j, cx, cy)];
        v += (q + cl->alt_var[a]) / cl->nalt;
    }
    return v;
}

static void make_stencil(const nl_subdiv_level *l, int dim, long cx, long cy, long I, long J, stencil *s)
{
    long i = I / 2, j = J / 2;
    int ox = (int)(I % 2), oy = (int)(J % 2), N = l->N, w = 2 * N;
    const nl_subdiv_class *cl;
    s->n = 0;
    s->ci = i, s->cj = j;
    if (!ox && !oy) {
        s->n = 1, s->idx[0] = j * cx + i, s->w[0] = 1, s->var = 0, s->cls = -1;
        return;
    }
    s->cls = dim == 1 ? 0 : ox && oy ? 0 : ox ? 1 : 2;
    if (l->cls[s->cls].nalt) {
        mean_stencil(&l->cls[s->cls], i, j, cx, cy, s);
        return;
    }
    if (dim == 1) {
        cl = &l->cls[0];
        for (int k = 0; k < w; k++)
            s->idx[s->n] = wrap(i + 1 - N + k, cx), s->w[s->n++] = cl->a[k];
    } else {
        cl = &l->cls[ox && oy ? 0 : ox ? 1 : 2];
        for (int r = 0; r < w; r++)
            for (int q = 0; q < w; q++)
                s->idx[s->n] = wrap(j + 1 - N + r, cy) * cx + wrap(i + 1 - N + q, cx), s->w[s->n++] = cl->a[r * w + q];
    }
    s->var = cl->variance;
}

/* The coefficient sets and sizes the propagation supports. */
static int check_supported(const nl_subdiv_coeffs *c, size_t nx, size_t ny, long cx, long cy)
{
    const int dim = c->dim;
    if ((dim == 2 ? 2 * c->level[c->levels - 1].N : 0) > 8 || (dim == 1 && c->level[c->levels - 1].N > 128))
        return NL_ERROR(NL_EINVAL, "exact covariance: neighbourhood too large");
    for (int k = 0; k < c->levels; k++)
        if (c->level[k].N > 8 && dim == 2)
            return NL_ERROR(NL_EINVAL, "exact covariance: 2D neighbourhoods up to 16x16");
    for (int k = 0; k < c->levels; k++)
        for (int j = 0; j < c->level[k].nclass; j++)
            if (c->level[k].cls[j].nalt && c->level[k].filt)
                return NL_ERROR(NL_EINVAL, "exact covariance: random neighbourhoods with correlated displacements");
    if (nx * ny > 4096)
        return NL_ERROR(NL_ETOOBIG, "exact covariance: expected at most 4096 samples, got %zu", nx * ny);
    if ((size_t)cx << c->levels != nx || (dim == 2 && (size_t)cy << c->levels != ny) || cx < 2)
        return NL_ERROR(NL_EINVAL, "exact covariance: the size must be the coarse size times 2^levels");
    return NL_OK;
}

/* The covariance matrix of the coarse grid (cx x cy, periodic): the model
 * wrapped on it (core/wk.h).  *out is malloc'd (n^2 doubles, n = cx cy). */
static int coarse_covariance(const nl_subdiv_coeffs *c, const nl_model *m, long cx, long cy, double **out)
{
    size_t cn[2] = {(size_t)cx, (size_t)cy};
    double h[2] = {c->spacing0, c->spacing0}, *C;
    int s;
    nl_field *R = nl_field_alloc(c->dim, cn, h, &s);
    if (!R)
        return s;
    if ((s = nl_wk_sample_acf(m, R))) {
        nl_field_free(R);
        return s;
    }
    if (!(C = malloc((size_t)(cx * cy) * (size_t)(cx * cy) * sizeof *C))) {
        nl_field_free(R);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (long p = 0; p < cx * cy; p++)
        for (long q = 0; q < cx * cy; q++) {
            long dx = wrap(q % cx - p % cx, cx), dy = wrap(q / cx - p / cx, cy);
            C[p * cx * cy + q] = R->data[dy * cx + dx];
        }
    nl_field_free(R);
    *out = C;
    return NL_OK;
}

/* The displacement covariance of the level on its periodic cell grid:
 * D[((a nc + b) cy + dy) cx + dx] = Cov(d_a(i), d_b(i + (dx, dy))), the
 * realised covariance summed over the offsets congruent to (dx, dy) (the
 * white numbers wrap with the level). */
static double *disp_table(const nl_subdiv_level *l, int dim, long cx, long cy)
{
    const int nc = l->nclass, R = 2 * l->taps, RY = dim == 2 ? R : 0;
    double *D = calloc((size_t)(nc * nc * cx * cy), sizeof *D);
    if (!D)
        return NULL;
    for (int a = 0; a < nc; a++)
        for (int b = 0; b < nc; b++)
            for (int my = -RY; my <= RY; my++)
                for (int mx = -R; mx <= R; mx++)
                    D[((a * nc + b) * cy + wrap(my, cy)) * cx + wrap(mx, cx)] +=
                        nl_subdiv_disp_realised(l, dim, a, b, mx, my);
    return D;
}

/* One level: C' = M C M^T + D on the grid twice as fine (Lewis 1987,
 * eqs. 4 and 7 per new point; D diagonal when the displacements are
 * independent, else the covariance their filter realises, subdiv.h).
 * *C (cx x cy points) is replaced by the new matrix. */
static int refine_level(const nl_subdiv_level *l, int dim, long cx, long cy, stencil *st, double **C)
{
    long nx2 = 2 * cx, ny2 = dim == 2 ? 2 * cy : 1, n1 = cx * cy, n2 = nx2 * ny2;
    double *T = calloc((size_t)(n2 * n1), sizeof *T), *C2 = malloc((size_t)(n2 * n2) * sizeof *C2);
    double *D = disp_table(l, dim, cx, cy);
    int *cls = malloc((size_t)n2 * sizeof *cls);
    long *cell = malloc((size_t)n2 * sizeof *cell);
    if (!T || !C2 || !D || !cls || !cell) {
        free(T), free(C2), free(D), free(cls), free(cell);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (long P = 0; P < n2; P++) {
        make_stencil(l, dim, cx, cy, P % nx2, P / nx2, st);
        cls[P] = st->cls, cell[P] = st->cj * cx + st->ci;
    }
    for (long P = 0; P < n2; P++) {  /* T = M C (M: the mean stencils) */
        make_stencil(l, dim, cx, cy, P % nx2, P / nx2, st);
        for (int q = 0; q < st->n; q++)
            for (long j = 0; j < n1; j++)
                T[P * n1 + j] += st->w[q] * (*C)[st->idx[q] * n1 + j];
    }
    for (long Q = 0; Q < n2; Q++) {  /* C' = T M^T + D */
        make_stencil(l, dim, cx, cy, Q % nx2, Q / nx2, st);
        for (long P = 0; P < n2; P++) {
            double v = 0;
            for (int q = 0; q < st->n; q++)
                v += st->w[q] * T[P * n1 + st->idx[q]];
            if (cls[P] >= 0 && cls[Q] >= 0) {
                long dx = wrap(cell[Q] % cx - cell[P] % cx, cx), dy = wrap(cell[Q] / cx - cell[P] / cx, cy);
                v += D[((cls[P] * l->nclass + cls[Q]) * cy + dy) * cx + dx];
            }
            C2[P * n2 + Q] = v;
        }
    }
    for (long P = 0; P < n2; P++)  /* a random neighbourhood's own variance */
        if (cls[P] >= 0 && l->cls[cls[P]].nalt)
            C2[P * n2 + P] = second_moment(&l->cls[cls[P]], cell[P] % cx, cell[P] / cx, cx, cy, *C);
    free(D), free(cls), free(cell);
    free(T);
    free(*C);
    *C = C2;
    return NL_OK;
}

/* A stencil big enough for every class of c: n points, or nalt n for the
 * mean of random neighbourhoods. */
static stencil *stencil_alloc(const nl_subdiv_coeffs *c)
{
    size_t cap = 1;
    stencil *s = calloc(1, sizeof *s);
    for (int k = 0; k < c->levels; k++)
        for (int j = 0; j < c->level[k].nclass; j++) {
            const nl_subdiv_class *cl = &c->level[k].cls[j];
            size_t n = cl->nalt ? (size_t)cl->nalt * cl->n : cl->n;
            cap = n > cap ? n : cap;
        }
    if (!s || !(s->idx = malloc(cap * sizeof *s->idx)) || !(s->w = malloc(cap * sizeof *s->w))) {
        if (s)
            free(s->idx);
        free(s);
        return NULL;
    }
    s->cap = (int)cap;
    return s;
}

static void stencil_free(stencil *s)
{
    if (s)
        free(s->idx), free(s->w);
    free(s);
}

/* The covariance at lag (lx, ly) averaged over the pairs inside the grid. */
static double lag_average(const double *C, long cx, long cy, long lx, long ly)
{
    double sum = 0;
    long cnt = 0;
    for (long y = 0; y < cy; y++)
        for (long x = 0; x < cx; x++) {
            long x2 = x + lx, y2 = y + ly;
            if (x2 < 0 || x2 >= cx || y2 < 0 || y2 >= cy)
                continue;
            sum += C[(y * cx + x) * cx * cy + y2 * cx + x2];
            cnt++;
        }
    return cnt ? sum / (double)cnt : 0;
}

int nl_subdiv_exact_acf(const nl_subdiv_coeffs *c, const nl_model *m, size_t nx, size_t ny, size_t nlags,
                        const long *lags, double *out)
{
    const int dim = c->dim;
    long cx = (long)(nx >> c->levels), cy = dim == 2 ? (long)(ny >> c->levels) : 1;
    double *C = NULL;
    stencil *st;
    int s;

    if ((s = check_supported(c, nx, ny, cx, cy)) || (s = coarse_covariance(c, m, cx, cy, &C)))
        return s;
    if (!(st = stencil_alloc(c))) {
        free(C);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    for (int k = 0; k < c->levels; k++) {
        if ((s = refine_level(&c->level[k], dim, cx, cy, st, &C))) {
            free(C), stencil_free(st);
            return s;
        }
        cx *= 2, cy = dim == 2 ? 2 * cy : 1;
    }
    for (size_t i = 0; i < nlags; i++)
        out[i] = lag_average(C, cx, cy, lags[2 * i], dim == 2 ? lags[2 * i + 1] : 0);
    free(C);
    stencil_free(st);
    return NL_OK;
}
