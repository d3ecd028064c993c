/* Rank-1 lattices: generators, wave vectors, one-FFT synthesis, Delaunay. */
#include "rank1.h"
#include "../core/fftw_plan.h"
#include "../core/field.h"
#include "../core/mem.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void nl_rank1_free(nl_rank1_lattice *L)
{
    free(L->k);
    L->k = NULL;
}

void nl_rank1_point(const nl_rank1_lattice *L, size_t n, double *x)
{
    for (int a = 0; a < L->s; a++)
        x[a] = (double)((unsigned long long)n * (unsigned long long)L->g[a] % L->N) / (double)L->N;
}

/* Minimum torus distance between distinct lattice points: that of x_n to 0,
 * with the coordinates n g_a mod N stepped by addition.  The scan stops
 * once the distance is at most `floor` (the value returned is then <=
 * floor: enough for a search that only keeps distances above it). */
static double min_distance_above(size_t N, int s, const long *g, double floor)
{
    double best = INFINITY, f2 = floor > 0 ? floor * floor : -1;
    unsigned long long r[NL_RANK1_MAX_DIM] = {0};
    for (size_t n = 1; n < N; n++) {
        double d2 = 0;
        for (int a = 0; a < s; a++) {
            r[a] += (unsigned long long)g[a];
            if (r[a] >= N)
                r[a] -= N;
            double x = (double)r[a] / (double)N;
            if (x > 0.5)
                x -= 1;
            d2 += x * x;
        }
        best = fmin(best, d2);
        if (best <= f2 && sqrt(best) <= floor)
            break;
    }
    return sqrt(best);
}

static double min_distance(size_t N, int s, const long *g) { return min_distance_above(N, s, g, -1); }

/* Enumerate k in shells of |k|_1 = L: all vectors with sum |k_a| = L. */
typedef struct {
    size_t N;
    int s;
    const long *g;
    double *best;  /* squared norm per residue */
    long *k;
} search;

static void visit(search *q, const long *k)
{
    long long m = 0;
    double n2 = 0;
    for (int a = 0; a < q->s; a++) {
        m += (long long)k[a] * q->g[a];
        n2 += (double)k[a] * (double)k[a];
    }
    m %= (long long)q->N;
    if (m < 0)
        m += (long long)q->N;
    if (n2 < q->best[m]) {
        q->best[m] = n2;
        memcpy(q->k + (size_t)m * q->s, k, (size_t)q->s * sizeof *k);
    }
}

/* Coordinates a.. with remaining |k|_1 budget r, lexicographic from -r up. */
static void shell(search *q, long *k, int a, long r)
{
    if (a == q->s - 1) {
        k[a] = -r;
        visit(q, k);
        if (r) {
            k[a] = r;
            visit(q, k);
        }
        return;
    }
    for (long v = -r; v <= r; v++) {
        k[a] = v;
        shell(q, k, a + 1, r - labs(v));
    }
}

static int wave_vectors(nl_rank1_lattice *L)
{
    search q = {L->N, L->s, L->g, malloc(L->N * sizeof(double)), malloc(L->N * (size_t)L->s * sizeof(long))};
    long k[NL_RANK1_MAX_DIM];
    if (!q.best || !q.k) {
        free(q.best), free(q.k);
        return NL_ERROR(NL_ENOMEM, "out of memory for %zu wave vectors", L->N);
    }
    for (size_t m = 0; m < L->N; m++)
        q.best[m] = INFINITY;
    /* worst: the largest minimal norm^2, scanned only when the shell bound
     * passes the last scan's value (norms only decrease, so the scanned
     * value bounds the current one: the loop stops at the same shell or,
     * scanning less often, after shells that cannot improve any residue) */
    double worst = INFINITY;
    for (long r = 0;; r++) {
        /* every vector of this shell has norm^2 >= r^2 / s */
        if ((double)r * (double)r / L->s > worst || isinf(worst)) {
            int all = 1;
            worst = 0;
            for (size_t m = 0; m < L->N && all; m++) {
                if (isinf(q.best[m]))
                    all = 0;
                else
                    worst = fmax(worst, q.best[m]);
            }
            if (!all)
                worst = INFINITY;
            else if ((double)r * (double)r / L->s > worst)
                break;
        }
        shell(&q, k, 0, r);
    }
    /* symmetric set for a real field */
    for (size_t m = 1; 2 * m < L->N; m++)
        for (int a = 0; a < L->s; a++)
            q.k[(L->N - m) * L->s + a] = -q.k[m * L->s + a];
    free(q.best);
    L->k = q.k;
    return NL_OK;
}

int nl_rank1_generator(size_t N, int s, const long *g, nl_rank1_lattice *L)
{
    memset(L, 0, sizeof *L);
    if (s < 1 || s > NL_RANK1_MAX_DIM)
        return NL_ERROR(NL_EINVAL, "dim: expected 1 to %d, got %d", NL_RANK1_MAX_DIM, s);
    if (N < 2 || N > (1u << 24))
        return NL_ERROR(NL_EINVAL, "points: expected 2 to 16777216, got %zu", N);
    if (g[0] != 1)
        return NL_ERROR(NL_EINVAL, "generator: expected a first component of 1, got %ld", g[0]);
    int st = nl_size_check(1, &N, sizeof(double) + (size_t)s * sizeof(long), 1, NULL);
    if (st)
        return st;
    L->s = s;
    L->N = N;
    for (int a = 0; a < s; a++)
        L->g[a] = ((g[a] % (long)N) + (long)N) % (long)N;
    L->min_dist = min_distance(N, s, L->g);
    return wave_vectors(L);
}

int nl_rank1_check_generator(size_t N, int s, const long *g)
{
    for (int a = 0; a < s; a++) {
        long ga = ((g[a] % (long)N) + (long)N) % (long)N;
        if (a > 0 && ga == 0)
            return NL_ERROR(NL_EINVAL, "generator: degenerate: component %d is 0 mod %zu (every point has x%d = 0)",
                            a + 1, N, a + 1);
        for (int b = 0; b < a; b++) {
            long gb = ((g[b] % (long)N) + (long)N) % (long)N;
            if (ga == gb || (ga + gb) % (long)N == 0)
                return NL_ERROR(NL_EINVAL, "generator: degenerate: components %d and %d are %s mod %zu (the points "
                                "lie on the plane x%d %s x%d = 0)", b + 1, a + 1, ga == gb ? "equal" : "opposite",
                                N, b + 1, ga == gb ? "-" : "+", a + 1);
        }
    }
    return NL_OK;
}

int nl_rank1_fibonacci(int index, nl_rank1_lattice *L)
{
    unsigned long long f[64] = {0, 1, 1};
    long g[2];
    if (index < 3 || index > 34)
        return NL_ERROR(NL_EINVAL, "fibonacci: expected an index from 3 to 34 (N = F_index), got %d", index);
    for (int i = 3; i <= index; i++)
        f[i] = f[i - 1] + f[i - 2];
    g[0] = 1, g[1] = (long)f[index - 1];
    return nl_rank1_generator((size_t)f[index], 2, g, L);
}

int nl_rank1_korobov(size_t N, int s, long a, nl_rank1_lattice *L)
{
    long g[NL_RANK1_MAX_DIM];
    int st;
    if (s < 1 || s > NL_RANK1_MAX_DIM)
        return NL_ERROR(NL_EINVAL, "dim: expected 1 to %d, got %d", NL_RANK1_MAX_DIM, s);
    if (N < 2 || N > (1u << 24))
        return NL_ERROR(NL_EINVAL, "points: expected 2 to 16777216, got %zu", N);
    if ((st = nl_size_check(1, &N, sizeof(double) + (size_t)s * sizeof(long), 1, NULL)))
        return st;
    if (a <= 0) {
        double best = -1;
        /* at most NL_RANK1_SEARCH_BUDGET point coordinates over the candidates */
        size_t tries = N > 4096 ? 4096 : N, cap = NL_RANK1_SEARCH_BUDGET / (N * (size_t)s);
        if (tries > cap)
            tries = cap < 18 ? 18 : cap;
        for (size_t t = 2; t < tries; t++) {
            long cand = (long)t;
            g[0] = 1;
            for (int d = 1; d < s; d++)
                g[d] = (long)((unsigned long long)g[d - 1] * (unsigned long long)cand % N);
            double md = min_distance_above(N, s, g, best + 1e-15);
            if (md > best + 1e-15)
                best = md, a = cand;
        }
        if (a <= 0)
            a = 1;
    }
    g[0] = 1;
    for (int d = 1; d < s; d++)
        g[d] = (long)((unsigned long long)g[d - 1] * (unsigned long long)a % N);
    return nl_rank1_generator(N, s, g, L);
}

int nl_rank1_coefficients(const nl_rank1_lattice *L, nl_rank1_spectrum S, void *ctx, uint64_t seed, double *c)
{
    size_t N = L->N;
    for (size_t m = 0; m <= N / 2; m++) {
        double v = S(L->k + m * L->s, L->s, ctx);
        if (!(v >= 0) || !isfinite(v))
            return NL_ERROR(NL_EINVAL, "spectrum: expected a finite non-negative value, got %g at wave vector %zu", v, m);
        double xi = nl_rng_gauss2(seed, NL_RANK1_STREAM, m, 0), eta = nl_rng_gauss2(seed, NL_RANK1_STREAM, m, 1);
        if (m == 0 || 2 * m == N) {
            c[2 * m] = sqrt(v) * xi, c[2 * m + 1] = 0;
        } else {
            c[2 * m] = sqrt(v / 2) * xi, c[2 * m + 1] = sqrt(v / 2) * eta;
            c[2 * (N - m)] = c[2 * m], c[2 * (N - m) + 1] = -c[2 * m + 1];
        }
    }
    return NL_OK;
}

int nl_rank1_synthesize(const nl_rank1_lattice *L, const double *c, double extent, double *f, double *grad, double *imag)
{
    size_t N = L->N;
    fftw_complex *b = nl_alloc(N * sizeof(fftw_complex));
    fftw_plan p = b ? fftw_plan_dft_1d((int)N, b, b, FFTW_BACKWARD, nl_fftw_flags(N)) : NULL;
    double im = 0;
    if (!p) {
        nl_free(b);
        return NL_ERROR(NL_ENOMEM, "cannot plan an FFT of %zu points", N);
    }
    for (int comp = -1; comp < (grad ? L->s : 0); comp++) {
        for (size_t m = 0; m < N; m++) {
            double complex v = c[2 * m] + I * c[2 * m + 1];
            if (comp >= 0)
                /* the N/2 term's derivative vanishes at every lattice point (sin(pi n) = 0) */
                v *= 2 * m == N ? 0 : I * 2 * M_PI * (double)L->k[m * L->s + comp] / extent;
            b[m] = v;
        }
        fftw_execute(p);
        for (size_t n = 0; n < N; n++) {
            if (comp < 0)
                f[n] = creal(b[n]);
            else
                grad[n * L->s + comp] = creal(b[n]);
            im = fmax(im, fabs(cimag(b[n])));
        }
    }
    if (imag)
        *imag = im;
    fftw_destroy_plan(p);
    nl_free(b);
    return NL_OK;
}

static void torus_vec(const nl_rank1_lattice *L, size_t n, double *v)
{
    nl_rank1_point(L, n, v);
    for (int a = 0; a < 2; a++)
        if (v[a] >= 0.5)
            v[a] -= 1;
}

int nl_rank1_delaunay(const nl_rank1_lattice *L, size_t *n1, size_t *n2, double *v1, double *v2)
{
    double b1 = INFINITY, b2 = INFINITY, v[2];
    if (L->s != 2)
        return NL_ERROR(NL_EINVAL, "delaunay: expected a 2D lattice, got %dD", L->s);
    if (L->N < 3)
        return NL_ERROR(NL_EINVAL, "delaunay: expected at least 3 points");
    for (size_t n = 1; n < L->N; n++) {
        torus_vec(L, n, v);
        double d = v[0] * v[0] + v[1] * v[1];
        if (d < b1)
            b1 = d, *n1 = n, v1[0] = v[0], v1[1] = v[1];
    }
    for (size_t n = 1; n < L->N; n++) {
        torus_vec(L, n, v);
        double d = v[0] * v[0] + v[1] * v[1], det = v1[0] * v[1] - v1[1] * v[0];
        if (fabs(fabs(det) * (double)L->N - 1) < 1e-6 && d < b2)
            b2 = d, *n2 = n, v2[0] = v[0], v2[1] = v[1];
    }
    if (isinf(b2))
        return NL_ERROR(NL_EFAIL, "delaunay: the %zu points of generator (%ld, %ld) lie on one line of the torus "
                        "(no second basis vector); expected a generator that is not degenerate", L->N, L->g[0], L->g[1]);
    if (v1[0] * v2[0] + v1[1] * v2[1] < 0) {
        v2[0] = -v2[0], v2[1] = -v2[1];
        *n2 = L->N - *n2;
    }
    return NL_OK;
}

/* The Delaunay cell of point n: the parallelogram's corners P (unwrapped)
 * and their point indices id; triangles tri[0] and tri[1] of it. */
static const int tri[2][3] = {{0, 1, 2}, {1, 3, 2}};

static void cell(const nl_rank1_lattice *L, size_t n, size_t n1, size_t n2, const double *v1, const double *v2,
                 size_t id[4], double P[4][2])
{
    size_t N = L->N;
    double x[2];
    id[0] = n, id[1] = (n + n1) % N, id[2] = (n + n2) % N, id[3] = (n + n1 + n2) % N;
    nl_rank1_point(L, n, x);
    P[0][0] = x[0], P[0][1] = x[1];
    P[1][0] = x[0] + v1[0], P[1][1] = x[1] + v1[1];
    P[2][0] = x[0] + v2[0], P[2][1] = x[1] + v2[1];
    P[3][0] = x[0] + v1[0] + v2[0], P[3][1] = x[1] + v1[1] + v2[1];
}

int nl_rank1_rasterize(const nl_rank1_lattice *L, const double *f, const double *grad, size_t W, double *img,
                    double *gx, double *gy)
{
    size_t n1, n2, N = L->N;
    double v1[2], v2[2];
    int st = nl_rank1_delaunay(L, &n1, &n2, v1, v2);
    if (st)
        return st;
    if (W < 1 || !f || !img)
        return NL_ERROR(NL_EINVAL, "rasterize: expected values and an image of at least 1 x 1 pixels");
    for (size_t n = 0; n < N; n++) {
        size_t id[4];
        double P[4][2];
        cell(L, n, n1, n2, v1, v2, id, P);
        for (int t = 0; t < 2; t++) {
            const double *a = P[tri[t][0]], *b = P[tri[t][1]], *c = P[tri[t][2]];
            double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
            double lo[2], hi[2];
            for (int q = 0; q < 2; q++) {
                lo[q] = fmin(a[q], fmin(b[q], c[q])) * (double)W - 0.5;
                hi[q] = fmax(a[q], fmax(b[q], c[q])) * (double)W - 0.5;
            }
            for (long py = (long)ceil(lo[1]); py <= (long)floor(hi[1]); py++)
                for (long px = (long)ceil(lo[0]); px <= (long)floor(hi[0]); px++) {
                    double X = ((double)px + 0.5) / (double)W, Y = ((double)py + 0.5) / (double)W;
                    double wb = ((X - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (Y - a[1])) / det;
                    double wc = ((b[0] - a[0]) * (Y - a[1]) - (X - a[0]) * (b[1] - a[1])) / det;
                    double wa = 1 - wb - wc;
                    if (wa < -1e-12 || wb < -1e-12 || wc < -1e-12)
                        continue;
                    size_t ix = (size_t)(((px % (long)W) + (long)W) % (long)W);
                    size_t iy = (size_t)(((py % (long)W) + (long)W) % (long)W), q = iy * W + ix;
                    size_t ia = id[tri[t][0]], ib = id[tri[t][1]], ic = id[tri[t][2]];
                    img[q] = wa * f[ia] + wb * f[ib] + wc * f[ic];
                    if (grad && gx && gy) {
                        gx[q] = wa * grad[2 * ia] + wb * grad[2 * ib] + wc * grad[2 * ic];
                        gy[q] = wa * grad[2 * ia + 1] + wb * grad[2 * ib + 1] + wc * grad[2 * ic + 1];
                    }
                }
        }
    }
    return NL_OK;
}

int nl_rank1_mesh_init(const nl_rank1_lattice *L, double extent, const double *f, nl_rank1_mesh *m)
{
    if (!(extent > 0) || !isfinite(extent))
        return NL_ERROR(NL_EINVAL, "mesh: expected a positive finite extent, got %g", extent);
    m->L = L, m->extent = extent, m->f = f;
    return nl_rank1_delaunay(L, &m->n1, &m->n2, m->v1, m->v2);
}

void nl_rank1_mesh_triangle(const void *mesh, size_t t, double xyz[9])
{
    const nl_rank1_mesh *m = mesh;
    size_t id[4];
    double P[4][2];
    cell(m->L, t / 2, m->n1, m->n2, m->v1, m->v2, id, P);
    for (int v = 0; v < 3; v++) {
        int c = tri[t % 2][v];
        xyz[3 * v] = P[c][0] * m->extent, xyz[3 * v + 1] = P[c][1] * m->extent;
        xyz[3 * v + 2] = m->f ? m->f[id[c]] : 0;
    }
}

int nl_rank1_fibonacci_index(size_t N)
{
    unsigned long long a = 1, b = 1;
    for (int i = 2; i < 80 && b <= N; i++) {
        if (b == N && i >= 3)
            return i;
        unsigned long long c = a + b;
        a = b, b = c;
    }
    return 0;
}

double nl_rank1_wave_norm(const nl_rank1_lattice *L, size_t m)
{
    double n2 = 0;
    for (int a = 0; a < L->s; a++)
        n2 += (double)L->k[m * L->s + a] * L->k[m * L->s + a];
    return sqrt(n2);
}
