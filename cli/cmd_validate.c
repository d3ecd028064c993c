/* noiselab validate: the whole pairing for one model, with a verdict. */
#include "cli.h"
#include "../analysis/check.h"
#include "../analysis/validate.h"
#include "../core/model.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char help[] =
    "usage: noiselab validate --acf SPEC --dim 1|2 -o DIR [--size N] [--realizations M]\n\n"
    "Checks the model (noiselab check), synthesises M realizations (default 32, seeds\n"
    "1..M) with every applicable method (fft, circulant, subdiv, sparse), estimates the\n"
    "ensemble ACF along x with its standard error from the ensemble's spread, and\n"
    "compares it with the target at 33 lags: max |z| against the Bonferroni threshold\n"
    "of Student's t(M-1) at a family-wise rate of 1e-3.  Writes DIR/index.md (tables,\n"
    "plots), DIR/verdict.json, DIR/acf.tsv and DIR/acf.png (gnuplot).  Subdivision is\n"
    "approximate: its own exact expected ACF is shown beside the target.  N is a power\n"
    "of two (default 2048 in 1D, 128 in 2D), and N^dim M at most 2^24.\n";

/* What validate works on and what it found. */
typedef struct {
    const char *spec, *dir;  /* model, output directory */
    int dim;                 /* 1 or 2 */
    size_t N, M;             /* side, realizations */
    nl_model *m;             /* the parsed model */
    nl_check k;              /* its check */
    nl_validate_result r;    /* target, threshold, exact ACF and the methods' verdicts */
} vctx;

#define L NL_VALIDATE_LAGS
#define NM NL_VALIDATE_METHODS

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
    /* every method synthesises and estimates M fields: about 2e5 samples a
     * second, so 2^24 samples keep each method near a minute */
    if ((double)v->M * pow((double)v->N, v->dim) > 16777216.0)
        cli_die(2, "--size %zu with --realizations %zu in %dD: %.3g samples per method; expected at most 2^24 "
                "(about a minute per method)", v->N, v->M, v->dim, (double)v->M * pow((double)v->N, v->dim));
}

static FILE *open_in(const vctx *v, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", v->dir, name);
    return fopen(path, "w");
}

/* One TSV cell: the number, or "-" where a method did not run (or its
 * estimate is undefined), so that the table holds no nan. */
static void cell(FILE *fp, int have, double v)
{
    if (have && isfinite(v))
        fprintf(fp, "\t%.8g", v);
    else
        fprintf(fp, "\t-");
}

/* A JSON number, or null where it is undefined. */
static json_t *num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

/* DIR/acf.tsv and the gnuplot script; returns whether the plot was made. */
static int write_data(const vctx *v)
{
    char cmd[4200];
    const char *col[NM] = {"#1f4e99", "#2e8b57", "#b22222", "#8b6914"};
    const nl_validate_result *r = &v->r;
    FILE *fp = open_in(v, "acf.tsv");
    if (!fp)
        cli_die(2, "-o: cannot write in \"%s\"", v->dir);
    fprintf(fp, "lag\ttarget\tsubdiv_exact");
    for (int meth = 0; meth < NM; meth++)
        fprintf(fp, "\t%s\t%s_se", nl_validate_method_name(meth), nl_validate_method_name(meth));
    fprintf(fp, "\n");
    for (int i = 0; i < L; i++) {
        fprintf(fp, "%d", i);
        cell(fp, 1, r->target[i]);
        cell(fp, r->have_exact, r->have_exact ? r->exact[i] : 0);
        for (int meth = 0; meth < NM; meth++) {
            cell(fp, r->method[meth].ran, r->method[meth].ran ? r->method[meth].mean[i] : 0);
            cell(fp, r->method[meth].ran, r->method[meth].ran ? r->method[meth].se[i] : 0);
        }
        fprintf(fp, "\n");
    }
    fclose(fp);
    fp = open_in(v, "acf.gp");
    fprintf(fp, "set terminal pngcairo size 900,560 font 'DejaVu Sans,11'\nset output '%s/acf.png'\n"
                "set title '%s, %dD: ensemble ACF along x (%zu realizations)'\nset xlabel 'lag (samples)'\n"
                "set grid\nset key top right\nset datafile missing '-'\n"
                "plot '%s/acf.tsv' using 1:2 with lines lw 3 lc rgb 'black' title 'target'",
            v->dir, v->spec, v->dim, v->M, v->dir);
    for (int meth = 0; meth < NM; meth++)
        if (r->method[meth].ran)
            fprintf(fp, ", '' using 1:%d:%d with yerrorlines pt 7 ps 0.5 lc rgb '%s' title '%s'", 4 + 2 * meth,
                    5 + 2 * meth, col[meth], nl_validate_method_name(meth));
    if (r->have_exact)
        fprintf(fp, ", '' using 1:3 with lines dt 2 lw 2 lc rgb '#b22222' title 'subdiv exact'");
    fprintf(fp, "\n");
    fclose(fp);
    snprintf(cmd, sizeof cmd, "gnuplot '%s/acf.gp' 2>/dev/null", v->dir);
    return system(cmd) == 0;
}

/* Why a method was refused; a model that is not positive definite is
 * described in the report's first section. */
static const char *refusal(const vctx *v, int meth)
{
    return v->k.positive_definite ? v->r.method[meth].why : "the model is not positive definite (see above)";
}

/* "%.*g", or what an undefined (NaN) or unbounded figure means. */
static const char *figure(char *buf, size_t size, int digits, double v, const char *nan_means)
{
    if (isfinite(v))
        snprintf(buf, size, "%.*g", digits, v);
    else
        snprintf(buf, size, "%s", isnan(v) ? nan_means : v < 0 ? "unbounded below (a kink at lag 0)" : "unbounded");
    return buf;
}

static void write_model_md(FILE *fp, const vctx *v)
{
    const nl_check *k = &v->k;
    char b1[64], b2[64], b3[64];
    fprintf(fp, "# noiselab validate: `%s` in %dD\n\n## The model\n\n%s. Smallest sampled spectrum / largest: "
                "%s; smallest covariance eigenvalue / R(0): %s%s. Mean-square differentiable %s; "
                "R''(0) = %s; %s.\n\n",
            v->spec, v->dim, k->positive_definite ? "**Positive definite**" : "**Not positive definite**",
            figure(b1, sizeof b1, 3, k->min_spectrum, "not computed"),
            figure(b2, sizeof b2, 3, k->min_eigenvalue, "not computed (a spectrum: model)"),
            k->isotropic ? (k->isotropic_bound_ok ? "; isotropic, above the -1/n bound" : "; isotropic, BELOW the -1/n bound") : "",
            k->differentiable_order < 0 ? "infinitely often" : k->differentiable_order == 0 ? "nowhere (rough)" : "a finite number of times",
            figure(b3, sizeof b3, 4, k->r2, "not computed (a spectrum: model)"), k->singular_below > 0 ? "numerically singular for subdivision below spacing" : "never numerically singular for subdivision");
    if (k->singular_below > 0)
        fprintf(fp, "(%.3g)\n\n", k->singular_below);
}

/* DIR/index.md and DIR/verdict.json. */
static void write_report(const vctx *v, int plotted)
{
    const nl_validate_result *res = &v->r;
    char path[4096];
    FILE *fp = open_in(v, "index.md");
    write_model_md(fp, v);
    fprintf(fp, "## The methods\n\n%zu realizations of %zu%s%zu samples (seeds 1..%zu); the unbiased ACF with "
                "known mean 0 along x at lags 0..32; max |z| = |mean - R| / se against %.2f (Student's t(%zu), "
                "Bonferroni over 33 lags, family-wise 1e-3).\n\n| method | max \\|z\\| | verdict |\n|---|---|---|\n",
            v->M, res->n[0], v->dim == 2 ? " x " : "", v->dim == 2 ? res->n[1] : (size_t)0, v->M, res->threshold,
            v->M - 1);
    json_t *vj = json_pack("{s:s,s:i,s:b,s:o,s:o}", "model", v->spec, "dim", v->dim, "positive_definite",
                           v->k.positive_definite, "threshold", num(res->threshold), "methods", json_object());
    for (int meth = 0; meth < NM; meth++) {
        const nl_validate_method_result *r = &res->method[meth];
        const char *name = r->name;
        if (r->ran && !isfinite(r->zmax))
            fprintf(fp, "| %s | - | undefined (the ensemble's spread is 0 at some lag) |\n", name);
        else if (r->ran)
            fprintf(fp, "| %s | %.2f | %s |\n", name, r->zmax,
                    r->pass ? "reproduces the target" : "does NOT reproduce the target");
        else
            fprintf(fp, "| %s | - | refused: %s |\n", name, refusal(v, meth));
        json_object_set_new(json_object_get(vj, "methods"), name,
                            r->ran ? json_pack("{s:o,s:b}", "max_abs_z", num(r->zmax), "pass", r->pass)
                                   : json_pack("{s:s}", "refused", refusal(v, meth)));
    }
    fprintf(fp, "\n%s\n\nSubdivision estimates new points from earlier levels only, so its covariance differs "
                "from R except for Markovian models in 1D; %s\n",
            plotted ? "![acf](acf.png)" : "(gnuplot failed: no plot)",
            res->have_exact ? "its exact expected ACF (dashed) shows how far by construction." : "its exact ACF is computed for grids up to 64x64 (2D) or 2048 (1D).");
    fclose(fp);
    snprintf(path, sizeof path, "%s/verdict.json", v->dir);
    if (json_dump_file(vj, path, JSON_INDENT(2) | JSON_PRESERVE_ORDER))
        cli_die(1, "cannot write %s", path);
    json_decref(vj);
}

/* Progress of the whole run: four methods of M realizations each. */
static void progress(void *ctx, int meth, size_t done, size_t total)
{
    (void)ctx;
    cli_progress("validate", (meth + (double)done / (double)total) / NM);
}

/* R finite at every lag of the validation grid (a model singular at one
 * lag would be refused by some methods with a message naming a NaN and
 * pass others unnoticed). */
static void check_grid_lags(const vctx *v)
{
    if (nl_model_get_kind(v->m) == NL_MODEL_SPECTRUM)
        return;
    for (size_t j = 0; j < (v->dim == 2 ? v->N : 1); j++)
        for (size_t i = 0; i < v->N; i++) {
            double lag[3] = {(double)i, (double)j, 0};
            double r = nl_model_acf(v->m, v->dim, lag);
            if (!isfinite(r))
                cli_die(2, "--acf: %s is not finite at lag (%zu, %zu) of the %zu-sample grid; expected a model "
                        "finite at every lag", v->spec, i, j, v->N);
        }
}

int cli_cmd_validate(int argc, char **argv)
{
    static vctx v;
    nl_validate_options o;
    size_t n[2];
    int st;
    memset(&v, 0, sizeof v);
    parse(argc, argv, &v);
    if ((st = nl_model_parse(v.spec, &v.m)) || (st = nl_check_model(v.m, v.dim, &v.k)))
        cli_die_status(st);
    check_grid_lags(&v);
    n[0] = n[1] = v.N;
    nl_validate_options_default(&o);
    o.realizations = v.M, o.progress = progress;
    /* the folder is made once every check has passed; a failure from here
     * on removes it, or what this run added to it (cli_out_dir) */
    cli_out_dir("-o", v.dir);
    if ((st = nl_validate_model(v.m, v.dim, n, v.k.positive_definite, &o, &v.r)))
        cli_die_status(st);
    cli_progress_done();
    write_report(&v, write_data(&v));
    printf("%s %dD: %s;", v.spec, v.dim, v.k.positive_definite ? "positive definite" : "NOT positive definite");
    for (int meth = 0; meth < NM; meth++)
        printf(" %s %s", nl_validate_method_name(meth), !v.r.method[meth].ran ? "refused" : v.r.method[meth].pass ? "ok" : "off");
    printf(" (report in %s/index.md)\n", v.dir);
    nl_model_free(v.m);
    return 0;
}
