/* noiselab sample: a field's values at given or random points, as a data table. */
#include "cli.h"
#include "opt.h"
#include "../core/field_sample.h"
#include "../core/io_coords.h"
#include "../core/nl_error.h"
#include "../core/provenance.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab sample FIELD (--points PTS.tsv | --random N [--seed S])\n"
    "                       [--interpolation nearest|bilinear] [-o OUT.tsv]\n\n"
    "The field's values at points, as a table x [y [z]] value (standard output\n"
    "without -o), ready for noiselab krige --data and synth --condition.\n"
    "Coordinates are the field's: sample i of an axis sits at (origin + i) h, with h\n"
    "its spacing and origin its recorded window origin (noiselab.origin; 0 when\n"
    "absent); a field made on an --extent a:b (synth --condition, krige) has its samples at\n"
    "the cell centres a + (i + 0.5) h.\n"
    "  --points PTS.tsv  a header x [y [z]] (any order; a value column is ignored), one\n"
    "                    row per point; every point must lie within the samples' span\n"
    "                    (the first one outside is refused, exit 2)\n"
    "  --random N        N points drawn uniformly within the samples' span, from --seed\n"
    "                    (default 1); coordinates are rounded to the 10 digits printed\n"
    "  --interpolation   nearest: the nearest sample's value; bilinear (default):\n"
    "                    multilinear between the 2^dim samples around the point\n";

/* The command's options. */
typedef struct {
    const char *field, *points, *out; /* as given, or NULL */
    size_t random;                    /* --random N, 0 when not given */
    uint64_t seed;                    /* --seed */
    int interp, given_seed;           /* NL_INTERP_*, --seed given */
} opts_t;

static const char *const interps[] = {"nearest", "bilinear", NULL}; /* NL_INTERP_* by index */

static const cli_opt rows[] = {
    CLI_STRING("points", opts_t, points), CLI_COUNT("random", opts_t, random, .lo = 1),
    CLI_OPT_SEED(opts_t, seed, given_seed), CLI_CHOICE("interpolation", opts_t, interp, .choices = interps),
    CLI_OPT_OUTPUT(opts_t, out), {0}};

static void parse(int argc, char **argv, opts_t *a)
{
    if (cli_opt_parse("sample", help, rows, a, argc, argv))
        exit(0);
    a->field = cli_one_operand("sample", "FIELD", argc, argv);
    if (!a->points == !a->random)
        cli_die(2, "sample: expected exactly one of --points PTS.tsv or --random N");
    if (a->given_seed && !a->random)
        cli_die(2, "--seed: applies to --random only");
    if (a->out && !cli_has_ext(a->out, ".tsv"))
        cli_die(2, "-o: expected a file name ending in .tsv, got \"%s\"", a->out);
}

/* Coordinate of sample 0 per axis, as the file records it (nl_meta_origin:
 * a window's origin, a map's first cell centre, whose spacing it may set). */
static void first_sample(const opts_t *a, nl_field *f, const nl_meta *meta, double *x0)
{
    if (nl_meta_origin(meta, f->dim, f->n, f->h, x0))
        cli_die(2, "sample: %s: %s", a->field, nl_errmsg());
}

/* The points: read (and matched to the field's dimension) or drawn. */
static double *get_points(const opts_t *a, const nl_field *f, const double *x0, size_t *n)
{
    double *pts;
    int dim;
    if (a->points) {
        int st = nl_coords_read(a->points, &dim, n, &pts);
        if (st)
            cli_die(nl_error_is_input(st) ? 2 : 1, "--points: %s", nl_errmsg());
        if (dim != f->dim) {
            free(pts);
            cli_die(2, "--points: %s has %d coordinates per point, expected %d (the dimension of %s)", a->points,
                    dim, f->dim, a->field);
        }
        return pts;
    }
    size_t want[2] = {a->random, (size_t)f->dim};
    int st = nl_size_check(2, want, sizeof *pts, 2, NULL);
    if (st)
        cli_die(2, "--random: %zu points of %d coordinates do not fit in the memory available", a->random, f->dim);
    pts = cli_malloc(a->random * (size_t)f->dim * sizeof *pts);
    nl_field_random_points(f, x0, a->seed, a->random, pts);
    for (size_t i = 0; i < a->random * (size_t)f->dim; i++) { /* the coordinates as printed */
        char buf[32];
        snprintf(buf, sizeof buf, "%.10g", pts[i]);
        pts[i] = strtod(buf, NULL);
    }
    *n = a->random;
    return pts;
}

static void write_table(const opts_t *a, const nl_field *f, const nl_meta *meta, size_t n, const double *pts,
                        const double *val, const char *tmp)
{
    static const char *const names[] = {"x", "y", "z", "value"};
    const char *hdr[4];
    const double *cols[4];
    double *c = cli_malloc(n * (size_t)f->dim * sizeof *c);
    char comment[1400];
    for (int d = 0; d < f->dim; d++) {
        for (size_t i = 0; i < n; i++)
            c[(size_t)d * n + i] = pts[i * (size_t)f->dim + d];
        hdr[d] = names[d], cols[d] = c + (size_t)d * n;
    }
    hdr[f->dim] = names[3], cols[f->dim] = val;
    snprintf(comment, sizeof comment, "noiselab sample: %s (model %s, seed %s), %s interpolation", a->field,
             meta->model[0] ? meta->model : "not recorded", meta->seed[0] ? meta->seed : "not recorded",
             a->interp == NL_INTERP_NEAREST ? "nearest" : "bilinear");
    cli_check(cli_write_table(a->out ? tmp : NULL, comment, f->dim + 1, hdr, n, cols));
    free(c);
}

int cli_cmd_sample(int argc, char **argv)
{
    opts_t a = {.seed = 1, .interp = NL_INTERP_LINEAR};
    nl_meta meta;
    double x0[3];
    size_t n;
    parse(argc, argv, &a);
    nl_field *f = cli_read_field(a.field, &meta);
    first_sample(&a, f, &meta, x0);
    double *pts = get_points(&a, f, x0, &n);
    const char *tmp = cli_out_begin(a.out);
    double *val = cli_malloc(n * sizeof *val);
    int st = nl_field_sample(f, x0, a.interp, n, pts, val);
    if (st)
        cli_die(2, "--points: %s: %s", a.points ? a.points : "--random", nl_errmsg());
    write_table(&a, f, &meta, n, pts, val, tmp);
    cli_out_commit(a.out);
    free(pts), free(val);
    nl_field_free(f);
    return 0;
}
