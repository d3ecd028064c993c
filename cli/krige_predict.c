/* noiselab krige: --at, external drift and k-fold cross-validation
 * (cli/krige_predict.h). */
#include "krige_predict.h"
#include "../core/provenance.h"
#include "cli.h"
#include "drift_terms.h"
#include "../core/io_table.h"
#include "../core/nl_error.h"
#include "../core/rng.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static void parse_covariate(void *obj, const char *label, const char *s)
{
    kp_opts *p = obj;
    const char *eq = strchr(s, '=');
    size_t k = p->nfield;
    if (!eq || eq == s || !eq[1] || (size_t)(eq - s) >= sizeof p->fname[0])
        cli_die(2, "%s: expected NAME=FIELD.exr, got \"%s\"", label, s);
    if (k == KP_MAX_COV)
        cli_die(2, "%s: expected at most %d, got \"%s\" beyond them", label, KP_MAX_COV, s);
    memcpy(p->fname[k], s, (size_t)(eq - s));
    p->fname[k][eq - s] = 0;
    for (size_t j = 0; j < k; j++)
        if (!strcmp(p->fname[j], p->fname[k]))
            cli_die(2, "%s: %s given twice (\"%s\"); expected one field per covariate", label, p->fname[k], s);
    p->fpath[k] = eq + 1;
    p->nfield++;
}

const cli_opt kp_rows[] = {
    CLI_CALL("covariate", parse_covariate, .flags = CLI_REPEAT),
    CLI_STRING("at", kp_opts, at),
    CLI_STRING("drift", kp_opts, drift, CLI_GIVEN(kp_opts, given_drift)),
    CLI_COUNT("cross-validate", kp_opts, kfold, CLI_GIVEN(kp_opts, given_cv), .flags = CLI_OPTIONAL, .lo = 2),
    CLI_STRING("folds", kp_opts, folds), CLI_OPT_SEED(kp_opts, seed, given_seed), {0}};

/* --drift TERMS (cli/drift_terms.h). */
static void parse_drift(kp_opts *p)
{
    cli_drift d;
    _Static_assert(sizeof p->cov == sizeof d.cov, "kp_opts.cov holds cli_drift.cov");
    cli_drift_parse(p->drift, "--data", &d);
    p->poly = d.poly, p->axes = d.axes, p->ncov = d.ncov;
    memcpy(p->cov, d.cov, sizeof p->cov);
}

void kp_parse(kp_opts *p, int argc, char **argv)
{
    if (p->given_cv && !p->kfold && optind + 1 == argc) /* --cross-validate K, K a word of its own */
        p->kfold = cli_parse_count("--cross-validate", argv[optind++], 2);
    if (p->drift)
        parse_drift(p);
    if (p->given_seed && !(p->given_cv && p->kfold && !p->folds))
        cli_die(2, "--seed: applies to --cross-validate K without --folds (the folds drawn)");
    if (p->folds && !p->given_cv)
        cli_die(2, "--folds: applies to --cross-validate");
    if (p->at && p->given_cv)
        cli_die(2, "--at: expected no --cross-validate (it predicts the data points)");
    if (p->nfield && (p->at || p->given_cv))
        cli_die(2, "--covariate: applies to grid outputs (--at and --cross-validate read covariates from tables)");
    for (size_t j = 0; j < p->nfield; j++) {
        size_t i = 0;
        while (i < p->ncov && strcmp(p->cov[i], p->fname[j]))
            i++;
        if (i == p->ncov)
            cli_die(2, "--covariate: \"%s\" is not a covariate of --drift%s%s; expected one named there", p->fname[j],
                    p->drift ? " " : "", p->drift ? p->drift : "");
    }
}

/* The column of the fold ids, or exit 2. */
static long need_column(const nl_table *t, const char *name)
{
    long c = nl_table_column(t, name);
    if (c < 0)
        cli_die(2, "--folds: %s has no column \"%s\"; expected it (the fold id of each datum)", t->path, name);
    return c;
}

/* The covariates of --drift from the columns of t (n * ncov, row-major). */
static double *table_cov(const kp_opts *p, const nl_table *t)
{
    return cli_drift_columns(t, p->ncov, p->cov);
}

static long *table_folds(const kp_opts *p, const nl_table *t)
{
    long c = need_column(t, p->folds), *fold = cli_malloc(t->n * sizeof *fold);
    for (size_t i = 0; i < t->n; i++) {
        double v = t->cols[c][i];
        if (v != floor(v) || fabs(v) > 1e15)
            cli_die(2, "--folds: row %zu of %s has %s = %.17g; expected an integer fold id", i + 1, t->path, p->folds,
                    v);
        fold[i] = (long)v;
    }
    return fold;
}

void kp_read_data(const kp_opts *p, const char *data, kp_data *d)
{
    int st;
    memset(d, 0, sizeof *d);
    if (!p->ncov && !p->folds && !p->at) {
        if ((st = nl_points_read(data, &d->pt)))
            cli_die(nl_error_is_input(st) ? 2 : 1, "--data: %s", nl_errmsg());
        return;
    }
    nl_table *t;
    if ((st = nl_table_read(data, &t)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--data: %s", nl_errmsg());
    d->pt = cli_malloc(sizeof *d->pt);
    d->pt->n = t->n;
    if ((st = nl_table_points(t, "value", &d->pt->dim, &d->pt->pts, &d->pt->val)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--data: %s", nl_errmsg());
    d->cov = p->ncov ? table_cov(p, t) : NULL;
    d->fold = p->folds ? table_folds(p, t) : NULL;
    nl_table_free(t);
}

void kp_data_free(kp_data *d)
{
    nl_points_free(d->pt), free(d->cov), free(d->fold);
}

nl_krige_local *kp_plan(const kp_opts *p, const kp_common *c, const kp_data *d, nl_model **m)
{
    nl_krige_local_options o = {.nmax = c->nmax, .radius = c->radius, .drift = p->poly, .missing = 1,
                                .ncov = p->ncov, .cov = d->cov};
    nl_krige_local *k;
    int dim = d->pt->dim;
    if (p->drift) {
        cli_drift t = {.poly = p->poly, .axes = p->axes};
        o.drift = cli_drift_poly(&t, p->drift, dim);
    }
    if (!isnan(c->mean)) {
        if (p->given_drift)
            cli_die(2, "--mean: expected no --drift with a known mean, got --mean %g", c->mean);
        o.drift = NL_DRIFT_NONE, o.mean = c->mean;
    }
    cli_check(nl_model_parse(c->spec, m));
    int st = nl_krige_local_alloc(*m, dim, d->pt->n, d->pt->pts, d->pt->val, &o, &k);
    if (st)
        cli_die(st == NL_EINVAL || nl_error_is_input(st) ? 2 : 1, "--data: %s: %s", c->data, nl_errmsg());
    return k;
}

size_t kp_missing(const double *est, size_t count, const char *what)
{
    size_t miss = 0;
    for (size_t i = 0; i < count; i++)
        miss += isnan(est[i]) != 0;
    if (miss)
        fprintf(stderr, "noiselab: krige: %zu of %zu %s have no data in their neighbourhood (or fewer than the drift "
                "terms): written as missing\n", miss, count, what);
    return miss;
}

/* A covariate field c that records where it lies (noiselab.origin, a
 * georeferenced file's extent, or the extent of an older map) must lie on
 * the grid of f, first cell centre at lo + h / 2: the same first sample and
 * spacing, to 1e-9 of a cell (the records' %.17g round trip is far below
 * that).  One recording nothing is taken as the grid's, sample for cell. */
static void check_cov_grid(const char *path, const nl_field *c, const nl_meta *meta, const double *lo,
                           const nl_field *f)
{
    double h[3] = {c->h[0], c->h[1], c->h[2]}, o[3];
    if (!meta->origin[0] && !meta->extent[0] && !strstr(meta->method, "extent="))
        return;
    if (nl_meta_origin(meta, c->dim, c->n, h, o))
        cli_die(2, "--covariate: %s: %s", path, nl_errmsg());
    for (int a = 0; a < f->dim; a++) {
        double g0 = lo[a] + 0.5 * f->h[a];
        if (fabs(o[a] - g0) > 1e-9 * f->h[a] || fabs(h[a] - f->h[a]) > 1e-9 * f->h[a])
            cli_die(2, "--covariate: %s lies on a grid of first sample %.10g and spacing %.10g on axis %c; expected "
                    "the kriging grid's first cell centre %.10g and spacing %.10g", path, o[a], h[a], "xyz"[a], g0,
                    f->h[a]);
    }
}

/* The covariates of the grid's cells (count * ncov) from --covariate. */
static double *grid_cov(const kp_opts *p, const double *lo, const nl_field *f)
{
    double *cov = cli_malloc(f->count * p->ncov * sizeof *cov);
    for (size_t j = 0; j < p->ncov; j++) {
        size_t i = 0;
        while (i < p->nfield && strcmp(p->fname[i], p->cov[j]))
            i++;
        if (i == p->nfield)
            cli_die(2, "--drift: covariate \"%s\" on a grid needs its values at the cells: expected --covariate "
                    "%s=FIELD.exr (or --at TABLE.tsv)", p->cov[j], p->cov[j]);
        nl_meta meta;
        nl_field *c = cli_read_field(p->fpath[i], &meta);
        int same = c->dim == f->dim;
        for (int a = 0; same && a < f->dim; a++)
            same = c->n[a] == f->n[a];
        if (!same)
            cli_die(2, "--covariate: %s has %zu x %zu x %zu samples; expected the grid's %zu x %zu x %zu", p->fpath[i],
                    c->n[0], c->dim > 1 ? c->n[1] : 1, c->dim > 2 ? c->n[2] : 1, f->n[0], f->dim > 1 ? f->n[1] : 1,
                    f->dim > 2 ? f->n[2] : 1);
        check_cov_grid(p->fpath[i], c, &meta, lo, f);
        for (size_t t = 0; t < f->count; t++)
            cov[t * p->ncov + j] = c->data[t];
        nl_field_free(c);
    }
    return cov;
}

void kp_grid(const kp_opts *p, const nl_krige_local *k, const double *lo, nl_field *f, nl_field *vf)
{
    int st, dim = f->dim;
    if (!p->ncov) {
        if ((st = nl_krige_local_grid(k, lo, f, vf)))
            cli_die(st == NL_EINVAL ? 2 : 1, "--grid: %s", nl_errmsg());
        return;
    }
    double *cov = grid_cov(p, lo, f), *x = cli_malloc(f->count * (size_t)dim * sizeof *x);
    for (size_t t = 0; t < f->count; t++) { /* cell t = i + n0 (j + n1 l), as nl_krige_local_grid */
        size_t ix[3] = {t % f->n[0], dim > 1 ? t / f->n[0] % f->n[1] : 0, dim > 2 ? t / (f->n[0] * f->n[1]) : 0};
        for (int a = 0; a < dim; a++)
            x[t * (size_t)dim + (size_t)a] = lo[a] + ((double)ix[a] + 0.5) * f->h[a];
    }
    if ((st = nl_krige_local_eval_at(k, f->count, x, cov, f->data, vf ? vf->data : NULL)))
        cli_die(st == NL_EINVAL ? 2 : 1, "--grid: %s", nl_errmsg());
    free(cov), free(x);
}

/* The --at table and its coordinates and covariates. */
static nl_table *read_at(const kp_opts *p, int dim, double **pts, double **cov)
{
    nl_table *t;
    int st, adim;
    if ((st = nl_table_read(p->at, &t)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--at: %s", nl_errmsg());
    if ((st = nl_table_points(t, NULL, &adim, pts, NULL)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--at: %s", nl_errmsg());
    if (adim != dim)
        cli_die(2, "--at: %s has %d coordinates per point, the data %d", p->at, adim, dim);
    if (nl_table_column(t, "estimate") >= 0 || nl_table_column(t, "variance") >= 0)
        cli_die(2, "--at: %s has a column \"%s\", which the output adds; expected other names", p->at,
                nl_table_column(t, "estimate") >= 0 ? "estimate" : "variance");
    *cov = p->ncov ? table_cov(p, t) : NULL;
    return t;
}

int kp_predict_at(const kp_opts *p, const kp_common *c)
{
    kp_data d;
    nl_model *m;
    double *pts, *cov;
    kp_read_data(p, c->data, &d);
    nl_table *t = read_at(p, d.pt->dim, &pts, &cov);
    nl_krige_local *k = kp_plan(p, c, &d, &m);
    const char *tmp = cli_out_begin(c->out);
    double *est = cli_malloc(t->n * sizeof *est), *var = cli_malloc(t->n * sizeof *var);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int st = nl_krige_local_eval_at(k, t->n, pts, cov, est, var);
    if (st)
        cli_die(st == NL_EINVAL ? 2 : 1, "--at: %s: %s", p->at, nl_errmsg());
    clock_gettime(CLOCK_MONOTONIC, &t1);
    size_t miss = kp_missing(est, t->n, "points of --at");
    static const char *const names[] = {"estimate", "variance"};
    const double *cols[] = {est, var};
    cli_check(nl_table_write(tmp, t, 2, names, cols));
    cli_out_commit(c->out);
    if (c->json)
        cli_json_print(json_pack("{s:I,s:I,s:I,s:s,s:I,s:f,s:I,s:f}", "points", (json_int_t)d.pt->n, "locations",
                                 (json_int_t)t->n, "missing", (json_int_t)miss, "kind", c->kind, "nmax",
                                 (json_int_t)c->nmax, "radius", c->radius, "terms",
                                 (json_int_t)nl_krige_local_terms(k),
                                 "seconds", (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec)));
    free(est), free(var), free(pts), free(cov);
    nl_table_free(t), nl_krige_local_free(k), nl_model_free(m), kp_data_free(&d);
    return 0;
}

/* Fold ids 1..K drawn for each datum from --seed (nl_krige_draw_folds). */
static long *draw_folds(const kp_opts *p, size_t n)
{
    long *fold = cli_malloc(n * sizeof *fold);
    nl_krige_draw_folds(p->seed, n, p->kfold, fold);
    return fold;
}

/* Distinct ids in fold (n). */
static size_t count_folds(const long *fold, size_t n)
{
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        size_t j = 0;
        while (j < i && fold[j] != fold[i])
            j++;
        k += j == i;
    }
    return k;
}

size_t kp_cross_validate(const kp_opts *p, const nl_krige_local *k, const kp_data *d, double *pred, double *var,
                         nl_krige_cv_summary *s, long **fold_out)
{
    size_t n = d->pt->n;
    long *fold = NULL;
    int st;
    if (p->kfold > n)
        cli_die(2, "--cross-validate: %zu folds for %zu data; expected at most %zu (one datum a fold: leave-one-out)",
                p->kfold, n, n);
    if (p->folds) {
        fold = cli_malloc(n * sizeof *fold);
        memcpy(fold, d->fold, n * sizeof *fold);
        size_t nf = count_folds(fold, n);
        if (p->kfold && nf > p->kfold)
            cli_die(2, "--folds: column %s holds %zu fold ids; expected at most --cross-validate %zu", p->folds, nf,
                    p->kfold);
    } else if (p->kfold && p->kfold < n)
        fold = draw_folds(p, n);
    st = fold ? nl_krige_local_cv_folds(k, fold, pred, var, s) : nl_krige_local_cv(k, pred, var, s);
    if (st)
        cli_die(st == NL_EINVAL || nl_error_is_input(st) ? 2 : 1, "--cross-validate: %s", nl_errmsg());
    size_t nf = fold ? count_folds(fold, n) : n;
    if (fold_out)
        *fold_out = fold;
    else
        free(fold);
    return nf;
}
