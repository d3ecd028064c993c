/* noiselab validate: the whole pairing for one model, with a verdict. */
#include "cli.h"
#include "../analysis/check.h"
#include "../analysis/subdiv_exact.h"
#include "../analysis/verdict.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/circulant.h"
#include "../synth/fft.h"
#include "../synth/sparse.h"
#include "../synth/subdiv.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char help[] =
    "usage: noiselab validate --acf SPEC --dim 1|2 -o DIR [--size N] [--realizations M]\n\n"
    "Checks the model (noiselab check), synthesises M realizations (default 32, seeds\n"
    "1..M) with every applicable method (fft, circulant, subdiv, sparse), estimates the\n"
    "ensemble ACF along x with its standard error from the ensemble's spread, and\n"
    "compares it with the target at 33 lags: max |z| against the Bonferroni threshold\n"
    "of Student's t(M-1) at a family-wise rate of 1e-3.  Writes DIR/index.md (tables,\n"
    "plots), DIR/verdict.json, DIR/acf.tsv and DIR/acf.png (gnuplot).  Subdivision is\n"
    "approximate: its own exact expected ACF is shown beside the target.\n";

typedef int (*run_fn)(void *ctx, uint64_t seed, nl_field *f);
static int run_fft(void *c, uint64_t s, nl_field *f) { return nl_synth_fft_execute(c, s, f); }
static int run_circ(void *c, uint64_t s, nl_field *f) { return nl_synth_circulant_execute(c, s, f); }
static int run_sparse(void *c, uint64_t s, nl_field *f) { return nl_synth_sparse_execute(c, s, 1, NULL, f); }
typedef struct {
    nl_subdiv_coeffs *c;
    const nl_model *m;
} sub_ctx;
static int run_sub(void *c, uint64_t s, nl_field *f)
{
    sub_ctx *x = c;
    return nl_subdiv_synth_periodic(x->c, x->m, s, 0, f);
}

#define L 33

/* One method's ensemble against the target. */
typedef struct {
    double mean[L], se[L];  /* ensemble mean ACF and its standard error */
    double zmax;            /* max |z| over the lags */
    int ran;                /* 0: refused, see why */
    char why[256];          /* the refusal */
} method_result;

/* What validate works on and what it found. */
typedef struct {
    const char *spec, *dir;  /* model, output directory */
    int dim;                 /* 1 or 2 */
    size_t N, M, n[2];       /* side, realizations, grid */
    nl_model *m;             /* the parsed model */
    nl_check k;              /* its check */
    double target[L];        /* R at lags 0..L-1 along x */
    double exact[L];         /* subdivision's exact expected ACF */
    int have_exact;          /* exact[] is set */
    double zcrit;            /* Bonferroni threshold */
    method_result res[4];    /* fft, circulant, subdiv, sparse */
} vctx;

static const char *const names[4] = {"fft", "circulant", "subdiv", "sparse"};

static void parse(int argc, char **argv, vctx *v)
{
    static const struct option opts[] = {{"acf", required_argument, 0, 'a'}, {"dim", required_argument, 0, 'd'},
                                         {"output", required_argument, 0, 'o'}, {"size", required_argument, 0, 'n'},
                                         {"realizations", required_argument, 0, 'M'}, {"help", no_argument, 0, 'h'},
                                         {0}};
    int c;
    v->M = 32;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'a': v->spec = optarg; break;
        case 'd': v->dim = cli_parse_dim(optarg, 2); break;
        case 'o': v->dir = optarg; break;
        case 'n': v->N = cli_parse_count("--size", optarg, 64); break;
        case 'M': v->M = cli_parse_count("--realizations", optarg, 4); break;
        case 'h': fputs(help, stdout); exit(0);
        default: cli_bad_option("validate", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "validate: unexpected argument \"%s\"", argv[optind]);
    if (!v->spec || !v->dim || !v->dir)
        cli_die(2, "validate: expected --acf SPEC, --dim 1|2 and -o DIR");
    if (v->M > 1000)
        cli_die(2, "--realizations: expected at most 1000, got %zu", v->M);
    if (!v->N)
        v->N = v->dim == 1 ? 2048 : 128;
    if (v->N & (v->N - 1))
        cli_die(2, "--size: expected a power of two, got %zu", v->N);
    if (mkdir(v->dir, 0755) && errno != EEXIST)
        cli_die(2, "-o: cannot create directory \"%s\": %s", v->dir, strerror(errno));
}

/* M realizations of one method into its ensemble verdict. */
static void run_ensemble(vctx *v, int meth, run_fn fn, void *ctx)
{
    method_result *r = &v->res[meth];
    nl_field *f = nl_field_alloc(v->dim, v->n, NULL, NULL);
    long lags[L][2];
    nl_verdict *vd = NULL;
    int st;
    for (int i = 0; i < L; i++)
        lags[i][0] = i, lags[i][1] = 0;
    st = f ? nl_verdict_alloc(v->dim, v->n, L, (const long (*)[2])lags, &vd) : NL_ENOMEM;
    for (size_t s = 1; s <= v->M && !st; s++) {
        cli_progress("validate", (meth + (double)(s - 1) / (double)v->M) / 4);
        if ((st = fn(ctx, s, f)) || (st = nl_verdict_add(vd, f)))
            break;
    }
    if (!st)
        st = nl_verdict_stats(vd, r->mean, r->se);
    if (st)
        snprintf(r->why, sizeof r->why, "%s", nl_errmsg());
    else {
        r->ran = 1;
        r->zmax = nl_verdict_zmax(L, r->mean, r->se, v->target, NULL);
    }
    nl_verdict_free(vd);
    nl_field_free(f);
}

/* Subdivision's coefficients, and its exact expected ACF on small grids. */
static int plan_subdiv(vctx *v, sub_ctx *sc)
{
    int Lv = 0, st;
    while ((v->N >> (Lv + 1)) >= 16)
        Lv++;
    st = nl_subdiv_coeffs_alloc(v->m, v->dim, Lv, ldexp(1.0, Lv), 2, 1e-4, 6, &sc->c);
    if (!st && (sc->c->flags & NL_SUBDIV_NOT_PD))
        st = NL_ERROR(NL_ENOTPD, "not positive definite at some level");
    if (!st && v->N <= (v->dim == 1 ? 2048 : 64)) {
        long lags[2 * L];
        for (int i = 0; i < L; i++)
            lags[2 * i] = i, lags[2 * i + 1] = 0;
        v->have_exact = nl_subdiv_exact_acf(sc->c, v->m, v->n[0], v->n[1], L, lags, v->exact) == 0;
    }
    return st;
}

static void run_method(vctx *v, int meth)
{
    void *ctx = NULL;
    run_fn fn = NULL;
    nl_synth_fft_plan *pf = NULL;
    nl_synth_circulant_plan *pc = NULL;
    nl_synth_sparse_plan *ps = NULL;
    sub_ctx sc = {NULL, v->m};
    int st = NL_OK;
    if (meth == 0) st = nl_synth_fft_plan_alloc(v->m, v->dim, v->n, NULL, 0, &pf), ctx = pf, fn = run_fft;
    if (meth == 1) st = nl_synth_circulant_plan_alloc(v->m, v->dim, v->n, NULL, 0, 16, &pc), ctx = pc, fn = run_circ;
    if (meth == 2) st = plan_subdiv(v, &sc), ctx = &sc, fn = run_sub;
    if (meth == 3) st = nl_synth_sparse_plan_model(v->m, v->dim, NULL, 0, 0, 32, &ps), ctx = ps, fn = run_sparse;
    if (!v->k.positive_definite)
        snprintf(v->res[meth].why, sizeof v->res[meth].why, "the model is not positive definite (see above)");
    else if (st)
        snprintf(v->res[meth].why, sizeof v->res[meth].why, "%s", nl_errmsg());
    else
        run_ensemble(v, meth, fn, ctx);
    nl_synth_fft_plan_free(pf), nl_synth_circulant_plan_free(pc), nl_synth_sparse_plan_free(ps);
    nl_subdiv_coeffs_free(sc.c);
}

static FILE *open_in(const vctx *v, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", v->dir, name);
    return fopen(path, "w");
}

/* DIR/acf.tsv and the gnuplot script; returns whether the plot was made. */
static int write_data(const vctx *v)
{
    char cmd[4200];
    const char *col[4] = {"#1f4e99", "#2e8b57", "#b22222", "#8b6914"};
    FILE *fp = open_in(v, "acf.tsv");
    if (!fp)
        cli_die(2, "-o: cannot write in \"%s\"", v->dir);
    fprintf(fp, "lag\ttarget\tsubdiv_exact");
    for (int meth = 0; meth < 4; meth++)
        fprintf(fp, "\t%s\t%s_se", names[meth], names[meth]);
    fprintf(fp, "\n");
    for (int i = 0; i < L; i++) {
        fprintf(fp, "%d\t%.8g\t%.8g", i, v->target[i], v->have_exact ? v->exact[i] : NAN);
        for (int meth = 0; meth < 4; meth++)
            fprintf(fp, "\t%.8g\t%.8g", v->res[meth].ran ? v->res[meth].mean[i] : NAN,
                    v->res[meth].ran ? v->res[meth].se[i] : NAN);
        fprintf(fp, "\n");
    }
    fclose(fp);
    fp = open_in(v, "acf.gp");
    fprintf(fp, "set terminal pngcairo size 900,560 font 'DejaVu Sans,11'\nset output '%s/acf.png'\n"
                "set title '%s, %dD: ensemble ACF along x (%zu realizations)'\nset xlabel 'lag (samples)'\n"
                "set grid\nset key top right\nset datafile missing 'nan'\n"
                "plot '%s/acf.tsv' using 1:2 with lines lw 3 lc rgb 'black' title 'target'",
            v->dir, v->spec, v->dim, v->M, v->dir);
    for (int meth = 0; meth < 4; meth++)
        if (v->res[meth].ran)
            fprintf(fp, ", '' using 1:%d:%d with yerrorlines pt 7 ps 0.5 lc rgb '%s' title '%s'", 4 + 2 * meth,
                    5 + 2 * meth, col[meth], names[meth]);
    if (v->have_exact)
        fprintf(fp, ", '' using 1:3 with lines dt 2 lw 2 lc rgb '#b22222' title 'subdiv exact'");
    fprintf(fp, "\n");
    fclose(fp);
    snprintf(cmd, sizeof cmd, "gnuplot '%s/acf.gp' 2>/dev/null", v->dir);
    return system(cmd) == 0;
}

static const char *verdict_word(const method_result *r, double zcrit)
{
    return !r->ran ? "refused" : r->zmax <= zcrit ? "reproduces the target" : "does NOT reproduce the target";
}

static void write_model_md(FILE *fp, const vctx *v)
{
    const nl_check *k = &v->k;
    fprintf(fp, "# noiselab validate: `%s` in %dD\n\n## The model\n\n%s. Smallest sampled spectrum / largest: "
                "%.3g; smallest covariance eigenvalue / R(0): %.3g%s. Mean-square differentiable %s; "
                "R''(0) = %.4g; %s.\n\n",
            v->spec, v->dim, k->positive_definite ? "**Positive definite**" : "**Not positive definite**",
            k->min_spectrum, k->min_eigenvalue,
            k->isotropic ? (k->isotropic_bound_ok ? "; isotropic, above the -1/n bound" : "; isotropic, BELOW the -1/n bound") : "",
            k->differentiable_order < 0 ? "infinitely often" : k->differentiable_order == 0 ? "nowhere (rough)" : "a finite number of times",
            k->r2, k->singular_below > 0 ? "numerically singular for subdivision below spacing" : "never numerically singular for subdivision");
    if (k->singular_below > 0)
        fprintf(fp, "(%.3g)\n\n", k->singular_below);
}

/* DIR/index.md and DIR/verdict.json. */
static void write_report(const vctx *v, int plotted)
{
    char path[4096];
    FILE *fp = open_in(v, "index.md");
    write_model_md(fp, v);
    fprintf(fp, "## The methods\n\n%zu realizations of %zu%s%zu samples (seeds 1..%zu); the unbiased ACF with "
                "known mean 0 along x at lags 0..32; max |z| = |mean - R| / se against %.2f (Student's t(%zu), "
                "Bonferroni over 33 lags, family-wise 1e-3).\n\n| method | max \\|z\\| | verdict |\n|---|---|---|\n",
            v->M, v->n[0], v->dim == 2 ? " x " : "", v->dim == 2 ? v->n[1] : (size_t)0, v->M, v->zcrit, v->M - 1);
    json_t *vj = json_pack("{s:s,s:i,s:b,s:f,s:o}", "model", v->spec, "dim", v->dim, "positive_definite",
                           v->k.positive_definite, "threshold", v->zcrit, "methods", json_object());
    for (int meth = 0; meth < 4; meth++) {
        const method_result *r = &v->res[meth];
        if (r->ran)
            fprintf(fp, "| %s | %.2f | %s |\n", names[meth], r->zmax, verdict_word(r, v->zcrit));
        else
            fprintf(fp, "| %s | - | refused: %s |\n", names[meth], r->why);
        json_object_set_new(json_object_get(vj, "methods"), names[meth],
                            r->ran ? json_pack("{s:f,s:b}", "max_abs_z", r->zmax, "pass", r->zmax <= v->zcrit)
                                   : json_pack("{s:s}", "refused", r->why));
    }
    fprintf(fp, "\n%s\n\nSubdivision estimates new points from earlier levels only, so its covariance differs "
                "from R except for Markovian models in 1D; %s\n",
            plotted ? "![acf](acf.png)" : "(gnuplot failed: no plot)",
            v->have_exact ? "its exact expected ACF (dashed) shows how far by construction." : "its exact ACF is computed for grids up to 64x64 (2D) or 2048 (1D).");
    fclose(fp);
    snprintf(path, sizeof path, "%s/verdict.json", v->dir);
    if (json_dump_file(vj, path, JSON_INDENT(2) | JSON_PRESERVE_ORDER))
        cli_die(1, "cannot write %s", path);
    json_decref(vj);
}

int cli_cmd_validate(int argc, char **argv)
{
    static vctx v;
    int st;
    memset(&v, 0, sizeof v);
    parse(argc, argv, &v);
    if ((st = nl_model_parse(v.spec, &v.m)) || (st = nl_check_model(v.m, v.dim, &v.k)))
        cli_die_status(st);
    v.n[0] = v.N, v.n[1] = v.dim == 2 ? v.N : 1;
    for (int i = 0; i < L; i++) {
        double lag1[3] = {i * 1.0, 0, 0};
        v.target[i] = nl_model_acf(v.m, v.dim, lag1);
    }
    v.zcrit = nl_verdict_threshold(1e-3, L, v.M - 1);
    for (int meth = 0; meth < 4; meth++)
        run_method(&v, meth);
    cli_progress_done();
    write_report(&v, write_data(&v));
    printf("%s %dD: %s;", v.spec, v.dim, v.k.positive_definite ? "positive definite" : "NOT positive definite");
    for (int meth = 0; meth < 4; meth++)
        printf(" %s %s", names[meth], !v.res[meth].ran ? "refused" : v.res[meth].zmax <= v.zcrit ? "ok" : "off");
    printf(" (report in %s/index.md)\n", v.dir);
    nl_model_free(v.m);
    return 0;
}
