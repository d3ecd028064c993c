/* libFuzzer targets for the number paths: FUZZ_TARGET selects one.
 *   7 synthnum  the library: a synthesis plan and its execution on a tiny
 *               grid, then the analysis of the output (full ACF,
 *               periodogram, moments)
 *   (8 synthcli, the same choice as a command line: fuzz_synthcli.c)
 *   9 fieldnum  the analysis on a tiny field (up to 16 x 16) of hostile
 *               finite samples (0, denormals, 1e154, 1e200, 1e308, ...):
 *               ACF (full, axis, radial, direct), periodogram, Welch,
 *               moments, histogram, spectral slope
 * The fuzzer's bytes are decoded into a structured choice (num_case.h),
 * not parsed as text: a method of the registry that takes a model, a model name with each parameter either absent or drawn from a
 * table of hostile but parseable numbers (0, -0, denormals, 1e308, values
 * just inside and outside each parameter's limits, nan, inf), anisotropy
 * options, a size of at most 32 x 32 (8^3 in 3D), a spacing and the
 * method's options (from its option table).  So every input reaches the numbers after the parser.
 *
 * The checker traps (__builtin_trap, a crash libFuzzer records) when
 *   - a call returns NL_OK and its output holds a non-finite number;
 *   - a call refuses with an empty nl_errmsg().
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
#include "../../synth/method.h"
#include "num_case.h"
#if FUZZ_TARGET == 9
#include "../../analysis/slope.h"
#include "../../analysis/welch.h"
#endif

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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

/* Plan and execute the method through the registry; returns the status
 * of the first failure. */
static int synth(const fcase *c, const nl_model *m, nl_field *out)
{
    const nl_method_type *t = c->method;
    nl_method_grid g = {c->dim, {c->n[0], c->n[1], c->n[2]}, {atof(c->h), atof(c->h), atof(c->h)},
                        {c->origin[0], c->origin[1]}};
    nl_method_options o;
    nl_method_plan *p;
    int st = NL_OK;
    nl_method_options_default(t, &o);
    o.flags = c->clamp ? NL_METHOD_OPT_CLAMP : 0;
    for (int k = 0; k < t->noptions && !st; k++)
        if (c->opt[k])
            st = nl_method_options_set(&o, t->options[k].name, c->opt[k], t->options[k].name);
    if (!st && (st = nl_method_plan_alloc(t, m, &g, &o, &p)) == NL_OK) {
        st = nl_method_execute(p, c->seed, out);
        nl_method_plan_free(p);
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
        check(st, c.method->name);
        if (st == NL_OK) {
            check_field(out, c.method->name);
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

#endif
