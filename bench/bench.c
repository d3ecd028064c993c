/* noiselab bench: speed of the methods against this machine's floor, both
 * measured in the same run (medians of repeats).  The floors call FFTW and
 * run OpenMP loops directly, so this harness lives outside the library and
 * the CLI; it is linked into bin/noiselab as the `bench` subcommand and uses
 * the CLI's option and error helpers (cli/cli.h). */
#include "../cli/cli.h"
#include "bench.h"
#include "../analysis/acf.h"
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../analysis/variogram.h"
#include "../core/spindex.h"
#include "../analysis/psd.h"
#include "../core/fftw_plan.h"
#include "../core/mem.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/rng.h"
#include "../synth/circulant.h"
#include "../synth/method.h"
#include "../synth/rank1.h"
#include "../synth/subdiv.h"

#include <complex.h>
#include <fftw3.h>
#include <getopt.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static const char help[] =
    "usage: noiselab bench [--quick] [--repeat R]\n\n"
    "Times each method and the floor it is measured against, in the same run, and\n"
    "prints TSV: case, size (samples), seconds (median of R runs; default 5, 3 with\n"
    "--quick), floor, floor_seconds, ratio (ours / floor), samples_per_s, bare,\n"
    "bare_seconds, ratio_bare (ours / bare; \"-\" where there is none).  --quick\n"
    "uses grids a quarter of the side.  Floors:\n"
    "  fft, circulant  fill the c2r input with Gaussian numbers + FFTW c2r, of the\n"
    "                  size the method transforms (circulant: its embedding)\n"
    "  subdiv, sparse  draw one Gaussian number per sample + one pass over the field\n"
    "  subdiv correlated  subdivision with independent displacements, same N and size\n"
    "                  (2 taps: the cost of correlating the displacements)\n"
    "  acf             FFTW r2c + c2r of the zero-padded field\n"
    "  psd             FFTW r2c of the field\n"
    "  gaussian fill   a streaming write of as many doubles (the memory bandwidth)\n"
    "  krige           one covariance evaluation per (grid point, data point)\n"
    "  krige (grid)    n^2 m flops (its triangular solves) at the dgemm row's rate\n"
    "  rank1           the tensor-product FFT with the same number of points\n"
    "  variogram       the k-d tree's enumeration of the pairs within the cutoff\n"
    "  krige nmax      the k-d tree's search of the 32 nearest data per cell\n"
    "Bare floors, without our random numbers: fft and circulant the FFTW c2r alone;\n"
    "acf and psd their floor; subdiv, sparse and the Gaussian fill a streaming write\n"
    "of the field (OpenMP threads writing one double per sample).\n"
    "The variogram and local kriging rows run once each, in a child process whose\n"
    "peak resident memory (getrusage) is given in the case's name.\n"
    "Planning is not timed; `make bench` measures the FFTW plans first (measured\n"
    "wisdom); run by hand, plans come from wisdom where it exists, else FFTW_ESTIMATE.\n";

double cli_bench_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double cli_bench_median(double *v, int n)
{
    gsl_sort(v, 1, (size_t)n);
    return gsl_stats_median_from_sorted_data(v, 1, (size_t)n);
}

void cli_bench_row(const char *name, size_t samples, double t, const char *floor_name, double tf, const char *bare,
                   double tb)
{
    printf("%s\t%zu\t%.4f\t%s\t%.4f\t%.2f\t%.3g", name, samples, t, floor_name, tf, t / tf, (double)samples / t);
    if (bare)
        printf("\t%s\t%.4f\t%.2f\n", bare, tb, t / tb);
    else
        printf("\t-\t-\t-\n");
    fflush(stdout);
}

static void row(const char *name, size_t samples, double t, const char *floor_name, double tf)
{
    cli_bench_row(name, samples, t, floor_name, tf, NULL, 0);
}

/* Gaussian numbers into the half spectrum, then c2r, on an n0 x n1 grid:
 * the median seconds, and in *bare those of the c2r alone. */
static double c2r_floor(size_t n0, size_t n1, int reps, double *bare)
{
    size_t half = n1 * (n0 / 2 + 1);
    double *x = nl_alloc(n0 * n1 * sizeof *x), t[16], tb[16];
    fftw_complex *c = nl_alloc(half * sizeof *c);
    fftw_plan b = fftw_plan_dft_c2r_2d((int)n1, (int)n0, c, x, nl_fftw_flags(n0 * n1));
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now(), t1;
        nl_rng_gauss_fill(1, 0, 0, 2 * half, (double *)c);
        t1 = cli_bench_now();
        fftw_execute(b);
        t[r] = cli_bench_now() - t0, tb[r] = cli_bench_now() - t1;
    }
    fftw_destroy_plan(b), nl_free(x), nl_free(c);
    *bare = cli_bench_median(tb, reps);
    return cli_bench_median(t, reps);
}

/* A streaming write of count doubles by the OpenMP threads (pages touched
 * before timing): this machine's memory bandwidth, the floor of any method
 * that writes the field once. */
static double stream_floor(size_t count, int reps)
{
    double *x = nl_alloc(count * sizeof *x), t[16];
    memset(x, 0, count * sizeof *x);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now(), v = (double)r + 0.5;
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < count; i++)
            x[i] = v;
        t[r] = cli_bench_now() - t0;
    }
    nl_free(x);
    return cli_bench_median(t, reps);
}

/* Bare r2c (+ c2r when both) of an n x n grid. */
static double fft_floor(size_t n, int both, int reps)
{
    double *x = nl_alloc(n * n * sizeof *x), t[16];
    fftw_complex *c = nl_alloc(n * (n / 2 + 1) * sizeof *c);
    fftw_plan f = fftw_plan_dft_r2c_2d((int)n, (int)n, x, c, nl_fftw_flags(n * n));
    fftw_plan b = fftw_plan_dft_c2r_2d((int)n, (int)n, c, x, nl_fftw_flags(n * n));
    for (size_t i = 0; i < n * n; i++)
        x[i] = (double)(i % 7);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        fftw_execute(f);
        if (both)
            fftw_execute(b);
        t[r] = cli_bench_now() - t0;
    }
    fftw_destroy_plan(f), fftw_destroy_plan(b), nl_free(x), nl_free(c);
    return cli_bench_median(t, reps);
}

/* One Gaussian number per sample, written once. */
static double rng_floor(size_t count, int reps)
{
    double *x = nl_alloc(count * sizeof *x), t[16];
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        nl_rng_gauss_fill(1, 0, 0, count, x);
        t[r] = cli_bench_now() - t0;
    }
    nl_free(x);
    return cli_bench_median(t, reps);
}

/* The Gaussian fill alone (core/rng.h, its code path in the name) against a
 * streaming write of as many doubles. */
static void bench_gauss(size_t n, int reps)
{
    double t[16], tw = stream_floor(n * n, reps), *x = nl_alloc(n * n * sizeof *x);
    char name[64];
    if (!x)
        cli_die(1, "out of memory");
    memset(x, 0, n * n * sizeof *x);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        nl_rng_gauss_fill((uint64_t)r + 1, 0, 0, n * n, x);
        t[r] = cli_bench_now() - t0;
    }
    nl_free(x);
    snprintf(name, sizeof name, "gaussian fill (%s)", nl_rng_simd());
    cli_bench_row(name, n * n, cli_bench_median(t, reps), "streaming write", tw, "streaming write", tw);
}

/* A method of the registry planned once for m on an n x n grid with its
 * defaults but for `opts` (pairs of option name and value, NULL-ended),
 * then executed reps times: the median time; the plan in *keep. */
static double method_time(const char *name, const nl_model *m, size_t n, const char *const *opts, int reps,
                          nl_method_plan **keep)
{
    const nl_method_type *t = nl_method_find(name);
    nl_method_grid g = {2, {n, n, 1}, {1, 1, 1}, {0, 0}};
    nl_method_options o;
    double tm[16];
    int st = t ? NL_OK : NL_ERROR(NL_EINVAL, "bench: no method \"%s\"", name);
    nl_field *f = t ? nl_field_alloc(2, g.n, NULL, &st) : NULL;
    if (t)
        nl_method_options_default(t, &o);
    for (int k = 0; !st && opts && opts[k]; k += 2)
        st = nl_method_options_set(&o, opts[k], opts[k + 1], opts[k]);
    if (!f || st || (st = nl_method_plan_alloc(t, m, &g, &o, keep)))
        cli_die_status(st);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        nl_method_execute(*keep, (uint64_t)r + 1, f);
        tm[r] = cli_bench_now() - t0;
    }
    nl_field_free(f);
    return cli_bench_median(tm, reps);
}

static void bench_fft(const nl_model *m, size_t n, int reps)
{
    nl_method_plan *p;
    double tb, t = method_time("fft", m, n, NULL, reps, &p);
    double tf = c2r_floor(n, n, reps, &tb);
    cli_bench_row("fft", n * n, t, "gaussian fill + c2r", tf, "fftw c2r", tb);
    nl_method_plan_free(p);
}

static void bench_circulant(const nl_model *m, size_t n, int reps)
{
    nl_method_plan *p;
    nl_synth_circulant_info info;
    double tb, tf, t = method_time("circulant", m, n, NULL, reps, &p);
    nl_synth_circulant_plan_info(nl_method_plan_impl(p), &info);
    tf = c2r_floor(info.m[0], info.m[1], reps, &tb);
    cli_bench_row("circulant", n * n, t, "gaussian fill + c2r of the embedding", tf, "fftw c2r of the embedding",
             tb);
    nl_method_plan_free(p);
}

/* A 2N x 2N neighbourhood, coarse grid 8x8, coefficients (and with taps
 * > 0 the correlated displacements' filters) made once; the median time of
 * the refinement alone (not through the registry: the plan's execute also
 * makes the coarse grid, which the floor leaves out). */
static double subdiv_time(const nl_model *m, size_t n, int N, int taps, int reps)
{
    size_t nn[2] = {n, n};
    double t[16];
    int st, L = 0;
    nl_subdiv_coeffs *co;
    while ((n >> (L + 1)) >= 8)
        L++;
    nl_field *f = nl_field_alloc(2, nn, NULL, &st);
    if (!f || (st = nl_subdiv_coeffs_alloc(m, 2, L, (double)(1 << L), N, 1e-4, 6, &co)) ||
        (taps && (st = nl_subdiv_coeffs_correlate(co, m, taps, NL_SUBDIV_DISP_ERROR))))
        cli_die_status(st);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        nl_subdiv_synth_periodic(co, m, (uint64_t)r + 1, 0, f);
        t[r] = cli_bench_now() - t0;
    }
    nl_subdiv_coeffs_free(co), nl_field_free(f);
    return cli_bench_median(t, reps);
}

/* Independent displacements against the Gaussian floor; correlated ones
 * (2 taps) against independent ones of the same N in the same run. */
static void bench_subdiv(const nl_model *m, size_t n, int reps)
{
    for (int N = 2; N <= 4; N += 2) {
        char name[64];
        double ti = subdiv_time(m, n, N, 0, reps), tc = subdiv_time(m, n, N, 2, reps), tw = stream_floor(n * n, reps);
        snprintf(name, sizeof name, "subdiv N=%d", N);
        cli_bench_row(name, n * n, ti, "gaussian rng + one pass", rng_floor(n * n, reps), "streaming write", tw);
        snprintf(name, sizeof name, "subdiv N=%d correlated", N);
        cli_bench_row(name, n * n, tc, "subdiv, independent displacements", ti, "streaming write", tw);
    }
}

/* The model's kernel, wrapped: a periodic tile. */
static void bench_sparse(const nl_model *m, size_t n, int reps)
{
    static const char *const opts[] = {"density", "4", "wrap", "", NULL};
    nl_method_plan *p;
    double t = method_time("sparse", m, n, opts, reps, &p);
    cli_bench_row("sparse", n * n, t, "gaussian rng + one pass", rng_floor(n * n, reps), "streaming write",
             stream_floor(n * n, reps));
    nl_method_plan_free(p);
}

static void bench_estimators(size_t n, int reps)
{
    size_t nn[2] = {n, n};
    double t[16], tf;
    int st;
    nl_field *f = nl_field_alloc(2, nn, NULL, &st), *out;
    if (!f)
        cli_die_status(st);
    nl_rng_gauss_fill(3, 0, 0, f->count, f->data);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        nl_acf_full(f, 0.0, 0, &out);
        t[r] = cli_bench_now() - t0;
        nl_field_free(out);
    }
    tf = fft_floor(2 * n, 1, reps);
    cli_bench_row("acf", f->count, cli_bench_median(t, reps), "fftw r2c + c2r padded", tf, "fftw r2c + c2r padded", tf);
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
        nl_psd_periodogram(f, NAN, &out);
        t[r] = cli_bench_now() - t0;
        nl_field_free(out);
    }
    tf = fft_floor(n, 0, reps);
    cli_bench_row("psd", f->count, cli_bench_median(t, reps), "fftw r2c", tf, "fftw r2c", tf);
    nl_field_free(f);
}

/* Ordinary kriging of np random points onto g x g (cell centres of the unit
 * square), with and without the variance; the plan (Cholesky) is timed. */
static void bench_krige(const nl_model *m, size_t np, size_t g, int reps)
{
    double *pts = malloc(2 * np * sizeof *pts), *val = malloc(np * sizeof *val), *est = malloc(g * g * sizeof *est);
    double tk[2][16], tf[16];
    int st;
    if (!pts || !val || !est)
        cli_die(1, "out of memory");
    for (size_t i = 0; i < np; i++)
        pts[2 * i] = nl_rng_uniform(5, 0, 2 * i), pts[2 * i + 1] = nl_rng_uniform(5, 0, 2 * i + 1),
        val[i] = nl_rng_gauss(5, 1, i);
    for (int var = 0; var < 2; var++)
        for (int r = 0; r < reps; r++) {
            double t0 = cli_bench_now();
            nl_krige_plan *p;
            if ((st = nl_krige_plan_alloc(m, 2, np, pts, val, 0, 0, 0, &p)))
                cli_die_status(st);
#pragma omp parallel for schedule(dynamic, 1)
            for (size_t q0 = 0; q0 < g * g; q0 += NL_KRIGE_BLOCK) {
                size_t nq = g * g - q0 < NL_KRIGE_BLOCK ? g * g - q0 : NL_KRIGE_BLOCK;
                double x[2 * NL_KRIGE_BLOCK], v[NL_KRIGE_BLOCK];
                for (size_t q = q0; q < q0 + nq; q++)
                    x[2 * (q - q0)] = ((double)(q % g) + 0.5) / (double)g,
                                 x[2 * (q - q0) + 1] = ((double)(q / g) + 0.5) / (double)g;
                nl_krige_eval_block(p, nq, x, &est[q0], var ? v : NULL);
            }
            nl_krige_plan_free(p);
            tk[var][r] = cli_bench_now() - t0;
        }
    for (int r = 0; r < reps; r++) {
        double t0 = cli_bench_now();
#pragma omp parallel for schedule(static)
        for (size_t q = 0; q < g * g; q++) {
            double x[2] = {((double)(q % g) + 0.5) / (double)g, ((double)(q / g) + 0.5) / (double)g}, s = 0;
            for (size_t i = 0; i < np; i++) {
                double d[2] = {x[0] - pts[2 * i], x[1] - pts[2 * i + 1]};
                s += nl_model_acf(m, 2, d);
            }
            est[q] = s;
        }
        tf[r] = cli_bench_now() - t0;
    }
    double fl = cli_bench_median(tf, reps);
    char name[64];
    snprintf(name, sizeof name, "krige %zu points", np);
    row(name, g * g, cli_bench_median(tk[0], reps), "one covariance per (grid, data) pair", fl);
    snprintf(name, sizeof name, "krige %zu points +variance", np);
    row(name, g * g, cli_bench_median(tk[1], reps), "one covariance per (grid, data) pair", fl);
    free(pts), free(val), free(est);
}

/* rank-1 lattice synthesis (Keller) against the tensor-product FFT with the
 * same number of points, s = 2, 3, 4: both are one O(N log N) transform; the
 * lattice does the whole field with a 1D FFT of length N */
static void bench_rank1(int quick, int reps)
{
    static const int side[5] = {0, 0, 128, 32, 16};
    int st;
    for (int sd = 2; sd <= 4; sd++) {
        size_t M = (size_t)(quick ? side[sd] / 2 : side[sd]), NN = 1;
        int dims[4];
        for (int a = 0; a < sd; a++)
            NN *= M, dims[a] = (int)M;
        nl_rank1_lattice L;
        if ((st = nl_rank1_korobov(NN, sd, 0, &L)))
            cli_die_status(st);
        double *cf = malloc(2 * NN * sizeof *cf), *f = malloc(NN * sizeof *f), tr[16], tt[16];
        fftw_complex *b = fftw_alloc_complex(NN);
        fftw_plan p = fftw_plan_dft(sd, dims, b, b, FFTW_BACKWARD, nl_fftw_flags(NN));
        for (int r = 0; r < reps; r++) {
            double t0 = cli_bench_now();
            for (size_t k = 0; k < NN; k++) {
                double k2 = 0;
                for (int a = 0; a < sd; a++)
                    k2 += (double)(L.k[k * sd + a] * L.k[k * sd + a]);
                cf[2 * k] = exp(-k2 / 64) * nl_rng_gauss2(1, 0, k, 0);
                cf[2 * k + 1] = exp(-k2 / 64) * nl_rng_gauss2(1, 0, k, 1);
            }
            nl_rank1_synthesize(&L, cf, 1, f, NULL, NULL);
            tr[r] = cli_bench_now() - t0;
            t0 = cli_bench_now();
            for (size_t k = 0; k < NN; k++)
                b[k] = exp(-(double)(k % 7) / 64) * (nl_rng_gauss2(1, 0, k, 0) + I * nl_rng_gauss2(1, 0, k, 1));
            fftw_execute(p);
            tt[r] = cli_bench_now() - t0;
        }
        char name[64], fl[64];
        snprintf(name, sizeof name, "rank1 %dD", sd);
        snprintf(fl, sizeof fl, "tensor FFT %dD %zu^%d", sd, M, sd);
        row(name, NN, cli_bench_median(tr, reps), fl, cli_bench_median(tt, reps));
        fftw_destroy_plan(p), fftw_free(b), free(cf), free(f), nl_rank1_free(&L);
    }
}

/* Uniform points in the unit square with Gaussian values (seeded). */
static nl_points *bench_points(size_t n)
{
    nl_points *p = cli_malloc(sizeof *p);
    p->dim = 2, p->n = n, p->pts = cli_malloc(2 * n * sizeof(double)), p->val = cli_malloc(n * sizeof(double));
    for (size_t i = 0; i < n; i++)
        p->pts[2 * i] = nl_rng_uniform(11, 0, 2 * i), p->pts[2 * i + 1] = nl_rng_uniform(11, 0, 2 * i + 1),
        p->val[i] = nl_rng_gauss(11, 1, i);
    return p;
}

static int count_pair(void *ctx, size_t i, size_t j, double d2)
{
    (void)i, (void)j, (void)d2;
    ++*(size_t *)ctx;
    return 0;
}

/* Run task(n, g) in a child: its seconds through a pipe, its peak resident
 * memory from wait4. */
static double in_child(double (*task)(size_t, size_t), size_t n, size_t g, double *mb)
{
    int fd[2];
    double t = NAN;
    struct rusage ru;
    int status;
    fflush(stdout);
    if (pipe(fd))
        cli_die(1, "bench: pipe failed");
    pid_t pid = fork();
    if (pid < 0)
        cli_die(1, "bench: fork failed");
    if (pid == 0) {
        close(fd[0]);
        t = task(n, g);
        if (write(fd[1], &t, sizeof t) != (ssize_t)sizeof t)
            _exit(1);
        _exit(0);
    }
    close(fd[1]);
    if (read(fd[0], &t, sizeof t) != (ssize_t)sizeof t)
        t = NAN;
    close(fd[0]);
    if (wait4(pid, &status, 0, &ru) < 0 || !WIFEXITED(status) || WEXITSTATUS(status))
        cli_die(1, "bench: the measured child failed");
    *mb = (double)ru.ru_maxrss / 1024;
    return t;
}

static double task_variogram(size_t n, size_t g)
{
    (void)g;
    nl_points *p = bench_points(n);
    nl_variogram_options o;
    nl_variogram *v;
    nl_variogram_options_default(&o);
    double t0 = cli_bench_now();
    cli_check(nl_variogram_points(p, &o, &v));
    t0 = cli_bench_now() - t0;
    nl_variogram_free(v), nl_points_free(p);
    return t0;
}

static double task_krige(size_t n, size_t g)
{
    nl_points *p = bench_points(n);
    nl_model *m;
    nl_krige_local *k;
    nl_krige_local_options o = {.nmax = 32, .drift = NL_DRIFT_CONSTANT};
    size_t sz[2] = {g, g};
    double h[2] = {1.0 / (double)g, 1.0 / (double)g}, lo[2] = {0, 0};
    cli_check(nl_model_parse("markov:scale=0.05", &m));
    nl_field *e = cli_field_alloc(2, sz, h), *var = cli_field_alloc(2, sz, h);
    double t0 = cli_bench_now();
    cli_check(nl_krige_local_alloc(m, 2, n, p->pts, p->val, &o, &k));
    cli_check(nl_krige_local_grid(k, lo, e, var));
    t0 = cli_bench_now() - t0;
    nl_krige_local_free(k), nl_model_free(m), nl_field_free(e), nl_field_free(var), nl_points_free(p);
    return t0;
}

/* The variogram of n scattered points (gstat's default cutoff and bins) and
 * ordinary kriging of them onto g x g with the variance, nmax = 32. */
static void bench_geo(size_t n, size_t g)
{
    char name[96];
    double mb, mk, t, tk, t0;
    size_t pairs = 0, idx[32];
    double d2[32];
    /* both children before any OpenMP loop of this process: libgomp's
     * threads do not survive fork */
    t = in_child(task_variogram, n, g, &mb);
    tk = in_child(task_krige, n, g, &mk);
    nl_points *p = bench_points(n);
    nl_spindex *s;
    cli_check(nl_spindex_alloc(2, n, p->pts, &s));
    t0 = cli_bench_now();
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : pairs)
    for (size_t a = 0; a < n; a++) {
        size_t c = 0;
        nl_spindex_pairs_at(s, a, 0.33333 * sqrt(2.0), count_pair, &c);
        pairs += c;
    }
    snprintf(name, sizeof name, "variogram %zu points (peak %.0f MB)", n, mb);
    row(name, pairs, t, "k-d tree pair enumeration", cli_bench_now() - t0);
    t0 = cli_bench_now();
#pragma omp parallel for schedule(dynamic, 256) private(idx, d2)
    for (size_t q = 0; q < g * g; q++) {
        double x[2] = {((double)(q % g) + 0.5) / (double)g, ((double)(q / g) + 0.5) / (double)g};
        nl_spindex_knn(s, x, 32, idx, d2);
    }
    snprintf(name, sizeof name, "krige %zu points nmax 32 +variance (peak %.0f MB)", n, mk);
    row(name, g * g, tk, "k-d tree 32-nearest search", cli_bench_now() - t0);
    nl_spindex_free(s), nl_points_free(p);
}


int cli_cmd_bench(int argc, char **argv)
{
    static const struct option opts[] = {{"quick", no_argument, 0, 'q'}, {"repeat", required_argument, 0, 'r'},
                                         {"help", no_argument, 0, 'h'}, {0}};
    int c, quick = 0, reps = 0, st;
    const char *rtext = NULL; /* --repeat as given */
    size_t d;
    nl_model *m, *me, *mk;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":h", opts, NULL)) != -1) {
        switch (c) {
        case 'q':
            if (quick)
                cli_die(2, "bench: --quick: given twice; expected it once");
            quick = 1;
            break;
        case 'r':
            if (rtext)
                cli_die(2, "bench: --repeat: given twice (\"%s\", then \"%s\"); expected it once", rtext, optarg);
            rtext = optarg;
            reps = (int)cli_parse_count("--repeat", optarg, 1);
            if (reps > 16)
                cli_die(2, "--repeat: expected 1 to 16, got \"%s\"", optarg);
            break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("bench", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "bench: unexpected argument \"%s\"", argv[optind]);
    if (!reps)
        reps = quick ? 3 : 5;
    d = quick ? 4 : 1;
    if ((st = nl_model_parse("markaussian:alpha=1.4,scale=16", &m)) ||
        (st = nl_model_parse("markov:scale=16", &me)) || (st = nl_model_parse("markov:scale=0.2", &mk)))
        cli_die_status(st);
    printf("case\tsize\tseconds\tfloor\tfloor_seconds\tratio\tsamples_per_s\tbare\tbare_seconds\tratio_bare\n");
    bench_geo(100000 / (d * d), 1000 / d); /* first: the children's peak memory starts from a small parent */
    for (size_t n = 1024; n <= 4096; n *= 2)
        bench_gauss(n / d, reps);
    for (size_t n = 1024; n <= 4096; n *= 2)
        bench_fft(m, n / d, reps);
    for (size_t n = 1024; n <= 2048; n *= 2)
        bench_circulant(me, n / d, reps);
    for (size_t n = 1024; n <= 4096; n *= 2)
        bench_subdiv(m, n / d, reps);
    bench_sparse(m, 1024 / d, reps);
    bench_estimators(2048 / d, reps);
    bench_krige(mk, 1000 / d, 256 / d, reps);
    cli_bench_blas(mk, 1000 / d, 256 / d, reps); /* bench/bench_blas.c */
    bench_rank1(quick, reps);
    nl_model_free(m), nl_model_free(me), nl_model_free(mk);
    return 0;
}
