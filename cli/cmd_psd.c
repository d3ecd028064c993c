/* noiselab psd: estimate the power spectral density of a field. */
#include "cli.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../analysis/slope.h"
#include "../analysis/welch.h"
#include "../core/model.h"
#include "../core/wk.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab psd IN [--radial] [--mean M] [--welch S] [--target SPEC] [--slope F1:F2]\n"
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
    "                is stated for profiles); in 2D/3D the fit is to every periodogram\n"
    "                ordinate in the band (each Hermitian pair once), not to the radial\n"
    "                average, whose interval would be too narrow\n"
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
        if ((st = nl_radial(P, NL_GRID_FREQ, step, nb, freq, val, cnt)))
            cli_die_status(st);
        return nb;
    }
}

int cli_cmd_psd(int argc, char **argv)
{
    static const struct option opts[] = {
        {"radial", no_argument, 0, 'r'},     {"mean", required_argument, 0, 'm'},
        {"target", required_argument, 0, 't'}, {"json", no_argument, 0, 'j'},
        {"output", required_argument, 0, 'o'}, {"help", no_argument, 0, 'h'},
        {"slope", required_argument, 0, 's'},  {"welch", required_argument, 0, 'W'},
        {"angular", no_argument, 0, 'A'},      {"preview", required_argument, 0, 'p'}, {0}};
    const char *out = NULL, *tmp = NULL, *target = NULL;
    double mean = NAN, *freq, *val, *tgt = NULL;
    int c, json = 0, st, slope = 0, angular = 0;
    size_t welch = 0, nseg = 1;
    const char *preview = NULL, *pvtmp = NULL;
    double f1 = 0, f2 = 0;
    nl_slope sl;
    size_t nf, maxn, *cnt;
    nl_field *x, *P;

    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'r': break; /* nD output is always radial; accepted for clarity */
        case 'm': mean = cli_parse_double("--mean", optarg); break;
        case 't': target = optarg; break;
        case 'W': welch = cli_parse_count("--welch", optarg, 4); break;
        case 'A': angular = 1; break;
        case 'p': preview = optarg; break;
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
    if ((angular || preview || (out && cli_has_ext(out, ".exr"))) && x->dim != 2)
        cli_die(2, "psd: --angular, --preview and EXR output need a 2D field, %s is %dD", argv[optind], x->dim);
    if (preview && !cli_has_ext(preview, ".png"))
        cli_die(2, "--preview: expected a .png file, got \"%s\"", preview);
    if (out)
        tmp = cli_out_begin(out);
    if (preview)
        pvtmp = cli_out_begin(preview);
    if ((st = welch ? nl_psd_welch(x, welch, mean, &P, &nseg) : nl_psd_periodogram(x, mean, &P)))
        cli_die_status(st);
    if ((out && cli_has_ext(out, ".exr")) || preview) {
        /* the 2D spectrum with zero frequency at the centre */
        nl_field *C = nl_field_alloc(2, P->n, P->h, &st);
        if (!C)
            cli_die_status(st);
        size_t W = P->n[0], Hh = P->n[1];
        double mx = 0;
        for (size_t j = 0; j < Hh; j++)
            for (size_t i = 0; i < W; i++) {
                C->data[((j + Hh / 2) % Hh) * W + (i + W / 2) % W] = P->data[j * W + i];
                mx = fmax(mx, P->data[j * W + i]);
            }
        if (out && cli_has_ext(out, ".exr")) {
            nl_meta meta;
            memset(&meta, 0, sizeof meta);
            snprintf(meta.method, sizeof meta.method, "psd%s, zero frequency at (%zu, %zu)", welch ? " welch" : "",
                     W / 2, Hh / 2);
            if ((st = nl_exr_write(tmp, C, &meta)))
                cli_die_status(st);
        }
        if (preview) {
            for (size_t q = 0; q < C->count; q++)
                C->data[q] = log10(fmax(C->data[q], mx * 1e-12));
            if ((st = nl_png_write_field(pvtmp, C, log10(mx) - 8, log10(mx))))
                cli_die_status(st);
            cli_out_commit(preview);
        }
        nl_field_free(C);
        if (out && cli_has_ext(out, ".exr")) {
            cli_out_commit(out);
            out = NULL;
        }
    }
    double sector[18] = {0}, aniso = NAN;
    if (angular) {
        size_t sc[18] = {0};
        for (size_t j = 0; j < P->n[1]; j++)
            for (size_t i = 0; i < P->n[0]; i++) {
                double fx = (double)nl_wrap(i, P->n[0]) / (double)P->n[0], fy = (double)nl_wrap(j, P->n[1]) / (double)P->n[1];
                double r = hypot(fx, fy), a = atan2(fy, fx);
                if (r < 0.05 || r > 0.45)
                    continue;
                if (a < 0)
                    a += M_PI;
                int b = (int)(a / M_PI * 18) % 18;
                sector[b] += P->data[j * P->n[0] + i], sc[b]++;
            }
        double mn = INFINITY, mx = 0;
        for (int b = 0; b < 18; b++) {
            sector[b] = sc[b] ? sector[b] / (double)sc[b] : NAN;
            mn = fmin(mn, sector[b]), mx = fmax(mx, sector[b]);
        }
        aniso = mx / mn;
    }
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
    if (slope && (st = x->dim == 1 ? nl_psd_slope(freq, val, nf, f1, f2, 1, &sl) : nl_psd_slope_grid(P, f1, f2, &sl)))
        cli_die_status(st);
    if (json) {
        json_t *o = json_pack("{s:o,s:o}", "freq", cli_json_array(freq, nf), "psd", cli_json_array(val, nf));
        if (tgt)
            json_object_set_new(o, "target", cli_json_array(tgt, nf));
        json_object_set_new(o, "sided", json_string("two-sided"));
        json_object_set_new(o, "average", json_string(x->dim == 1 ? "none" : "radial"));
        if (angular) {
            json_object_set_new(o, "sectors", cli_json_array(sector, 18));
            json_object_set_new(o, "anisotropy", json_real(aniso));
        }
        if (welch)
            json_object_set_new(o, "welch_segments", json_integer((json_int_t)nseg));
        if (slope)
            json_object_set_new(o, "slope", json_pack("{s:f,s:f,s:I,s:f,s:[f,f]}", "slope", sl.slope, "ci95", sl.ci95,
                                                      "points", (json_int_t)sl.points, "fractal_dimension",
                                                      sl.fractal_dim, "band", f1, f2));
        cli_json_print(o);
    }
    if (angular && !json) {
        printf("# sector power (0.05..0.45 cycles/sample), 10-degree sectors from +x:");
        for (int b = 0; b < 18; b++)
            printf(" %.4g", sector[b]);
        printf("\n# anisotropy (max/min sector power) %.4f\n", aniso);
    }
    if (slope && !json)
        printf("# slope %.4f +- %.4f (95%%, %zu frequencies in [%g, %g]); fractal dimension "
                "%.4f\n", sl.slope, sl.ci95, sl.points, f1, f2, sl.fractal_dim);
    if (out || (!json && !angular && !preview)) {
        static const char *const names[] = {"freq", "psd", "target"};
        const double *cols[] = {freq, val, tgt};
        st = cli_write_table(out ? tmp : NULL, x->dim == 1 ? "noiselab psd: two-sided periodogram density, freq in cycles per unit"
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
