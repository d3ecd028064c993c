/* noiselab synth --condition: conditional simulation (analysis/condsim.h)
 * of the methods' unconditional fields, K realizations to K files, or to K
 * columns of a table with --at. */
#include "synth.h"
#include "../core/field_sample.h"
#include "../core/io_points.h"
#include "../core/nl_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_synth_cond_option(cli_synth_cond *c, int opt, const char *arg)
{
    switch (opt) {
    case 'Y': c->data = arg; break;
    case 'Z': c->extent = arg; break;
    case 'k': c->K = cli_parse_count("--realizations", arg, 1), c->given_K = 1; break;
    case 'g': c->emean = arg; break;
    case 'q': c->nmax = cli_parse_count("--nmax", arg, 1); break;
    case 'J': c->evar = arg; break;
    case 'T': c->at = arg; break;
    case 'W': c->grid_out = arg; break;
    case 'M': c->mean = cli_parse_double("--mean", arg), c->simple = 1; break;
    case 'Q': /* deprecated: U between samples is drawn given the grid */
        if (strcmp(arg, "nearest") && strcmp(arg, "bilinear"))
            cli_die(2, "--interpolation: expected nearest or bilinear, got \"%s\"", arg);
        c->given_interp = 1;
        break;
    }
}

/* The options that only make sense together. */
static void check_given(const cli_synth_cond *c, const cli_synth_job *job, int from, int spacing)
{
    if (!c->data) {
        if (c->extent || c->given_K || c->simple || c->given_interp || c->emean || c->evar || c->nmax || c->at ||
            c->grid_out)
            cli_die(2, "synth: --extent, --realizations, --mean, --interpolation, --ensemble-mean, "
                    "--ensemble-variance, --nmax, --at and --grid-out apply to --condition only");
        return;
    }
    if (c->grid_out && !c->at)
        cli_die(2, "--grid-out: applies to --at (without --at, -o is the grid), got \"%s\"", c->grid_out);
    if (from)
        cli_die(2, "synth: --from FILE and --condition exclude each other (a conditional field regenerates with "
                "its data: give the options again)");
    if (!(job->type->caps & NL_METHOD_CONDITIONABLE)) {
        char list[256];
        nl_method_names(NL_METHOD_CONDITIONABLE | NL_METHOD_EXACT_FIRST, NULL, ", ", " and ", list, sizeof list);
        cli_die(2, "synth %s: --condition applies to %s only", job->method, list);
    }
    if (!c->extent)
        cli_die(2, "synth: --extent: expected the grid's extent a:b[,c:d[,e:f]] with --condition");
    if (spacing)
        cli_die(2, "synth: --spacing and --extent exclude each other (the spacing is the extent over the size)");
    if (c->K > 9999)
        cli_die(2, "--realizations: expected at most 9999, got %zu", c->K);
    if (c->evar && c->K < 2)
        cli_die(2, "--ensemble-variance: expected --realizations K with K >= 2, got %zu", c->K);
    if (c->emean)
        cli_field_out_check("--ensemble-mean", c->emean, 0);
    if (c->evar)
        cli_field_out_check("--ensemble-variance", c->evar, 0);
}

static void parse_extent(cli_synth_cond *c, const cli_synth_job *job)
{
    const char *p = c->extent;
    for (int d = 0; d < job->dim; d++) {
        char *end;
        c->lo[d] = strtod(p, &end);
        if (end == p || *end != ':')
            cli_die(2, "--extent: expected a:b per axis separated by commas, got \"%s\"", c->extent);
        p = end + 1;
        c->hi[d] = strtod(p, &end);
        if (end == p || !(c->hi[d] > c->lo[d]) || (d + 1 < job->dim ? *end != ',' : *end != 0))
            cli_die(2, "--extent: expected %d ranges a:b with a < b, got \"%s\"", job->dim, c->extent);
        if (!isfinite(4 * (c->hi[d] - c->lo[d])) || !isfinite(c->lo[d]) || !isfinite(c->hi[d]))
            cli_die(2, "--extent: expected finite ranges whose width does not overflow, got \"%s\"", c->extent);
        p = end + 1;
    }
}

const char *cli_synth_cond_grid(const cli_synth_cond *c, const char *out)
{
    return c->at ? c->grid_out : out;
}

int cli_synth_cond_check_out(const cli_synth_cond *c, const char *out, int dim)
{
    if (!c->at)
        return 0;
    if (!cli_has_ext(out, ".tsv"))
        cli_die(2, "-o: with --at, expected the table's output, a file name ending in .tsv, got \"%s\" (the grids "
                "go to --grid-out)", out);
    const char *g = c->grid_out;
    if (g && !cli_has_ext(g, ".exr") && !(dim == 1 && cli_has_ext(g, ".tsv")))
        cli_die(2, "--grid-out: expected a file name ending in .exr%s, got \"%s\"", dim == 1 ? " or .tsv" : "", g);
    return 1;
}

/* The --at table: its points, each inside the extent (exit 2 naming the
 * first outside by its row), no column the output adds, and room for the K
 * columns. */
static void read_at(cli_synth_cond *c, const cli_synth_job *job)
{
    int st, dim;
    if ((st = nl_table_read(c->at, &c->table)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--at: %s", nl_errmsg());
    if ((st = nl_table_points(c->table, NULL, &dim, &c->at_pts, NULL)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--at: %s", nl_errmsg());
    if (dim != job->dim)
        cli_die(2, "--at: %s has %d coordinates per point, the grid %d", c->at, dim, job->dim);
    c->np = c->table->n;
    for (size_t j = 0; j < c->np; j++)
        for (int a = 0; a < dim; a++) {
            double x = c->at_pts[j * (size_t)dim + (size_t)a], top = c->lo[a] + (double)job->n[a] * job->h[a];
            if (!(x >= c->lo[a] && x <= top))
                cli_die(2, "--at: %s: row %zu has %c = %.10g, outside --extent %s; expected points within the grid",
                        c->at, j + 1, "xyz"[a], x, c->extent);
        }
    for (size_t k = 0; k < c->K; k++) {
        char name[32];
        snprintf(name, sizeof name, "sim%zu", k + 1);
        if (nl_table_column(c->table, name) >= 0)
            cli_die(2, "--at: %s has a column \"%s\", which the output adds; expected other names", c->at, name);
    }
    size_t shape[2] = {c->np, c->K};
    if ((st = nl_size_check(2, shape, sizeof *c->zat, 1, NULL)))
        cli_die(2, "--realizations: %zu realizations at the %zu points of --at: %s", c->K, c->np, nl_errmsg());
    c->zat = cli_malloc(c->np * c->K * sizeof *c->zat);
}

void cli_synth_cond_prepare(cli_synth_cond *c, cli_synth_job *job, int from, int spacing)
{
    nl_points *pt;
    int st;
    check_given(c, job, from, spacing);
    if (!c->data)
        return;
    parse_extent(c, job);
    for (int a = 0; a < job->dim; a++)
        job->h[a] = (c->hi[a] - c->lo[a]) / (double)job->n[a];
    if (c->at)
        read_at(c, job);
    if ((st = nl_points_read(c->data, &pt)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--condition: %s", nl_errmsg());
    if (pt->dim != job->dim) {
        int d = pt->dim;
        nl_points_free(pt);
        cli_die(2, "--condition: %s has %d coordinates per point, the grid %d", c->data, d, job->dim);
    }
    nl_field grid = {.dim = job->dim, .n = {job->n[0], job->n[1], job->n[2]},
                     .h = {job->h[0], job->h[1], job->h[2]}};
    nl_condsim_options o = {.simple = c->simple, .mean = c->mean, .nmax = c->nmax};
    st = nl_condsim_plan_alloc(job->m, pt->n, pt->pts, pt->val, c->lo, &grid, &o, c->np, c->at_pts, &c->plan);
    nl_points_free(pt);
    if (st)
        cli_die(nl_error_is_input(st) ? 2 : 1, "--condition: %s: %s", c->data, nl_errmsg());
    nl_condsim_plan_info(c->plan, &c->info);
}

/* Realization k (from 0) of K: OUT itself when K = 1, else OUT with -k+1
 * before its extension (out.exr: out-1.exr, out-2.exr, ...). */
const char *cli_synth_cond_name(const cli_synth_cond *c, const char *path, size_t k, char *buf, size_t len)
{
    if (!path || !c->data || c->K == 1)
        return path;
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash))
        dot = path + strlen(path);
    snprintf(buf, len, "%.*s-%zu%s", (int)(dot - path), path, k + 1, dot);
    return buf;
}

void cli_synth_cond_apply(const cli_synth_cond *c, const cli_synth_job *job, nl_field *f, cli_synth_result *r,
                          size_t k)
{
    if (!c->data)
        return;
    cli_check(nl_condsim_execute(c->plan, f, job->seed, c->zat ? c->zat + k * c->np : NULL));
    size_t l = strlen(r->method);
    /* the space marks a field that --from cannot regenerate */
    snprintf(r->method + l, sizeof r->method - l, " conditioned:data=%s,points=%zu,kriging=%s,extent=%s,"
             "nmax=%zu,realization=%zu/%zu", c->data, c->info.n, c->simple ? "simple" : "ordinary", c->extent, c->nmax,
             k + 1, c->K);
    l = strlen(r->method);
    if (c->at) /* the points are drawn with the data: the grid depends on them */
        snprintf(r->method + l, sizeof r->method - l, ",at=%s", c->at);
}

void cli_synth_cond_write(const cli_synth_cond *c, const char *path, const char *tmp, const nl_field *f,
                          const nl_meta *meta)
{
    nl_meta m = *meta;
    if (!path)
        return; /* --at without --grid-out */
    if (c->data) /* the grid's cells on the extent */
        cli_meta_extent(&m, f->dim, c->lo, c->hi, f->n), meta = &m;
    if (!c->data || !cli_has_ext(path, ".tsv")) {
        cli_write_field(path, tmp, f, meta);
        return;
    }
    double *xs = cli_malloc(f->n[0] * sizeof *xs); /* 1D: the cell centres as x */
    for (size_t i = 0; i < f->n[0]; i++)
        xs[i] = c->lo[0] + ((double)i + 0.5) * f->h[0];
    int st = nl_tsv_write_field(tmp, f, meta, "x", xs);
    free(xs);
    cli_check(st);
}

void cli_synth_cond_report(const cli_synth_cond *c, json_t *o)
{
    if (!c->data)
        return;
    json_object_set_new(o, "condition",
                        json_pack("{s:s,s:I,s:I,s:s,s:I,s:I,s:I,s:f,s:f,s:b,s:I}", "data", c->data, "points",
                                  (json_int_t)c->info.n, "on_samples", (json_int_t)c->info.on_samples, "kriging",
                                  c->simple ? "simple" : "ordinary", "hood", (json_int_t)c->info.hood, "groups",
                                  (json_int_t)c->info.groups, "largest_group", (json_int_t)c->info.largest,
                                  "screening", c->info.screening, "max_move", c->info.max_move, "weights_kept",
                                  c->info.reuse, "realizations", (json_int_t)c->K));
    if (c->at)
        json_object_set_new(json_object_get(o, "condition"), "at",
                            json_pack("{s:s,s:I,s:s}", "table", c->at, "points", (json_int_t)c->np, "output", c->out));
}

void cli_synth_cond_note(const cli_synth_cond *c)
{
    if (c->data && c->given_interp)
        fprintf(stderr, "noiselab: synth: --interpolation is deprecated and ignored: the field at data between "
                "samples is drawn from its conditional law given the grid\n");
    if (!c->data || c->info.on_samples == c->info.n)
        return;
    fprintf(stderr, "noiselab: synth: %zu of %zu data lie between samples; the unconditional field there is drawn "
            "given the %zu samples per axis around them, to a screening error of %.2g standard deviations\n",
            c->info.n - c->info.on_samples, c->info.n, c->info.hood, c->info.screening);
}

void cli_synth_cond_begin(cli_synth_cond *c, const char *out)
{
    c->out = c->at ? out : NULL;
    c->ttmp = cli_out_begin(c->out);
    c->etmp[0] = cli_out_begin(c->emean);
    c->etmp[1] = cli_out_begin(c->evar);
}

/* Realization k (from 0) into the running mean and variance. */
void cli_synth_cond_accumulate(cli_synth_cond *c, const nl_field *f, size_t k)
{
    (void)k;
    if (!c->emean && !c->evar)
        return;
    if (!c->acc)
        cli_check(nl_welford_alloc(f->dim, f->n, f->h, &c->acc));
    cli_check(nl_welford_add(c->acc, f));
}

/* The table of --at: its rows as read (as krige --at writes them), then
 * the K realizations at its points, sim1..simK. */
static void write_at(const cli_synth_cond *c)
{
    char (*buf)[32] = cli_malloc(c->K * sizeof *buf);
    const char **names = cli_malloc(c->K * sizeof *names);
    const double **cols = cli_malloc(c->K * sizeof *cols);
    for (size_t k = 0; k < c->K; k++) {
        snprintf(buf[k], sizeof buf[k], "sim%zu", k + 1);
        names[k] = buf[k], cols[k] = c->zat + k * c->np;
    }
    cli_check(nl_table_write(c->ttmp, c->table, c->K, names, cols));
    cli_out_commit(c->out);
    free(buf), free(names), free(cols);
}

void cli_synth_cond_finish(cli_synth_cond *c, const nl_meta *meta)
{
    nl_meta m = *meta;
    nl_field *var;
    if (c->at)
        write_at(c);
    if (!c->emean && !c->evar)
        return;
    cli_check(nl_welford_variance(c->acc, &var)); /* unbiased, divisor K - 1 */
    m.seed[0] = 0, m.flags[0] = 0;
    cli_meta_extent(&m, var->dim, c->lo, c->hi, var->n);
    snprintf(m.method, sizeof m.method, "ensemble mean of %zu conditional realizations (data=%s,extent=%s)", c->K,
             c->data, c->extent);
    if (c->emean)
        cli_write_field(c->emean, c->etmp[0], nl_welford_mean(c->acc), &m);
    snprintf(m.method, sizeof m.method, "ensemble variance of %zu conditional realizations (data=%s,extent=%s)",
             c->K, c->data, c->extent);
    if (c->evar)
        cli_write_field(c->evar, c->etmp[1], var, &m);
    nl_field_free(var);
    cli_out_commit(c->emean);
    cli_out_commit(c->evar);
}

void cli_synth_cond_free(cli_synth_cond *c)
{
    nl_condsim_plan_free(c->plan);
    nl_welford_free(c->acc);
    nl_table_free(c->table);
    free(c->at_pts), free(c->zat);
}
