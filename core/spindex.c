/* k-d tree over 1-3D points (Friedman, Bentley and Finkel 1977): median
 * splits on the axis of largest spread, buckets of NL_SPINDEX_LEAF points,
 * a bounding box per node for pruning. */
#include "spindex.h"
#include "field.h"
#include "mem.h"
#include "nl_error.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    size_t lo, hi;         /* tree positions [lo, hi) */
    size_t left, right;    /* children (node numbers), 0 for a leaf */
    double bmin[3], bmax[3]; /* bounding box */
} node_t;

struct nl_spindex {
    int dim;       /* 1..3 */
    size_t n;      /* points */
    double *x;     /* n * dim coordinates in tree order */
    size_t *perm;  /* tree position -> original index */
    node_t *node;  /* nodes, root at 0 */
    size_t nnode;  /* nodes used */
};

void nl_spindex_free(nl_spindex *s)
{
    if (!s)
        return;
    nl_free(s->x), nl_free(s->perm), nl_free(s->node), free(s);
}

size_t nl_spindex_size(const nl_spindex *s) { return s->n; }
int nl_spindex_dim(const nl_spindex *s) { return s->dim; }

/* Move the k-th smallest of perm[lo, hi) along axis a to position k
 * (quickselect with a three-way partition, so repeated values terminate). */
static void select_k(const double *pts, int dim, size_t *perm, size_t lo, size_t hi, size_t k, int a)
{
    while (hi - lo > 1) {
        size_t m = lo + (hi - lo) / 2;
        double p0 = pts[perm[lo] * dim + a], p1 = pts[perm[m] * dim + a], p2 = pts[perm[hi - 1] * dim + a];
        double piv = fmax(fmin(p0, p1), fmin(fmax(p0, p1), p2)); /* median of three */
        size_t lt = lo, i = lo, gt = hi;
        while (i < gt) {
            double v = pts[perm[i] * dim + a];
            size_t t;
            if (v < piv)
                t = perm[i], perm[i] = perm[lt], perm[lt] = t, lt++, i++;
            else if (v > piv)
                gt--, t = perm[i], perm[i] = perm[gt], perm[gt] = t;
            else
                i++;
        }
        if (k < lt)
            hi = lt;
        else if (k >= gt)
            lo = gt;
        else
            return;
    }
}

/* Build the subtree over [lo, hi) at node number id (depth: the tree's height). */
static void build(nl_spindex *s, const double *pts, size_t id, size_t lo, size_t hi)
{
    node_t *nd = &s->node[id];
    int dim = s->dim, axis = 0;
    nd->lo = lo, nd->hi = hi, nd->left = nd->right = 0;
    for (int a = 0; a < dim; a++)
        nd->bmin[a] = INFINITY, nd->bmax[a] = -INFINITY;
    for (size_t i = lo; i < hi; i++)
        for (int a = 0; a < dim; a++) {
            double v = pts[s->perm[i] * dim + a];
            nd->bmin[a] = fmin(nd->bmin[a], v), nd->bmax[a] = fmax(nd->bmax[a], v);
        }
    if (hi - lo <= NL_SPINDEX_LEAF)
        return;
    for (int a = 1; a < dim; a++)
        if (nd->bmax[a] - nd->bmin[a] > nd->bmax[axis] - nd->bmin[axis])
            axis = a;
    size_t mid = lo + (hi - lo) / 2;
    select_k(pts, dim, s->perm, lo, hi, mid, axis);
    size_t l = s->nnode++, r = s->nnode++;
    nd->left = l, nd->right = r;
    build(s, pts, l, lo, mid);
    build(s, pts, r, mid, hi);
}

int nl_spindex_alloc(int dim, size_t n, const double *pts, nl_spindex **out)
{
    *out = NULL;
    if (dim < 1 || dim > 3)
        return NL_ERROR(NL_EINVAL, "spatial index: expected 1 to 3 coordinates per point, got %d", dim);
    if (n == 0)
        return NL_ERROR(NL_EINVAL, "spatial index: expected at least one point, got 0");
    for (size_t i = 0; i < n * (size_t)dim; i++)
        if (!isfinite(pts[i]))
            return NL_ERROR(NL_EINVAL, "spatial index: coordinate %d of point %zu is %g; expected a finite number",
                            (int)(i % (size_t)dim) + 1, i / (size_t)dim + 1, pts[i]);
    size_t nmax = n / 2 + 2; /* leaves hold > NL_SPINDEX_LEAF / 2 points: at most n / 4 leaves */
    size_t bytes = n * (dim * sizeof(double) + sizeof(size_t)) + nmax * sizeof(node_t);
    size_t avail = nl_mem_available();
    if (n > SIZE_MAX / 64 || (avail && bytes > avail))
        return NL_ERROR(NL_ETOOBIG, "spatial index: %zu points need %zu bytes, more than the %zu available", n,
                        bytes, avail);
    nl_spindex *s = calloc(1, sizeof *s);
    if (!s)
        return NL_ERROR(NL_ENOMEM, "spatial index: out of memory");
    s->dim = dim, s->n = n;
    s->x = nl_alloc(n * dim * sizeof(double)), s->perm = nl_alloc(n * sizeof(size_t));
    s->node = nl_alloc(nmax * sizeof(node_t));
    if (!s->x || !s->perm || !s->node) {
        nl_spindex_free(s);
        return NL_ERROR(NL_ENOMEM, "spatial index: out of memory for %zu points", n);
    }
    for (size_t i = 0; i < n; i++)
        s->perm[i] = i;
    s->nnode = 1;
    build(s, pts, 0, 0, n);
    for (size_t i = 0; i < n; i++)
        memcpy(s->x + i * dim, pts + s->perm[i] * dim, dim * sizeof(double));
    *out = s;
    return NL_OK;
}

/* The best `cap` candidates so far: a max-heap on (d2, index). */
typedef struct {
    size_t cap, len, count; /* capacity, held, all within the bound */
    size_t *idx;            /* cap indices */
    double *d2;             /* cap squared distances */
    double bound;           /* squared radius (INFINITY for knn) */
    int count_all;          /* count every point within the bound (no pruning by the heap) */
} heap_t;

static int worse(double da, size_t ia, double db, size_t ib) { return da > db || (da == db && ia > ib); }

/* Where (d, i) goes when it replaces the root of the h->len entries:
 * larger children move up along the way. */
static size_t sift_down(heap_t *h, double d, size_t i)
{
    size_t c = 0;
    for (;;) {
        size_t l = 2 * c + 1, r = l + 1, b = c;
        double bd = d;
        size_t bi = i;
        if (l < h->len && worse(h->d2[l], h->idx[l], bd, bi))
            b = l, bd = h->d2[l], bi = h->idx[l];
        if (r < h->len && worse(h->d2[r], h->idx[r], bd, bi))
            b = r;
        if (b == c)
            return c;
        h->d2[c] = h->d2[b], h->idx[c] = h->idx[b];
        c = b;
    }
}

static void heap_push(heap_t *h, double d, size_t i)
{
    size_t c;
    if (h->len < h->cap) {
        c = h->len++;
        while (c > 0 && worse(d, i, h->d2[(c - 1) / 2], h->idx[(c - 1) / 2])) {
            h->d2[c] = h->d2[(c - 1) / 2], h->idx[c] = h->idx[(c - 1) / 2];
            c = (c - 1) / 2;
        }
    } else {
        if (h->cap == 0 || !worse(h->d2[0], h->idx[0], d, i))
            return;
        c = sift_down(h, d, i); /* replace the root */
    }
    h->d2[c] = d, h->idx[c] = i;
}

static double box_d2(const node_t *nd, int dim, const double *x)
{
    double s = 0;
    for (int a = 0; a < dim; a++) {
        double e = x[a] < nd->bmin[a] ? nd->bmin[a] - x[a] : x[a] > nd->bmax[a] ? x[a] - nd->bmax[a] : 0;
        s += e * e;
    }
    return s;
}

/* Depth-first search, nearer child first; depth is the tree's height. */
static void search(const nl_spindex *s, size_t id, const double *x, heap_t *h)
{
    const node_t *nd = &s->node[id];
    int dim = s->dim;
    if (!nd->left) {
        for (size_t p = nd->lo; p < nd->hi; p++) {
            double d = 0;
            for (int a = 0; a < dim; a++) {
                double e = s->x[p * dim + a] - x[a];
                d += e * e;
            }
            if (d <= h->bound) {
                h->count++;
                heap_push(h, d, s->perm[p]);
            }
        }
        return;
    }
    size_t c[2] = {nd->left, nd->right};
    double dc[2] = {box_d2(&s->node[c[0]], dim, x), box_d2(&s->node[c[1]], dim, x)};
    int first = dc[1] < dc[0];
    for (int k = 0; k < 2; k++) {
        int j = k ? !first : first;
        double lim = !h->count_all && h->len == h->cap && h->cap ? fmin(h->bound, h->d2[0]) : h->bound;
        if (dc[j] <= lim)
            search(s, c[j], x, h);
    }
}

/* Sort the heap's entries ascending (heap sort in place). */
static void heap_sort(heap_t *h)
{
    size_t len = h->len;
    while (h->len > 1) {
        double d = h->d2[0];
        size_t i = h->idx[0], last = --h->len;
        double dl = h->d2[last];
        size_t il = h->idx[last];
        h->cap = h->len; /* sift dl down from the root over len - 1 entries */
        size_t c = sift_down(h, dl, il);
        h->d2[c] = dl, h->idx[c] = il;
        h->d2[last] = d, h->idx[last] = i;
    }
    h->len = len;
}

size_t nl_spindex_knn(const nl_spindex *s, const double *x, size_t k, size_t *idx, double *d2)
{
    heap_t h = {.cap = k < s->n ? k : s->n, .idx = idx, .d2 = d2, .bound = INFINITY};
    if (h.cap)
        search(s, 0, x, &h);
    heap_sort(&h);
    return h.len;
}

size_t nl_spindex_within(const nl_spindex *s, const double *x, double r, size_t cap, size_t *idx, double *d2)
{
    heap_t h = {.cap = cap, .idx = idx, .d2 = d2, .bound = r * r, .count_all = 1};
    if (r >= 0)
        search(s, 0, x, &h);
    heap_sort(&h);
    return h.count;
}

/* Pairs of tree position a with positions b > a within the bound. */
static int pairs_of(const nl_spindex *s, size_t a, double c2, nl_spindex_pair_fn fn, void *ctx)
{
    size_t stack[128], top = 0;
    int dim = s->dim;
    const double *x = s->x + a * dim;
    stack[top++] = 0;
    while (top) {
        const node_t *nd = &s->node[stack[--top]];
        if (nd->hi <= a + 1 || box_d2(nd, dim, x) >= c2)
            continue;
        if (nd->left) {
            if (top + 2 > sizeof stack / sizeof *stack)
                return NL_ERROR(NL_EFAIL, "spatial index: tree deeper than 64 levels");
            stack[top++] = nd->right, stack[top++] = nd->left;
            continue;
        }
        for (size_t p = nd->lo > a + 1 ? nd->lo : a + 1; p < nd->hi; p++) {
            double d = 0;
            for (int k = 0; k < dim; k++) {
                double e = s->x[p * dim + k] - x[k];
                d += e * e;
            }
            if (d < c2) {
                size_t i = s->perm[a], j = s->perm[p];
                int st = fn(ctx, i < j ? i : j, i < j ? j : i, d);
                if (st)
                    return st;
            }
        }
    }
    return 0;
}

int nl_spindex_pairs_at(const nl_spindex *s, size_t a, double cutoff, nl_spindex_pair_fn fn, void *ctx)
{
    return a + 1 < s->n ? pairs_of(s, a, cutoff * cutoff, fn, ctx) : 0;
}

int nl_spindex_pairs(const nl_spindex *s, double cutoff, nl_spindex_pair_fn fn, void *ctx)
{
    double c2 = cutoff * cutoff;
    for (size_t a = 0; a + 1 < s->n; a++) {
        int st = pairs_of(s, a, c2, fn, ctx);
        if (st)
            return st;
    }
    return 0;
}
