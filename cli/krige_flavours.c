/* noiselab krige --block, --transform, --indicator: parse the flavours'
 * options, krige onto the grid or in cross-validation, write the outputs. */
#include "krige_flavours.h"
#include "cli.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void add_iacf(void *obj, const char *label, const char *arg)
{
    cli_krige_fl *f = obj;
    if (f->niacf == CLI_KRIGE_NK_MAX)
        cli_die(2, "%s: expected at most %d models (one per threshold), got more", label, CLI_KRIGE_NK_MAX);
    f->iacf[f->niacf++] = arg;
    f->any = 1;
}

const cli_opt cli_krige_fl_rows[] = {
    CLI_STRING("block", cli_krige_fl, block, CLI_GIVEN(cli_krige_fl, any)),
    CLI_INT("block-points", cli_krige_fl, block_points, CLI_GIVEN(cli_krige_fl, any),
            CLI_FROM_TO(2, NL_KRIGE_BLOCK_AXIS_MAX)),
    CLI_STRING("transform", cli_krige_fl, transform, CLI_GIVEN(cli_krige_fl, any)),
    CLI_STRING("indicator", cli_krige_fl, indicator, CLI_GIVEN(cli_krige_fl, any)),
    CLI_CALL("indicator-acf", add_iacf, .flags = CLI_REPEAT), {0}};

/* A number that is all of s[0..len) (no hex, no trailing text). */
static int number(const char *s, size_t len, double *v)
{
    char buf[64], *end;
    if (len == 0 || len >= sizeof buf || strspn(s, "0123456789.eE+-") < len)
        return 0;
    memcpy(buf, s, len), buf[len] = 0;
    *v = strtod(buf, &end);
    return *end == 0;
}

/* --block WxH[xD]: one positive edge per axis of the data. */
static void parse_block(const cli_krige_fl *f, int dim, nl_krige_block *b)
{
    const char *p = f->block;
    int k = 0;
    memset(b, 0, sizeof *b);
    while (k < 3) {
        size_t len = strcspn(p, "x");
        if (!number(p, len, &b->size[k]) || !(b->size[k] > 0) || !isfinite(b->size[k]))
            break;
        k++, p += len;
        if (*p == 0)
            break;
        p++;
    }
    if (*p != 0 || k == 0)
        cli_die(2, "--block: expected positive edges WxH[xD] (one per axis), got \"%s\"", f->block);
    if (k != dim)
        cli_die(2, "--block: expected %d edge%s (the data have %d coordinates), got \"%s\"", dim, dim > 1 ? "s" : "",
                dim, f->block);
    b->points = f->block_points;
}

/* --transform log|boxcox:LAMBDA */
static double parse_transform(const char *s)
{
    double l;
    if (strcmp(s, "log") == 0)
        return 0;
    if (strncmp(s, "boxcox:", 7) == 0 && number(s + 7, strlen(s + 7), &l) && fabs(l) <= 5)
        return l;
    cli_die(2, "--transform: expected log or boxcox:LAMBDA with LAMBDA in [-5, 5], got \"%s\"", s);
}

/* --indicator T1,T2,...: finite and increasing. */
static size_t parse_thresholds(const char *s, double *t)
{
    const char *p = s;
    size_t k = 0;
    while (1) {
        size_t len = strcspn(p, ",");
        if (k == CLI_KRIGE_NK_MAX)
            cli_die(2, "--indicator: expected at most %d thresholds, got \"%s\"", CLI_KRIGE_NK_MAX, s);
        if (!number(p, len, &t[k]) || !isfinite(t[k]) || (k && !(t[k] > t[k - 1])))
            cli_die(2, "--indicator: expected finite thresholds T1,T2,... in increasing order, got \"%s\"", s);
        k++, p += len;
        if (*p == 0)
            return k;
        p++;
    }
}

void cli_krige_fl_check(const cli_krige_fl *f, const char **spec, int cv, int simple, int drift, const char *vout)
{
    double t[CLI_KRIGE_NK_MAX];
    if (f->block_points && !f->block)
        cli_die(2, "--block-points: expected --block WxH[xD] with it, got --block-points %d alone", f->block_points);
    if (f->niacf && !f->indicator)
        cli_die(2, "--indicator-acf: expected --indicator T1,T2,... with it, got \"%s\"", f->iacf[0]);
    if (f->transform && f->indicator)
        cli_die(2, "--transform: expected no --indicator with it (one flavour), got --transform %s", f->transform);
    if (f->block && cv)
        cli_die(2, "--block: expected no --cross-validate (leave-one-out predicts the data points, not blocks), "
                "got --block %s", f->block);
    if (f->transform) {
        parse_transform(f->transform);
        if (simple || drift != NL_DRIFT_CONSTANT)
            cli_die(2, "--transform: expected ordinary kriging (no --mean, no --drift; as gstat's krigeTg), got %s",
                    simple ? "--mean" : "--drift");
    }
    if (f->indicator) {
        size_t nk = parse_thresholds(f->indicator, t);
        if (f->niacf && *spec)
            cli_die(2, "--indicator-acf: expected either --acf (one model for all thresholds) or --indicator-acf "
                    "once per threshold, got both");
        if (f->niacf && f->niacf != nk)
            cli_die(2, "--indicator-acf: expected one model per threshold (%zu), got %zu", nk, f->niacf);
        if (simple)
            cli_die(2, "--mean: expected no --mean with --indicator (each indicator has its own mean, the CDF at "
                    "its threshold: ordinary indicator kriging estimates it)");
        if (vout)
            cli_die(2, "--variance: expected no --variance with --indicator (it writes probabilities), got \"%s\"",
                    vout);
        if (f->niacf)
            *spec = f->iacf[0];
    }
}

/* The cell centres of the grid, x fastest (count * gdim). */
static double *centres(const cli_krige_fl_ctx *c, size_t count)
{
    double *x = cli_malloc(count * (size_t)c->gdim * sizeof *x);
    for (size_t t = 0; t < count; t++) {
        size_t ix[3] = {t % c->g[0], t / c->g[0] % c->g[1], t / (c->g[0] * c->g[1])};
        for (int a = 0; a < c->gdim; a++)
            x[t * c->gdim + a] = c->lo[a] + ((double)ix[a] + 0.5) * (c->hi[a] - c->lo[a]) / (double)c->g[a];
    }
    return x;
}

static nl_krige_local_options local_options(const cli_krige_fl_ctx *c)
{
    nl_krige_local_options o = {.nmax = c->nmax, .radius = c->radius, .drift = c->drift};
    if (!isnan(c->mean))
        o.drift = NL_DRIFT_NONE, o.mean = c->mean;
    return o;
}

static void die_lib(const char *opt, int st)
{
    cli_die(st == NL_EINVAL || nl_error_is_input(st) ? 2 : 1, "%s: %s", opt, nl_errmsg());
}

/* A field of the grid holding v (count values) to path (EXR, or 1D TSV with cell centres as x). */
static void write_grid(const cli_krige_fl_ctx *c, const char *opt, const char *path, const char *tmp, const double *v,
                       const nl_meta *meta)
{
    double h[3];
    for (int a = 0; a < 3; a++)
        h[a] = a < c->gdim ? (c->hi[a] - c->lo[a]) / (double)c->g[a] : 1;
    nl_field *f = cli_field_alloc(c->gdim, c->g, h);
    nl_meta m = *meta;
    memcpy(f->data, v, f->count * sizeof *v);
    cli_meta_extent(&m, c->gdim, c->lo, c->hi, c->g);
    meta = &m;
    int st;
    if (strcmp(cli_field_out_check(opt, path, c->gdim)->name, "tsv")) {
        for (size_t i = 0; cli_field_is_float32(path) && i < f->count; i++)
            if (!(fabs(f->data[i]) <= FLT_MAX))
                cli_die(2, "%s: sample %zu is %g, beyond the float32 range of \"%s\"", opt, i, f->data[i], path);
        cli_write_field(path, tmp, f, meta), st = NL_OK;
    } else {
        double *xs = cli_malloc(c->g[0] * sizeof *xs);
        for (size_t i = 0; i < c->g[0]; i++)
            xs[i] = c->lo[0] + ((double)i + 0.5) * h[0];
        st = nl_tsv_write_field(tmp, f, meta, "x", xs);
        free(xs);
    }
    cli_check(st);
    cli_out_commit(path);
    nl_field_free(f);
}

/* The grid and the data together span finite distances (as krige's check). */
static void check_grid(const cli_krige_fl_ctx *c, const nl_points *pt, size_t copies, size_t *count)
{
    int st;
    if (pt->dim != c->gdim)
        cli_die(2, "--data: %s has %d coordinates per point, the grid %d", c->data, pt->dim, c->gdim);
    for (int d = 0; d < c->gdim; d++) {
        double lo = c->lo[d], hi = c->hi[d];
        for (size_t i = 0; i < pt->n; i++)
            lo = fmin(lo, pt->pts[i * (size_t)pt->dim + d]), hi = fmax(hi, pt->pts[i * (size_t)pt->dim + d]);
        if (!isfinite(4 * (hi - lo)))
            cli_die(2, "--extent: the grid and the data of %s span %g to %g on axis %d, whose distances overflow; "
                    "expected a span below %g", c->data, lo, hi, d + 1, DBL_MAX / 4);
    }
    if ((st = nl_size_check(c->gdim, c->g, sizeof(double), copies, count))) {
        char why[NL_ERRMSG_MAX];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        cli_die(st == NL_ETOOBIG || nl_error_is_input(st) ? 2 : 1, "--grid: %s", why);
    }
}

static void flavour_meta(const cli_krige_fl *f, const cli_krige_fl_ctx *c, size_t n, nl_meta *meta)
{
    char blk[96] = "";
    memset(meta, 0, sizeof *meta);
    snprintf(meta->model, sizeof meta->model, "%s", c->spec);
    if (f->block)
        snprintf(blk, sizeof blk, ",block=%s,block-points=%s%d", f->block, f->block_points ? "" : "gauss",
                 f->block_points ? f->block_points : 4);
    char ext[200];
    size_t at = 0;
    ext[0] = 0;
    for (int d = 0; d < c->gdim && at < sizeof ext; d++) /* the grid's extent: sample reads the map at it */
        at += (size_t)snprintf(ext + at, sizeof ext - at, "%s%.17g:%.17g", d ? "," : "", c->lo[d], c->hi[d]);
    if (snprintf(meta->method, sizeof meta->method, "krige:%s%s%s,nmax=%zu,radius=%g,points=%zu,extent=%s",
                 f->indicator ? "indicator=" : f->transform ? "transform=" : "block",
                 f->indicator ? f->indicator : f->transform ? f->transform : "", blk, c->nmax, c->radius, n,
                 ext) >= (int)sizeof meta->method)
        cli_die(2, "--extent: too long to record with the map; expected shorter numbers");
}

/* Cross-validation's table: coordinates, observed, then ncol named columns. */
static void write_cv(const cli_krige_fl_ctx *c, const nl_points *pt, int ncol, const char *const *names,
                     double *const *cols)
{
    static const char *xyz[] = {"x", "y", "z"};
    const char *tmp = cli_out_begin(c->out);
    int dim = pt->dim, nc = dim + 1 + ncol;
    const char **nm = cli_malloc((size_t)nc * sizeof *nm);
    double **col = cli_malloc((size_t)nc * sizeof *col);
    if (!c->out) {
        free(nm), free(col);
        return;
    }
    for (int a = 0; a < dim; a++) {
        nm[a] = xyz[a], col[a] = cli_malloc(pt->n * sizeof(double));
        for (size_t i = 0; i < pt->n; i++)
            col[a][i] = pt->pts[i * dim + a];
    }
    nm[dim] = "observed", col[dim] = pt->val;
    for (int j = 0; j < ncol; j++)
        nm[dim + 1 + j] = names[j], col[dim + 1 + j] = cols[j];
    cli_check(cli_write_table(tmp, NULL, nc, nm, pt->n, (const double *const *)col));
    cli_out_commit(c->out);
    for (int a = 0; a < dim; a++)
        free(col[a]);
    free(nm), free(col);
}

/* --transform with --cross-validate: errors in the data's units. */
static void tg_cv(const cli_krige_fl_ctx *c, const nl_points *pt, const nl_krige_local *k, double lambda)
{
    size_t n = pt->n;
    double *pred = cli_malloc(n * sizeof *pred), *var = cli_malloc(n * sizeof *var);
    double *err = cli_malloc(n * sizeof *err), *z = cli_malloc(n * sizeof *z);
    nl_krige_cv_summary s;
    int st = nl_krige_tg_cv(k, lambda, pt->val, pred, var, &s);
    if (st)
        die_lib("--cross-validate", st);
    for (size_t i = 0; i < n; i++)
        err[i] = pt->val[i] - pred[i], z[i] = err[i] / sqrt(var[i]);
    static const char *names[] = {"predicted", "variance", "error", "zscore"};
    double *cols[] = {pred, var, err, z};
    write_cv(c, pt, 4, names, cols);
    if (c->json)
        cli_json_print(json_pack("{s:I,s:s,s:f,s:f,s:f,s:f,s:f}", "points", (json_int_t)n, "kind", "trans-gaussian",
                                 "mean_error", s.mean_error, "var_error", s.var_error, "mean_zscore", s.mean_z,
                                 "var_zscore", s.var_z, "rmse", s.rmse));
    else
        printf("points\t%zu\nmean_error\t%.10g\nvar_error\t%.10g\nmean_zscore\t%.10g\nvar_zscore\t%.10g\nrmse\t%.10g\n",
               n, s.mean_error, s.var_error, s.mean_z, s.var_z, s.rmse);
    free(pred), free(var), free(err), free(z);
}

/* --block or --transform: one estimate and variance per cell. */
static int run_block_tg(const cli_krige_fl *f, const cli_krige_fl_ctx *c, nl_points *pt)
{
    nl_model *m;
    nl_krige_block b, *bp = NULL;
    nl_krige_local *k;
    nl_krige_local_options o = local_options(c);
    double lambda = f->transform ? parse_transform(f->transform) : 0, *y = pt->val;
    size_t count = 0;
    int st;
    if (f->block)
        parse_block(f, pt->dim, &b), bp = &b;
    if (!c->cv)
        check_grid(c, pt, (size_t)c->gdim + 4, &count);
    cli_check(nl_model_parse(c->spec, &m));
    if (f->transform) {
        y = cli_malloc(pt->n * sizeof *y);
        if ((st = nl_krige_tg_transform(lambda, pt->n, pt->val, y)))
            cli_die(2, "--transform: %s: %s", c->data, nl_errmsg());
    }
    if ((st = nl_krige_local_alloc(m, pt->dim, pt->n, pt->pts, y, &o, &k)))
        die_lib("--data", st);
    if (c->cv)
        tg_cv(c, pt, k, lambda);
    else {
        const char *tmp = cli_out_begin(c->out), *vtmp = cli_out_begin(c->vout);
        double *x = centres(c, count), *est = cli_malloc(count * sizeof *est);
        double *var = c->vout ? cli_malloc(count * sizeof *var) : NULL;
        st = f->transform ? nl_krige_tg_eval(k, bp, lambda, count, x, est, var)
                          : nl_krige_block_eval(k, bp, count, x, est, var);
        if (st)
            die_lib("--grid", st);
        nl_meta meta;
        flavour_meta(f, c, pt->n, &meta);
        write_grid(c, "-o", c->out, tmp, est, &meta);
        if (var)
            write_grid(c, "--variance", c->vout, vtmp, var, &meta);
        if (c->json)
            cli_json_print(json_pack("{s:I,s:s,s:I,s:I}", "points", (json_int_t)pt->n, "kind",
                                     f->transform ? "trans-gaussian" : "block", "cells", (json_int_t)count, "terms",
                                     (json_int_t)nl_krige_local_terms(k)));
        free(x), free(est), free(var);
    }
    if (y != pt->val)
        free(y);
    nl_krige_local_free(k), nl_model_free(m);
    return 0;
}

/* The path of threshold j's output: OUT.exr -> OUT.j.exr (numbered from 1). */
static char *threshold_path(const char *out, size_t j)
{
    size_t len = strlen(out) - 4;
    char *p = cli_malloc(len + 32);
    snprintf(p, len + 32, "%.*s.%zu.exr", (int)len, out, j + 1);
    return p;
}

/* --indicator: the corrected probabilities to one EXR per threshold, or a
 * 1D TSV of columns x, p1 .. pK. */
static void write_indicator(const cli_krige_fl *f, const cli_krige_fl_ctx *c, size_t nk, size_t count,
                            const double *cdf, const char *const *tmp, char *const *paths, const nl_meta *meta)
{
    double *col = cli_malloc(count * sizeof *col);
    if (cli_has_ext(c->out, ".exr")) {
        for (size_t j = 0; j < nk; j++) {
            for (size_t t = 0; t < count; t++)
                col[t] = cdf[t * nk + j];
            write_grid(c, "-o", paths[j], tmp[j], col, meta);
        }
    } else {
        char (*nm)[24] = cli_malloc(nk * sizeof *nm);
        const char **names = cli_malloc((nk + 1) * sizeof *names);
        double **cols = cli_malloc((nk + 1) * sizeof *cols);
        names[0] = "x", cols[0] = col;
        for (size_t t = 0; t < count; t++)
            col[t] = c->lo[0] + ((double)t + 0.5) * (c->hi[0] - c->lo[0]) / (double)c->g[0];
        for (size_t j = 0; j < nk; j++) {
            snprintf(nm[j], sizeof nm[j], "p%zu", j + 1);
            names[j + 1] = nm[j], cols[j + 1] = cli_malloc(count * sizeof(double));
            for (size_t t = 0; t < count; t++)
                cols[j + 1][t] = cdf[t * nk + j];
        }
        char comment[1400];
        snprintf(comment, sizeof comment, "method: %s; thresholds: %s", meta->method, f->indicator);
        cli_check(cli_write_table(tmp[0], comment, (int)nk + 1, names, count, (const double *const *)cols));
        cli_out_commit(c->out);
        for (size_t j = 0; j < nk; j++)
            free(cols[j + 1]);
        free(nm), free(names), free(cols);
    }
    free(col);
}

/* --indicator with --cross-validate: the corrected probabilities at the
 * data, each from the others, and each threshold's Brier score. */
static void indicator_cv(const cli_krige_fl_ctx *c, const nl_points *pt, size_t nk, const double *thr,
                         const double *cdf, size_t corrected)
{
    size_t n = pt->n;
    char (*nm)[24] = cli_malloc(nk * sizeof *nm);
    const char **names = cli_malloc(nk * sizeof *names);
    double **cols = cli_malloc(nk * sizeof *cols), *brier = cli_malloc(nk * sizeof *brier);
    for (size_t j = 0; j < nk; j++) {
        snprintf(nm[j], sizeof nm[j], "p%zu", j + 1);
        names[j] = nm[j], cols[j] = cli_malloc(n * sizeof(double)), brier[j] = 0;
        for (size_t i = 0; i < n; i++) {
            double e = (pt->val[i] <= thr[j]) - cdf[i * nk + j];
            cols[j][i] = cdf[i * nk + j], brier[j] += e * e / (double)n;
        }
    }
    write_cv(c, pt, (int)nk, names, cols);
    if (c->json)
        cli_json_print(json_pack("{s:I,s:s,s:o,s:o,s:I}", "points", (json_int_t)n, "kind", "indicator", "thresholds",
                                 cli_json_array(thr, nk), "brier", cli_json_array(brier, nk), "corrected",
                                 (json_int_t)corrected));
    else {
        printf("points\t%zu\ncorrected\t%zu\n", n, corrected);
        for (size_t j = 0; j < nk; j++)
            printf("brier_%zu\t%.10g\n", j + 1, brier[j]);
    }
    for (size_t j = 0; j < nk; j++)
        free(cols[j]);
    free(nm), free(names), free(cols), free(brier);
}

static int run_indicator(const cli_krige_fl *f, const cli_krige_fl_ctx *c, nl_points *pt)
{
    double thr[CLI_KRIGE_NK_MAX];
    size_t nk = parse_thresholds(f->indicator, thr), count = pt->n, nc = 0;
    nl_model *m[CLI_KRIGE_NK_MAX];
    nl_krige_block b, *bp = NULL;
    nl_krige_local_options o = local_options(c);
    int st;
    if (f->block)
        parse_block(f, pt->dim, &b), bp = &b;
    if (!c->cv)
        check_grid(c, pt, (size_t)c->gdim + 2 * nk + 1, &count);
    for (size_t j = 0; j < nk; j++)
        if (f->niacf || j == 0)
            cli_check(nl_model_parse(f->niacf ? f->iacf[j] : c->spec, &m[j]));
        else
            m[j] = m[0];
    const char *tmp[CLI_KRIGE_NK_MAX] = {0};
    char *paths[CLI_KRIGE_NK_MAX] = {0};
    int exr = !c->cv && cli_has_ext(c->out, ".exr");
    for (size_t j = 0; j < (c->cv ? 0 : exr ? nk : 1); j++)
        paths[j] = exr ? threshold_path(c->out, j) : NULL, tmp[j] = cli_out_begin(exr ? paths[j] : c->out);
    double *x = c->cv ? NULL : centres(c, count), *cdf = cli_malloc(count * nk * sizeof *cdf);
    st = nl_krige_indicator((const nl_model *const *)m, nk, thr, pt->dim, pt->n, pt->pts, pt->val, &o, bp, count, x,
                            NULL, cdf, &nc);
    if (st)
        die_lib(c->cv ? "--cross-validate" : "--indicator", st);
    if (c->cv)
        indicator_cv(c, pt, nk, thr, cdf, nc);
    else {
        nl_meta meta;
        flavour_meta(f, c, pt->n, &meta);
        write_indicator(f, c, nk, count, cdf, tmp, paths, &meta);
        if (c->json)
            cli_json_print(json_pack("{s:I,s:s,s:o,s:I,s:I}", "points", (json_int_t)pt->n, "kind", "indicator",
                                     "thresholds", cli_json_array(thr, nk), "cells", (json_int_t)count, "corrected",
                                     (json_int_t)nc));
        else if (nc)
            fprintf(stderr, "noiselab: krige: order relations corrected at %zu of %zu cells\n", nc, count);
    }
    for (size_t j = 0; j < nk; j++) {
        if (f->niacf || j == 0)
            nl_model_free(m[j]);
        free(paths[j]);
    }
    free(x), free(cdf);
    return 0;
}

int cli_krige_fl_run(const cli_krige_fl *f, const cli_krige_fl_ctx *c, nl_points *pt)
{
    int st = f->indicator ? run_indicator(f, c, pt) : run_block_tg(f, c, pt);
    nl_points_free(pt);
    return st;
}
