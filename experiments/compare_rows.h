/* The rows of the comparison of synthesis methods (experiments/
 * compare_methods.c, its only includer): the four targets, and every
 * synthesis method of noiselab behind one interface (plan for a target on
 * an n x n grid, run a seed, free), with what each one is. */
#ifndef NL_EXPERIMENTS_COMPARE_ROWS_H
#define NL_EXPERIMENTS_COMPARE_ROWS_H

#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/cholesky.h"
#include "../synth/circulant.h"
#include "../synth/faulting.h"
#include "../synth/fft.h"
#include "../synth/lattice.h"
#include "../synth/midpoint.h"
#include "../synth/rank1.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { NT = 4 };

typedef struct {
    const char *name, *acf, *spec; /* label, R and S in closed form */
    nl_model *ma, *ms;
} target;

static target targets[NT] = {
    {"markov", "markov:scale=6", "spectrum:2*pi*36/(1+(12*pi*k)^2)^1.5", NULL, NULL},
    {"gauss", "gauss:scale=6", "spectrum:pi*36*exp(-(6*pi*k)^2)", NULL, NULL},
    {"ring", "expr:(1-2*(r/8)^2+0.5*(r/8)^4)*exp(-(r/8)^2)", "spectrum:0.5*pi^5*8^6*k^4*exp(-(8*pi*k)^2)", NULL,
     NULL},
    {"fractal", "power:d=3", "power:d=3", NULL, NULL},
};

/* A method: plan for a target on a grid (NL code; the state in *st), run a
 * seed, free. */
typedef struct {
    const char *name;
    int periodic;       /* spectrum expectation: sampled (1) or Fejer (0) */
    int fractal_only;   /* fBm methods: only the fractal target */
    int (*plan)(const target *t, const size_t *n, void **st);
    int (*run)(void *st, uint64_t seed, nl_field *f);
    void (*free)(void *st);
} method;

/* ---- the methods ---- */
/* R sampled on the torus; the sampled spectrum when that is not positive
 * definite (the ring's R on a 64-periodic grid). */
static int p_fft(const target *t, const size_t *n, void **st)
{
    int e = nl_synth_fft_plan_alloc(t->ma, 2, n, NULL, 0, (nl_synth_fft_plan **)st);
    return e == NL_ENOTPD ? nl_synth_fft_plan_alloc(t->ms, 2, n, NULL, 0, (nl_synth_fft_plan **)st) : e;
}
static int r_fft(void *st, uint64_t s, nl_field *f) { return nl_synth_fft_execute(st, s, f); }
static void f_fft(void *st) { nl_synth_fft_plan_free(st); }

static int p_circ(const target *t, const size_t *n, void **st)
{
    return nl_synth_circulant_plan_alloc(t->ma, 2, n, NULL, 0, 16, (nl_synth_circulant_plan **)st);
}
static int r_circ(void *st, uint64_t s, nl_field *f) { return nl_synth_circulant_execute(st, s, f); }
static void f_circ(void *st) { nl_synth_circulant_plan_free(st); }

static int p_chol(const target *t, const size_t *n, void **st)
{
    *st = NULL;
    if (nl_model_family(t->ma) == &nl_family_power)
        return NL_ERROR(NL_EINVAL, "not run: power:'s R is a quadrature per lag, and the plan evaluates R at "
                        "every pair of samples (N^2 / 2 quadratures: a minute at 32x32)");
    return nl_synth_cholesky_plan_alloc(t->ma, 2, n, NULL, (nl_synth_cholesky_plan **)st);
}
static int r_chol(void *st, uint64_t s, nl_field *f) { return nl_synth_cholesky_execute(st, s, f); }
static void f_chol(void *st) { nl_synth_cholesky_plan_free(st); }

static int p_subdiv_with(const target *t, const size_t *n, int disp, void **st)
{
    nl_subdiv_options o;
    nl_subdiv_options_default(&o);
    o.displacements = disp;
    return nl_subdiv_plan_alloc(t->ma, 2, n, 1.0, &o, (nl_subdiv_plan **)st);
}
static int p_subdiv(const target *t, const size_t *n, void **st)
{
    return p_subdiv_with(t, n, NL_SUBDIV_DISP_INDEPENDENT, st);
}
static int p_subdivc(const target *t, const size_t *n, void **st)
{
    return p_subdiv_with(t, n, NL_SUBDIV_DISP_ERROR, st);
}
static int r_subdiv(void *st, uint64_t s, nl_field *f) { return nl_subdiv_plan_execute(st, s, f); }
static void f_subdiv(void *st) { nl_subdiv_plan_free(st); }

static int p_midpoint(const target *t, const size_t *n, void **st)
{
    double H;
    int e = nl_subdiv_midpoint_hurst(t->ma, 2, &H);
    return e ? e : nl_subdiv_plan_alloc_midpoint(2, n, 1.0, 0, H, 1.0, 1.0, (nl_subdiv_plan **)st);
}

/* Miller and faulting keep their parameter in the state. */
static int p_miller(const target *t, const size_t *n, void **st)
{
    double *H = malloc(sizeof *H);
    int e;
    (void)n;
    if (!H)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((e = nl_subdiv_midpoint_hurst(t->ma, 2, H)))
        free(H), H = NULL;
    *st = H;
    return e;
}
static int r_miller(void *st, uint64_t s, nl_field *f)
{
    return nl_synth_midpoint_miller(0, *(double *)st, 1, 1, s, f);
}

static int p_fault(const target *t, const size_t *n, void **st)
{
    (void)n;
    *st = NULL;
    if (nl_model_family(t->ma) != &nl_family_power)
        return NL_ERROR(NL_EINVAL, "faulting: Brownian (k^-3) only");
    return NL_OK;
}
static int r_fault(void *st, uint64_t s, nl_field *f)
{
    size_t K;
    (void)st;
    return nl_synth_faulting(s, 1.0, f, &K);
}

/* The kernel at its default radius, or cut at the largest radius the
 * periodic tile holds (n/2 - 1, flagged truncated by the method). */
static int p_sparse(const target *t, const size_t *n, void **st)
{
    nl_synth_sparse_info info;
    int e = nl_synth_sparse_plan_model(t->ma, 2, NULL, &(nl_synth_sparse_options){0, 0, 1.0, 0},
                                       (nl_synth_sparse_plan **)st);
    if (!e) {
        nl_synth_sparse_plan_info(*st, &info);
        if (2 * (size_t)info.radius + 1 <= n[0])
            return NL_OK;
        nl_synth_sparse_plan_free(*st);
    }
    return nl_synth_sparse_plan_model(t->ma, 2, NULL, &(nl_synth_sparse_options){(int)(n[0] / 2) - 1, 0, 1.0, 0},
                                      (nl_synth_sparse_plan **)st);
}
static int r_sparse(void *st, uint64_t s, nl_field *f)
{
    return nl_synth_sparse_execute(st, s, NL_SYNTH_SPARSE_WRAP, NULL, f);
}
static void f_sparse(void *st) { nl_synth_sparse_plan_free(st); }

static int p_perlin(const target *t, const size_t *n, void **st)
{
    nl_synth_lattice_plan *p = malloc(sizeof *p);
    double c0 = nl_synth_lattice_default_cell(n);
    int e;
    if (!p)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((e = nl_synth_lattice_plan_init(t->ms, 2, c0, nl_synth_lattice_default_octaves(c0), 0, p)))
        free(p), p = NULL;
    *st = p;
    return e;
}
static int r_perlin(void *st, uint64_t s, nl_field *f) { return nl_synth_lattice_execute(st, s, f); }

static int p_wiener(const target *t, const size_t *n, void **st)
{
    return nl_synth_lattice_wiener_plan_alloc(t->ma, 2, n, 4, 0, (nl_synth_lattice_wiener_plan **)st);
}
static int r_wiener(void *st, uint64_t s, nl_field *f) { return nl_synth_lattice_wiener_execute(st, s, f, NULL); }
static void f_wiener(void *st) { nl_synth_lattice_wiener_plan_free(st); }

/* Keller's rank-1 lattice: the Fibonacci lattice of at most n^2 / 2 points
 * on the torus of side n samples, each wave vector carrying
 * S(k / n) / n^2; the field is the trigonometric series itself, summed
 * on the n x n grid by one inverse FFT. */
typedef struct {
    nl_rank1_lattice L;
    const nl_model *m;
    size_t n;
    double *c;
    fftw_complex *g;
    fftw_plan fp;
} rank1_state;

static double rank1_S(const long *k, int s, void *ctx)
{
    const rank1_state *r = ctx;
    double f[2] = {(double)k[0] / (double)r->n, s > 1 ? (double)k[1] / (double)r->n : 0};
    double v = nl_model_spectrum(r->m, 2, f) / ((double)r->n * (double)r->n);
    return isfinite(v) && v > 0 ? v : 0;
}

static void f_rank1(void *st)
{
    rank1_state *r = st;
    if (!r)
        return;
    nl_rank1_free(&r->L);
    free(r->c);
    if (r->fp)
        fftw_destroy_plan(r->fp);
    if (r->g)
        fftw_free(r->g);
    free(r);
}

static int p_rank1(const target *t, const size_t *n, void **st)
{
    rank1_state *r = calloc(1, sizeof *r);
    double a = 1, b = 1; /* F_(k-1), F_k */
    int k = 2, e;
    *st = NULL;
    if (!r)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    while (k < 34 && a + b <= (double)(n[0] * n[1]) / 2) {
        double c = a + b;
        a = b, b = c, k++;
    }
    r->m = t->ms, r->n = n[0];
    if ((e = nl_rank1_fibonacci(k, &r->L))) {
        f_rank1(r);
        return e;
    }
    r->c = malloc(2 * r->L.N * sizeof *r->c);
    r->g = fftw_malloc(n[0] * n[1] * sizeof *r->g);
    if (!r->c || !r->g) {
        f_rank1(r);
        return NL_ERROR(NL_ENOMEM, "out of memory");
    }
    r->fp = fftw_plan_dft_2d((int)n[1], (int)n[0], r->g, r->g, FFTW_BACKWARD, FFTW_ESTIMATE);
    *st = r;
    return NL_OK;
}

static int r_rank1(void *st, uint64_t s, nl_field *f)
{
    rank1_state *r = st;
    size_t n = r->n;
    int e = nl_rank1_coefficients(&r->L, rank1_S, r, s, r->c);
    if (e)
        return e;
    memset(r->g, 0, n * n * sizeof *r->g);
    for (size_t m = 0; m < r->L.N; m++) {
        long kx = r->L.k[2 * m], ky = r->L.k[2 * m + 1];
        size_t i = (size_t)(((kx % (long)n) + (long)n) % (long)n), j = (size_t)(((ky % (long)n) + (long)n) % (long)n);
        r->g[j * n + i][0] += r->c[2 * m], r->g[j * n + i][1] += r->c[2 * m + 1];
    }
    fftw_execute(r->fp);
    for (size_t i = 0; i < n * n; i++)
        f->data[i] = r->g[i][0];
    return NL_OK;
}

static void f_free(void *st) { free(st); }

static const method methods[] = {
    {"fft", 1, 0, p_fft, r_fft, f_fft},
    {"circulant", 0, 0, p_circ, r_circ, f_circ},
    {"cholesky", 0, 0, p_chol, r_chol, f_chol},
    {"subdiv", 1, 0, p_subdiv, r_subdiv, f_subdiv},
    {"subdiv-correlated", 1, 0, p_subdivc, r_subdiv, f_subdiv},
    {"midpoint", 1, 1, p_midpoint, r_subdiv, f_subdiv},
    {"midpoint-miller", 1, 1, p_miller, r_miller, f_free},
    {"faulting", 0, 1, p_fault, r_fault, f_free},
    {"sparse", 1, 0, p_sparse, r_sparse, f_sparse},
    {"lattice", 1, 0, p_perlin, r_perlin, f_free},
    {"lattice-wiener", 1, 0, p_wiener, r_wiener, f_wiener},
    {"rank1", 1, 0, p_rank1, r_rank1, f_rank1},
};
enum { NM = sizeof methods / sizeof *methods };

/* Static facts of each method (the table's descriptive columns), in the
 * order of methods[]: locality, refinement, what it claims, Lewis 1987's
 * words (or where it comes from). */
static const struct {
    const char *local, *refine, *exact, *paper;
} facts[NM] = {
    {"global", "no", "exact (periodic R)", "FFT: global; simple, efficient for a global method; exact spectral control"},
    {"global", "no", "exact (R on the grid)", "beyond the paper (Dietrich-Newsam, Wood-Chan)"},
    {"global", "no (an exact refinement is conditional simulation)", "exact",
     "Fellous et al.: Cholesky factor of the correlation matrix; global, \"O(N^2)\"; incremental local "
     "refinement in limited precision (not built: see notes)"},
    {"semi-local (N = 2: 4x4)", "yes, any level", "approximate (exact 1D Markov)",
     "generalized subdivision: semi-local; arbitrary spectrum to a chosen accuracy; refines an existing database"},
    {"semi-local + filter of the level", "yes, any level", "approximate",
     "beyond the paper: displacements with the covariance of the estimation errors"},
    {"local", "yes, any level", "approximate (fBm only)",
     "stochastic subdivision: local; approximate f^-d, exact Brownian for d = 2 (1D); creases for d > 2; "
     "unique in refining; Haruyama-Barsky variances (--variance-scale) widen it, oscillation impossible"},
    {"local", "yes, any level (the grid moves by s/4)", "approximate (fBm only)",
     "Miller: a higher quality interpolant for the point estimation, alleviating creases"},
    {"global (each fault crosses the grid)", "no", "Brownian only (k^-3)",
     "Poisson faulting: random steps; Brownian (f^-2) only"},
    {"local (cells)", "no", "exact in expectation (kernel truncated)",
     "sparse convolution: local, as efficient as convolution; any spectrum that is a kernel's power spectrum; "
     "superposition visible when sparse"},
    {"local", "no", "approximate (octave basis)",
     "interpolated noise lattice: local; low-frequency leakage cannot be removed in summation; axis bias"},
    {"local interpolation, lattice by FFT", "no", "exact at node lags only",
     "Wiener interpolation: greater spectral control (with restrictions), no spectral summation"},
    {"global (one 1D FFT)", "no", "approximate (N minimal wave vectors)", "beyond the paper (Keller 2001)"},
};

#endif
