/* noiselab krige: ordinary or simple kriging of scattered data onto a grid. */
#include "cli.h"
#include "opt.h"
#include "krige_predict.h"
#include "krige_flavours.h"
#include "../analysis/krige.h"
#include "../analysis/krige_local.h"
#include "../core/io_points.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <float.h>
#include <string.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static const char help[] =
    "usage: noiselab krige --data PTS.tsv --acf SPEC --grid W[xH[xD]] --extent a:b[,c:d[,e:f]]\n"
    "                      [--mean M] [--strict] [--json] -o OUT [--variance VAR] [--format NAME]\n"
    "                      [--nmax K] [--radius D] [--drift TERMS [--covariate NAME=FIELD.exr]...]\n"
    "       noiselab krige --data PTS.tsv --acf SPEC --at TABLE.tsv -o OUT.tsv [--nmax K] [--radius D]\n"
    "                      [--drift TERMS] [--mean M] [--json]\n"
    "       noiselab krige --data PTS.tsv --acf SPEC --cross-validate [K] [--folds COLUMN | --seed S]\n"
    "                      [--nmax K] [--radius D] [--drift TERMS] [--mean M] [--json] [-o CV.tsv]\n"
    "       flavours: [--block WxH[xD] [--block-points N]] [--transform log|boxcox:LAMBDA]\n"
    "                 [--indicator T1,T2,... [--indicator-acf SPEC]...]\n\n"
    "Kriging (Stam and Fiume 1991, eqs. 19-22): ordinary (unknown mean, unbiased by a\n"
    "Lagrange multiplier) or, with --mean, simple.  PTS.tsv: a header line naming the\n"
    "columns x [y [z]] and value (in any order), then rows; with --at, --folds or a\n"
    "covariate in --drift, other numeric columns are allowed (covariates, fold ids).\n"
    "Grid cell centres are a + (i + 0.5)(b - a)/W; the extent is recorded in the map\n"
    "(noiselab.method, --json) so that noiselab sample reads it at its coordinates.\n"
    "A singular system (duplicate points, a smooth model with close points) is solved\n"
    "by the pseudo-inverse and flagged, or refused with --strict.  --variance writes\n"
    "the kriging variance (O(n^2) per cell).\n"
    "--nmax K: each cell from its K nearest data (as gstat's nmax); --radius D: from the\n"
    "data within D (gstat's maxdist).  A cell or point with no datum in its\n"
    "neighbourhood (or fewer than the drift terms) is missing, as gstat's NA: NaN in\n"
    "EXR, NA in TSV, counted on stderr and in --json (\"missing\"); when all are, the\n"
    "first one's error (exit 2).\n"
    "--drift TERMS: universal kriging; comma-separated terms added to the constant:\n"
    "linear (x, y[, z]; or name them: x,y), quadratic, and names of numeric columns of\n"
    "--data and of --at (an external drift).  gstat's value ~ x + y is --drift linear,\n"
    "value ~ sqrt(dist) is --drift sdist with a column sdist = sqrt(dist) in both.  On a\n"
    "grid, --covariate NAME=FIELD.exr gives each covariate's values at the cells (a\n"
    "field of the grid's size, sample i at cell i).\n"
    "--at TABLE.tsv: predict at the table's points (columns x [y [z]], any others):\n"
    "-o gets the table's rows as read (the original text of every cell) and two\n"
    "columns, estimate and variance (17 significant digits; NA when missing).\n"
    "--cross-validate: leave-one-out (as gstat's krige.cv); with K < n, k-fold: each\n"
    "fold predicted from the other data alone, folds from the column --folds COLUMN\n"
    "(integer ids; gstat's krige.cv(nfold = K) after set.seed(s) draws them as\n"
    "sample(K, n, replace = TRUE)) or drawn from --seed (default 0).  Per point\n"
    "observed, predicted, variance, error = observed - predicted, zscore = error /\n"
    "sqrt(variance) (and fold) to -o, and the mean and variance of error and zscore\n"
    "on stdout (missing predictions left out).\n" CLI_KRIGE_FL_HELP;

/* The command's options. */
typedef struct {
    const char *data, *spec, *grid, *ext, *out, *vout;  /* as given, or NULL */
    double mean, lo[3], hi[3];                          /* --mean (NAN: ordinary), --extent */
    int npz;                                            /* -o is an .npz: the variance goes in it too */
    int strict, json, gdim;                             /* --strict, --json, grid dimension */
    int local, cv, drift;                               /* local/universal path, --cross-validate, --drift */
    size_t nmax;                                        /* --nmax (0: all) */
    double radius;                                      /* --radius (0: no limit) */
    size_t g[3];                                        /* --grid */
    kp_opts pr;                                         /* --at, --drift, --cross-validate, --folds, --seed */
    cli_krige_fl fl;                                    /* --block, --transform, --indicator */
} opts_t;

static void parse_extent(opts_t *a)
{
    const char *p = a->ext;
    for (int d = 0; d < a->gdim; d++) {
        char *end;
        a->lo[d] = strtod(p, &end);
        if (end == p || *end != ':')
            cli_die(2, "--extent: expected a:b per axis separated by commas, got \"%s\"", a->ext);
        p = end + 1;
        a->hi[d] = strtod(p, &end);
        if (end == p || !(a->hi[d] > a->lo[d]) || (d + 1 < a->gdim ? *end != ',' : *end != 0))
            cli_die(2, "--extent: expected %d ranges a:b with a < b, got \"%s\"", a->gdim, a->ext);
        if (!isfinite(4 * (a->hi[d] - a->lo[d])))
            cli_die(2, "--extent: expected finite ranges whose width does not overflow, got \"%s\"", a->ext);
        p = end + 1;
    }
}

/* The grid and the data together span finite distances on every axis. */
static void check_reach(const opts_t *a, const nl_points *pt)
{
    for (int d = 0; d < a->gdim; d++) {
        double lo = a->lo[d], hi = a->hi[d];
        for (size_t i = 0; i < pt->n; i++)
            lo = fmin(lo, pt->pts[i * (size_t)pt->dim + d]), hi = fmax(hi, pt->pts[i * (size_t)pt->dim + d]);
        if (!isfinite(4 * (hi - lo)))
            cli_die(2, "--extent: \"%s\" and the data of %s span %g to %g on axis %d, whose distances overflow; "
                    "expected a span below %g", a->ext, a->data, lo, hi, d + 1, DBL_MAX / 4);
    }
}

static const cli_opt rows[] = {
    CLI_STRING("data", opts_t, data, .need = "a table of points (x, y[, z], value)"),
    CLI_STRING("acf", opts_t, spec, .need = "a covariance model (see noiselab models)"),
    CLI_STRING("grid", opts_t, grid, .need = "the output grid WxH[xD]"),
    CLI_STRING("extent", opts_t, ext, .need = "the grid's extent a:b,c:d[,e:f]"), CLI_DOUBLE("mean", opts_t, mean),
    CLI_FLAG("strict", opts_t, strict), CLI_OPT_JSON(opts_t, json),
    CLI_OPT_OUTPUT(opts_t, out, .need = "an output file (noiselab formats)"), CLI_STRING("variance", opts_t, vout),
    CLI_OPT_FORMAT,
    /* the local or universal path */
    CLI_COUNT("nmax", opts_t, nmax, CLI_GIVEN(opts_t, local), .lo = 1),
    CLI_POSITIVE("radius", opts_t, radius, CLI_GIVEN(opts_t, local), .what = "distance"),
    CLI_GROUP(kp_rows, opts_t, pr),
    /* the flavours (cli/krige_flavours.c) */
    CLI_GROUP(cli_krige_fl_rows, opts_t, fl), {0}};

/* --cross-validate: no grid; -o (optional) is a TSV of the points. */
static void parse_cv(opts_t *a)
{
    if (!a->data)
        cli_die(2, "krige: --data: expected a table of points (x, y[, z], value)");
    if (!a->spec)
        cli_die(2, "krige: --acf: expected a covariance model (see noiselab models)");
    if (a->grid || a->ext || a->vout)
        cli_die(2, "--cross-validate: expected no %s (it predicts the data points)",
                a->grid ? "--grid" : a->ext ? "--extent" : "--variance");
    if (a->out && !cli_has_ext(a->out, ".tsv"))
        cli_die(2, "-o: expected a .tsv file with --cross-validate, got \"%s\"", a->out);
    if ((a->drift != NL_DRIFT_CONSTANT || a->pr.ncov) && !isnan(a->mean))
        cli_die(2, "--mean: expected no --drift with a known mean, got --mean %g", a->mean);
}

/* --at: no grid; -o is a TSV of the table with the estimates. */
static void parse_at(opts_t *a)
{
    if (!a->data)
        cli_die(2, "krige: --data: expected a table of points (x, y[, z], value)");
    if (!a->spec)
        cli_die(2, "krige: --acf: expected a covariance model (see noiselab models)");
    if (a->grid || a->ext || a->vout || a->strict)
        cli_die(2, "--at: expected no %s (the estimates and variances go to -o, a table)",
                a->grid ? "--grid" : a->ext ? "--extent" : a->vout ? "--variance" : "--strict");
    if (!a->out || !cli_has_ext(a->out, ".tsv"))
        cli_die(2, "-o: expected a .tsv file with --at, got %s%s%s", a->out ? "\"" : "", a->out ? a->out : "none",
                a->out ? "\"" : "");
    if ((a->drift != NL_DRIFT_CONSTANT || a->pr.ncov) && !isnan(a->mean))
        cli_die(2, "--mean: expected no --drift with a known mean, got --mean %g", a->mean);
}

static void parse(int argc, char **argv, opts_t *a)
{
    if (cli_opt_parse("krige", help, rows, a, argc, argv))
        exit(0);
    kp_parse(&a->pr, argc, argv);
    cli_no_operands("krige", argc, argv);
    a->cv = a->pr.given_cv, a->drift = a->pr.poly;
    if (a->pr.axes && a->drift == NL_DRIFT_CONSTANT)
        a->drift = NL_DRIFT_LINEAR;
    a->local |= a->pr.given_drift || a->cv || a->pr.at;
    if (a->fl.any && (a->pr.at || a->pr.ncov || a->pr.kfold || a->pr.folds))
        cli_die(2, "krige: --block, --transform and --indicator: expected no %s (not combined with them)",
                a->pr.at ? "--at" : a->pr.ncov ? "covariate in --drift" : a->pr.kfold ? "--cross-validate K"
                                                                                      : "--folds");
    cli_krige_fl_check(&a->fl, &a->spec, a->cv, !isnan(a->mean), a->drift, a->vout);
    if (a->cv) {
        parse_cv(a);
        return;
    }
    if (a->pr.at) {
        parse_at(a);
        return;
    }
    cli_opt_need("krige", rows, a);
    if ((a->drift != NL_DRIFT_CONSTANT || a->pr.ncov) && !isnan(a->mean))
        cli_die(2, "--mean: expected no --drift with a known mean, got --mean %g", a->mean);
    a->gdim = cli_parse_size("--grid", a->grid, a->g, 1);
    parse_extent(a);
    a->npz = strcmp(cli_field_out_check("-o", a->out, a->gdim)->name, "npz") == 0;
    if (a->vout)
        cli_field_out_check("--variance", a->vout, a->gdim);
    if (a->vout && strcmp(a->vout, a->out) == 0)
        cli_die(2, "--variance: expected a file other than -o, got \"%s\" for both -o and --variance", a->vout);
}

/* The kind of kriging, for the record and the report. */
static const char *kind_name(const opts_t *a)
{
    if (!isnan(a->mean))
        return "simple";
    if (a->pr.ncov)
        return "universal-external";
    return a->drift == NL_DRIFT_LINEAR ? "universal-linear" : a->drift == NL_DRIFT_QUADRATIC ? "universal-quadratic"
                                                                                                : "ordinary";
}

/* A field bound for a float32 EXR fits it. */
static void check_float(const char *opt, const char *path, const nl_field *f)
{
    if (!path || !cli_field_is_float32(path))
        return;
    for (size_t i = 0; i < f->count; i++)
        if (!(fabs(f->data[i]) <= FLT_MAX) && !isnan(f->data[i])) /* NaN: a missing cell */
            cli_die(2, "%s: sample %zu is %g, beyond the float32 range of \"%s\"; expected |value| <= %g "
                    "(write .tsv in 1D, or scale the data)", opt, i, f->data[i], path, FLT_MAX);
}

/* The grid's extent "a:b[,c:d[,e:f]]", exact (17 digits), as recorded in
 * noiselab.method and --json: noiselab sample reads cell centres from it. */
static const char *extent_text(const opts_t *a, char *buf, size_t len)
{
    size_t at = 0;
    buf[0] = 0;
    for (int d = 0; d < a->gdim && at < len; d++)
        at += (size_t)snprintf(buf + at, len - at, "%s%.17g:%.17g", d ? "," : "", a->lo[d], a->hi[d]);
    return buf;
}

/* The estimates (EXR or, 1D, TSV) and the variances. */
static void write_outputs(const opts_t *a, const nl_field *f, const nl_field *vf, const nl_krige_info *info,
                          size_t n, const char *tmp, const char *vtmp)
{
    nl_meta meta = {0};
    int st;
    snprintf(meta.model, sizeof meta.model, "%s", a->spec);
    char ext[200];
    int len;
    extent_text(a, ext, sizeof ext);
    if (a->local)
        len = snprintf(meta.method, sizeof meta.method, "krige:%s,nmax=%zu,radius=%g,points=%zu,extent=%s",
                       kind_name(a), a->nmax, a->radius, n, ext);
    else
        len = snprintf(meta.method, sizeof meta.method, "krige:%s,points=%zu,extent=%s",
                       isnan(a->mean) ? "ordinary" : "simple", n, ext);
    if (len >= (int)sizeof meta.method)
        cli_die(2, "--extent: \"%s\" is too long to record with the map (%d characters of method); expected "
                "shorter numbers", a->ext, len);
    if (info->pseudo_inverse)
        snprintf(meta.flags, sizeof meta.flags, "singular,pseudo-inverse");
    cli_meta_extent(&meta, a->gdim, a->lo, a->hi, a->g);
    check_float("-o", a->out, f);
    if (vf && a->vout)
        check_float("--variance", a->vout, vf);
    if (a->npz) /* the map and its variance, numpy.load's "field" and "variance" */
        st = nl_npz_write(tmp, f, vf, cli_field_single ? 32 : 64);
    else if (strcmp(cli_field_out_check("-o", a->out, a->gdim)->name, "tsv"))
        cli_write_field(a->out, tmp, f, &meta), st = NL_OK;
    else { /* 1D: the record as in EXR, and cell centres as x */
        double *xs = cli_malloc(a->g[0] * sizeof *xs);
        for (size_t i = 0; i < a->g[0]; i++)
            xs[i] = a->lo[0] + ((double)i + 0.5) * f->h[0];
        st = nl_tsv_write_field(tmp, f, &meta, "x", xs);
        free(xs);
    }
    cli_check(st);
    if (vf && a->vout)
        cli_write_field(a->vout, vtmp, vf, &meta);
    cli_out_commit(a->out);
    cli_out_commit(a->vout);
}

static void report(const opts_t *a, const nl_krige_info *info, size_t n, double secs)
{
    char ext[200];
    if (a->json)
        cli_json_print(json_pack("{s:I,s:s,s:f,s:f,s:o,s:s,s:I,s:f}", "points", (json_int_t)n, "kind",
                                 isnan(a->mean) ? "ordinary" : "simple", "mean", info->mean, "rcond", info->rcond,
                                 "flags",
                                 info->pseudo_inverse ? json_pack("[s,s]", "singular", "pseudo-inverse") : json_array(),
                                 "extent", extent_text(a, ext, sizeof ext), "missing", (json_int_t)0, "seconds", secs));
    else if (info->pseudo_inverse)
        fprintf(stderr, "noiselab: krige: the system is singular (reciprocal condition %.2g); solved by the "
                "pseudo-inverse (flagged in the output)\n", info->rcond);
}

/* What the local path needs of the options (cli/krige_predict.h). */
static kp_common common(const opts_t *a)
{
    return (kp_common){.data = a->data, .spec = a->spec, .out = a->out, .mean = a->mean, .radius = a->radius,
                       .nmax = a->nmax, .json = a->json, .kind = kind_name(a)};
}

/* Cross-validation (leave-one-out, or k-fold): the table to -o, the summary to stdout. */
static int krige_cv(const opts_t *a, const kp_data *d)
{
    nl_model *m;
    kp_common c = common(a);
    const nl_points *pt = d->pt;
    nl_krige_local *k = kp_plan(&a->pr, &c, d, &m);
    size_t n = pt->n;
    int dim = pt->dim;
    const char *tmp = cli_out_begin(a->out);
    double *col[9], *pred = cli_malloc(n * sizeof *pred), *var = cli_malloc(n * sizeof *var);
    long *fold;
    nl_krige_cv_summary s;
    size_t nfold = kp_cross_validate(&a->pr, k, d, pred, var, &s, &fold);
    if (a->out) {
        static const char *xyz[] = {"x", "y", "z"};
        const char *names[9];
        int nc = dim + 5 + (fold != NULL);
        for (int c = 0; c < nc; c++)
            col[c] = cli_malloc(n * sizeof(double)), names[c] = c < dim ? xyz[c] : NULL;
        names[dim] = "observed", names[dim + 1] = "predicted", names[dim + 2] = "variance";
        names[dim + 3] = "error", names[dim + 4] = "zscore", names[nc - 1] = fold ? "fold" : names[nc - 1];
        for (size_t i = 0; i < n; i++) {
            for (int c = 0; c < dim; c++)
                col[c][i] = pt->pts[i * dim + c];
            col[dim][i] = pt->val[i], col[dim + 1][i] = pred[i], col[dim + 2][i] = var[i];
            col[dim + 3][i] = pt->val[i] - pred[i], col[dim + 4][i] = (pt->val[i] - pred[i]) / sqrt(var[i]);
            if (fold)
                col[dim + 5][i] = (double)fold[i];
        }
        cli_check(cli_write_table(tmp, NULL, nc, names, n, (const double *const *)col));
        cli_out_commit(a->out);
        for (int c = 0; c < nc; c++)
            free(col[c]);
    }
    size_t miss = kp_missing(pred, n, "data");
    if (a->json)
        cli_json_print(json_pack("{s:I,s:s,s:I,s:I,s:f,s:f,s:f,s:f,s:f}", "points", (json_int_t)n, "kind",
                                 kind_name(a), "folds", (json_int_t)nfold, "missing",
                                 (json_int_t)miss, "mean_error", s.mean_error, "var_error", s.var_error,
                                 "mean_zscore", s.mean_z, "var_zscore", s.var_z, "rmse", s.rmse));
    else
        printf("points\t%zu\nmean_error\t%.10g\nvar_error\t%.10g\nmean_zscore\t%.10g\nvar_zscore\t%.10g\nrmse\t%.10g\n",
               s.n, s.mean_error, s.var_error, s.mean_z, s.var_z, s.rmse);
    free(pred), free(var), free(fold);
    nl_krige_local_free(k), nl_model_free(m);
    return 0;
}

/* --nmax, --radius, --drift, --at, --cross-validate: local or universal
 * kriging onto the grid, at the points of a table, or at the data. */
static int cli_krige_local(opts_t *a)
{
    kp_data d;
    kp_common c = common(a);
    if (a->pr.at)
        return kp_predict_at(&a->pr, &c);
    kp_read_data(&a->pr, a->data, &d);
    if (a->cv) {
        krige_cv(a, &d);
        kp_data_free(&d);
        return 0;
    }
    nl_points *pt = d.pt;
    if (pt->dim != a->gdim)
        cli_die(2, "--data: %s has %d coordinates per point, the grid %d", a->data, pt->dim, a->gdim);
    check_reach(a, pt);
    nl_model *m;
    nl_krige_local *k = kp_plan(&a->pr, &c, &d, &m);
    const char *tmp = cli_out_begin(a->out), *vtmp = cli_out_begin(a->vout);
    double h[3];
    int st;
    for (int dd = 0; dd < 3; dd++)
        h[dd] = (a->hi[dd] - a->lo[dd]) / (double)a->g[dd];
    if ((st = nl_size_check(a->gdim, a->g, sizeof(double), a->vout || a->npz ? 2 : 1, NULL))) {
        char why[NL_ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        cli_die(st == NL_ETOOBIG || nl_error_is_input(st) ? 2 : 1, "--grid %s: %s", a->grid, why);
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    nl_field *f = cli_field_alloc(a->gdim, a->g, h);
    nl_field *vf = a->vout || a->npz ? cli_field_alloc(a->gdim, a->g, h) : NULL;
    kp_grid(&a->pr, k, a->lo, f, vf);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    nl_krige_info info = {.n = pt->n, .mean = NAN};
    size_t miss = kp_missing(f->data, f->count, "cells");
    write_outputs(a, f, vf, &info, pt->n, tmp, vtmp);
    char ext[200];
    if (a->json)
        cli_json_print(json_pack("{s:I,s:s,s:I,s:f,s:I,s:I,s:s,s:f}", "points", (json_int_t)pt->n, "kind", kind_name(a),
                                 "nmax", (json_int_t)a->nmax, "radius", a->radius, "terms",
                                 (json_int_t)nl_krige_local_terms(k), "missing", (json_int_t)miss, "extent",
                                 extent_text(a, ext, sizeof ext), "seconds", secs));
    nl_krige_local_free(k), nl_model_free(m), nl_field_free(f), nl_field_free(vf);
    kp_data_free(&d);
    return 0;
}

int cli_cmd_krige(int argc, char **argv)
{
    opts_t a = {.mean = NAN, .lo = {0, 0, 0}, .hi = {1, 1, 1}, .g = {1, 1, 1}};
    const char *tmp, *vtmp = NULL;
    int st;
    size_t n;
    parse(argc, argv, &a);
    if (a.local && !a.fl.any)
        return cli_krige_local(&a);
    nl_points *pt;
    if ((st = nl_points_read(a.data, &pt)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--data: %s", nl_errmsg());
    if (a.fl.any) {
        cli_krige_fl_ctx c = {a.data, a.spec, a.out, a.vout, a.json, a.cv, a.drift, a.gdim, a.mean, a.radius, a.nmax,
                              {a.g[0], a.g[1], a.g[2]}, {a.lo[0], a.lo[1], a.lo[2]}, {a.hi[0], a.hi[1], a.hi[2]}};
        return cli_krige_fl_run(&a.fl, &c, pt);
    }
    if (pt->dim != a.gdim)
        cli_die(2, "--data: %s has %d coordinates per point, the grid %d", a.data, pt->dim, a.gdim);
    n = pt->n;
    check_reach(&a, pt);
    nl_model *m;
    nl_krige_plan *p;
    nl_krige_info info;
    cli_check(nl_model_parse(a.spec, &m));
    tmp = cli_out_begin(a.out);
    vtmp = cli_out_begin(a.vout);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    cli_check(nl_krige_plan_alloc(m, pt->dim, n, pt->pts, pt->val, !isnan(a.mean), isnan(a.mean) ? 0 : a.mean,
                                  a.strict, &p));
    nl_krige_plan_info(p, &info);
    double h[3];
    for (int d = 0; d < 3; d++)
        h[d] = (a.hi[d] - a.lo[d]) / (double)a.g[d];
    if ((st = nl_size_check(a.gdim, a.g, sizeof(double), a.vout || a.npz ? 2 : 1, NULL))) {
        char why[NL_ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        cli_die(st == NL_ETOOBIG || nl_error_is_input(st) ? 2 : 1, "--grid %s: %s", a.grid, why);
    }
    nl_field *f = cli_field_alloc(a.gdim, a.g, h), *vf = a.vout || a.npz ? cli_field_alloc(a.gdim, a.g, h) : NULL;
    cli_check(nl_krige_eval_grid(p, a.lo, f, vf));
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    write_outputs(&a, f, vf, &info, n, tmp, vtmp);
    report(&a, &info, n, secs);
    nl_krige_plan_free(p), nl_model_free(m), nl_field_free(f), nl_field_free(vf);
    nl_points_free(pt);
    return 0;
}
