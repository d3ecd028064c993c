/* noiselab krige: ordinary or simple kriging of scattered data onto a grid. */
#include "cli.h"
#include "../analysis/krige.h"
#include "../core/io_points.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <float.h>
#include <getopt.h>
#include <string.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static const char help[] =
    "usage: noiselab krige --data PTS.tsv --acf SPEC --grid W[xH[xD]] --extent a:b[,c:d[,e:f]]\n"
    "                      [--mean M] [--strict] [--json] -o OUT.exr|OUT.tsv [--variance VAR.exr]\n\n"
    "Kriging (Stam and Fiume 1991, eqs. 19-22): ordinary (unknown mean, unbiased by a\n"
    "Lagrange multiplier) or, with --mean, simple.  PTS.tsv: a header line, then rows\n"
    "x [y [z]] value.  Grid cell centres are a + (i + 0.5)(b - a)/W.  A singular system\n"
    "(duplicate points, a smooth model with close points) is solved by the pseudo-\n"
    "inverse and flagged, or refused with --strict.  --variance writes the kriging\n"
    "variance (O(n^2) per cell).\n";

/* The command's options. */
typedef struct {
    const char *data, *spec, *grid, *ext, *out, *vout;  /* as given, or NULL */
    double mean, lo[3], hi[3];                          /* --mean (NAN: ordinary), --extent */
    int strict, json, gdim;                             /* --strict, --json, grid dimension */
    size_t g[3];                                        /* --grid */
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

static void parse(int argc, char **argv, opts_t *a)
{
    static const struct option opts[] = {
        {"data", required_argument, 0, 'd'}, {"acf", required_argument, 0, 'a'},    {"grid", required_argument, 0, 'g'},
        {"extent", required_argument, 0, 'e'}, {"mean", required_argument, 0, 'm'}, {"strict", no_argument, 0, 's'},
        {"json", no_argument, 0, 'j'},       {"output", required_argument, 0, 'o'}, {"variance", required_argument, 0, 'v'},
        {"help", no_argument, 0, 'h'},       {0}};
    int c;
    while ((c = cli_getopt(argc, argv, ":ho:", opts, "krige")) != -1) {
        switch (c) {
        case 'd': a->data = optarg; break;
        case 'a': a->spec = optarg; break;
        case 'g': a->grid = optarg; break;
        case 'e': a->ext = optarg; break;
        case 'm': a->mean = cli_parse_double("--mean", optarg); break;
        case 's': a->strict = 1; break;
        case 'j': a->json = 1; break;
        case 'o': a->out = optarg; break;
        case 'v': a->vout = optarg; break;
        case 'h': fputs(help, stdout); exit(0);
        }
    }
    cli_no_operands("krige", argc, argv);
    if (!a->data)
        cli_die(2, "krige: --data: expected a table of points (x, y[, z], value)");
    if (!a->spec)
        cli_die(2, "krige: --acf: expected a covariance model (see noiselab models)");
    if (!a->grid)
        cli_die(2, "krige: --grid: expected the output grid WxH[xD]");
    if (!a->ext)
        cli_die(2, "krige: --extent: expected the grid's extent a:b,c:d[,e:f]");
    if (!a->out)
        cli_die(2, "krige: -o: expected an output file (.exr or .tsv)");
    a->gdim = cli_parse_size("--grid", a->grid, a->g, 1);
    parse_extent(a);
    if (!cli_has_ext(a->out, ".exr") && !cli_has_ext(a->out, ".tsv"))
        cli_die(2, "-o: expected .exr or .tsv, got \"%s\"", a->out);
    if (cli_has_ext(a->out, ".tsv") && a->gdim != 1)
        cli_die(2, "-o: TSV holds 1D grids; use .exr, got \"%s\"", a->out);
    if (a->vout && !cli_has_ext(a->vout, ".exr"))
        cli_die(2, "--variance: expected a .exr file, got \"%s\"", a->vout);
    if (a->vout && strcmp(a->vout, a->out) == 0)
        cli_die(2, "--variance: expected a file other than -o, got \"%s\" for both -o and --variance", a->vout);
}

/* A field bound for a float32 EXR fits it. */
static void check_float(const char *opt, const char *path, const nl_field *f)
{
    if (!path || !cli_has_ext(path, ".exr"))
        return;
    for (size_t i = 0; i < f->count; i++)
        if (!(fabs(f->data[i]) <= FLT_MAX))
            cli_die(2, "%s: sample %zu is %g, beyond the float32 range of \"%s\"; expected |value| <= %g "
                    "(write .tsv in 1D, or scale the data)", opt, i, f->data[i], path, FLT_MAX);
}

/* The estimates (EXR or, 1D, TSV) and the variances. */
static void write_outputs(const opts_t *a, const nl_field *f, const nl_field *vf, const nl_krige_info *info,
                          size_t n, const char *tmp, const char *vtmp)
{
    nl_meta meta = {0};
    int st;
    snprintf(meta.model, sizeof meta.model, "%s", a->spec);
    snprintf(meta.method, sizeof meta.method, "krige:%s,points=%zu", isnan(a->mean) ? "ordinary" : "simple", n);
    if (info->pseudo_inverse)
        snprintf(meta.flags, sizeof meta.flags, "singular,pseudo-inverse");
    check_float("-o", a->out, f);
    if (vf)
        check_float("--variance", a->vout, vf);
    if (cli_has_ext(a->out, ".exr"))
        st = nl_exr_write(tmp, f, &meta);
    else { /* 1D: the record as in EXR, and cell centres as x */
        double *xs = cli_malloc(a->g[0] * sizeof *xs);
        for (size_t i = 0; i < a->g[0]; i++)
            xs[i] = a->lo[0] + ((double)i + 0.5) * f->h[0];
        st = nl_tsv_write_field(tmp, f, &meta, "x", xs);
        free(xs);
    }
    if (!st && vf)
        st = nl_exr_write(vtmp, vf, &meta);
    cli_check(st);
    cli_out_commit(a->out);
    cli_out_commit(a->vout);
}

static void report(const opts_t *a, const nl_krige_info *info, size_t n, double secs)
{
    if (a->json)
        cli_json_print(json_pack("{s:I,s:s,s:f,s:f,s:o,s:f}", "points", (json_int_t)n, "kind",
                                 isnan(a->mean) ? "ordinary" : "simple", "mean", info->mean, "rcond", info->rcond,
                                 "flags",
                                 info->pseudo_inverse ? json_pack("[s,s]", "singular", "pseudo-inverse") : json_array(),
                                 "seconds", secs));
    else if (info->pseudo_inverse)
        fprintf(stderr, "noiselab: krige: the system is singular (reciprocal condition %.2g); solved by the "
                "pseudo-inverse (flagged in the output)\n", info->rcond);
}

int cli_cmd_krige(int argc, char **argv)
{
    opts_t a = {.mean = NAN, .lo = {0, 0, 0}, .hi = {1, 1, 1}, .g = {1, 1, 1}};
    const char *tmp, *vtmp = NULL;
    int st;
    size_t n;
    parse(argc, argv, &a);
    nl_points *pt;
    if ((st = nl_points_read(a.data, &pt)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "--data: %s", nl_errmsg());
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
    if ((st = nl_size_check(a.gdim, a.g, sizeof(double), a.vout ? 2 : 1, NULL))) {
        char why[256];
        snprintf(why, sizeof why, "%s", nl_errmsg());
        cli_die(st == NL_ETOOBIG || nl_error_is_input(st) ? 2 : 1, "--grid %s: %s", a.grid, why);
    }
    nl_field *f = cli_field_alloc(a.gdim, a.g, h), *vf = a.vout ? cli_field_alloc(a.gdim, a.g, h) : NULL;
    cli_check(nl_krige_eval_grid(p, a.lo, f, vf));
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    write_outputs(&a, f, vf, &info, n, tmp, vtmp);
    report(&a, &info, n, secs);
    nl_krige_plan_free(p), nl_model_free(m), nl_field_free(f), nl_field_free(vf);
    nl_points_free(pt);
    return 0;
}
