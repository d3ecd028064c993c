/* noiselab psd: estimate the power spectral density of a field. */
#include "cli.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../analysis/slope.h"
#include "../core/model.h"
#include "../core/wk.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab psd IN [--radial] [--mean M] [--target SPEC] [--slope F1:F2] [--json]\n"
    "                    [-o OUT.tsv]\n\n"
    "Periodogram of IN (EXR, PNG or 1D TSV): P(f) = (h/N) |DFT(x - mean)|^2, a\n"
    "TWO-SIDED density in variance per (cycles per unit length)^dim, so that the sum\n"
    "of P over all grid frequencies times the frequency cell is the mean square.\n"
    "1D fields give f = 0 .. Nyquist; 2D and 3D fields give the radial average in\n"
    "bins one frequency step wide.\n\n"
    "  --mean M      known mean to remove (default: the sample mean)\n"
    "  --target SPEC add the model's spectrum on the same grid (the spectrum of the\n"
    "                sampled process, aliasing included)\n"
    "  --slope F1:F2 fit log psd = c + slope log f over F1 <= f <= F2: slope, its 95%\n"
    "                confidence interval, and the fractal dimension D = E + (3 - d)/2,\n"
    "                d = -slope (Lewis 1987, eq. 16)\n"
    "  --json        {\"freq\": [...], \"psd\": [...], \"sided\": \"two-sided\"} on stdout\n"
    "  -o            TSV with columns freq, psd[, target] (default: TSV on stdout)\n";

/* 1D: f = 0..n/2; nD: radial bins.  Fills freq and val from grid P. */
static size_t profile(const nl_field *P, double *freq, double *val, size_t *cnt)
{
    if (P->dim == 1) {
        size_t nf = P->n[0] / 2 + 1;
        for (size_t i = 0; i < nf; i++) {
            freq[i] = (double)i / ((double)P->n[0] * P->h[0]);
            val[i] = P->data[i];
        }
        return nf;
    } else {
        double step = INFINITY, fmax = INFINITY;
        size_t nb;
        int st;
        for (int a = 0; a < P->dim; a++) {
            step = fmin(step, 1.0 / ((double)P->n[a] * P->h[a]));
            fmax = fmin(fmax, 0.5 / P->h[a]);
        }
        nb = (size_t)floor(fmax / step) + 1;
        if ((st = an_radial(P, AN_GRID_FREQ, step, nb, freq, val, cnt)))
            cli_die_status(st);
        return nb;
    }
}

int cmd_psd(int argc, char **argv)
{
    static const struct option opts[] = {
        {"radial", no_argument, 0, 'r'},     {"mean", required_argument, 0, 'm'},
        {"target", required_argument, 0, 't'}, {"json", no_argument, 0, 'j'},
        {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
        {"slope", required_argument, 0, 's'},  {0}};
    const char *out = NULL, *tmp = NULL, *target = NULL;
    double mean = NAN, *freq, *val, *tgt = NULL;
    int c, json = 0, st, slope = 0;
    double f1 = 0, f2 = 0;
    an_slope sl;
    size_t nf, maxn, *cnt;
    nl_field *x, *P;

    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'r': break; /* nD output is always radial; accepted for clarity */
        case 'm': mean = cli_parse_double("--mean", optarg); break;
        case 't': target = optarg; break;
        case 's': {
            char *end;
            f1 = strtod(optarg, &end);
            if (end == optarg || *end != ':' || (f2 = strtod(end + 1, &end), *end) || !(f1 > 0) || !(f2 > f1))
                cli_die(2, "--slope: expected F1:F2 with 0 < F1 < F2, got \"%s\"", optarg);
            slope = 1;
            break;
        }
        case 'j': json = 1; break;
        case 'o': out = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("psd", c, argv);
        }
    }
    if (optind + 1 != argc)
        cli_die(2, "psd: expected one input file, got %d", argc - optind);
    x = cli_read_field(argv[optind], NULL);
    if (out)
        tmp = cli_out_begin(out);
    if ((st = an_psd_periodogram(x, mean, &P)))
        cli_die_status(st);
    maxn = x->n[0] + x->n[1] + x->n[2];
    freq = malloc(maxn * sizeof *freq);
    val = malloc(maxn * sizeof *val);
    cnt = malloc(maxn * sizeof *cnt);
    if (!freq || !val || !cnt)
        cli_die(1, "out of memory");
    nf = profile(P, freq, val, cnt);
    if (target) {
        nl_model *m;
        nl_field *S = nl_field_alloc(x->dim, x->n, x->h, &st);
        tgt = malloc(maxn * sizeof *tgt);
        if (!S || !tgt)
            cli_die(1, "out of memory");
        if ((st = nl_model_parse(target, &m)) || (st = nl_wk_sample_spectrum(m, S)))
            cli_die_status(st);
        profile(S, freq + 0, tgt, cnt);
        nf = profile(P, freq, val, cnt);
        nl_model_free(m);
        nl_field_free(S);
    }
    if (slope && (st = an_psd_slope(freq, val, nf, f1, f2, x->dim, &sl)))
        cli_die_status(st);
    if (json) {
        json_t *o = json_pack("{s:o,s:o}", "freq", cli_json_array(freq, nf), "psd", cli_json_array(val, nf));
        if (tgt)
            json_object_set_new(o, "target", cli_json_array(tgt, nf));
        json_object_set_new(o, "sided", json_string("two-sided"));
        json_object_set_new(o, "average", json_string(x->dim == 1 ? "none" : "radial"));
        if (slope)
            json_object_set_new(o, "slope", json_pack("{s:f,s:f,s:I,s:f,s:[f,f]}", "slope", sl.slope, "ci95", sl.ci95,
                                                      "points", (json_int_t)sl.points, "fractal_dimension",
                                                      sl.fractal_dim, "band", f1, f2));
        cli_json_print(o);
    }
    if (slope && !json)
        printf("# slope %.4f +- %.4f (95%%, %zu frequencies in [%g, %g]); fractal dimension "
                "%.4f\n", sl.slope, sl.ci95, sl.points, f1, f2, sl.fractal_dim);
    if (out || !json) {
        static const char *const names[] = {"freq", "psd", "target"};
        const double *cols[] = {freq, val, tgt};
        st = write_table(out ? tmp : NULL, x->dim == 1 ? "noiselab psd: two-sided periodogram density, freq in cycles per unit"
                                      : "noiselab psd: two-sided periodogram density, radial average, freq in "
                                        "cycles per unit",
                          tgt ? 3 : 2, names, nf, cols);
        if (st)
            cli_die_status(st);
    }
    if (out)
        cli_out_commit(out);
    free(freq);
    free(val);
    free(cnt);
    free(tgt);
    nl_field_free(P);
    nl_field_free(x);
    return 0;
}
