/* noiselab nonlin: predicted ACF and spectrum after a memoryless nonlinearity. */
#include "cli.h"
#include "opt.h"
#include "../core/field.h"
#include "../analysis/nonlin.h"
#include "../core/model.h"
#include "../core/wk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab nonlin --acf SPEC --g DIST [--size N] [--spacing H] [--terms K]\n"
    "                       [--json] [-o ACF.tsv] [--psd PSD.tsv]\n\n"
    "Predicts what the shaping y = F_DIST^-1(Phi(x / sd)) (noiselab shape), or any\n"
    "memoryless nonlinearity y = G(x / sd) given as --g expr:G (a function of x, e.g.\n"
    "expr:x^2, expr:exp(x), expr:2*step(x)-1; its Hermite coefficients by adaptive\n"
    "quadrature, which finds jumps and kinks), does to a\n"
    "Gaussian input with autocorrelation SPEC (Beckmann's Hermite series, GI '86\n"
    "section 4.1): output ACF sum_n c_n^2 n! rho^n and its spectrum, the sum of\n"
    "n-fold self-convolutions of the input's, on a periodic 1D grid of N samples\n"
    "(default 4096) at spacing H (default 1); K Hermite terms (default 24).\n"
    "JSON keys: lag, input_acf, output_acf, freq, input_psd, output_psd,\n"
    "hermite_coefficients, output_mean, output_variance, truncation.\n\n"
    "noiselab nonlin --design --target SPEC --g DIST [--size N] [--spacing H] [--verify M]\n"
    "                [--json] [-o DESIGN.tsv]\n"
    "The inverse: the Gaussian input whose output after g has the autocorrelation\n"
    "SPEC (its shape; rescaled to g's output variance): the series inverted lag by\n"
    "lag, then projected onto the nearest valid spectrum.  --verify M synthesises M\n"
    "inputs (seeds 1..M) from the design, shapes them with g and measures the output\n"
    "ACF.  Output: lag, target, designed input_acf, predicted output, measured output.\n";

/* The command's options. */
typedef struct {
    const char *spec, *gspec, *out, *pout, *tspec;  /* as given, or NULL */
    size_t n, verify;                               /* --size, --verify */
    double h;                                       /* --spacing */
    int K, json, design;                            /* --terms, --json, --design */
} opts_t;

static const cli_opt rows[] = {
    CLI_STRING("acf", opts_t, spec), CLI_STRING("g", opts_t, gspec), CLI_COUNT("size", opts_t, n, .lo = 16),
    CLI_POSITIVE("spacing", opts_t, h, .what = "number"), CLI_INT("terms", opts_t, K, .lo = 2),
    CLI_OPT_JSON(opts_t, json), CLI_FLAG("design", opts_t, design), CLI_STRING("target", opts_t, tspec),
    CLI_COUNT("verify", opts_t, verify, .lo = 1), CLI_OPT_OUTPUT(opts_t, out), CLI_STRING("psd", opts_t, pout), {0}};

static void parse(int argc, char **argv, opts_t *a)
{
    if (cli_opt_parse("nonlin", help, rows, a, argc, argv))
        exit(0);
    cli_no_operands("nonlin", argc, argv);
    if (a->design) {
        if (a->spec)
            cli_die(2, "nonlin --design: --acf: not taken by --design (the wanted output is --target), got \"%s\"",
                    a->spec);
        if (!a->tspec)
            cli_die(2, "nonlin --design: --target: expected the wanted output model (see noiselab models)");
        if (!a->gspec)
            cli_die(2, "nonlin --design: --g: expected a distribution (e.g. --g laplace)");
        a->spec = a->tspec;
        if (a->pout)
            cli_die(2, "--psd: not written by --design (its table goes to -o), got \"%s\"", a->pout);
    } else if (!a->spec)
        cli_die(2, "nonlin: --acf: expected the input's autocorrelation model (see noiselab models)");
    else if (!a->gspec)
        cli_die(2, "nonlin: --g: expected a distribution (e.g. --g laplace)");
    else if (a->verify)
        cli_die(2, "--verify: goes with --design, got --verify %zu without it", a->verify);
    if (a->verify > 1000)
        cli_die(2, "--verify: expected at most 1000 realizations, got %zu", a->verify);
    if (a->K > NL_HERMITE_MAX)
        cli_die(2, "--terms: expected at most %d, got %d", NL_HERMITE_MAX, a->K);
    if (a->n > (1u << 24))
        cli_die(2, "--size: expected at most 16777216, got %zu", a->n);
    /* about eight arrays of n samples live at once (fields, spectra, FFT scratch) */
    if (nl_size_check(1, &a->n, sizeof(double), 8, NULL))
        cli_die(2, "--size %zu: eight arrays of that many samples do not fit in the memory available", a->n);
}

/* The design's columns (nl2 lags) and figures. */
typedef struct {
    size_t nl2, bad;                           /* lags written; unreachable lags */
    double *lag, *tg, *rho, *pred, *meas;      /* columns (meas NULL without --verify) */
    double err, merr;                          /* projection and measured errors */
} design_t;

static void print_design(const opts_t *a, const nl_hermite *he, const design_t *r, const char *tmp)
{
    size_t nl2 = r->nl2;
    if (a->json) {
        json_t *o = json_pack("{s:s,s:s,s:o,s:o,s:o,s:o,s:f,s:I,s:o}", "target", a->tspec, "g", a->gspec, "lag",
                              cli_json_array(r->lag, nl2), "target_acf", cli_json_array(r->tg, nl2), "input_acf",
                              cli_json_array(r->rho, nl2), "predicted_output_acf", cli_json_array(r->pred, nl2),
                              "projection_error", r->err, "unreachable_lags", (json_int_t)r->bad,
                              "hermite_coefficients", cli_json_array(he->c, (size_t)a->K));
        if (a->verify)
            json_object_set_new(o, "measured_output_acf", cli_json_array(r->meas, nl2)),
                json_object_set_new(o, "measured_error", isfinite(r->merr) ? json_real(r->merr) : json_null());
        cli_json_print(o);
    } else {
        printf("# design for %s after %s: projection error %.3g of the output variance, %zu unreachable lags",
               a->tspec, a->gspec, r->err, r->bad);
        if (a->verify)
            printf("; measured over %zu realizations: %.3g", a->verify, r->merr);
        printf("\n");
    }
    if (a->out || !a->json) {
        const char *names[5] = {"lag", "target", "input_acf", "predicted", "measured"};
        const double *cols[5] = {r->lag, r->tg, r->rho, r->pred, r->meas};
        cli_check(cli_write_table(tmp, "noiselab nonlin --design: covariances; input_acf is normalised",
                        a->verify ? 5 : 4, names, nl2, cols));
        cli_out_commit(a->out);
    }
}

static void design(const opts_t *a, const nl_model *m, const nl_dist *d, const nl_hermite *he, const char *tmp)
{
    size_t n = a->n;
    double h = a->h;
    int st;
    design_t r = {.nl2 = n / 2 + 1 < 129 ? n / 2 + 1 : 129, .merr = NAN};
    nl_field *T = nl_field_alloc(1, &n, &h, &st), *S = T ? nl_field_alloc(1, &n, &h, &st) : NULL;
    double var = nl_hermite_cov(he, 1);
    r.rho = malloc(n * sizeof *r.rho);
    if (!S || !r.rho)
        cli_die(1, "out of memory");
    if ((st = nl_wk_sample_acf(m, T)) || (st = nl_nonlin_design(he, T->data, n, h, r.rho, S->data, &r.err, &r.bad)))
        cli_die_status(st);
    double scale = var / T->data[0];
    if (a->verify) {
        r.meas = cli_malloc(r.nl2 * sizeof *r.meas);
        cli_check(nl_nonlin_verify(S, d, a->verify, r.nl2, r.meas));
        r.merr = nl_nonlin_max_deviation(r.meas, T->data, r.nl2, scale, var);
    }
    r.lag = cli_malloc(r.nl2 * sizeof *r.lag), r.tg = cli_malloc(r.nl2 * sizeof *r.tg);
    r.pred = cli_malloc(r.nl2 * sizeof *r.pred);
    for (size_t i = 0; i < r.nl2; i++)
        r.lag[i] = (double)i * h, r.tg[i] = T->data[i] * scale;
    nl_nonlin_output_acf(he, r.rho, r.nl2, 1, r.pred);
    print_design(a, he, &r, tmp);
    free(r.lag), free(r.tg), free(r.pred), free(r.rho), free(r.meas);
    nl_field_free(T), nl_field_free(S);
}

/* The forward prediction: input and output ACF (R, Ry) and spectra (S, Sy). */
static void predict(const opts_t *a, const nl_model *m, const nl_hermite *he, const char *tmp, const char *ptmp)
{
    size_t n = a->n, nl = n / 2 + 1;
    double h = a->h;
    nl_field *R = cli_field_alloc(1, &n, &h), *Ry = cli_field_alloc(1, &n, &h);
    nl_field *S = cli_field_alloc(1, &n, &h), *Sy = cli_field_alloc(1, &n, &h);
    cli_check(nl_wk_sample_acf(m, R));
    if (!(R->data[0] > 0))
        cli_die(2, "--acf: %s has R(0) = %g; expected a positive variance", a->spec, R->data[0]);
    nl_nonlin_output_acf(he, R->data, n, R->data[0], Ry->data);
    cli_check(nl_wk_acf_to_spectrum(R, S));
    cli_check(nl_wk_acf_to_spectrum(Ry, Sy));
    double *lag = cli_malloc(nl * sizeof *lag), *freq = cli_malloc(nl * sizeof *freq);
    for (size_t i = 0; i < nl; i++)
        lag[i] = (double)i * h, freq[i] = (double)i / ((double)n * h);
    if (a->json) {
        cli_json_print(json_pack("{s:s,s:s,s:o,s:o,s:o,s:o,s:o,s:o,s:o,s:f,s:f,s:f}", "model", a->spec, "g", a->gspec,
                                 "lag", cli_json_array(lag, nl), "input_acf", cli_json_array(R->data, nl), "output_acf",
                                 cli_json_array(Ry->data, nl), "freq", cli_json_array(freq, nl), "input_psd",
                                 cli_json_array(S->data, nl), "output_psd", cli_json_array(Sy->data, nl),
                                 "hermite_coefficients", cli_json_array(he->c, (size_t)a->K), "output_mean", he->c[0],
                                 "output_variance", he->variance, "truncation", he->truncation));
    } else if (!a->out && !a->pout) {
        printf("# g = %s on %s: output mean %.6g, variance %.6g; %d Hermite terms leave %.3g of it\n", a->gspec,
               a->spec, he->c[0], he->variance, a->K, he->truncation);
        printf("# hermite coefficients c_n:");
        for (int k = 0; k < a->K; k++)
            printf(" %.4g", he->c[k]);
        printf("\n");
    }
    if (a->out || (!a->json && !a->pout)) {
        static const char *const names[] = {"lag", "input_acf", "output_acf"};
        const double *cols[] = {lag, R->data, Ry->data};
        cli_check(cli_write_table(tmp, "noiselab nonlin: predicted output autocovariance", 3, names, nl, cols));
    }
    if (a->pout) {
        static const char *const names[] = {"freq", "input_psd", "output_psd"};
        const double *cols[] = {freq, S->data, Sy->data};
        cli_check(cli_write_table(ptmp, "noiselab nonlin: two-sided spectra, cycles per unit", 3, names, nl, cols));
    }
    free(lag), free(freq);
    nl_field_free(R), nl_field_free(Ry), nl_field_free(S), nl_field_free(Sy);
}

int cli_cmd_nonlin(int argc, char **argv)
{
    opts_t a = {.n = 4096, .h = 1, .K = 24};
    const char *tmp = NULL, *ptmp = NULL;
    int st;
    nl_model *m;
    nl_dist *d;
    nl_hermite he;
    parse(argc, argv, &a);
    if ((st = nl_model_parse(a.spec, &m)) || (st = nl_dist_parse(a.gspec, &d)))
        cli_die_status(st);
    tmp = cli_out_begin(a.out);
    ptmp = cli_out_begin(a.pout);
    cli_check(nl_hermite_expand(d, a.K, &he));
    if (a.design) {
        design(&a, m, d, &he, tmp);
    } else {
        predict(&a, m, &he, tmp, ptmp);
        cli_out_commit(a.out);
        cli_out_commit(a.pout);
    }
    nl_model_free(m), nl_dist_free(d);
    return 0;
}
