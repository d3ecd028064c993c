/* libFuzzer targets for the number paths: FUZZ_TARGET selects one.
 *   7 synthnum  the library: a synthesis plan and its execution on a tiny
 *               grid, then the analysis of the output (full ACF,
 *               periodogram, moments)
 *   8 synthcli  the same choice as a command line, `noiselab synth ...`,
 *               run in-process by cli_main (cli_die's exit replaced by a
 *               longjmp, as in fuzz_cli.c)
 *   9 fieldnum  the analysis on a tiny field (up to 16 x 16) of hostile
 *               finite samples (0, denormals, 1e154, 1e200, 1e308, ...):
 *               ACF (full, axis, radial, direct), periodogram, Welch,
 *               moments, histogram, spectral slope
 * The fuzzer's bytes are decoded into a structured choice (decode below),
 * not parsed as text: a method (fft, circulant, cholesky, sparse, lattice,
 * subdiv), a model name with each parameter either absent or drawn from a
 * table of hostile but parseable numbers (0, -0, denormals, 1e308, values
 * just inside and outside each parameter's limits, nan, inf), anisotropy
 * options, a size of at most 32 x 32 (8^3 in 3D), a spacing and the
 * method's options.  So every input reaches the numbers after the parser.
 *
 * The checker traps (__builtin_trap, a crash libFuzzer records) when
 *   - a call returns NL_OK and its output holds a non-finite number;
 *   - a call refuses with an empty nl_errmsg();
 *   - (synthcli) a refusal leaves a file in the working folder, or its
 *     stderr is not one line "noiselab: ...", or a success writes a field
 *     that is not finite or prints nan or inf on stdout.
 * Memory is limited to 16 MiB per request (NOISELAB_MEMORY_LIMIT) and
 * Cholesky to 256 samples, to keep each run short.  FUZZ_DEBUG=1 in the
 * environment prints the decoded case on stderr (to reproduce a finding
 * on the command line). */
#include "../../analysis/acf.h"
#include "../../analysis/hist.h"
#include "../../analysis/psd.h"
#include "../../core/io.h"
#include "../../core/model.h"
#include "../../core/nl_error.h"
#include "../../synth/cholesky.h"
#include "../../synth/circulant.h"
#include "../../synth/fft.h"
#include "../../synth/lattice.h"
#include "../../synth/sparse.h"
#include "../../synth/subdiv.h"
#if FUZZ_TARGET == 9
#include "../../analysis/slope.h"
#include "../../analysis/welch.h"
#endif
#if FUZZ_TARGET == 8
#include "../../cli/cli.h"
#include <dirent.h>
#include <setjmp.h>
#endif

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Hostile but parseable numbers (as text, so the library and the command
 * line see the same value). */
static const char *const num[] = {
    "0",      "-0",     "1",     "-1",    "0.5",   "2",      "1e-300", "4.9e-324", "2.2250738585072014e-308",
    "1e308",  "1.7976931348623157e308", "-1e308",  "1e-8",   "1e8",    "1e80",     "1e-80",
    "2.0000000000000004", "1.9999999999999998", "0.001", "100", "1000", "50", "1e15", "3", "0.25",
    "7",      "64",     "-2",    "1e-5",  "0.99999999", "1.0000001", "1e4", "nan", "inf", "-inf", "4",
    "1e-3",   "200",    "0.1",   "12",    "1e6",   "1e7",    "8193",   "4096",     "1e-12",  "90", "-45"};
enum { NNUM = sizeof num / sizeof *num };

static const char *const methods[] = {"fft", "circulant", "cholesky", "sparse", "lattice", "subdiv"};
static const char *const names[] = {"markov", "gauss", "markaussian", "oscillatory", "gauss-osc", "matern", "power"};
/* Each name's own parameters (besides var and scale). */
static const char *const own[][3] = {{0}, {0}, {"alpha"}, {"omega"}, {"omega"}, {"nu"}, {"d", "fmin", "fmax"}};
static const char *const exprs[] = {"exp(-abs(t)/%s)", "%s*exp(-t^2)", "exp(-abs(t)^%s)", "cos(%s*t)*exp(-abs(t))",
                                    "1/(1+(t/%s)^2)",  "sin(%s*t)/t", "1-abs(t)/%s",      "exp(-r/%s)*(1+r/%s)",
                                    "exp(-abs(x)/%s-abs(y))"};
static const char *const spectra[] = {"exp(-(f/%s)^2)", "1/(1+(%s*f)^2)", "abs(f)^-%s", "%s", "exp(-k*%s)",
                                      "1/(1+(k/%s)^2)^2", "1/f"};

typedef struct {
    const uint8_t *p;
    size_t left;
} bytes;

static unsigned take(bytes *b)
{
    if (!b->left)
        return 0;
    b->left--;
    return *b->p++;
}

static const char *pick_num(bytes *b) { return num[take(b) % NNUM]; }

typedef struct {
    int method, dim;
    size_t n[3];
    const char *h;
    char model[512];
    uint64_t seed;
    int clamp;
    int max_factor;                       /* circulant (library only) */
    const char *radius, *cell, *density;  /* sparse; cell also lattice's cell0 */
    int octaves;                          /* lattice, 0 = default */
    int levels, N, nonperiodic, random_nb; /* subdiv */
    const char *tol;
    long origin[2];                       /* windows of subdiv and sparse */
} fcase;

/* Window origins, near the integer limits too. */
static const long origins[] = {0, -1, 7, 1000, -100000, 1L << 40, -(1L << 40), LONG_MAX - 5, LONG_MIN + 5, LONG_MAX};

static void add(char *s, size_t cap, const char *fmt, const char *a, const char *v)
{
    size_t k = strlen(s);
    snprintf(s + k, cap - k, fmt, a, v);
}

static void decode_model(bytes *b, char *s, size_t cap)
{
    unsigned k = take(b) % 10;
    if (k >= 7 && k <= 8) {
        const char *t = k == 7 ? exprs[take(b) % (sizeof exprs / sizeof *exprs)]
                               : spectra[take(b) % (sizeof spectra / sizeof *spectra)];
        const char *v = pick_num(b);
        char body[256];
        snprintf(body, sizeof body, t, v, v);
        snprintf(s, cap, "%s:%s", k == 7 ? "expr" : "spectrum", body);
        if (take(b) & 1) /* options after a ';' */
            add(s, cap, ";%s=%s", take(b) & 1 ? "var" : "ratio", pick_num(b));
        return;
    }
    k %= 7;
    snprintf(s, cap, "%s", names[k]);
    char sep = ':';
    for (int i = 0; i < 3 && own[k][i]; i++) {
        unsigned c = take(b);
        if (i == 0 || (c & 1)) { /* the first own parameter is required */
            char key[16];
            snprintf(key, sizeof key, "%c%s", sep, own[k][i]);
            add(s, cap, "%s=%s", key, num[(c >> 1) % NNUM]);
            sep = ',';
        }
    }
    static const char *const opt[] = {"var", "scale", "angle", "ratio", "zratio"};
    unsigned mask = take(b);
    for (int i = 0; i < 5; i++)
        if (mask & (1u << i)) {
            char key[16];
            snprintf(key, sizeof key, "%c%s", sep, opt[i]);
            add(s, cap, "%s=%s", key, pick_num(b));
            sep = ',';
        }
    if (mask & 0x20)
        add(s, cap, "%s%s", sep == ':' ? ":" : ",", "sep");
}

static void decode(const uint8_t *data, size_t size, fcase *c)
{
    bytes b = {data, size};
    memset(c, 0, sizeof *c);
    c->method = take(&b) % 6;
    c->dim = 1 + take(&b) % 3;
    for (int a = 0; a < 3; a++)
        c->n[a] = a < c->dim ? 1 + take(&b) % (c->dim == 3 ? 8 : 32) : 1;
    c->h = take(&b) & 1 ? pick_num(&b) : "1";
    decode_model(&b, c->model, sizeof c->model);
    c->seed = take(&b);
    unsigned o = take(&b);
    c->clamp = o & 1;
    c->nonperiodic = (o >> 1) & 1;
    c->max_factor = (int[]){2, 4, 16, 1}[(o >> 2) & 3];
    c->radius = o & 0x10 ? pick_num(&b) : "0";
    c->cell = o & 0x20 ? pick_num(&b) : "0";
    c->density = o & 0x40 ? pick_num(&b) : "1";
    c->tol = o & 0x80 ? pick_num(&b) : "1e-4";
    c->octaves = take(&b) % 20;
    c->levels = take(&b) % 10;
    c->N = take(&b) % 10;
    c->random_nb = take(&b) % 4;
    unsigned w = take(&b);
    c->origin[0] = origins[(w & 15) % (sizeof origins / sizeof *origins)];
    c->origin[1] = origins[(w >> 4) % (sizeof origins / sizeof *origins)];
    if (c->method == 2) /* Cholesky: O(count^3), at most 256 samples here */
        while (c->n[0] * c->n[1] * c->n[2] > 256)
            for (int a = 0; a < c->dim; a++)
                c->n[a] = c->n[a] > 1 ? c->n[a] / 2 : 1;
}

static void debug(const fcase *c)
{
    if (!getenv("FUZZ_DEBUG"))
        return;
    fprintf(stderr,
            "case: %s dim %d n %zux%zux%zu h %s model '%s' seed %llu clamp %d nonperiodic %d max_factor %d radius %s "
            "cell %s density %s tol %s octaves %d levels %d N %d random_nb %d origin %ld,%ld\n",
            methods[c->method], c->dim, c->n[0], c->n[1], c->n[2], c->h, c->model, (unsigned long long)c->seed,
            c->clamp, c->nonperiodic, c->max_factor, c->radius, c->cell, c->density, c->tol, c->octaves, c->levels,
            c->N, c->random_nb, c->origin[0], c->origin[1]);
}

/* FUZZ_IGNORE=tag,tag,...: findings already recorded that should not stop
 * an exploration run (tags: METHOD-nonfinite, METHOD-silent, with METHOD a
 * method or nl_acf_full, nl_psd_periodogram, nl_moments_compute, and
 * cli-METHOD-nonfinite, -stdout, -stderr, -leftover).  `make fuzz` sets none. */
static int ignored(const char *what, const char *kind)
{
    const char *list = getenv("FUZZ_IGNORE");
    char tag[64];
    snprintf(tag, sizeof tag, "%s-%s", what, kind);
    for (const char *p = list; p && (p = strstr(p, tag)); p += strlen(tag))
        if ((p == list || p[-1] == ',') && (p[strlen(tag)] == ',' || !p[strlen(tag)]))
            return 1;
    return 0;
}

static void setup(void)
{
    static int done;
    if (done++)
        return;
    setenv("NOISELAB_MEMORY_LIMIT", "16777216", 1);
    setenv("NOISELAB_FFTW", "estimate", 1);
}

#if FUZZ_TARGET == 7 || FUZZ_TARGET == 9
/* A refusal must say why; a success must be finite. */
static void check(int st, const char *what)
{
    const char *e = nl_errmsg();
    if (st != NL_OK && (!e || !*e) && !ignored(what, "silent")) {
        fprintf(stderr, "fuzz: %s refused (status %d) with an empty message\n", what, st);
        __builtin_trap();
    }
}

static void check_field(const nl_field *f, const char *what)
{
    for (size_t i = 0; i < f->count; i++)
        if (!isfinite(f->data[i])) {
            if (ignored(what, "nonfinite"))
                return;
            fprintf(stderr, "fuzz: %s returned NL_OK with sample %zu = %g\n", what, i, f->data[i]);
            __builtin_trap();
        }
}

#endif

#if FUZZ_TARGET == 7
static void analyse(const nl_field *x)
{
    nl_field *a = NULL, *p = NULL;
    int st = nl_acf_full(x, 0, 1, &a);
    check(st, "nl_acf_full");
    if (st == NL_OK)
        check_field(a, "nl_acf_full");
    st = nl_psd_periodogram(x, 0, &p);
    check(st, "nl_psd_periodogram");
    if (st == NL_OK)
        check_field(p, "nl_psd_periodogram");
    nl_moments mo;
    st = nl_moments_compute(x, &mo);
    check(st, "nl_moments_compute");
    nl_field_free(a);
    nl_field_free(p);
}

/* Plan and execute the method; returns the status of the first failure. */
static int synth(const fcase *c, const nl_model *m, nl_field *out)
{
    double h[3] = {atof(c->h), atof(c->h), atof(c->h)};
    unsigned fl = c->clamp ? NL_SYNTH_FFT_CLAMP : 0;
    int st;
    if (c->method == 0) {
        nl_synth_fft_plan *p;
        if ((st = nl_synth_fft_plan_alloc(m, c->dim, c->n, h, fl, &p)) == NL_OK) {
            st = nl_synth_fft_execute(p, c->seed, out);
            nl_synth_fft_plan_free(p);
        }
    } else if (c->method == 1) {
        nl_synth_circulant_plan *p;
        if ((st = nl_synth_circulant_plan_alloc(m, c->dim, c->n, h, fl, c->max_factor, &p)) == NL_OK) {
            st = nl_synth_circulant_execute(p, c->seed, out);
            nl_synth_circulant_plan_free(p);
        }
    } else if (c->method == 2) {
        nl_synth_cholesky_plan *p;
        if ((st = nl_synth_cholesky_plan_alloc(m, c->dim, c->n, h, &p)) == NL_OK) {
            st = nl_synth_cholesky_execute(p, c->seed, out);
            nl_synth_cholesky_plan_free(p);
        }
    } else if (c->method == 3) {
        nl_synth_sparse_plan *p;
        if ((st = nl_synth_sparse_plan_model(m, c->dim, h, atoi(c->radius), atoi(c->cell), atof(c->density), &p)) ==
            NL_OK) {
            st = nl_synth_sparse_execute(p, c->seed, c->nonperiodic, c->nonperiodic ? NULL : c->origin, out);
            nl_synth_sparse_plan_free(p);
        }
    } else if (c->method == 4) {
        nl_synth_lattice_plan p;
        double cell0 = atof(c->cell) > 0 ? atof(c->cell) : nl_synth_lattice_default_cell(c->n);
        int oct = c->octaves ? c->octaves : nl_synth_lattice_default_octaves(cell0);
        if ((st = nl_synth_lattice_plan_init(m, c->dim, cell0, oct, &p)) == NL_OK)
            st = nl_synth_lattice_execute(&p, c->seed, out);
    } else {
        nl_subdiv_options o;
        nl_subdiv_options_default(&o);
        o.levels = c->levels;
        o.N = c->N;
        o.tol = atof(c->tol);
        o.nonperiodic = c->nonperiodic;
        o.allow_not_pd = c->clamp;
        o.random_nb = c->dim == 2 ? c->random_nb : 0;
        o.random_seed = c->seed;
        nl_subdiv_plan *p;
        if ((st = nl_subdiv_plan_alloc(m, c->dim, c->n, h[0], &o, &p)) == NL_OK) {
            st = c->nonperiodic ? nl_subdiv_plan_execute_window(p, c->seed, c->origin, out)
                                : nl_subdiv_plan_execute(p, c->seed, out);
            nl_subdiv_plan_free(p);
        }
    }
    return st;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fcase c;
    setup();
    decode(data, size, &c);
    debug(&c);
    nl_model *m;
    int st = nl_model_parse(c.model, &m);
    check(st, "nl_model_parse");
    if (st)
        return 0;
    double h[3] = {atof(c.h), atof(c.h), atof(c.h)};
    nl_field *out = nl_field_alloc(c.dim, c.n, h, &st);
    check(st, "nl_field_alloc");
    if (out) {
        st = synth(&c, m, out);
        check(st, methods[c.method]);
        if (st == NL_OK) {
            check_field(out, methods[c.method]);
            analyse(out);
        }
        nl_field_free(out);
    }
    nl_model_free(m);
    return 0;
}

#elif FUZZ_TARGET == 9
/* Finite sample values that stress sums of squares and fourth powers. */
static const double vals[] = {0, -0.0, 1, -1, 0.5, 4.9e-324, 2.2250738585072014e-308, 1e-300, 1e-154, 1e77,
                              1e154, -1e154, 1e200, -1e200, 1e308, -1e308, 1.7976931348623157e308, 3, 1e15, -7};
enum { NVAL = sizeof vals / sizeof *vals };

static void finite_array(const double *v, size_t n, const char *what)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i])) {
            if (ignored(what, "nonfinite"))
                return;
            fprintf(stderr, "fuzz: %s returned NL_OK with value %zu = %g\n", what, i, v[i]);
            __builtin_trap();
        }
}

static void acfs(const nl_field *x, int unbiased, size_t maxlag)
{
    nl_field *a = NULL;
    int st = nl_acf_full(x, 0, unbiased, &a);
    check(st, "nl_acf_full");
    if (st)
        return;
    check_field(a, "nl_acf_full");
    double lag[16], val[16];
    size_t cnt[16];
    if ((st = nl_acf_axis(a, 0, maxlag, lag, val)) == NL_OK)
        finite_array(val, maxlag + 1, "nl_acf_axis");
    check(st, "nl_acf_axis");
    if ((st = nl_acf_radial(a, 8, lag, val, cnt)) == NL_OK)
        for (size_t i = 0; i < 8; i++)
            if (cnt[i])
                finite_array(&val[i], 1, "nl_acf_radial");
    check(st, "nl_acf_radial");
    if ((st = nl_acf_direct(x, 0, unbiased, 0, maxlag, val)) == NL_OK)
        finite_array(val, maxlag + 1, "nl_acf_direct");
    check(st, "nl_acf_direct");
    nl_field_free(a);
}

static void psds(const nl_field *x, size_t S)
{
    nl_field *P = NULL;
    int st = nl_psd_periodogram(x, 0, &P);
    check(st, "nl_psd_periodogram");
    if (st == NL_OK) {
        check_field(P, "nl_psd_periodogram");
        nl_slope sl;
        if ((st = nl_psd_slope_grid(P, 0.01, 0.5, &sl)) == NL_OK)
            finite_array(&sl.slope, 1, "nl_psd_slope_grid");
        check(st, "nl_psd_slope_grid");
        nl_field_free(P);
    }
    nl_welch_plan *w;
    if ((st = nl_welch_plan_alloc(x->dim, S, &w)) == NL_OK) {
        size_t n[2] = {S, S};
        nl_field *W = nl_field_alloc(x->dim, n, x->h, &st);
        if (W && (st = nl_welch_plan_execute(w, x, NAN, W, NULL)) == NL_OK)
            check_field(W, "nl_welch_plan_execute");
        check(st, "nl_welch_plan_execute");
        nl_field_free(W);
        nl_welch_plan_free(w);
    }
    check(st, "nl_welch_plan_alloc");
}

static void moments(const nl_field *x, size_t bins)
{
    nl_moments mo;
    int st = nl_moments_compute(x, &mo);
    check(st, "nl_moments_compute");
    if (st)
        return;
    double m4[4] = {mo.mean, mo.variance, mo.min, mo.max};
    finite_array(m4, 4, "nl_moments_compute");
    double edges[65], counts[64], mid[64], dens[64], gauss[64];
    if ((st = nl_hist(x, bins, edges, counts)) == NL_OK)
        finite_array(edges, bins + 1, "nl_hist");
    check(st, "nl_hist");
    if ((st = nl_hist_density(x, &mo, bins, mid, dens, gauss)) == NL_OK) {
        finite_array(mid, bins, "nl_hist_density");
        finite_array(dens, bins, "nl_hist_density");
    }
    check(st, "nl_hist_density");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    bytes b = {data, size};
    setup();
    int dim = 1 + take(&b) % 2;
    size_t n[2] = {1 + take(&b) % 16, dim == 2 ? 1 + take(&b) % 16 : 1};
    double h[2];
    h[0] = h[1] = take(&b) & 1 ? atof(pick_num(&b)) : 1;
    unsigned o = take(&b);
    size_t S = (size_t[]){4, 8, 16, 3}[o & 3], bins = 1 + (o >> 2) % 64, maxlag = take(&b) % 16;
    int st;
    nl_field *x = nl_field_alloc(dim, n, h, &st);
    check(st, "nl_field_alloc");
    if (!x)
        return 0;
    for (size_t i = 0; i < x->count; i++)
        x->data[i] = vals[(b.left ? take(&b) : (unsigned)(i * 7)) % NVAL];
    if (getenv("FUZZ_DEBUG")) {
        fprintf(stderr, "case: dim %d n %zux%zu h %g unbiased %u S %zu bins %zu maxlag %zu values", dim, n[0], n[1],
                h[0], o & 1, S, bins, maxlag);
        for (size_t i = 0; i < x->count; i++)
            fprintf(stderr, " %g", x->data[i]);
        fputc('\n', stderr);
    }
    acfs(x, o & 1, maxlag);
    psds(x, S);
    moments(x, bins);
    nl_field_free(x);
    return 0;
}

#else /* FUZZ_TARGET == 8: the same choice through the command line */

static jmp_buf back;
static char errpath[64], outpath[64];

static void escape(int code) { longjmp(back, code + 1); }

static void setup_cli(void)
{
    static int done;
    if (done++)
        return;
    cli_exit_hook = escape;
    snprintf(errpath, sizeof errpath, "/tmp/noiselab-fuzz-err-%ld", (long)getpid());
    snprintf(outpath, sizeof outpath, "/tmp/noiselab-fuzz-out-%ld", (long)getpid());
}

static long slurp(const char *path, char *buf, size_t cap)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return -1;
    size_t k = fread(buf, 1, cap - 1, fp);
    buf[k] = 0;
    fclose(fp);
    return (long)k;
}

/* nan or inf as a word of the text (not "info"). */
static int has_nonfinite(const char *s)
{
    for (const char *p = s; *p; p++) {
        int start = p == s || !((p[-1] | 32) >= 'a' && (p[-1] | 32) <= 'z');
        if (start && (!strncasecmp(p, "nan", 3) || !strncasecmp(p, "inf", 3))) {
            char e = p[3];
            if (!((e | 32) >= 'a' && (e | 32) <= 'z') || !strncasecmp(p, "infinity", 8))
                return 1;
        }
    }
    return 0;
}

static void fail(const fcase *c, const char *kind, const char *why, const char *detail)
{
    char what[32];
    snprintf(what, sizeof what, "cli-%s", methods[c->method]);
    if (ignored(what, kind))
        return;
    fprintf(stderr, "fuzz: %s: %s\n", why, detail);
    setenv("FUZZ_DEBUG", "1", 1);
    debug(c);
    __builtin_trap();
}

/* Files in the working folder other than the ones expected. */
static void leftovers(const fcase *c, int ok)
{
    DIR *d = opendir(".");
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && !(ok && !strcmp(e->d_name, "out.exr")))
        {
            fail(c, "leftover", ok ? "a success left an extra file" : "a refusal left a file", e->d_name);
            unlink(e->d_name); /* ignored (FUZZ_IGNORE): clean up for the next run */
        }
    if (d)
        closedir(d);
}

/* Empty the working folder: a run that crashed or timed out (fork mode)
 * could not clean up, and its files would be blamed on the next one. */
static void sweep(void)
{
    DIR *d = opendir(".");
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            unlink(e->d_name);
    if (d)
        closedir(d);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fcase c;
    setup();
    setup_cli();
    sweep();
    decode(data, size, &c);
    debug(&c);
    char sz[64], seed[32];
    if (c.dim == 1)
        snprintf(sz, sizeof sz, "%zu", c.n[0]);
    else if (c.dim == 2)
        snprintf(sz, sizeof sz, "%zux%zu", c.n[0], c.n[1]);
    else
        snprintf(sz, sizeof sz, "%zux%zux%zu", c.n[0], c.n[1], c.n[2]);
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)c.seed);
    char lv[8], nb[8], oc[8], rn[8];
    snprintf(lv, sizeof lv, "%d", c.levels);
    snprintf(nb, sizeof nb, "%d", c.N);
    snprintf(oc, sizeof oc, "%d", c.octaves);
    snprintf(rn, sizeof rn, "%d", c.random_nb);
    char *argv[40];
    int argc = 0;
#define ARG(s) (argv[argc++] = (char *)(s))
    nl_model *m;
    int spectral = 0;
    if (nl_model_parse(c.model, &m) == NL_OK) {
        spectral = nl_model_is_spectral(m);
        nl_model_free(m);
    }
    char org[64];
    if (c.dim == 1)
        snprintf(org, sizeof org, "%ld", c.origin[0]);
    else
        snprintf(org, sizeof org, "%ld,%ld", c.origin[0], c.origin[1]);
    ARG("noiselab"), ARG("synth"), ARG(methods[c.method]), ARG(spectral ? "--spectrum" : "--acf"), ARG(c.model);
    ARG("--size"), ARG(sz);
    ARG("--seed"), ARG(seed), ARG("--spacing"), ARG(c.h), ARG("--json");
    if (c.clamp)
        ARG("--clamp");
    if (c.method == 3)
        ARG("--density"), ARG(c.density), ARG("--radius"), ARG(c.radius), ARG("--cell"), ARG(c.cell);
    if (c.method == 3 && c.nonperiodic)
        ARG("--wrap");
    else if (c.method == 3 && (c.origin[0] || c.origin[1]))
        ARG("--origin"), ARG(org);
    if (c.method == 4) {
        if (strcmp(c.cell, "0"))
            ARG("--cell"), ARG(c.cell);
        if (c.octaves)
            ARG("--octaves"), ARG(oc);
    }
    if (c.method == 5) {
        if (c.levels)
            ARG("--levels"), ARG(lv);
        if (c.N)
            ARG("--neighborhood"), ARG(nb);
        ARG("--tol"), ARG(c.tol);
        if (c.nonperiodic)
            ARG("--nonperiodic"), ARG("--origin"), ARG(org);
        if (c.random_nb && c.dim == 2)
            ARG("--random-neighborhoods"), ARG(rn);
    }
    ARG("-o"), ARG("out.exr");
    argv[argc] = NULL;
    fflush(stdout);
    fflush(stderr);
    int so = dup(1), se = dup(2);
    if (!freopen(outpath, "w", stdout) || !freopen(errpath, "w", stderr))
        abort();
    extern int optind;
    optind = 0;
    int code;
    if ((code = setjmp(back)) == 0)
        code = cli_main(argc, argv);
    else
        code--;
    fflush(stdout);
    fflush(stderr);
    dup2(so, 1), dup2(se, 2);
    close(so), close(se);
    static char text[1 << 16];
    if (code != 0) {
        long k = slurp(errpath, text, sizeof text);
        char *nl = k > 0 ? strchr(text, '\n') : NULL;
        if (k <= 0 || strncmp(text, "noiselab: ", 10) || !nl || nl[1] || nl == text + 10)
            fail(&c, "stderr", "a refusal's stderr is not one line \"noiselab: ...\"", k > 0 ? text : "(empty)");
        leftovers(&c, 0);
    } else {
        if (slurp(outpath, text, sizeof text) > 0 && has_nonfinite(text))
            fail(&c, "stdout", "stdout holds nan or inf", text);
        nl_field *f;
        nl_meta meta;
        if (nl_field_read("out.exr", &f, &meta) != NL_OK)
            fail(&c, "nonfinite", "a success wrote an out.exr that does not read back (the reader refuses non-finite samples)",
                 nl_errmsg());
        else {
            for (size_t i = 0; i < f->count; i++)
                if (!isfinite(f->data[i])) {
                    fail(&c, "nonfinite", "a success wrote a non-finite sample into out.exr", "");
                    break;
                }
            nl_field_free(f);
        }
        leftovers(&c, 1);
        unlink("out.exr");
    }
    return 0;
}
#endif
