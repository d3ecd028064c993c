/* noiselab krige: ordinary or simple kriging of scattered data onto a grid. */
#include "cli.h"
#include "../analysis/krige.h"
#include "../core/model.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

static double *read_points(const char *path, int *dim, size_t *n)
{
    FILE *fp = fopen(path, "r");
    char line[4096];
    size_t cap = 256, lineno = 0, cols = 0;
    double *v = NULL;
    *n = 0;
    if (!fp)
        cli_die(2, "--data: cannot open \"%s\": %s", path, strerror(errno));
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        if (line[0] == '#' || line[0] == '\n')
            continue;
        if (!cols) {  /* header */
            char *p = line;
            cols = 1;
            while ((p = strchr(p, '\t')))
                cols++, p++;
            if (cols < 2 || cols > 4)
                cli_die(2, "--data: %s:%zu: expected a header of 2 to 4 columns (x [y [z]] value), got %zu", path,
                        lineno, cols);
            v = malloc(cap * cols * sizeof *v);
            continue;
        }
        if (*n == cap) {
            cap *= 2;
            v = realloc(v, cap * cols * sizeof *v);
        }
        if (!v)
            cli_die(1, "out of memory");
        char *p = line, *end;
        for (size_t c = 0; c < cols; c++) {
            double x = strtod(p, &end);
            if (end == p || !isfinite(x) || (c + 1 < cols && *end != '\t') ||
                (c + 1 == cols && *end && *end != '\n' && *end != '\r'))
                cli_die(2, "--data: %s:%zu: expected %zu tab-separated finite numbers", path, lineno, cols);
            v[*n * cols + c] = x;
            p = end + 1;
        }
        (*n)++;
    }
    fclose(fp);
    if (!*n)
        cli_die(2, "--data: %s: expected at least one data row", path);
    *dim = (int)cols - 1;
    return v;
}

int cli_cmd_krige(int argc, char **argv)
{
    static const struct option opts[] = {
        {"data", required_argument, 0, 'd'}, {"acf", required_argument, 0, 'a'},    {"grid", required_argument, 0, 'g'},
        {"extent", required_argument, 0, 'e'}, {"mean", required_argument, 0, 'm'}, {"strict", no_argument, 0, 's'},
        {"json", no_argument, 0, 'j'},       {"output", required_argument, 0, 'o'}, {"variance", required_argument, 0, 'v'},
        {"help", no_argument, 0, 'h'},       {0}};
    const char *data = NULL, *spec = NULL, *grid = NULL, *ext = NULL, *out = NULL, *vout = NULL, *tmp, *vtmp = NULL;
    double mean = NAN, lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    int c, strict = 0, json = 0, st, dim, gdim;
    size_t n, g[3] = {1, 1, 1};
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'd': data = optarg; break;
        case 'a': spec = optarg; break;
        case 'g': grid = optarg; break;
        case 'e': ext = optarg; break;
        case 'm': mean = cli_parse_double("--mean", optarg); break;
        case 's': strict = 1; break;
        case 'j': json = 1; break;
        case 'o': out = optarg; break;
        case 'v': vout = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("krige", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "krige: unexpected argument \"%s\"", argv[optind]);
    if (!data || !spec || !grid || !ext || !out)
        cli_die(2, "krige: expected --data, --acf, --grid, --extent and -o");
    gdim = cli_parse_size("--grid", grid, g, 1);
    {
        const char *p = ext;
        for (int a = 0; a < gdim; a++) {
            char *end;
            lo[a] = strtod(p, &end);
            if (end == p || *end != ':')
                cli_die(2, "--extent: expected a:b per axis separated by commas, got \"%s\"", ext);
            p = end + 1;
            hi[a] = strtod(p, &end);
            if (end == p || !(hi[a] > lo[a]) || (a + 1 < gdim ? *end != ',' : *end != 0))
                cli_die(2, "--extent: expected %d ranges a:b with a < b, got \"%s\"", gdim, ext);
            p = end + 1;
        }
    }
    if (!cli_has_ext(out, ".exr") && !cli_has_ext(out, ".tsv"))
        cli_die(2, "-o: expected .exr or .tsv, got \"%s\"", out);
    if (cli_has_ext(out, ".tsv") && gdim != 1)
        cli_die(2, "-o: TSV holds 1D grids; use .exr, got \"%s\"", out);
    if (vout && !cli_has_ext(vout, ".exr"))
        cli_die(2, "--variance: expected a .exr file, got \"%s\"", vout);
    double *raw = read_points(data, &dim, &n);
    if (dim != gdim)
        cli_die(2, "--data: %s has %d coordinates per point, the grid %d", data, dim, gdim);
    double *pts = malloc(n * (size_t)dim * sizeof *pts), *val = malloc(n * sizeof *val);
    if (!pts || !val)
        cli_die(1, "out of memory");
    for (size_t i = 0; i < n; i++) {
        for (int a = 0; a < dim; a++)
            pts[i * dim + a] = raw[i * (dim + 1) + a];
        val[i] = raw[i * (dim + 1) + dim];
    }
    nl_model *m;
    nl_krige_plan *p;
    nl_krige_info info;
    if ((st = nl_model_parse(spec, &m)))
        cli_die_status(st);
    tmp = cli_out_begin(out);
    if (vout)
        vtmp = cli_out_begin(vout);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    if ((st = nl_krige_plan_alloc(m, dim, n, pts, val, !isnan(mean), isnan(mean) ? 0 : mean, strict, &p)))
        cli_die_status(st);
    nl_krige_plan_info(p, &info);
    double h[3];
    for (int a = 0; a < 3; a++)
        h[a] = (hi[a] - lo[a]) / (double)g[a];
    nl_field *f = nl_field_alloc(gdim, g, h, &st), *vf = vout ? nl_field_alloc(gdim, g, h, &st) : NULL;
    if (!f || (vout && !vf))
        cli_die_status(st);
    int parallel = nl_model_get_kind(m) != NL_MODEL_EXPR;
    size_t nblk = (f->count + NL_KRIGE_BLOCK - 1) / NL_KRIGE_BLOCK;
#pragma omp parallel for schedule(dynamic, 1) if (parallel && f->count > 4096)
    for (size_t blk = 0; blk < nblk; blk++) {
        size_t q0 = blk * NL_KRIGE_BLOCK, nq = f->count - q0 < NL_KRIGE_BLOCK ? f->count - q0 : NL_KRIGE_BLOCK;
        double x[NL_KRIGE_BLOCK * 3];
        for (size_t q = q0; q < q0 + nq; q++) {
            size_t idx[3] = {q % g[0], (q / g[0]) % g[1], q / (g[0] * g[1])};
            for (int a = 0; a < dim; a++)
                x[(q - q0) * (size_t)dim + a] = lo[a] + ((double)idx[a] + 0.5) * h[a];
        }
        nl_krige_eval_block(p, nq, x, &f->data[q0], vf ? &vf->data[q0] : NULL);
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    nl_meta meta;
    memset(&meta, 0, sizeof meta);
    snprintf(meta.model, sizeof meta.model, "%s", spec);
    snprintf(meta.method, sizeof meta.method, "krige:%s,points=%zu", isnan(mean) ? "ordinary" : "simple", n);
    if (info.pseudo_inverse)
        snprintf(meta.flags, sizeof meta.flags, "singular,pseudo-inverse");
    if (cli_has_ext(out, ".exr"))
        st = nl_exr_write(tmp, f, &meta);
    else {
        static const char *const names[] = {"x", "value"};
        double *xs = malloc(g[0] * sizeof *xs);
        for (size_t i = 0; i < g[0]; i++)
            xs[i] = lo[0] + ((double)i + 0.5) * h[0];
        const double *cols[2] = {xs, f->data};
        st = nl_tsv_write(tmp, NULL, 2, names, g[0], cols);
        free(xs);
    }
    if (!st && vf)
        st = nl_exr_write(vtmp, vf, &meta);
    if (st)
        cli_die_status(st);
    cli_out_commit(out);
    if (vout)
        cli_out_commit(vout);
    if (json)
        cli_json_print(json_pack("{s:I,s:s,s:f,s:f,s:o,s:f}", "points", (json_int_t)n, "kind",
                                 isnan(mean) ? "ordinary" : "simple", "mean", info.mean, "rcond", info.rcond, "flags",
                                 info.pseudo_inverse ? json_pack("[s,s]", "singular", "pseudo-inverse") : json_array(),
                                 "seconds", secs));
    else if (info.pseudo_inverse)
        fprintf(stderr, "noiselab: krige: the system is singular (reciprocal condition %.2g); solved by the "
                "pseudo-inverse (flagged in the output)\n", info.rcond);
    nl_krige_plan_free(p), nl_model_free(m), nl_field_free(f), nl_field_free(vf);
    free(raw), free(pts), free(val);
    return 0;
}
