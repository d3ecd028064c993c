/* noiselab acf: estimate the autocorrelation of a field. */
#include "cli.h"
#include "dist_inputs.h"
#include "inputs.h"
#include "../analysis/acf.h"
#include "../analysis/ensemble.h"
#include "../analysis/fftshift.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab acf IN...|--realizations K --acf SPEC --size N [--seed S]\n"
    "                    [--max-lag L] [--axis x|y|z] [--radial] [--unbiased]\n"
    "                    [--mean M] [--target SPEC] [--json] [-o OUT.tsv|OUT.exr]\n\n"
    "Estimates the autocorrelation of IN (EXR, PNG or 1D TSV) by FFT with zero\n"
    "padding.  Lags are in length units (index times spacing).  Biased estimate\n"
    "(divisor N) by default; --unbiased divides by the number of overlapping\n"
    "pairs.  The sample mean is removed unless --mean gives the known mean.\n\n"
    "  --max-lag L   largest lag, a length (default a quarter of the axis's length)\n"
    "  --axis        lag direction for 2D/3D fields (default x)\n"
    "  --radial      average over directions, bins of one sample spacing\n"
    "  --target SPEC add the model's R at each lag (radial: at lag (r, 0, 0))\n"
    "  --direct      the direct sum of eq. (15) instead of the FFT (same numbers to rounding)\n"
    "  --bands       1D: a 95% band lo, hi from Bartlett's formula for the variance of the\n"
    "                (biased) estimate, with the estimate in place of R up to 4 max-lag\n"
    "  --json        {\"lag\": [...], \"acf\": [...], ...} on stdout: every number of the table\n"
    "  -o            TSV with columns lag, acf[, se][, target][, lo, hi] (default: TSV on\n"
    "                stdout), or .exr: the 2D/3D estimate with lag 0 at the centre, every\n"
    "                lag or with --max-lag L the lags -L..L of each axis (a picture of\n"
    "                the ACF: noiselab render OUT.exr --axes lags)\n\n"
    "Several inputs (fields of one size and spacing, e.g. realizations with\n"
    "different seeds) make an ensemble: acf is the mean of their estimates and\n"
    "se its standard error (their scatter over the square root of their\n"
    "number), to set one realization's wander against the target.  --bands and\n"
    "-o OUT.exr take one input.  --realizations K --acf SPEC --size N [--seed S]\n"
    "analyses, in place of files, the K fields of noiselab synth fft --acf SPEC\n"
    "--size N with seeds S (default 1) to S + K - 1.\n\n"
    "Under mpirun with one .h5 input, each process reads and transforms its\n"
    "slab of the field (FFTW-MPI) and rank 0 prints the same table; --direct,\n"
    "--bands, -o OUT.exr and a spectral --target are refused there.\n";

/* Options of noiselab acf. */
typedef struct {
    cli_inputs src;                      /* files or realizations */
    size_t nin;                          /* their number (2 or more: an ensemble) */
    const char *in0, *out, *tmp, *target; /* first input's name, output (and its temporary), model */
    double maxlag, mean;                 /* NAN: default */
    int axis, radial, unbiased, json, direct, bands;
    size_t nl;                           /* lags 0 .. nl - 1 */
} acf_opts;

static const char *const axes[] = {"x", "y", "z", NULL};

static const cli_opt rows[] = {
    CLI_DOUBLE("max-lag", acf_opts, maxlag, .flags = CLI_RANGE_LO, .lo = 0, .what = "a non-negative lag"),
    CLI_CHOICE("axis", acf_opts, axis, .choices = axes), CLI_FLAG("radial", acf_opts, radial),
    CLI_FLAG("unbiased", acf_opts, unbiased), CLI_DOUBLE("mean", acf_opts, mean),
    CLI_STRING("target", acf_opts, target), CLI_OPT_JSON(acf_opts, json), CLI_OPT_OUTPUT(acf_opts, out),
    CLI_FLAG("direct", acf_opts, direct), CLI_FLAG("bands", acf_opts, bands),
    CLI_GROUP(cli_inputs_rows, acf_opts, src), {0}};

static void parse(int argc, char **argv, acf_opts *o)
{
    o->maxlag = o->mean = NAN;
    if (cli_opt_parse("acf", help, rows, o, argc, argv))
        exit(0);
    cli_inputs_operands(&o->src, "acf", argc, argv);
    o->nin = o->src.count;
    if (o->nin > 1 && (o->bands || (o->out && cli_has_ext(o->out, ".exr"))))
        cli_die(2, "acf: %s takes one input file, got %zu", o->bands ? "--bands" : "-o OUT.exr", o->nin);
}

/* Checks that need the field; sets the number of lags. */
static void check_field(acf_opts *o, const nl_field *x)
{
    if (o->axis >= x->dim)
        cli_die(2, "--axis: the field is %dD, got axis \"%c\"", x->dim, 'x' + o->axis);
    if (o->radial && x->dim == 1)
        cli_die(2, "--radial: expected a 2D or 3D field, %s is 1D", o->in0);
    if (isnan(o->maxlag))
        o->nl = x->n[o->axis] / 4;
    else if (!(o->maxlag / x->h[o->axis] < (double)x->n[o->axis]) ||
             (o->nl = (size_t)floor(o->maxlag / x->h[o->axis] + 1e-9)) >= x->n[o->axis])
        cli_die(2, "--max-lag: expected at most %g for %zu samples, got %g",
                (double)(x->n[o->axis] - 1) * x->h[o->axis], x->n[o->axis], o->maxlag);
    o->nl += 1;
}

/* The centred estimate C cut to lags -L_a..L_a per axis, L_a = max-lag
 * over h_a (at most n_a - 1): lag 0 stays at the centre. */
static nl_field *crop(const nl_field *C, double maxlag)
{
    size_t n[3] = {1, 1, 1}, off[3] = {0, 0, 0};
    for (int a = 0; a < C->dim; a++) {
        size_t half = (C->n[a] - 1) / 2, L = (size_t)floor(maxlag / C->h[a] + 1e-9);
        L = L < half ? L : half;
        n[a] = 2 * L + 1, off[a] = half - L;
    }
    nl_field *out = cli_field_alloc(C->dim, n, C->h);
    for (size_t k = 0; k < n[2]; k++)
        for (size_t j = 0; j < n[1]; j++)
            for (size_t i = 0; i < n[0]; i++)
                out->data[(k * n[1] + j) * n[0] + i] =
                    C->data[((k + off[2]) * C->n[1] + j + off[1]) * C->n[0] + i + off[0]];
    return out;
}

/* The whole estimate, or with --max-lag its lags -L..L, lag 0 at the
 * centre, to EXR. */
static void write_centred(const acf_opts *o, const nl_field *full)
{
    nl_field *C;
    nl_meta meta = {0};
    cli_check(nl_acf_centred_alloc(full, &C));
    if (!isnan(o->maxlag)) {
        nl_field *cut = crop(C, o->maxlag);
        nl_field_free(C);
        C = cut;
    }
    for (size_t i = 0; i < C->count; i++)
        if (!(fabs(C->data[i]) <= FLT_MAX))
            cli_die(2, "-o: the estimate %g does not fit the float32 samples of \"%s\"; expected |acf| <= %g "
                    "(scale the input)", C->data[i], o->out, FLT_MAX);
    snprintf(meta.method, sizeof meta.method, "acf %s, lag 0 at the centre", o->unbiased ? "unbiased" : "biased");
    cli_write_field(o->out, o->tmp, C, &meta);
    cli_out_commit(o->out);
    nl_field_free(C);
}

/* Lags and estimates (and the band) along the axis or radially. */
static void estimate(const acf_opts *o, const nl_field *x, const nl_field *full, double *lag, double *val,
                     double *blo, double *bhi)
{
    size_t nl = o->nl, *cnt = cli_malloc(nl * sizeof *cnt);
    int st;
    if (o->direct) {
        st = nl_acf_direct(x, o->mean, o->unbiased, o->axis, nl - 1, val);
        for (size_t i = 0; i < nl; i++)
            lag[i] = (double)i * x->h[o->axis];
    } else if (o->radial) {
        st = nl_acf_radial(full, nl, lag, val, cnt);
    } else {
        st = nl_acf_axis(full, o->axis, nl - 1, lag, val);
    }
    cli_check(st);
    if (o->bands) {
        if ((x->n[0] < 4 * (nl - 1) + 1 ? x->n[0] : 4 * (nl - 1) + 1) < 2 * (nl - 1) + 1)
            cli_die(2, "--bands: expected a field of at least %zu samples for --max-lag %zu", 2 * (nl - 1) + 1, nl - 1);
        cli_check(nl_acf_bartlett_band(full, x->count, nl - 1, val, blo, bhi));
    }
    free(cnt);
}

static void target_values(const acf_opts *o, const nl_field *x, const double *lag, double *tgt)
{
    nl_model *m;
    int st;
    if ((st = nl_model_parse(o->target, &m)) ||
        (st = nl_acf_model_values(m, x->dim, x->n, x->h, o->radial ? 0 : o->axis, lag, o->nl, tgt)))
        cli_die_status(st);
    nl_model_free(m);
}

/* The index of the first lag at which the target is not finite, or -1. */
static long target_not_finite(const acf_opts *o, const double *lag, const double *tgt)
{
    for (size_t i = 0; i < o->nl; i++)
        if (!isfinite(tgt[i]) && !isnan(lag[i]))
            return (long)i;
    return -1;
}

static void output(const acf_opts *o, const double *lag, const double *val, const double *se, const double *tgt,
                   const double *blo, const double *bhi)
{
    size_t nl = o->nl;
    if (o->json) {
        json_t *j = json_pack("{s:o,s:o}", "lag", cli_json_array(lag, nl), "acf", cli_json_array(val, nl));
        if (se) {
            json_object_set_new(j, "se", cli_json_array(se, nl));
            json_object_set_new(j, "fields", json_integer((json_int_t)o->nin));
        }
        if (tgt)
            json_object_set_new(j, "target", cli_json_array(tgt, nl));
        if (o->bands) {
            json_object_set_new(j, "band_lo", cli_json_array(blo, nl));
            json_object_set_new(j, "band_hi", cli_json_array(bhi, nl));
        }
        json_object_set_new(j, "estimator", json_string(o->unbiased ? "unbiased" : "biased"));
        json_object_set_new(j, "direction", json_string(o->radial ? "radial" : (const char *[]){"x", "y", "z"}[o->axis]));
        cli_json_print(j);
    }
    if (o->out || !o->json) {
        const char *names[5] = {"lag", "acf"};
        const double *cols[5] = {lag, val};
        int ncol = 2;
        char comment[256];
        if (se)
            names[ncol] = "se", cols[ncol++] = se;
        if (tgt)
            names[ncol] = "target", cols[ncol++] = tgt;
        if (o->bands)
            names[ncol] = "lo", cols[ncol++] = blo, names[ncol] = "hi", cols[ncol++] = bhi;
        snprintf(comment, sizeof comment, "noiselab acf: %s estimate, %s, lags in length units (index times spacing)%s",
                 o->unbiased ? "unbiased" : "biased", o->radial ? "radial average" : "along one axis",
                 se ? ", mean over the fields with its standard error" : "");
        cli_check(cli_write_table(o->out ? o->tmp : NULL, comment, ncol, names, nl, cols));
    }
    cli_out_commit(o->out);
}

/* An ensemble: the mean and standard error of every input's estimate
 * (val holds the first one's on entry). */
static void ensemble(acf_opts *o, const nl_field *x0, double *lag, double *val, double *se)
{
    cli_ensemble e = {&o->src, x0};
    nl_ensemble_source src = cli_inputs_source(&e);
    nl_ensemble_acf_opts eo = {o->mean, o->unbiased, o->axis, o->radial, o->direct, o->nl};
    size_t bad;
    int st = nl_ensemble_acf(&src, &eo, lag, val, se, &bad);
    if (st == NL_ETOOBIG && bad == o->nin)
        cli_die(2, "acf: %zu estimates of %zu lags do not fit in the memory available; expected fewer inputs", o->nin,
                o->nl);
    if (st && bad < o->nin)
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", cli_inputs_name(&o->src, bad), nl_errmsg());
    cli_check(st);
}

/* The target (when asked) and the output. */
static void report(const acf_opts *o, const nl_field *x, const double *lag, const double *val, const double *se,
                   double *tgt, const double *blo, const double *bhi)
{
    if (o->target)
        target_values(o, x, lag, tgt);
    long bad = o->target ? target_not_finite(o, lag, tgt) : -1;
    if (bad >= 0)
        cli_die(2, "--target: %s is %g at lag %g; expected a model finite at every lag of the estimate", o->target,
                tgt[bad], lag[bad]);
    output(o, lag, val, se, tgt, blo, bhi);
}

/* Under an MPI launcher with one .h5 input: the estimate over every
 * process's slab (cli/dist_inputs.h); rank 0 writes it.  A spectral target
 * is refused: it is sampled on a grid of the field's padded size. */
static int distributed(acf_opts *o)
{
    cli_slab s;
    nl_field hdr;
    nl_model *m;
    double *lag, *val, *tgt = NULL;
    if (o->direct || o->bands || (o->out && cli_has_ext(o->out, ".exr")))
        cli_dist_refuse("acf", o->direct ? "--direct" : o->bands ? "--bands" : "-o OUT.exr");
    if (o->target) {
        cli_check(nl_model_parse(o->target, &m));
        int spectral = nl_model_is_spectral(m);
        nl_model_free(m);
        if (spectral)
            cli_dist_refuse("acf", "--target with a spectral model");
    }
    cli_dist_read(&o->src, &s, &hdr);
    o->in0 = o->src.files[0];
    check_field(o, &hdr);
    lag = cli_malloc(o->nl * sizeof *lag), val = cli_malloc(o->nl * sizeof *val);
    cli_dist_check(&o->src, cli_h5->acf(&s, o->mean, o->unbiased, o->radial, o->axis, o->nl, lag, val));
    cli_dist_free(&s);
    if (cli_dist_leader()) {
        o->tmp = cli_out_begin(o->out);
        if (o->target)
            tgt = cli_malloc(o->nl * sizeof *tgt);
        report(o, &hdr, lag, val, NULL, tgt, NULL, NULL);
    }
    free(lag), free(val), free(tgt);
    return 0;
}

int cli_cmd_acf(int argc, char **argv)
{
    acf_opts o = {0};
    double *lag, *val, *se = NULL, *tgt = NULL, *blo = NULL, *bhi = NULL;
    nl_field *x, *full;
    int st;

    parse(argc, argv, &o);
    if (cli_dist_wanted(&o.src, "acf"))
        return distributed(&o);
    x = cli_inputs_read(&o.src, 0, NULL);
    o.in0 = o.src.K ? "the realizations" : o.src.files[0];
    check_field(&o, x);
    o.tmp = cli_out_begin(o.out);
    if ((st = nl_acf_full(x, o.mean, o.unbiased, &full)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", o.in0, nl_errmsg());
    if (o.out && cli_has_ext(o.out, ".exr")) {
        write_centred(&o, full);
        nl_field_free(full), nl_field_free(x);
        return 0;
    }
    if ((o.direct || o.bands) && o.radial)
        cli_die(2, "acf: --direct and --bands go with an axis, not --radial");
    if (o.bands && (x->dim != 1 || o.unbiased))
        cli_die(2, "acf: --bands is for the biased estimate of a 1D field");
    lag = cli_malloc(o.nl * sizeof *lag), val = cli_malloc(o.nl * sizeof *val);
    if (o.bands)
        blo = cli_malloc(o.nl * sizeof *blo), bhi = cli_malloc(o.nl * sizeof *bhi);
    if (o.target)
        tgt = cli_malloc(o.nl * sizeof *tgt);
    estimate(&o, x, full, lag, val, blo, bhi);
    if (o.nin > 1) {
        se = cli_malloc(o.nl * sizeof *se);
        ensemble(&o, x, lag, val, se);
    }
    report(&o, x, lag, val, se, tgt, blo, bhi);
    free(lag), free(val), free(tgt), free(blo), free(bhi), free(se);
    nl_field_free(full);
    nl_field_free(x);
    cli_inputs_free(&o.src);
    return 0;
}
