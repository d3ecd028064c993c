/* noiselab psd: estimate the power spectral density of a field. */
#include "cli.h"
#include "dist_inputs.h"
#include "inputs.h"
#include "slope_band.h"
#include "../analysis/ensemble.h"
#include "../analysis/fftshift.h"
#include "../analysis/psd.h"
#include "../analysis/slope.h"
#include "../analysis/spectral.h"
#include "../analysis/welch.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab psd IN...|--realizations K --acf SPEC --size N [--seed S]\n"
    "                    [--radial] [--mean M] [--welch S] [--target SPEC] [--slope F1:F2]\n"
    "                    [--angular] [--json] [-o OUT.tsv|OUT.exr] [--preview P.png]\n\n"
    "Periodogram of IN (EXR, PNG or 1D TSV): P(f) = (h/N) |DFT(x - mean)|^2, a\n"
    "TWO-SIDED density in variance per (cycles per unit length)^dim, so that the sum\n"
    "of P over all grid frequencies times the frequency cell is the mean square.\n"
    "1D fields give f = 0 .. Nyquist; 2D and 3D fields give the radial average in\n"
    "bins one frequency step wide.\n\n"
    "  --mean M      known mean to remove (default: the sample mean)\n"
    "  --welch S     Welch's average of Hann-windowed segments of S samples (per axis),\n"
    "                overlapping by half, instead of one periodogram\n"
    "  --angular     2D: mean power in 18 sectors of 10 degrees (0.05 to 0.45 cycles per\n"
    "                sample) and the anisotropy ratio max/min over the sectors\n"
    "  -o OUT.exr    2D: the whole spectrum, zero frequency at the centre\n"
    "  --preview     2D: log10 of the spectrum as an 8-bit picture, centred\n"
    "  --target SPEC add the model's spectrum on the same grid (the spectrum of the\n"
    "                sampled process, aliasing included)\n"
    "  --slope F1:F2 fit log psd = c + slope log f over F1 <= f <= F2: slope, its 95%\n"
    "                confidence interval, and the fractal dimension D = E + (3 - d)/2,\n"
    "                d = -slope in 1D, -slope - (E - 1) in E-D (Lewis 1987, eq. 16, which\n"
    "                is stated for profiles, for 1 < d < 3: a d whose interval lies outside\n"
    "                is flagged, JSON flags flatter-than-eq16 or steeper-than-eq16); in\n"
    "                2D/3D the fit is to every periodogram ordinate in the band (each\n"
    "                Hermitian pair once), not to the radial average, whose interval\n"
    "                would be too narrow.  A field that records its model (a file's\n"
    "                \"model\" provenance, --realizations' --acf) is refused a band\n"
    "                reaching outside the model's (power: fmin..fmax), where its\n"
    "                periodogram holds leakage and rounding alone, which would flatten\n"
    "                the slope; a field made by noiselab shape is not checked\n"
    "  --json        {\"freq\": [...], \"psd\": [...], \"sided\": \"two-sided\", ...} on stdout:\n"
    "                every number of the table and of the comment lines\n"
    "  -o            TSV with columns freq, psd[, se][, target] (default: TSV on stdout)\n\n"
    "Several inputs (fields of one size and spacing, e.g. realizations with\n"
    "different seeds) make an ensemble: psd is the mean of their estimates and\n"
    "se its standard error (the scatter of one estimate over the square root of\n"
    "their number), and --angular, -o OUT.exr and --preview show the mean\n"
    "spectrum.  One periodogram scatters by 100% of its value at every\n"
    "frequency; K realizations or Welch's segments bring that down to about\n"
    "1/sqrt(K).  --slope takes one input.  --realizations K --acf SPEC --size N\n"
    "[--seed S] analyses, in place of files, the K fields of noiselab synth fft\n"
    "--acf SPEC --size N with seeds S (default 1) to S + K - 1.\n\n"
    "Under mpirun with one .h5 input, each process reads and transforms its\n"
    "slab of the field (FFTW-MPI) and rank 0 prints the same results;\n"
    "--welch, --target, --preview and -o OUT.exr are refused there.\n";

/* Options of noiselab psd and what it found. */
typedef struct {
    cli_inputs src;                        /* files or realizations */
    size_t nin;                            /* their number (2 or more: an ensemble) */
    const char *out, *tmp, *target;        /* output (and its temporary), model */
    const char *preview, *pvtmp;           /* picture (and its temporary) */
    double mean, f1, f2;                   /* known mean (NAN: sample), slope band */
    int json, slope, angular;
    int radial;                            /* --radial: nD output is always radial; accepted for clarity */
    size_t welch, nseg;                    /* segment side (0: periodogram), segments */
    double sector[18], aniso;              /* angular sectors */
    nl_slope sl;                           /* slope fit */
} psd_opts;

static void slope_option(void *obj, const char *label, const char *arg)
{
    psd_opts *o = obj;
    char *end;
    o->f1 = strtod(arg, &end);
    if (end == arg || *end != ':' || (o->f2 = strtod(end + 1, &end), *end) || !(o->f1 > 0) || !(o->f2 > o->f1))
        cli_die(2, "%s: expected F1:F2 with 0 < F1 < F2, got \"%s\"", label, arg);
    o->slope = 1;
}

static const cli_opt rows[] = {
    CLI_FLAG("radial", psd_opts, radial), CLI_DOUBLE("mean", psd_opts, mean), CLI_STRING("target", psd_opts, target),
    CLI_OPT_JSON(psd_opts, json), CLI_OPT_OUTPUT(psd_opts, out), CLI_CALL("slope", slope_option),
    CLI_COUNT("welch", psd_opts, welch, .lo = 4), CLI_FLAG("angular", psd_opts, angular),
    CLI_STRING("preview", psd_opts, preview), CLI_GROUP(cli_inputs_rows, psd_opts, src), {0}};

static void parse(int argc, char **argv, psd_opts *o)
{
    o->mean = NAN, o->nseg = 1, o->aniso = NAN;
    if (cli_opt_parse("psd", help, rows, o, argc, argv))
        exit(0);
    cli_inputs_operands(&o->src, "psd", argc, argv);
    o->nin = o->src.count;
    if (o->slope && o->nin > 1)
        cli_die(2, "--slope: expected one input file (the interval is that of one periodogram), got %zu", o->nin);
}

/* The 2D spectrum with zero frequency at the centre: EXR and/or picture. */
static void write_centred(psd_opts *o, const nl_field *P)
{
    nl_field *C;
    cli_check(nl_fftshift_alloc(P, &C));
    if (o->out && cli_has_ext(o->out, ".exr")) {
        nl_meta meta = {0};
        snprintf(meta.method, sizeof meta.method, "psd%s, zero frequency at (%zu, %zu)", o->welch ? " welch" : "",
                 P->n[0] / 2, P->n[1] / 2);
        cli_write_field(o->out, o->tmp, C, &meta);
    }
    if (o->preview) {
        double mx = nl_fftshift_log10_floor(C, 1e-12);
        cli_check(nl_png_write_field(o->pvtmp, C, log10(mx) - 8, log10(mx)));
        cli_out_commit(o->preview);
    }
    nl_field_free(C);
    if (o->out && cli_has_ext(o->out, ".exr")) {
        cli_out_commit(o->out);
        o->out = NULL;
    }
}

/* A JSON number, or null where it is undefined. */
static json_t *num(double v) { return isfinite(v) ? json_real(v) : json_null(); }

/* The estimate's columns. */
typedef struct {
    double *freq, *val, *se, *tgt;  /* frequency, estimate, its standard error (ensembles), model */
    size_t nf;                      /* rows */
} psd_table;

static void print_json(const psd_opts *o, int dim, const psd_table *t)
{
    size_t nf = t->nf;
    json_t *j = json_pack("{s:o,s:o}", "freq", cli_json_array(t->freq, nf), "psd", cli_json_array(t->val, nf));
    if (t->se) {
        json_object_set_new(j, "se", cli_json_array(t->se, nf));
        json_object_set_new(j, "fields", json_integer((json_int_t)o->nin));
    }
    if (t->tgt)
        json_object_set_new(j, "target", cli_json_array(t->tgt, nf));
    json_object_set_new(j, "sided", json_string("two-sided"));
    json_object_set_new(j, "average", json_string(dim == 1 ? "none" : "radial"));
    if (o->angular) {
        json_object_set_new(j, "sectors", cli_json_array(o->sector, 18));
        json_object_set_new(j, "anisotropy", num(o->aniso));
    }
    if (o->welch)
        json_object_set_new(j, "welch_segments", json_integer((json_int_t)o->nseg));
    if (o->slope) {
        int r = nl_slope_fractal_range(&o->sl, dim);
        json_object_set_new(j, "slope", json_pack("{s:o,s:o,s:I,s:o,s:[f,f],s:o}", "slope", num(o->sl.slope), "ci95",
                                                  num(o->sl.ci95), "points", (json_int_t)o->sl.points,
                                                  "fractal_dimension", num(o->sl.fractal_dim), "band", o->f1, o->f2,
                                                  "flags", r ? json_pack("[s]", r < 0 ? "flatter-than-eq16"
                                                                                       : "steeper-than-eq16")
                                                             : json_array()));
    }
    cli_json_print(j);
}

static void output(const psd_opts *o, int dim, const psd_table *t)
{
    int st;
    if (o->json)
        print_json(o, dim, t);
    if (o->angular && !o->json) {
        printf("# sector power (0.05..0.45 cycles/sample), 10-degree sectors from +x:");
        for (int b = 0; b < 18; b++)
            printf(" %.4g", o->sector[b]);
        if (isfinite(o->aniso))
            printf("\n# anisotropy (max/min sector power) %.4f\n", o->aniso);
        else
            printf("\n# anisotropy (max/min sector power) undefined (a sector holds no power)\n");
    }
    if (o->slope && !o->json) {
        int r = nl_slope_fractal_range(&o->sl, dim);
        printf("# slope %.4f +- %.4f (95%%, %zu frequencies in [%g, %g]); fractal dimension "
                "%.4f", o->sl.slope, o->sl.ci95, o->sl.points, o->f1, o->f2, o->sl.fractal_dim);
        if (r)
            printf(" (outside eq. 16, which holds for 1 < d < 3: d = %.4f, %s)", -o->sl.slope - (dim - 1),
                   r < 0 ? "a flatter spectrum, whose graph fills its space" : "a steeper spectrum, whose graph is "
                   "smooth, D = E");
        printf("\n");
    }
    if (o->out || (!o->json && !o->angular && !o->preview)) {
        const char *names[4] = {"freq", "psd"};
        const double *cols[4] = {t->freq, t->val};
        int nc = 2;
        char comment[400], welch[200];
        if (t->se)
            names[nc] = "se", cols[nc++] = t->se;
        if (t->tgt)
            names[nc] = "target", cols[nc++] = t->tgt;
        snprintf(welch, sizeof welch, "Welch density (Welch's average of the periodograms of %zu Hann-windowed, "
                 "half-overlapping segments of %zu samples per axis)", o->nseg, o->welch);
        snprintf(comment, sizeof comment, "noiselab psd: two-sided %s%s, freq in cycles per unit%s",
                 o->welch ? welch : "periodogram density", dim == 1 ? "" : ", radial average",
                 t->se ? ", mean over the fields with its standard error" : "");
        st = cli_write_table(o->out ? o->tmp : NULL, comment, nc, names, t->nf, cols);
        cli_check(st);
    }
    cli_out_commit(o->out);
}

/* The model's profile on the estimate's grid P (the field's for a
 * periodogram, S samples per axis for Welch), so that row i of the target
 * stands for the same frequency as row i of the estimate. */
static void target_profile(const psd_opts *o, const nl_field *P, double *tgt)
{
    nl_model *m;
    size_t nt;
    int st;
    if ((st = nl_model_parse(o->target, &m)) || (st = nl_psd_model_profile(m, P->dim, P->n, P->h, tgt, &nt)))
        cli_die_status(st);
    nl_model_free(m);
}

/* The periodogram or Welch estimate of input k. */
static nl_field *estimate(psd_opts *o, size_t k, const nl_field *x)
{
    nl_field *P;
    int st;
    if (o->welch && (st = nl_psd_welch(x, o->welch, o->mean, &P, &o->nseg)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: --welch %zu: %s", cli_inputs_name(&o->src, k), o->welch, nl_errmsg());
    if (!o->welch && (st = nl_psd_periodogram(x, o->mean, &P)))
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", cli_inputs_name(&o->src, k), nl_errmsg());
    return P;
}

/* An ensemble: the mean estimate in place of *P (the first one's), and
 * the mean and standard error of the profiles into t. */
static void ensemble(psd_opts *o, const nl_field *x0, nl_field **P, psd_table *t)
{
    cli_ensemble e = {&o->src, x0};
    nl_ensemble_source src = cli_inputs_source(&e);
    nl_ensemble_psd_opts eo = {o->mean, o->welch};
    nl_field *mean;
    size_t bad;
    int st;
    t->se = cli_malloc((x0->n[0] + x0->n[1] + x0->n[2]) * sizeof *t->se);
    st = nl_ensemble_psd(&src, &eo, &mean, t->freq, t->val, t->se, &t->nf, &o->nseg, &bad);
    if (st == NL_ETOOBIG && bad == o->nin)
        cli_die(2, "psd: %zu estimates of %zu frequencies do not fit in the memory available; expected fewer inputs",
                o->nin, nl_psd_profile_size(*P));
    if (st && bad < o->nin && o->welch)
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: --welch %zu: %s", cli_inputs_name(&o->src, bad), o->welch,
                nl_errmsg());
    if (st && bad < o->nin)
        cli_die(nl_error_is_input(st) ? 2 : 1, "%s: %s", cli_inputs_name(&o->src, bad), nl_errmsg());
    cli_check(st);
    nl_field_free(*P);
    *P = mean;
}

/* Under an MPI launcher with one .h5 input: the periodogram's profile
 * (and sectors) over every process's slab (cli/dist_inputs.h); rank 0
 * writes it.  What needs the whole spectrum on one process is refused. */
static int distributed(psd_opts *o)
{
    cli_slab s;
    nl_field hdr;
    psd_table t = {0};
    size_t maxn;
    char msg[512];
    int st;
    if (o->welch || o->preview || o->target || (o->out && cli_has_ext(o->out, ".exr")))
        cli_dist_refuse("psd", o->welch ? "--welch" : o->preview ? "--preview" : o->target ? "--target" : "-o OUT.exr");
    cli_dist_read(&o->src, &s, &hdr);
    if (o->slope) { /* every process alike */
        nl_meta meta;
        cli_check(cli_h5_read_meta(o->src.files[0], &meta));
        cli_slope_band_check("psd", "--slope", o->f1, o->f2, cli_meta_model(&meta), hdr.dim);
    }
    if (o->angular && hdr.dim != 2)
        cli_die(2, "psd: --angular, --preview and EXR output need a 2D field, %s is %dD", o->src.files[0], hdr.dim);
    maxn = hdr.n[0] + hdr.n[1] + hdr.n[2];
    t.freq = cli_malloc(maxn * sizeof *t.freq), t.val = cli_malloc(maxn * sizeof *t.val);
    st = cli_h5->psd(&s, o->mean, t.freq, t.val, &t.nf, 18, 0.05, 0.45, o->angular ? o->sector : NULL, &o->aniso,
                     o->slope ? (double[]){o->f1, o->f2} : NULL, &o->sl);
    snprintf(msg, sizeof msg, "%s", nl_errmsg());
    /* as one process: the estimate's failure names the file, the fit's --slope */
    cli_dist_check(&o->src, st && o->slope ? cli_h5->psd(&s, o->mean, t.freq, t.val, &t.nf, 0, 0, 0, NULL, NULL,
                                                         NULL, NULL) : st);
    cli_dist_free(&s);
    if (cli_dist_leader()) {
        o->tmp = cli_out_begin(o->out);
        if (o->slope && st == NL_OK && !(isfinite(o->sl.slope) && isfinite(o->sl.ci95)))
            st = NL_ERROR(NL_EINVAL, "the fit is undefined (slope %g +- %g); expected a band where the periodogram "
                          "varies", o->sl.slope, o->sl.ci95);
        else if (o->slope && st)
            nl_error_set(st, __FILE__, __LINE__, "%s", msg);
        if (o->slope && st)
            cli_die(nl_error_is_input(st) ? 2 : 1, "--slope %g:%g: %s", o->f1, o->f2, nl_errmsg());
        output(o, hdr.dim, &t);
    }
    free(t.freq), free(t.val);
    return 0;
}

int cli_cmd_psd(int argc, char **argv)
{
    psd_opts o = {0};
    psd_table t = {0};
    size_t maxn, *cnt;
    nl_field *x, *P;
    int st;

    parse(argc, argv, &o);
    if (cli_dist_wanted(&o.src, "psd"))
        return distributed(&o);
    x = cli_inputs_read(&o.src, 0, NULL);
    if (o.slope)
        cli_slope_band_check("psd", "--slope", o.f1, o.f2, cli_inputs_model(&o.src), x->dim);
    if ((o.angular || o.preview || (o.out && cli_has_ext(o.out, ".exr"))) && x->dim != 2)
        cli_die(2, "psd: --angular, --preview and EXR output need a 2D field, %s is %dD", cli_inputs_name(&o.src, 0), x->dim);
    if (o.preview && !cli_has_ext(o.preview, ".png"))
        cli_die(2, "--preview: expected a .png file, got \"%s\"", o.preview);
    o.tmp = cli_out_begin(o.out);
    o.pvtmp = cli_out_begin(o.preview);
    P = estimate(&o, 0, x);
    maxn = x->n[0] + x->n[1] + x->n[2];
    t.freq = cli_malloc(maxn * sizeof *t.freq), t.val = cli_malloc(maxn * sizeof *t.val);
    cnt = cli_malloc(maxn * sizeof *cnt);
    t.nf = nl_psd_profile_size(P);
    if (o.nin > 1)
        ensemble(&o, x, &P, &t);
    if ((o.out && cli_has_ext(o.out, ".exr")) || o.preview)
        write_centred(&o, P);
    if (o.angular && (st = nl_psd_sectors(P, 18, 0.05, 0.45, o.sector, &o.aniso)))
        cli_die_status(st);
    if (o.target)
        t.tgt = cli_malloc(maxn * sizeof *t.tgt);
    if (o.target)
        target_profile(&o, P, t.tgt);
    if (o.nin == 1)
        cli_check(nl_psd_profile(P, t.freq, t.val, cnt, &t.nf));
    if (o.slope && (st = x->dim == 1 ? nl_psd_slope(t.freq, t.val, t.nf, o.f1, o.f2, 1, &o.sl)
                                     : nl_psd_slope_grid(P, o.f1, o.f2, &o.sl)) == NL_OK &&
        !(isfinite(o.sl.slope) && isfinite(o.sl.ci95)))
        st = NL_ERROR(NL_EINVAL, "the fit is undefined (slope %g +- %g); expected a band where the periodogram "
                      "varies", o.sl.slope, o.sl.ci95);
    if (o.slope && st) {
        free(t.freq), free(t.val), free(cnt), free(t.tgt), free(t.se);
        nl_field_free(P), nl_field_free(x);
        cli_die(nl_error_is_input(st) ? 2 : 1, "--slope %g:%g: %s", o.f1, o.f2, nl_errmsg());
    }
    output(&o, x->dim, &t);
    free(t.freq), free(t.val), free(cnt), free(t.tgt), free(t.se);
    nl_field_free(P);
    nl_field_free(x);
    cli_inputs_free(&o.src);
    return 0;
}
