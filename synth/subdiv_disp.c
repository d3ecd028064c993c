/* Correlated displacements for generalized stochastic subdivision.
 *
 * Lewis 1987 draws the displacement of every new point independently with
 * the variance of eq. (7).  The estimation errors of the new points of one
 * level are correlated, though, and so are the values the field needs
 * there.  Here the new points of a level are grouped by cell: cell i (2D:
 * (i, j)) holds the new points of the classes a (1D: the midpoint; 2D:
 * face, edge-x, edge-y, in the order of nl_subdiv_level.cls), at
 *     p_a(i) = (i + t_a) s,  t_mid = 1/2; t_face = (1/2, 1/2),
 *     t_edge-x = (1/2, 0), t_edge-y = (0, 1/2),
 * each estimated as sum_k a^a_k x((i + o^a_k) s) from its neighbourhood
 * (subdiv.h).  Two covariances of the displacements are of interest, both
 * stationary over cells (C^{ab}(m) = Cov(d_a(i), d_b(i + m))):
 *   error    the covariance of the true estimation errors
 *            e_a(i) = x(p_a(i)) - sum_k a^a_k x((i + o^a_k) s),
 *              C = R_nn - A R_on - R_no A^T + A R_oo A^T;
 *   new-new  the covariance that makes the new points' block exact when the
 *            old level is exact: x_new = A x_old + d gives
 *            Cov(x_new) = A R_oo A^T + C, so
 *              C = R_nn - A R_oo A^T.
 * Both have eq. (7) on the diagonal (C^{aa}(0)): the orthogonality
 * principle (eq. 4) makes the cross terms equal there.  They differ by the
 * cross terms of new points with old points outside their neighbourhoods.
 *
 * The displacements are d = g * w: w_b(i) the white numbers the independent
 * construction draws for the same points, and g a matrix-valued filter of
 * taps g^{ab}(p), |p| <= M per axis, such that
 *     Cov(d_a(i), d_b(i + m)) = sum_c sum_p g^{ac}(p) g^{bc}(p - m)
 * approximates C: g is the Hermitian square root of C's spectral matrix
 * S(f) = sum_m C(m) e^{-2 pi i f.m} (negative eigenvalues set to 0),
 * transformed back and truncated to |p| <= M; each row is then scaled so
 * that the variances C^{aa}(0) are kept exactly.  Every displacement stays a
 * function of (seed, level, integer position) through a finite window of
 * white noise, so windows and seed images work as with independent draws. */
#include "subdiv_internal.h"
#include "../core/gsl_guard_internal.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_eigen.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Covariance offsets |m| <= DISP_K (per axis) enter the spectrum, sampled on
 * DISP_L (per axis) frequencies. */
#define DISP_K1 64
#define DISP_L1 256
#define DISP_K2 12
#define DISP_L2 32

/* A class's error as a weighted point set in half-cell units:
 * e_a = x(t_a) - sum_k a_k x(o_k); point 0 is the target (weight 1). */
typedef struct {
    int n;
    int *hx, *hy;
    double *w;
} pattern;

static void pattern_free(pattern *p) { free(p->hx), free(p->hy), free(p->w); }

static int pattern_make(const nl_subdiv_level *l, int dim, int a, pattern *p)
{
    const nl_subdiv_class *cl = &l->cls[a];
    const int N = l->N, w = 2 * N;
    p->n = (int)cl->n + 1;
    p->hx = malloc((size_t)p->n * sizeof *p->hx);
    p->hy = malloc((size_t)p->n * sizeof *p->hy);
    p->w = malloc((size_t)p->n * sizeof *p->w);
    if (!p->hx || !p->hy || !p->w)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    p->hx[0] = cl->cls == NL_SUBDIV_EDGE_Y ? 0 : 1;
    p->hy[0] = dim == 2 && cl->cls != NL_SUBDIV_EDGE_X ? 1 : 0;
    p->w[0] = 1;
    for (int k = 0; k < (int)cl->n; k++) {
        p->hx[k + 1] = dim == 1 ? 2 * (k + 1 - N) : 2 * (k % w + 1 - N);
        p->hy[k + 1] = dim == 1 ? 0 : 2 * (k / w + 1 - N);
        p->w[k + 1] = -cl->a[k];
    }
    return NL_OK;
}

/* R on the half-cell grid |hx|, |hy| <= H (hy = 0 in 1D), at spacing s / 2. */
typedef struct {
    int H, HY, W;  /* HY = H in 2D, 0 in 1D */
    double *v;
} rtable;

static int rtable_make(const nl_model *m, int dim, double s, int H, rtable *t)
{
    t->H = H, t->HY = dim == 2 ? H : 0, t->W = 2 * H + 1;
    t->v = malloc((size_t)t->W * (size_t)(dim == 2 ? t->W : 1) * sizeof *t->v);
    if (!t->v)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (int y = dim == 2 ? -H : 0; y <= (dim == 2 ? H : 0); y++)
        for (int x = -H; x <= H; x++) {
            double lag[3] = {0.5 * s * x, 0.5 * s * y, 0};
            double v = nl_model_acf(m, dim, lag);
            if (!isfinite(v)) {
                free(t->v);
                return NL_ERROR(NL_EINVAL, "%s: the covariance is not finite (%g) at lag (%g, %g), which "
                                "correlated displacements evaluate", nl_model_spec(m), v, lag[0], lag[1]);
            }
            t->v[(y + t->HY) * t->W + x + H] = v;
        }
    return NL_OK;
}

static inline double rt(const rtable *t, int x, int y) { return t->v[(y + t->HY) * t->W + x + t->H]; }

/* The sign of the term (i, j) of C (points i of a's pattern, j of b's): the
 * error covariance takes every term as weighted; new-new, R_nn - A R_oo A^T,
 * drops the cross terms and negates the old-old ones. */
static double term_sign(int i, int j, int target)
{
    if (target != NL_SUBDIV_DISP_NEWNEW)
        return 1;
    return (i == 0) != (j == 0) ? 0 : i > 0 ? -1 : 1;
}

/* C^{ab}(m) at cell offset (mx, my) for the chosen target (see the top). */
static double disp_cov(const pattern *pa, const pattern *pb, const rtable *t, int mx, int my, int target)
{
    double v = 0;
    for (int i = 0; i < pa->n; i++)
        for (int j = 0; j < pb->n; j++)
            v += term_sign(i, j, target) * pa->w[i] * pb->w[j] *
                 rt(t, pb->hx[j] + 2 * mx - pa->hx[i], pb->hy[j] + 2 * my - pa->hy[i]);
    return v;
}

double nl_subdiv_disp_target(const nl_subdiv_level *l, const nl_model *m, int dim, int target, int a, int b, int mx,
                             int my)
{
    pattern p[2] = {{0}};
    double v = NAN;
    if (pattern_make(l, dim, a, &p[0]) == NL_OK && pattern_make(l, dim, b, &p[1]) == NL_OK) {
        v = 0;
        for (int i = 0; i < p[0].n; i++)
            for (int j = 0; j < p[1].n; j++) {
                double lag[3] = {0.5 * l->spacing * (p[1].hx[j] + 2 * mx - p[0].hx[i]),
                                 0.5 * l->spacing * (p[1].hy[j] + 2 * my - p[0].hy[i]), 0};
                v += term_sign(i, j, target) * p[0].w[i] * p[1].w[j] * nl_model_acf(m, dim, lag);
            }
    }
    pattern_free(&p[0]), pattern_free(&p[1]);
    return v;
}

/* The taps: Hermitian square root of the spectral matrix, per frequency. */
static int filter_from_cov(int dim, int nc, int K, int L, int M, const double *C, double *g)
{
    const int ly = dim == 2 ? L : 1, ky = dim == 2 ? K : 0, my = dim == 2 ? M : 0, W = 2 * K + 1;
    const int T = 2 * M + 1, TY = dim == 2 ? T : 1;
    gsl_matrix_complex *S = gsl_matrix_complex_alloc((size_t)nc, (size_t)nc);
    gsl_matrix_complex *V = gsl_matrix_complex_alloc((size_t)nc, (size_t)nc);
    gsl_vector *lam = gsl_vector_alloc((size_t)nc);
    gsl_eigen_hermv_workspace *ws = gsl_eigen_hermv_alloc((size_t)nc);
    double *cs = malloc(2 * (size_t)L * sizeof *cs);
    int st = NL_OK;
    if (!S || !V || !lam || !ws || !cs) {
        st = NL_ERROR(NL_ENOMEM, "out of memory");
        goto done;
    }
    /* e^{2 pi i q / L}, q = 0..L-1: every phase below, 2 pi (fx x + fy y) / L,
     * is one of these (L = ly in 2D, fy = 0 in 1D) */
    for (int q = 0; q < L; q++)
        cs[2 * q] = cos(2 * M_PI * q / L), cs[2 * q + 1] = sin(2 * M_PI * q / L);
    memset(g, 0, (size_t)(nc * nc * T * TY) * sizeof *g);
    for (int fy = 0; fy < ly; fy++)
        for (int fx = 0; fx < L; fx++) {
            for (int a = 0; a < nc; a++)
                for (int b = 0; b < nc; b++) {
                    double re = 0, im = 0;
                    for (int y = -ky; y <= ky; y++)
                        for (int x = -K; x <= K; x++) {
                            /* phase -2 pi (fx x + fy y) / L */
                            int q = ((-(fx * x + fy * y)) % L + L) % L;
                            double c = C[((a * nc + b) * (dim == 2 ? W : 1) + y + ky) * W + x + K];
                            re += c * cs[2 * q], im += c * cs[2 * q + 1];
                        }
                    gsl_matrix_complex_set(S, (size_t)a, (size_t)b, gsl_complex_rect(re, im));
                }
            if (gsl_eigen_hermv(S, lam, V, ws)) {
                st = NL_ERROR(NL_EFAIL, "correlated displacements: an eigenvalue problem did not converge");
                goto done;
            }
            /* G = V sqrt(max(lam, 0)) V^H, accumulated into the taps */
            for (int a = 0; a < nc; a++)
                for (int b = 0; b < nc; b++) {
                    gsl_complex G = gsl_complex_rect(0, 0);
                    for (int e = 0; e < nc; e++) {
                        double sl = sqrt(fmax(gsl_vector_get(lam, (size_t)e), 0));
                        gsl_complex u = gsl_matrix_complex_get(V, (size_t)a, (size_t)e);
                        gsl_complex v = gsl_complex_conjugate(gsl_matrix_complex_get(V, (size_t)b, (size_t)e));
                        G = gsl_complex_add(G, gsl_complex_mul_real(gsl_complex_mul(u, v), sl));
                    }
                    for (int py = -my; py <= my; py++)
                        for (int px = -M; px <= M; px++) {
                            int q = ((fx * px + fy * py) % L + L) % L;
                            g[((a * nc + b) * TY + py + my) * T + px + M] +=
                                (GSL_REAL(G) * cs[2 * q] - GSL_IMAG(G) * cs[2 * q + 1]) / ((double)L * ly);
                        }
                }
        }
done:
    gsl_matrix_complex_free(S);
    gsl_matrix_complex_free(V);
    gsl_vector_free(lam);
    gsl_eigen_hermv_free(ws);
    free(cs);
    return st;
}

double nl_subdiv_disp_realised(const nl_subdiv_level *l, int dim, int a, int b, int mx, int my)
{
    const int nc = l->nclass, M = l->taps, T = 2 * M + 1, TY = dim == 2 ? T : 1, yM = dim == 2 ? M : 0;
    double v = 0;
    if (!l->filt)
        return a == b && mx == 0 && my == 0 ? l->cls[a].variance : 0.0;
    for (int c = 0; c < nc; c++)
        for (int py = -yM; py <= yM; py++)
            for (int px = -M; px <= M; px++) {
                int qx = px - mx, qy = py - my;
                if (qx < -M || qx > M || qy < -yM || qy > yM)
                    continue;
                v += l->filt[((a * nc + c) * TY + py + yM) * T + px + M] *
                     l->filt[((b * nc + c) * TY + qy + yM) * T + qx + M];
            }
    return v;
}

/* Scale each row a of the taps so that its variance is C^{aa}(0); then the
 * largest |realised - C| / R(0) over the offsets C was given at. */
static void normalise(nl_subdiv_level *l, int dim, int K, const double *C, double r0)
{
    const int nc = l->nclass, M = l->taps, T = 2 * M + 1, TY = dim == 2 ? T : 1, W = 2 * K + 1;
    const int ky = dim == 2 ? K : 0;
    double err = 0;
    for (int a = 0; a < nc; a++) {
        double want = C[((a * nc + a) * (dim == 2 ? W : 1) + ky) * W + K];
        double have = nl_subdiv_disp_realised(l, dim, a, a, 0, 0);
        double f = have > 0 ? sqrt(fmax(want, 0) / have) : 0;
        for (int k = 0; k < nc * TY * T; k++)
            l->filt[a * nc * TY * T + k] *= f;
    }
    for (int a = 0; a < nc; a++)
        for (int b = 0; b < nc; b++)
            for (int y = -ky; y <= ky; y++)
                for (int x = -K; x <= K; x++) {
                    double c = C[((a * nc + b) * (dim == 2 ? W : 1) + y + ky) * W + x + K];
                    err = fmax(err, fabs(nl_subdiv_disp_realised(l, dim, a, b, x, y) - c) / r0);
                }
    l->filt_error = err;
}

static int correlate_level(nl_subdiv_level *l, const nl_model *m, int dim, int M, int target, double r0)
{
    const int nc = l->nclass, K = dim == 1 ? DISP_K1 : DISP_K2, L = dim == 1 ? DISP_L1 : DISP_L2;
    const int W = 2 * K + 1, WY = dim == 2 ? W : 1, T = 2 * M + 1, TY = dim == 2 ? T : 1;
    pattern p[3] = {{0}};
    rtable t = {0};
    double *C = malloc((size_t)(nc * nc * W * WY) * sizeof *C);
    int st = C ? NL_OK : NL_ERROR(NL_ENOMEM, "out of memory");
    for (int a = 0; a < nc && !st; a++)
        st = pattern_make(l, dim, a, &p[a]);
    if (!st)
        st = rtable_make(m, dim, l->spacing, 2 * K + 4 * l->N, &t); /* |pattern offsets| <= 4N - 2 half-cells */
    for (int a = 0; a < nc && !st; a++)
        for (int b = 0; b < nc; b++)
            for (int y = 0; y < WY; y++)
                for (int x = 0; x < W; x++)
                    C[((a * nc + b) * WY + y) * W + x] =
                        disp_cov(&p[a], &p[b], &t, x - K, dim == 2 ? y - K : 0, target);
    if (!st && !(l->filt = calloc((size_t)(nc * nc * T * TY), sizeof *l->filt)))
        st = NL_ERROR(NL_ENOMEM, "out of memory");
    l->taps = M;
    if (!st && !(st = filter_from_cov(dim, nc, K, L, M, C, l->filt)))
        normalise(l, dim, K, C, r0);
    for (int a = 0; a < nc; a++)
        pattern_free(&p[a]);
    free(t.v);
    free(C);
    return st;
}

static int correlate(nl_subdiv_coeffs *c, const nl_model *m, int taps, int target)
{
    if (taps < 0 || taps > NL_SUBDIV_MAX_TAPS)
        return NL_ERROR(NL_EINVAL, "taps: expected 0 to %d, got %d", NL_SUBDIV_MAX_TAPS, taps);
    if (target != NL_SUBDIV_DISP_ERROR && target != NL_SUBDIV_DISP_NEWNEW)
        return NL_ERROR(NL_EINVAL, "displacements: unknown covariance target %d", target);
    for (int k = 0; k < c->levels; k++) {
        nl_subdiv_level *l = &c->level[k];
        int st;
        for (int j = 0; j < l->nclass; j++)
            if (l->cls[j].nalt)
                return NL_ERROR(NL_EINVAL, "correlated displacements: random neighbourhoods are not supported");
        free(l->filt);
        l->filt = NULL;
        if ((st = correlate_level(l, m, c->dim, taps, target, c->r0))) {
            free(l->filt);
            l->filt = NULL;
            l->taps = 0;
            return st;
        }
    }
    return NL_OK;
}

int nl_subdiv_coeffs_correlate(nl_subdiv_coeffs *c, const nl_model *m, int taps, int target)
{
    int st;
    nl_gsl_enter();
    st = correlate(c, m, taps, target);
    nl_gsl_leave();
    return st;
}

static long wrapc(long i, long n) { return n ? ((i % n) + n) % n : i; }

/* The white numbers of one row of cells, per class: the numbers the
 * independent construction draws for the same points (subdiv.h): 1D the
 * midpoint 2i + 1's own; 2D the pairs of the standard neighbourhoods, on
 * row 2j + 1 key i for (edge-y, face) of cell i, on row 2j key k for the
 * edge-x points of cells 2k and 2k + 1.  x0 is the first cell, per the
 * period in cells (0: none); w[b * stride + x]. */
static void white_row(int dim, uint64_t seed, unsigned lv, long x0, long j, long n, long per, double *w,
                      long stride)
{
    const uint32_t st = NL_SUBDIV_STREAM + lv + 1;
    long cached = LONG_MIN;
    double g[2], e[2] = {0, 0};
    for (long x = 0; x < n; x++) {
        long i = wrapc(x0 + x, per), k = i >= 0 ? i / 2 : -((-i + 1) / 2);
        if (dim == 1) {
            w[x] = nl_rng_gauss(seed, st, rng_index(1, 2 * i + 1, 0));
            continue;
        }
        nl_rng_gauss_pair(seed, st, rng_index(2, i, 2 * j + 1), g);
        if (k != cached) {
            nl_rng_gauss_pair(seed, st, rng_index(2, k, 2 * j), e);
            cached = k;
        }
        w[x] = g[1];                   /* face (2i + 1, 2j + 1) */
        w[stride + x] = e[i - 2 * k];  /* edge-x (2i + 1, 2j) */
        w[2 * stride + x] = g[0];      /* edge-y (2i, 2j + 1) */
    }
}

int nl_subdiv_disp_fill(const nl_subdiv_level *l, int dim, uint64_t seed, unsigned lv, const long *c0,
                        const long *nc_, const long *per, double *out)
{
    const int nc = l->nclass, M = l->taps, T = 2 * M + 1, yM = dim == 2 ? M : 0, TY = dim == 2 ? T : 1;
    const long nx = nc_[0], ny = dim == 2 ? nc_[1] : 1, wx = nx + 2 * M, wy = ny + 2 * yM;
    double *w = malloc((size_t)(nc * wx * wy) * sizeof *w);
    if (!w)
        return NL_ERROR(NL_ENOMEM, "out of memory for the displacements of level %u", lv);
    /* w[(b wy + y) wx + x]: class b, cell (c0 - M + x, c1 - M + y) */
#pragma omp parallel for schedule(static) if (wx * wy > 16384)
    for (long y = 0; y < wy; y++)
        white_row(dim, seed, lv, c0[0] - M, dim == 2 ? wrapc(c0[1] - yM + y, per[1]) : 0, wx, per[0],
                  w + y * wx, wx * wy);
    /* d_a = sum_b g^{ab} * w_b, a row of cells at a time, the taps outside
     * so that the innermost loop runs along the row */
#pragma omp parallel for schedule(static) if (nx * ny > 16384)
    for (long y = 0; y < ny; y++)
        for (int a = 0; a < nc; a++) {
            double *restrict o = out + (a * ny + y) * nx;
            memset(o, 0, (size_t)nx * sizeof *o);
            for (int b = 0; b < nc; b++)
                for (int py = 0; py < TY; py++) {
                    const double *restrict gr = l->filt + ((a * nc + b) * TY + py) * T;
                    for (int px = 0; px < T; px++) {
                        const double gv = gr[px], *restrict wr = w + (b * wy + y + py) * wx + px;
#pragma omp simd
                        for (long x = 0; x < nx; x++)
                            o[x] += gv * wr[x];
                    }
                }
        }
    free(w);
    return NL_OK;
}
