/* noiselab nonlin: predicted ACF and spectrum after a memoryless nonlinearity. */
#include "cli.h"
#include "../analysis/nonlin.h"
#include "../core/dist.h"
#include "../core/model.h"
#include "../core/wk.h"

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
    "hermite_coefficients, output_mean, output_variance, truncation.\n";

int cmd_nonlin(int argc, char **argv)
{
    static const struct option opts[] = {
        {"acf", required_argument, 0, 'a'},   {"g", required_argument, 0, 'g'},   {"size", required_argument, 0, 'n'},
        {"spacing", required_argument, 0, 'H'}, {"terms", required_argument, 0, 'K'}, {"json", no_argument, 0, 'j'},
        {"output", required_argument, 0, 'o'}, {"psd", required_argument, 0, 'p'}, {"help", no_argument, 0, 'h'},
        {0}};
    const char *spec = NULL, *gspec = NULL, *out = NULL, *pout = NULL, *tmp = NULL, *ptmp = NULL;
    size_t n = 4096;
    double h = 1, zero = 0;
    int c, K = 24, json = 0, st;
    nl_model *m;
    nl_dist *d;
    an_hermite he;
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
        case 'o': out = optarg; break;
        case 'p': pout = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("nonlin", c, argv);
        }
    }
    if (optind < argc)
        cli_die(2, "nonlin: unexpected argument \"%s\"", argv[optind]);
    if (!spec || !gspec)
        cli_die(2, "nonlin: expected --acf SPEC and --g DIST");
    if (K > AN_HERMITE_MAX)
        cli_die(2, "--terms: expected at most %d, got %d", AN_HERMITE_MAX, K);
    if (n > (1u << 24))
        cli_die(2, "--size: expected at most 16777216, got %zu", n);
    if ((st = nl_model_parse(spec, &m)) || (st = nl_dist_parse(gspec, &d)))
        cli_die_status(st);
    if (out)
        tmp = cli_out_begin(out);
    if (pout)
        ptmp = cli_out_begin(pout);
    if ((st = an_hermite_expand(d, K, &he)))
        cli_die_status(st);
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
        Ry->data[i] = an_hermite_cov(&he, fmax(-1, fmin(1, R->data[i] / r0)));
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
        if ((st = write_table(tmp, "noiselab nonlin: predicted output autocovariance", 3, names, nl, cols)))
            cli_die_status(st);
    }
    if (pout) {
        static const char *const names[] = {"freq", "input_psd", "output_psd"};
        const double *cols[] = {freq, S->data, Sy->data};
        if ((st = write_table(ptmp, "noiselab nonlin: two-sided spectra, cycles per unit", 3, names, nl, cols)))
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
