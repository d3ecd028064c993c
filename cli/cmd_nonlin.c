/* noiselab nonlin: predicted ACF and spectrum after a memoryless nonlinearity. */
#include "cli.h"
#include "../analysis/nonlin.h"
#include "../core/dist.h"
#include "../core/model.h"
#include "../core/wk.h"
#include "../analysis/acf.h"
#include "../synth/fft.h"
#include "../synth/shape.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab nonlin --acf SPEC --g DIST [--size N] [--spacing H] [--terms K]\n"
    "                       [--json] [-o ACF.tsv] [--psd PSD.tsv]\n\n"
    "Predicts what the shaping y = F_DIST^-1(Phi(x / sd)) (noiselab shape) does to a\n"
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

int cli_cmd_nonlin(int argc, char **argv)
{
    static const struct option opts[] = {
        {"acf", required_argument, 0, 'a'},   {"g", required_argument, 0, 'g'},   {"size", required_argument, 0, 'n'},
        {"spacing", required_argument, 0, 'H'}, {"terms", required_argument, 0, 'K'}, {"json", no_argument, 0, 'j'},
        {"design", no_argument, 0, 'D'},      {"target", required_argument, 0, 'T'}, {"verify", required_argument, 0, 'V'},
        {"output", required_argument, 0, 'o'}, {"psd", required_argument, 0, 'p'}, {"help", no_argument, 0, 'h'},
        {0}};
    const char *spec = NULL, *gspec = NULL, *out = NULL, *pout = NULL, *tmp = NULL, *ptmp = NULL;
    size_t n = 4096;
    double h = 1, zero = 0;
    int c, K = 24, json = 0, st, design = 0;
    const char *tspec = NULL;
    size_t verify = 0;
    nl_model *m;
    nl_dist *d;
    nl_hermite he;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'a': spec = optarg; break;
        case 'g': gspec = optarg; break;
        case 'n': n = cli_parse_count("--size", optarg, 16); break;
        case 'H':
            h = cli_parse_double("--spacing", optarg);
            if (!(h > 0))
                cli_die(2, "--spacing: expected a positive number, got \"%s\"", optarg);
            break;
        case 'K': K = (int)cli_parse_count("--terms", optarg, 2); break;
        case 'j': json = 1; break;
        case 'D': design = 1; break;
        case 'T': tspec = optarg; break;
        case 'V': verify = cli_parse_count("--verify", optarg, 1); break;
        case 'o': out = optarg; break;
        case 'p': pout = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("nonlin", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "nonlin: unexpected argument \"%s\"", argv[optind]);
    if (design) {
        if (!tspec || !gspec || spec)
            cli_die(2, "nonlin --design: expected --target SPEC and --g DIST (not --acf)");
        spec = tspec;
    } else if (!spec || !gspec)
        cli_die(2, "nonlin: expected --acf SPEC and --g DIST");
    if (verify > 1000)
        cli_die(2, "--verify: expected at most 1000 realizations, got %zu", verify);
    if (K > NL_HERMITE_MAX)
        cli_die(2, "--terms: expected at most %d, got %d", NL_HERMITE_MAX, K);
    if (n > (1u << 24))
        cli_die(2, "--size: expected at most 16777216, got %zu", n);
    if ((st = nl_model_parse(spec, &m)) || (st = nl_dist_parse(gspec, &d)))
        cli_die_status(st);
    if (out)
        tmp = cli_out_begin(out);
    if (pout)
        ptmp = cli_out_begin(pout);
    if ((st = nl_hermite_expand(d, K, &he)))
        cli_die_status(st);
    if (design) {
        nl_field *T = nl_field_alloc(1, &n, &h, &st), *S = T ? nl_field_alloc(1, &n, &h, &st) : NULL;
        double *rho = malloc(n * sizeof *rho), err, var = nl_hermite_cov(&he, 1), *meas = NULL, merr = NAN;
        size_t bad, nl2 = n / 2 + 1 < 129 ? n / 2 + 1 : 129;
        if (!S || !rho)
            cli_die(1, "out of memory");
        if ((st = nl_wk_sample_acf(m, T)))
            cli_die_status(st);
        if ((st = nl_nonlin_design(&he, T->data, n, h, rho, S->data, &err, &bad)))
            cli_die_status(st);
        double scale = var / T->data[0];
        if (verify) {
            nl_synth_fft_plan *p;
            nl_field *x = nl_field_alloc(1, &n, &h, &st), *full;
            meas = calloc(nl2, sizeof *meas);
            if ((st = nl_synth_fft_plan_spectrum(S, NL_SYNTH_FFT_CLAMP, &p)))
                cli_die_status(st);
            for (size_t s = 1; s <= verify; s++) {
                nl_synth_fft_execute(p, s, x);
                if ((st = nl_synth_shape(x, d, 0)) || (st = nl_acf_full(x, NAN, NL_ACF_UNBIASED, &full)))
                    cli_die_status(st);
                for (size_t i = 0; i < nl2; i++)
                    meas[i] += full->data[i] / (double)verify;
                nl_field_free(full);
            }
            merr = 0;
            for (size_t i = 0; i < nl2; i++)
                merr = fmax(merr, fabs(meas[i] - T->data[i] * scale) / var);
            nl_synth_fft_plan_free(p), nl_field_free(x);
        }
        double *lag = malloc(nl2 * sizeof *lag), *tg = malloc(nl2 * sizeof *tg), *pred = malloc(nl2 * sizeof *pred);
        for (size_t i = 0; i < nl2; i++) {
            lag[i] = (double)i * h;
            tg[i] = T->data[i] * scale;
            pred[i] = nl_hermite_cov(&he, fmax(-1, fmin(1, rho[i])));
        }
        if (json) {
            json_t *o = json_pack("{s:s,s:s,s:o,s:o,s:o,s:o,s:f,s:I,s:o}", "target", tspec, "g", gspec, "lag",
                                  cli_json_array(lag, nl2), "target_acf", cli_json_array(tg, nl2), "input_acf",
                                  cli_json_array(rho, nl2), "predicted_output_acf", cli_json_array(pred, nl2),
                                  "projection_error", err, "unreachable_lags", (json_int_t)bad, "hermite_coefficients",
                                  cli_json_array(he.c, (size_t)K));
            if (verify)
                json_object_set_new(o, "measured_output_acf", cli_json_array(meas, nl2)),
                    json_object_set_new(o, "measured_error", json_real(merr));
            cli_json_print(o);
        } else {
            printf("# design for %s after %s: projection error %.3g of the output variance, %zu unreachable lags",
                   tspec, gspec, err, bad);
            if (verify)
                printf("; measured over %zu realizations: %.3g", verify, merr);
            printf("\n");
        }
        if (out || !json) {
            const char *names[5] = {"lag", "target", "input_acf", "predicted", "measured"};
            const double *cols[5] = {lag, tg, rho, pred, meas};
            if ((st = cli_write_table(tmp, "noiselab nonlin --design: covariances; input_acf is normalised",
                                  verify ? 5 : 4, names, nl2, cols)))
                cli_die_status(st);
            if (out)
                cli_out_commit(out);
        }
        free(lag), free(tg), free(pred), free(rho), free(meas);
        nl_field_free(T), nl_field_free(S), nl_model_free(m), nl_dist_free(d);
        return 0;
    }
    nl_field *R = nl_field_alloc(1, &n, &h, &st), *Ry = R ? nl_field_alloc(1, &n, &h, &st) : NULL;
    nl_field *S = Ry ? nl_field_alloc(1, &n, &h, &st) : NULL, *Sy = S ? nl_field_alloc(1, &n, &h, &st) : NULL;
    if (!Sy)
        cli_die_status(st);
    if ((st = nl_wk_sample_acf(m, R)))
        cli_die_status(st);
    double r0 = R->data[0];
    (void)zero;
    if (!(r0 > 0))
        cli_die(2, "--acf: %s has R(0) = %g; expected a positive variance", spec, r0);
    for (size_t i = 0; i < n; i++)
        Ry->data[i] = nl_hermite_cov(&he, fmax(-1, fmin(1, R->data[i] / r0)));
    if ((st = nl_wk_acf_to_spectrum(R, S)) || (st = nl_wk_acf_to_spectrum(Ry, Sy)))
        cli_die_status(st);
    size_t nl = n / 2 + 1;
    double *lag = malloc(nl * sizeof *lag), *freq = malloc(nl * sizeof *freq);
    if (!lag || !freq)
        cli_die(1, "out of memory");
    for (size_t i = 0; i < nl; i++)
        lag[i] = (double)i * h, freq[i] = (double)i / ((double)n * h);
    if (json) {
        cli_json_print(json_pack("{s:s,s:s,s:o,s:o,s:o,s:o,s:o,s:o,s:o,s:f,s:f,s:f}", "model", spec, "g", gspec, "lag",
                                 cli_json_array(lag, nl), "input_acf", cli_json_array(R->data, nl), "output_acf",
                                 cli_json_array(Ry->data, nl), "freq", cli_json_array(freq, nl), "input_psd",
                                 cli_json_array(S->data, nl), "output_psd", cli_json_array(Sy->data, nl),
                                 "hermite_coefficients", cli_json_array(he.c, (size_t)K), "output_mean", he.c[0],
                                 "output_variance", he.variance, "truncation", he.truncation));
    } else if (!out && !pout) {
        printf("# g = %s on %s: output mean %.6g, variance %.6g; %d Hermite terms leave %.3g of it\n", gspec, spec,
               he.c[0], he.variance, K, he.truncation);
        printf("# hermite coefficients c_n:");
        for (int k = 0; k < K; k++)
            printf(" %.4g", he.c[k]);
        printf("\n");
    }
    if (out || (!json && !pout)) {
        static const char *const names[] = {"lag", "input_acf", "output_acf"};
        const double *cols[] = {lag, R->data, Ry->data};
        if ((st = cli_write_table(tmp, "noiselab nonlin: predicted output autocovariance", 3, names, nl, cols)))
            cli_die_status(st);
    }
    if (pout) {
        static const char *const names[] = {"freq", "input_psd", "output_psd"};
        const double *cols[] = {freq, S->data, Sy->data};
        if ((st = cli_write_table(ptmp, "noiselab nonlin: two-sided spectra, cycles per unit", 3, names, nl, cols)))
            cli_die_status(st);
    }
    if (out)
        cli_out_commit(out);
    if (pout)
        cli_out_commit(pout);
    free(lag), free(freq);
    nl_field_free(R), nl_field_free(Ry), nl_field_free(S), nl_field_free(Sy);
    nl_model_free(m), nl_dist_free(d);
    return 0;
}
