/* Experiment: the comparison of stochastic synthesis methods (Lewis 1987,
 * "Comparison of Stochastic Synthesis Methods") measured, for every
 * synthesis method of noiselab, on the same targets.
 *
 * usage: compare_methods OUTDIR [full]
 * Targets (2D, unit spacing): markov:scale=6 (exp(-r/6): rough, not
 * fractal), gauss:scale=6 (smooth, a singular process), a ring spectrum
 * R = (1 - 2 q + q^2/2) exp(-q), q = (r/8)^2, S proportional to
 * k^4 exp(-(8 pi k)^2) (valid in 2D, oscillating R: the biharmonic of a
 * Gaussian), and the fractal power:d=3 (H = 1/2 in 2D).  Each target is
 * given both as R and as S in closed form; a method takes the form it
 * can use (R first).
 * Accuracy: M = 32 realizations (seeds 1..32) on 64 x 64 (cholesky:
 * 32 x 32, its plan is O(N^3)); the unbiased ACF with the known mean 0
 * along x, y and the diagonal, lags 0..16 (cholesky 0..8); the largest
 * |mean - R| / R(0) with its simultaneous 95% interval, and max |z|
 * against the Bonferroni threshold of t(M - 1) at 1e-3
 * (analysis/validate.h); the ensemble-mean periodogram over three octave
 * bands, |f| in (1/64, 1/32] (low), (1/16, 1/8] (mid), (1/4, 1/2] (high),
 * over its expectation (sampled spectrum for periodic methods, Fejer for
 * the others); for the fractal target the log-periodogram slope over
 * 1/32 <= |f| <= 1/4 against -3.
 * Cost: wall time of plan + one realization of markov (fractal methods:
 * the fractal target) at 128^2, 256^2, 512^2 (full: 256^2 .. 1024^2;
 * cholesky 16^2, 24^2, 32^2), one thread, in a child process whose peak
 * RSS above its start is the memory; exponent = least-squares slope of
 * log t on log samples; the time at 1024^2 measured (full) or extrapolated.
 * Writes OUTDIR/compare-tables.frag (the tables and verdicts, markdown),
 * compare-cost.tsv (cost against ACF error) and compare-ring-acf.tsv (the
 * ring's ensemble ACF along x by method); exit 1 when a verdict fails. */
#include "../analysis/acf.h"
#include "../analysis/psd.h"
#include "../analysis/slope.h"
#include "../analysis/validate.h"
#include "../analysis/verdict.h"
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
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

enum { NT = 4, M = 32, MAXL = 16 };

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

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

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
    if (nl_model_get_kind(t->ma) == NL_MODEL_POWER)
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
static int r_miller(void *st, uint64_t s, nl_field *f) { return nl_midpoint_miller(0, *(double *)st, 1, 1, s, f); }

static int p_fault(const target *t, const size_t *n, void **st)
{
    (void)n;
    *st = NULL;
    if (nl_model_get_kind(t->ma) != NL_MODEL_POWER)
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
    int e = nl_synth_sparse_plan_model_flags(t->ma, 2, NULL, 0, 0, 1.0, 0, (nl_synth_sparse_plan **)st);
    if (!e) {
        nl_synth_sparse_plan_info(*st, &info);
        if (2 * (size_t)info.radius + 1 <= n[0])
            return NL_OK;
        nl_synth_sparse_plan_free(*st);
    }
    return nl_synth_sparse_plan_model_flags(t->ma, 2, NULL, (int)(n[0] / 2) - 1, 0, 1.0, 0,
                                            (nl_synth_sparse_plan **)st);
}
static int r_sparse(void *st, uint64_t s, nl_field *f) { return nl_synth_sparse_execute(st, s, 1, NULL, f); }
static void f_sparse(void *st) { nl_synth_sparse_plan_free(st); }

static int p_perlin(const target *t, const size_t *n, void **st)
{
    nl_synth_lattice_plan *p = malloc(sizeof *p);
    double c0 = nl_synth_lattice_default_cell(n);
    int e;
    if (!p)
        return NL_ERROR(NL_ENOMEM, "out of memory");
    if ((e = nl_synth_lattice_plan_init(t->ms, 2, c0, nl_synth_lattice_default_octaves(c0), p)))
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
     "Fellous et al.: Cholesky factor of the correlation matrix; global, O(N^2) (sic); incremental local "
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
     "sparse convolution: local, as efficient as convolution; any |H|^2 spectrum; superposition visible when sparse"},
    {"local", "no", "approximate (octave basis)",
     "interpolated noise lattice: local; low-frequency leakage cannot be removed in summation; axis bias"},
    {"local interpolation, lattice by FFT", "no", "exact at node lags only",
     "Wiener interpolation: greater spectral control (with restrictions), no spectral summation"},
    {"global (one 1D FFT)", "no", "approximate (N minimal wave vectors)", "beyond the paper (Keller 2001)"},
};

/* ---- accuracy ---- */
typedef struct {
    int ran;                   /* 0: refused (why) */
    char why[200];
    nl_validate_effect eff;    /* ACF: max |mean - R| / R(0) */
    double zmax, thr;          /* against the Bonferroni threshold */
    double band[3], band_se[3];/* periodogram / expectation: low, mid, high (NAN: no power there) */
    nl_slope slope;            /* fractal target */
    double acfx[MAXL + 1];     /* ensemble-mean ACF along x */
    int L;                     /* lags 0..L */
} acc_t;

static nl_validate_result vres[2];  /* the grids' lags and spectrum expectations: 64^2 and 32^2 */

/* Lag l along direction d (0 x, 1 y, 2 diagonal) of a full ACF estimate. */
static double lag_of(const nl_field *full, int d, long l)
{
    size_t nx = full->n[0], ny = full->n[1];
    long lx = d == 1 ? 0 : l, ly = d == 0 ? 0 : l;
    return full->data[(size_t)((ly + (long)ny) % (long)ny) * nx + (size_t)((lx + (long)nx) % (long)nx)];
}

/* Band b (octave, validate's numbering) mean of periodogram P. */
static double band_mean(const nl_field *P, int b)
{
    size_t n = P->n[0], cnt = 0;
    double lo = 0.5 * ldexp(1, -(b + 1)), hi = 0.5 * ldexp(1, -b), s = 0;
    for (size_t j = 0; j < n; j++)
        for (size_t i = 0; i < n; i++) {
            double fx = (double)(i <= n / 2 ? (long)i : (long)i - (long)n) / (double)n;
            double fy = (double)(j <= n / 2 ? (long)j : (long)j - (long)n) / (double)n, r = hypot(fx, fy);
            if (r > lo && (r <= hi || b == 0))
                s += P->data[j * n + i], cnt++;
        }
    return cnt ? s / (double)cnt : NAN;
}

static const int bands[3] = {4, 2, 0}; /* low (1/64, 1/32], mid (1/16, 1/8], high (1/4, 1/2] */

/* Accumulate one realization's ACF and band means; fractal: its periodogram too. */
static int measure_one(const nl_field *f, int L, double (*s1)[MAXL + 1], double (*s2)[MAXL + 1], double *b1,
                       double *b2, nl_field *Pacc)
{
    nl_field *full, *P;
    int e;
    if ((e = nl_acf_full(f, 0, NL_ACF_UNBIASED, &full)))
        return e;
    for (int d = 0; d < 3; d++)
        for (int l = 0; l <= L; l++) {
            double v = lag_of(full, d, l);
            s1[d][l] += v, s2[d][l] += v * v;
        }
    nl_field_free(full);
    if ((e = nl_psd_periodogram(f, 0, &P)))
        return e;
    for (int k = 0; k < 3; k++) {
        double v = band_mean(P, bands[k]);
        b1[k] += v, b2[k] += v * v;
    }
    for (size_t i = 0; i < P->count; i++)
        Pacc->data[i] += P->data[i] / M;
    nl_field_free(P);
    return NL_OK;
}

/* Ensemble statistics into a: the ACF effect and z test, the bands, the slope. */
static void summarise(const method *me, const target *t, const nl_validate_result *v, int L,
                      double (*s1)[MAXL + 1], double (*s2)[MAXL + 1], const double *b1, const double *b2,
                      const nl_field *Pacc, acc_t *a)
{
    double mean[3 * (MAXL + 1)], se[3 * (MAXL + 1)], R[3 * (MAXL + 1)], zero[2] = {0, 0};
    size_t T = 3 * (size_t)(L + 1), worst;
    for (int d = 0; d < 3; d++)
        for (int l = 0; l <= L; l++) {
            size_t i = (size_t)d * (size_t)(L + 1) + (size_t)l;
            double lag[2] = {d == 1 ? 0 : l, d == 0 ? 0 : l};
            mean[i] = s1[d][l] / M;
            se[i] = sqrt(fmax(s2[d][l] / M - mean[i] * mean[i], 0) / (M - 1));
            R[i] = nl_model_acf(t->ma, 2, lag);
        }
    for (int l = 0; l <= L; l++)
        a->acfx[l] = mean[l];
    a->L = L;
    double c = nl_verdict_threshold(0.05, T, M - 1);
    nl_validate_effect_of(T, mean, se, R, nl_model_acf(t->ma, 2, zero), c, c, &a->eff, &worst);
    a->zmax = nl_verdict_zmax(T, mean, se, R, &worst);
    a->thr = nl_verdict_threshold(1e-3, T, M - 1);
    for (int k = 0; k < 3; k++) {
        double ex = me->periodic ? v->band_periodic[bands[k]] : v->band_fejer[bands[k]], m = b1[k] / M;
        double big = fmax(v->band_periodic[0], fmax(v->band_periodic[2], v->band_periodic[4]));
        int ok = ex > 1e-6 * big;
        a->band[k] = ok ? m / ex : NAN;
        a->band_se[k] = ok ? sqrt(fmax(b2[k] / M - m * m, 0) / (M - 1)) / ex : NAN;
    }
    if (nl_psd_slope_grid(Pacc, 1 / 32.0, 0.25, &a->slope))
        a->slope.slope = NAN;
}

static void run_accuracy(const method *me, const target *t, acc_t *a)
{
    int chol = me->plan == p_chol, L = chol ? 8 : MAXL, e;
    size_t n[2] = {chol ? 32 : 64, chol ? 32 : 64};
    double s1[3][MAXL + 1] = {{0}}, s2[3][MAXL + 1] = {{0}}, b1[3] = {0}, b2[3] = {0};
    void *st = NULL;
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *Pacc = nl_field_alloc(2, n, NULL, NULL);
    memset(a, 0, sizeof *a);
    if (!f || !Pacc) {
        snprintf(a->why, sizeof a->why, "out of memory");
        goto done;
    }
    if ((e = me->plan(t, n, &st))) {
        snprintf(a->why, sizeof a->why, "%s", nl_errmsg());
        goto done;
    }
    for (uint64_t s = 1; s <= M; s++)
        if ((e = me->run(st, s, f)) || (e = measure_one(f, L, s1, s2, b1, b2, Pacc))) {
            snprintf(a->why, sizeof a->why, "%s", nl_errmsg());
            goto done;
        }
    a->ran = 1;
    summarise(me, t, &vres[chol], L, s1, s2, b1, b2, Pacc, a);
done:
    if (st && me->free)
        me->free(st);
    nl_field_free(f), nl_field_free(Pacc);
}

/* ---- cost ---- */
typedef struct {
    double plan[3];     /* plan time at sizes[] (one run) */
    double sec[3];      /* one realization, best of 3, at sizes[] */
    size_t size[3];     /* samples per axis */
    double rss_mb;      /* peak RSS above the child's start at the largest size */
    int ok;
    char why[160];
} cost_t;

/* In a child: the plan once, then the best of 3 realizations at n x n;
 * writes the two times and the peak-RSS growth (kB) to fd. */
static void child_time(const method *me, const target *t, size_t n, int fd)
{
    struct rusage ru0, ru1;
    double best = INFINITY, out[3];
    size_t nn[2] = {n, n};
    void *st = NULL;
    omp_set_num_threads(1);
    getrusage(RUSAGE_SELF, &ru0);
    nl_field *f = nl_field_alloc(2, nn, NULL, NULL);
    double t0 = now();
    if (!f || me->plan(t, nn, &st))
        _exit(3);
    out[0] = now() - t0;
    for (int rep = 0; rep < 3; rep++) {
        t0 = now();
        if (me->run(st, (uint64_t)rep + 1, f))
            _exit(3);
        best = fmin(best, now() - t0);
    }
    getrusage(RUSAGE_SELF, &ru1);
    if (me->free)
        me->free(st);
    nl_field_free(f);
    out[1] = best, out[2] = (double)(ru1.ru_maxrss - ru0.ru_maxrss);
    if (write(fd, out, sizeof out) != (ssize_t)sizeof out)
        _exit(4);
    _exit(0);
}

static void run_cost(const method *me, const target *t, int full, cost_t *c)
{
    static const size_t quick[3] = {128, 256, 512}, wide[3] = {256, 512, 1024}, chol[3] = {16, 24, 32};
    const size_t *sz = me->plan == p_chol ? chol : full ? wide : quick;
    memset(c, 0, sizeof *c);
    c->ok = 1;
    for (int k = 0; k < 3; k++) {
        int fd[2], status;
        double out[3];
        c->size[k] = sz[k];
        fflush(NULL);
        if (pipe(fd))
            break;
        pid_t pid = fork();
        if (pid == 0) {
            close(fd[0]);
            child_time(me, t, sz[k], fd[1]);
        }
        close(fd[1]);
        ssize_t got = pid > 0 ? read(fd[0], out, sizeof out) : -1;
        close(fd[0]);
        if (pid > 0)
            waitpid(pid, &status, 0);
        if (got != (ssize_t)sizeof out) {
            c->ok = 0;
            snprintf(c->why, sizeof c->why, "failed at %zu^2", sz[k]);
            return;
        }
        c->plan[k] = out[0], c->sec[k] = out[1];
        c->rss_mb = out[2] / 1024;
    }
}

/* Least-squares slope of log t on log samples (t: the realizations' times,
 * or the plans' with plan set). */
static double exponent_of(const cost_t *c, int plan)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 0; k < 3; k++) {
        double x = log((double)c->size[k] * (double)c->size[k]), y = log(plan ? c->plan[k] : c->sec[k]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
}

static double exponent(const cost_t *c) { return exponent_of(c, 0); }

/* The time at 1024^2: measured, or extrapolated from the largest size. */
static double at1024(const cost_t *c, int *measured)
{
    *measured = c->size[2] == 1024;
    return c->sec[2] * pow(1024.0 * 1024.0 / ((double)c->size[2] * (double)c->size[2]), exponent(c));
}

/* ---- output ---- */
static acc_t acc[NM][NT];
static cost_t cost[NM];

static const char *short_why(const char *why, char *buf, size_t len)
{
    snprintf(buf, len, "refused: %.70s%s", why, strlen(why) > 70 ? "..." : "");
    for (char *p = buf; *p; p++)
        if (*p == '|')
            *p = '/';
    return buf;
}

static void acf_cell(const acc_t *a, FILE *o)
{
    char b[128];
    if (!a->ran)
        fprintf(o, " %s |", short_why(a->why, b, sizeof b));
    else
        fprintf(o, " %.3f [%.3f, %.3f]%s |", a->eff.effect.est, a->eff.effect.lo, a->eff.effect.hi,
                a->zmax > a->thr ? " (z)" : "");
}

static void band_cell(const acc_t *a, FILE *o)
{
    if (!a->ran) {
        fprintf(o, " - |");
        return;
    }
    for (int k = 0; k < 3; k++) {
        if (isnan(a->band[k]))
            fprintf(o, "%s-", k ? " / " : " ");
        else
            fprintf(o, "%s%.2f±%.2f", k ? " / " : " ", a->band[k], 2 * a->band_se[k]);
    }
    fprintf(o, " |");
}

static const char *capability(const acc_t *a)
{
    if (!a->ran)
        return "refused";
    return a->eff.effect.hi <= 0.1 ? "yes" : a->eff.effect.lo > 0.1 ? "approx. (error > 0.1)" : "approx.";
}

static void write_accuracy(FILE *o)
{
    fprintf(o, "| method | ACF error, markov | ACF error, gauss | ACF error, ring | spectrum ratio markov "
               "(low / mid / high) | gauss | ring | fractal: slope (target -3) |\n"
               "|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < NM; i++) {
        fprintf(o, "| %s |", methods[i].name);
        for (int t = 0; t < 3; t++)
            acf_cell(&acc[i][t], o);
        for (int t = 0; t < 3; t++)
            band_cell(&acc[i][t], o);
        const acc_t *f = &acc[i][3];
        if (f->ran && !isnan(f->slope.slope))
            fprintf(o, " %.2f ± %.2f |\n", f->slope.slope, f->slope.ci95);
        else
            fprintf(o, " %s |\n", f->ran ? "-" : "refused");
    }
}

static void write_cost(FILE *o)
{
    fprintf(o, "| method | one realization at 1024^2 (s) | its growth exponent (sizes) | plan at the largest size "
               "(s) | peak RSS at the largest size (MB) | local or global | refines an existing field | oscillatory "
               "(ring) | non-fractal (markov, gauss) | exact or approximate | Lewis 1987 |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < NM; i++) {
        const cost_t *c = &cost[i];
        int meas;
        fprintf(o, "| %s |", methods[i].name);
        if (!c->ok)
            fprintf(o, " %s | - | - | - |", c->why);
        else {
            double t = at1024(c, &meas);
            fprintf(o, " %s%.3g | %.2f (%zu^2..%zu^2) | %.3g | %.1f |", meas ? "" : "≈ ", t, exponent(c), c->size[0],
                    c->size[2], c->plan[2], c->rss_mb);
        }
        fprintf(o, " %s | %s | %s | %s, %s | %s | %s |\n", facts[i].local, facts[i].refine, capability(&acc[i][2]),
                capability(&acc[i][0]), capability(&acc[i][1]), facts[i].exact, facts[i].paper);
    }
}

static void write_tsv(const char *dir)
{
    char path[4096];
    FILE *o;
    snprintf(path, sizeof path, "%s/compare-cost.tsv", dir);
    if ((o = fopen(path, "w"))) {
        fprintf(o, "method\tseconds_1024\texponent\tacf_error\n");
        for (int i = 0; i < NM; i++) {
            int meas = 0;
            double e = 0;
            for (int t = 0; t < 3; t++)
                if (acc[i][t].ran)
                    e = fmax(e, acc[i][t].eff.effect.est);
            if (cost[i].ok && e > 0)
                fprintf(o, "%s\t%.6g\t%.3f\t%.6g\n", methods[i].name, at1024(&cost[i], &meas), exponent(&cost[i]),
                        fmax(e, 1e-3));
        }
        fclose(o);
    }
    snprintf(path, sizeof path, "%s/compare-ring-acf.tsv", dir);
    if ((o = fopen(path, "w"))) {
        fprintf(o, "lag\ttarget");
        for (int i = 0; i < NM; i++)
            fprintf(o, "\t%s", methods[i].name);
        fprintf(o, "\n");
        for (int l = 0; l <= MAXL; l++) {
            double lag[2] = {l, 0};
            fprintf(o, "%d\t%.6g", l, nl_model_acf(targets[2].ma, 2, lag));
            for (int i = 0; i < NM; i++)
                if (acc[i][2].ran && l <= acc[i][2].L)
                    fprintf(o, "\t%.6g", acc[i][2].acfx[l]);
                else
                    fprintf(o, "\tNaN");
            fprintf(o, "\n");
        }
        fclose(o);
    }
}

static int find(const char *name)
{
    for (int i = 0; i < NM; i++)
        if (!strcmp(methods[i].name, name))
            return i;
    return 0;
}

/* The verdicts (module comment of the script); 0 when all hold. */
static int verdicts(FILE *o)
{
    static const char *const exact[] = {"fft", "circulant", "cholesky"};
    static const char *const linear[] = {"fft", "circulant", "subdiv", "subdiv-correlated", "midpoint",
                                         "midpoint-miller", "sparse", "lattice", "lattice-wiener"};
    int fail = 0, ok;
    for (size_t k = 0; k < 3; k++) {
        int i = find(exact[k]);
        for (int t = 0; t < 3; t++) {
            const acc_t *a = &acc[i][t];
            ok = a->ran ? a->zmax <= a->thr : i == find("cholesky");
            fail |= !ok;
            fprintf(o, "- %s: %s on %s: %s\n", ok ? "PASS" : "FAIL", exact[k], targets[t].name,
                    a->ran ? "" : "refused (allowed only for cholesky, whose factorisation needs a regular matrix)");
            if (a->ran)
                fprintf(o, "  max |z| %.2f against the Bonferroni threshold %.2f\n", a->zmax, a->thr);
        }
    }
    for (size_t k = 0; k < sizeof linear / sizeof *linear; k++) {
        int i = find(linear[k]);
        double x = cost[i].ok ? exponent(&cost[i]) : NAN;
        ok = x >= 0.8 && x < 1.8;
        fail |= !ok;
        fprintf(o, "- %s: %s: one realization grows as samples^%.2f, in [0.8, 1.8): linear or n log n, not "
                "quadratic\n", ok ? "PASS" : "FAIL", linear[k], x);
    }
    int c = find("cholesky");
    double xc = cost[c].ok ? exponent_of(&cost[c], 1) : NAN;
    ok = xc >= 2.5;
    fail |= !ok;
    fprintf(o, "- %s: cholesky: its plan grows as samples^%.2f >= 2.5 (the factorisation is O(N^3))\n",
            ok ? "PASS" : "FAIL", xc);
    int w = find("lattice-wiener"), p = find("lattice");
    for (int t = 1; t < 3; t++) {
        const acc_t *aw = &acc[w][t], *ap = &acc[p][t];
        ok = aw->ran && aw->eff.effect.hi <= 0.25;
        fail |= !ok;
        fprintf(o, "- %s: the Wiener lattice reproduces %s within 0.25 of R(0) (95%% interval %.3f [%.3f, %.3f]); "
                "the Perlin octave sum: %s\n", ok ? "PASS" : "FAIL", targets[t].name, aw->eff.effect.est,
                aw->eff.effect.lo, aw->eff.effect.hi, ap->ran ? "ran" : "refused (no octave weight)");
    }
    return fail;
}

int main(int argc, char **argv)
{
    char path[4096];
    int full = argc > 2 && !strcmp(argv[2], "full"), fail;
    size_t n64[2] = {64, 64}, n32[2] = {32, 32};
    nl_validate_options vo;
    FILE *o;
    if (argc < 2) {
        fprintf(stderr, "usage: compare_methods OUTDIR [full]\n");
        return 2;
    }
    nl_validate_options_default(&vo);
    vo.realizations = M;
    for (int t = 0; t < NT; t++)
        if (nl_model_parse(targets[t].acf, &targets[t].ma) || nl_model_parse(targets[t].spec, &targets[t].ms)) {
            fprintf(stderr, "compare_methods: %s\n", nl_errmsg());
            return 1;
        }
    for (int t = 0; t < NT; t++) {
        if (nl_validate_init(targets[t].ma, 2, n64, 1, &vo, &vres[0]) ||
            nl_validate_init(targets[t].ma, 2, n32, 1, &vo, &vres[1])) {
            fprintf(stderr, "compare_methods: %s: %s\n", targets[t].name, nl_errmsg());
            return 1;
        }
        for (int i = 0; i < NM; i++) {
            double t0 = now();
            run_accuracy(&methods[i], &targets[t], &acc[i][t]);
            if (getenv("COMPARE_VERBOSE"))
                fprintf(stderr, "accuracy %s %s %.2fs\n", methods[i].name, targets[t].name, now() - t0);
        }
    }
    for (int i = 0; i < NM; i++) {
        double t0 = now();
        run_cost(&methods[i], &targets[methods[i].fractal_only ? 3 : 0], full, &cost[i]);
        if (getenv("COMPARE_VERBOSE"))
            fprintf(stderr, "cost %s %.2fs\n", methods[i].name, now() - t0);
    }
    snprintf(path, sizeof path, "%s/compare-tables.frag", argv[1]);
    if (!(o = fopen(path, "w"))) {
        perror(path);
        return 1;
    }
    fprintf(o, "#### Accuracy (M = %d realizations, 64x64; cholesky 32x32)\n\n", M);
    write_accuracy(o);
    fprintf(o, "\n#### Cost and properties (%s)\n\n", full ? "measured at 256^2, 512^2, 1024^2" :
            "measured at 128^2, 256^2, 512^2, 1024^2 extrapolated; `full` measures 1024^2");
    write_cost(o);
    fprintf(o, "\n#### Verdicts\n\n");
    fail = verdicts(o);
    fclose(o);
    write_tsv(argv[1]);
    for (int t = 0; t < NT; t++)
        nl_model_free(targets[t].ma), nl_model_free(targets[t].ms);
    printf("compare_methods: %s\n", fail ? "FAIL" : "PASS");
    return fail;
}
