/* noiselab variogram: the empirical variogram of scattered points or of a field. */
#include "cli.h"
#include "opt.h"
#include "drift_terms.h"
#include "../analysis/variogram.h"
#include "../core/io_points.h"
#include "../core/io_table.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab variogram DATA.tsv|FIELD.exr [--width W] [--cutoff C]\n"
    "                          [--bins gstat|floor] [--drift TERMS]\n"
    "                          [--direction ANGLE --angle-tolerance T]\n"
    "                          [--estimator matheron|cressie] [--json] [-o OUT.tsv]\n\n"
    "Empirical semivariogram, binned as gstat's variogram(): pairs at distance h in\n"
    "(k W, (k + 1) W] for h <= C, a pair at distance 0 in the first bin (--bins\n"
    "gstat, the default; --bins floor: [k W, (k + 1) W) for h < C); each bin\n"
    "reports the mean pair distance, gamma (Matheron: sum of squared differences\n"
    "/ 2N; Cressie and Hawkins' robust estimator) and the pair count; empty bins\n"
    "are left out.  Defaults as gstat:\n"
    "C = a third of the bounding-box diagonal (for 3D points gstat's box, whose z\n"
    "extent runs from the smallest z to the first point's), W = C / 15.  DATA.tsv:\n"
    "a header x [y [z]] value (any order), a row per point; a field (.exr, .png) is\n"
    "read as its samples at i * spacing.  --drift TERMS (points): the variogram of\n"
    "the residuals of the drift's least-squares fit, TERMS as krige's: comma-\n"
    "separated linear (or x,y: gstat's variogram(value ~ x + y)), quadratic (adds\n"
    "the squares and cross products) and names of covariate columns of DATA.tsv\n"
    "(--drift sdist: gstat's variogram(value ~ sdist); read with the columns x\n"
    "[y [z]], value and any others).  --direction: gstat's\n"
    "alpha, degrees clockwise from +y towards +x, keeping pairs within T degrees\n"
    "(tol.hor) of it: a model's angle= runs the other way, from +x towards +y\n"
    "(angle = 90 - alpha; gstat's peer names take gstat's anis angle, see\n"
    "noiselab models).\n"
    "Writes a TSV (distance, gamma, pairs) to -o or stdout; --json prints the three\n"
    "arrays.\n";

/* The command's options. */
typedef struct {
    const char *in, *out;   /* input, -o (NULL: stdout) */
    int json, has_dir, has_tol; /* --json, --direction and --angle-tolerance given */
    const char *drift;      /* --drift TERMS, or NULL */
    cli_drift terms;        /* its terms */
    nl_variogram_options o; /* the library's options */
} opts_t;

static const char *const estimators[] = {"matheron", "cressie", NULL}; /* NL_VARIOGRAM_* by index */

static const cli_opt rows[] = {
    CLI_OPT_BINS(opts_t, o), CLI_DOUBLE("direction", opts_t, o.direction, CLI_GIVEN(opts_t, has_dir)),
    CLI_DOUBLE("angle-tolerance", opts_t, o.tolerance, CLI_GIVEN(opts_t, has_tol),
               .flags = CLI_RANGE_LO | CLI_RANGE_HI, .lo = 0, .hi = 90, .what = "degrees in [0, 90]"),
    CLI_CHOICE("estimator", opts_t, o.estimator, .choices = estimators),
    CLI_STRING("drift", opts_t, drift), CLI_OPT_JSON(opts_t, json),
    CLI_OPT_OUTPUT(opts_t, out), {0}};

static void parse(int argc, char **argv, opts_t *a)
{
    nl_variogram_options_default(&a->o);
    if (cli_opt_parse("variogram", help, rows, a, argc, argv))
        exit(0);
    a->in = cli_one_operand("variogram", "input (points .tsv or field .exr)", argc, argv);
    if (a->has_dir != a->has_tol)
        cli_die(2, "%s: expected --direction and --angle-tolerance together, got only %s",
                a->has_dir ? "--angle-tolerance" : "--direction", a->has_dir ? "--direction" : "--angle-tolerance");
    if (a->has_dir && !isfinite(a->o.direction))
        cli_die(2, "--direction: expected a finite angle in degrees, got %g", a->o.direction);
    a->o.directional = a->has_dir;
    if (a->drift)
        cli_drift_parse(a->drift, "DATA.tsv", &a->terms);
    if ((a->terms.poly || a->terms.axes || a->terms.ncov) && !cli_has_ext(a->in, ".tsv"))
        cli_die(2, "--drift: expected points (a .tsv), got the field \"%s\" (sample it first)", a->in);
    if (a->out && !cli_has_ext(a->out, ".tsv"))
        cli_die(2, "-o: expected a .tsv file, got \"%s\"", a->out);
}

/* --drift: the table's points and covariate columns (others allowed),
 * the variogram of the drift's residuals. */
static int table_variogram(const opts_t *a, nl_variogram **v)
{
    nl_table *t;
    nl_points p;
    nl_variogram_options o = a->o;
    int st;
    if ((st = nl_table_read(a->in, &t)) || (st = nl_table_points(t, "value", &p.dim, &p.pts, &p.val)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s", nl_errmsg());
    p.n = t->n;
    double *cov = cli_drift_columns(t, a->terms.ncov, a->terms.cov);
    o.drift = cli_drift_poly(&a->terms, a->drift, p.dim);
    st = nl_variogram_points_design(&p, cov, a->terms.ncov, &o, v);
    free(cov), free(p.pts), free(p.val);
    nl_table_free(t);
    return st;
}

static nl_variogram *compute(const opts_t *a)
{
    nl_variogram *v;
    int st;
    if (a->drift && cli_has_ext(a->in, ".tsv"))
        st = table_variogram(a, &v);
    else if (cli_has_ext(a->in, ".tsv")) {
        nl_points *p;
        if ((st = nl_points_read(a->in, &p)))
            cli_die(nl_error_is_input(st) ? 2 : 1, "%s", nl_errmsg());
        st = nl_variogram_points(p, &a->o, &v);
        nl_points_free(p);
    } else {
        nl_field *f = cli_read_field(a->in, NULL);
        st = nl_variogram_field(f, &a->o, &v);
        nl_field_free(f);
    }
    if (st)
        cli_die(nl_error_is_input(st) || st == NL_EINVAL ? 2 : 1, "%s: %s", a->in, nl_errmsg());
    return v;
}

int cli_cmd_variogram(int argc, char **argv)
{
    opts_t a = {0};
    parse(argc, argv, &a);
    const char *tmp = cli_out_begin(a.out);
    nl_variogram *v = compute(&a);
    const char *names[] = {"distance", "gamma", "pairs"};
    const double *cols[] = {v->distance, v->gamma, v->pairs};
    if (a.out || !a.json) {
        cli_check(cli_write_table(tmp, NULL, 3, names, v->nbins, cols));
        cli_out_commit(a.out);
    }
    if (a.json)
        cli_json_print(json_pack("{s:o,s:o,s:o}", "distance", cli_json_array(v->distance, v->nbins), "gamma",
                                 cli_json_array(v->gamma, v->nbins), "pairs", cli_json_array(v->pairs, v->nbins)));
    nl_variogram_free(v);
    return 0;
}
