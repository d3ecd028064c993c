/* Neighbourhoods whose nmax-th and next nearest data are equidistant (a
 * tie): which of them gstat takes is decided by the order in which its
 * search visits them, gstat's quadtree (src/nsearch.c: init_qtree,
 * qtree_push, get_nearest_point; 4 points a leaf, depth 11 at most, the
 * root box the data's minimum corner and 1.01 times their widest span) and
 * its priority queue (src/pqueue.c: a batch is sorted by distance, points
 * before boxes at equal distance, and inserted before the equal elements
 * already queued).  This file replays that search for the data of a plan
 * (less the datum a cross-validation leaves out, as gstat.cv rebuilds its
 * tree without it), so that the neighbourhoods equal gstat's ties
 * included.  Used at ties only: elsewhere the nearest nmax are one set. */
#include "krige_local_internal.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { GQ_SPLIT = 4, GQ_DEPTH = 11 };

struct nl_gq_node {
    double lo[3], size;       /* the box: lo[a] .. lo[a] + size */
    int leaf;                 /* a leaf holds points; else up to 2^dim children */
    size_t npts, cap, *pts;   /* a leaf's data indices, in the order pushed */
    struct nl_gq_node *kid[8];
};

static void node_free(nl_gq_node *q)
{
    if (!q)
        return;
    for (int i = 0; i < 8; i++)
        node_free(q->kid[i]);
    free(q->pts), free(q);
}

void nl_gq_free(nl_gq_node *root) { node_free(root); }

static nl_gq_node *node_new(const double *lo, double size)
{
    nl_gq_node *q = calloc(1, sizeof *q);
    if (q)
        memcpy(q->lo, lo, sizeof q->lo), q->size = size, q->leaf = 1;
    return q;
}

/* gstat's get_index: the child of box q holding point p. */
static int child_of(const nl_gq_node *q, int dim, const double *p)
{
    int i = 0;
    for (int a = 0; a < dim; a++)
        i |= (p[a] >= q->lo[a] + 0.5 * q->size) << a;
    return i;
}

static int push(const nl_krige_local *k, size_t j, nl_gq_node *q, int depth);

/* gstat's qtree_split_node: the leaf becomes a box, its points pushed again. */
static int split(const nl_krige_local *k, nl_gq_node *q, int depth)
{
    size_t n = q->npts, *list = q->pts;
    q->leaf = 0, q->pts = NULL, q->npts = q->cap = 0;
    int st = 0;
    for (size_t i = 0; !st && i < n; i++)
        st = push(k, list[i], q, depth);
    free(list);
    return st;
}

/* gstat's qtree_push: down to the leaf of datum j (made when absent),
 * split when full and not too deep. */
static int push(const nl_krige_local *k, size_t j, nl_gq_node *q, int depth)
{
    const double *p = k->pts + j * (size_t)k->dim;
    depth++;
    while (!q->leaf) {
        int c = child_of(q, k->dim, p);
        if (!q->kid[c]) {
            double lo[3];
            for (int a = 0; a < 3; a++)
                lo[a] = q->lo[a] + (c >> a & 1) * 0.5 * q->size;
            if (!(q->kid[c] = node_new(lo, 0.5 * q->size)))
                return -1;
        }
        q = q->kid[c];
    }
    if (q->npts == GQ_SPLIT && depth < GQ_DEPTH)
        return split(k, q, depth) ? -1 : push(k, j, q, depth);
    if (q->npts == q->cap) {
        size_t *w = realloc(q->pts, (q->cap ? 2 * q->cap : GQ_SPLIT) * sizeof *w);
        if (!w)
            return -1;
        q->pts = w, q->cap = q->cap ? 2 * q->cap : GQ_SPLIT;
    }
    q->pts[q->npts++] = j;
    return 0;
}

nl_gq_node *nl_gq_build(const nl_krige_local *k, size_t skip)
{
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, span = 0;
    int dim = k->dim, first = 1;
    size_t used = 0;
    for (size_t i = 0; i < k->n; i++) {
        if (i == skip)
            continue;
        for (int a = 0; a < dim; a++) {
            double v = k->pts[i * (size_t)dim + (size_t)a];
            lo[a] = first || v < lo[a] ? v : lo[a], hi[a] = first || v > hi[a] ? v : hi[a];
        }
        first = 0, used++;
    }
    for (int a = 0; a < dim; a++)
        span = fmax(span, fabs(hi[a] - lo[a]));
    nl_gq_node *root = node_new(lo, span * 1.01);
    if (!root)
        return NULL;
    root->leaf = used < GQ_SPLIT; /* gstat's init_qnode(root, n < split) */
    for (size_t i = 0; i < k->n; i++)
        if (i != skip && push(k, i, root, 0)) {
            node_free(root);
            return NULL;
        }
    return root;
}

/* The queue: elements linked by index, as gstat's (src/pqueue.c). */
typedef struct {
    double d2;
    int is_node;
    const nl_gq_node *node;
    size_t pt;
    long next;
} gq_el;

typedef struct {
    gq_el *e;
    size_t len, cap;
    long head;
} gq_queue;

/* gstat's node_cmp: distance, then points before boxes. */
static int cmp(const gq_el *a, const gq_el *b)
{
    if (a->d2 != b->d2)
        return a->d2 < b->d2 ? -1 : 1;
    return a->is_node == b->is_node ? 0 : a->is_node ? 1 : -1;
}

static long add(gq_queue *q, const gq_el *el)
{
    if (q->len == q->cap) {
        size_t c = q->cap ? 2 * q->cap : 64;
        gq_el *w = realloc(q->e, c * sizeof *w);
        if (!w)
            return -1;
        q->e = w, q->cap = c;
    }
    q->e[q->len] = *el;
    return (long)q->len++;
}

/* gstat's enqueue: el (n, sorted here stably) merged into the queue. */
static int enqueue(gq_queue *q, gq_el *el, size_t n)
{
    for (size_t i = 1; i < n; i++) /* insertion sort: stable, as glibc's merge sort */
        for (size_t j = i; j > 0 && cmp(&el[j - 1], &el[j]) > 0; j--) {
            gq_el t = el[j];
            el[j] = el[j - 1], el[j - 1] = t;
        }
    size_t p = n;
    if (q->head >= 0)
        for (; p > 0; p--)
            if (cmp(&el[p - 1], &q->e[q->head]) <= 0)
                break;
    for (size_t i = p; i > 0; i--) {
        long e = add(q, &el[i - 1]);
        if (e < 0)
            return -1;
        q->e[e].next = q->head, q->head = e;
    }
    long where = q->head, next = where >= 0 ? q->e[where].next : -1;
    for (size_t i = p; i < n; i++) {
        long e = add(q, &el[i]);
        if (e < 0)
            return -1;
        while (next >= 0 && cmp(&q->e[e], &q->e[next]) > 0)
            where = next, next = q->e[where].next;
        q->e[e].next = next, q->e[where].next = e;
        where = e;
    }
    return 0;
}

/* gstat's pb_norm2: squared distance from x to a box. */
static double box_d2(const nl_gq_node *q, int dim, const double *x)
{
    double s = 0;
    for (int a = 0; a < dim; a++) {
        double d = 0, b = q->lo[a];
        if (x[a] < b)
            d = b - x[a];
        else if (x[a] > b + q->size)
            d = x[a] - (b + q->size);
        s += d * d;
    }
    return s;
}

double nl_gq_d2(int dim, const double *x, const double *p)
{
    double s = 0;
    for (int a = 0; a < dim; a++)
        s += (x[a] - p[a]) * (x[a] - p[a]);
    return s;
}

/* gstat's get_nearest_point; SIZE_MAX when the queue runs out (or memory). */
static size_t nearest(const nl_krige_local *k, gq_queue *q, const double *x, double *d2)
{
    gq_el el[8 + GQ_SPLIT], *big = NULL;
    while (q->head >= 0) {
        gq_el h = q->e[q->head];
        q->head = h.next;
        if (!h.is_node) {
            *d2 = h.d2;
            return h.pt;
        }
        const nl_gq_node *nd = h.node;
        size_t n = 0;
        gq_el *v = el;
        if (nd->leaf && nd->npts > sizeof el / sizeof *el && !(v = big = malloc(nd->npts * sizeof *v)))
            return SIZE_MAX;
        if (nd->leaf)
            for (size_t i = 0; i < nd->npts; i++)
                v[n++] = (gq_el){nl_gq_d2(k->dim, x, k->pts + nd->pts[i] * (size_t)k->dim), 0, NULL, nd->pts[i], -1};
        else
            for (int c = 0; c < 1 << k->dim; c++)
                if (nd->kid[c])
                    v[n++] = (gq_el){box_d2(nd->kid[c], k->dim, x), 1, nd->kid[c], 0, -1};
        int st = n ? enqueue(q, v, n) : 0;
        free(big), big = NULL;
        if (st)
            return SIZE_MAX;
    }
    return SIZE_MAX;
}

size_t nl_gq_select(const nl_krige_local *k, const nl_gq_node *root, const double *x, size_t want, size_t *out)
{
    gq_queue q = {.head = -1};
    gq_el r = {0, 1, root, 0, -1};
    double rad2 = k->o.radius * k->o.radius, d2;
    size_t m = 0, j;
    if (add(&q, &r) < 0)
        return 0;
    q.head = 0;
    while (m < want && (j = nearest(k, &q, x, &d2)) != SIZE_MAX && (k->o.radius == 0 || d2 <= rad2))
        out[m++] = j;
    free(q.e);
    return m;
}
