/* noiselab acf: estimate the autocorrelation of a field. */
#include "cli.h"
#include "../analysis/acf.h"
#include "../analysis/radial.h"
#include "../core/model.h"
#include "../core/wk.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab acf IN [--max-lag L] [--axis x|y|z] [--radial] [--unbiased]\n"
    "                    [--mean M] [--target SPEC] [--json] [-o OUT.tsv|OUT.exr]\n\n"
    "Estimates the autocorrelation of IN (EXR, PNG or 1D TSV) by FFT with zero\n"
    "padding.  Lags are in spacing units.  Biased estimate (divisor N) by default;\n"
    "--unbiased divides by the number of overlapping pairs.  The sample mean is\n"
    "removed unless --mean gives the known mean.\n\n"
    "  --max-lag L   largest lag, in spacing units (default a quarter of the axis)\n"
    "  --axis        lag direction for 2D/3D fields (default x)\n"
    "  --radial      average over directions, bins of one sample spacing\n"
    "  --target SPEC add the model's R at each lag (radial: at lag (r, 0, 0))\n"
    "  --direct      the direct sum of eq. (15) instead of the FFT (same numbers to rounding)\n"
    "  --bands       1D: a 95% band lo, hi from Bartlett's formula for the variance of the\n"
    "                (biased) estimate, with the estimate in place of R up to 4 max-lag\n"
    "  --json        {\"lag\": [...], \"acf\": [...], ...} on stdout\n"
    "  -o            TSV with columns lag, acf[, target] (default: TSV on stdout), or .exr:\n"
    "                the whole 2D/3D estimate with lag 0 at the centre\n";

/* R of the target model at distance lag[i] along `axis`. */
static void target_values(const char *spec, const nl_field *x, int axis, const double *lag, size_t nl,
                          double *out)
{
    nl_model *m;
    int st = nl_model_parse(spec, &m);
    if (st)
        cli_die_status(st);
    if ((st = nl_model_check_dim(m, x->dim)))
        cli_die_status(st);
    if (nl_model_is_spectral(m)) {
        /* R of a spectral model: the inverse transform on a grid twice the data's */
        size_t n2[3];
        nl_field *R;
        for (int a = 0; a < 3; a++)
            n2[a] = a < x->dim ? 2 * x->n[a] : 1;
        R = nl_field_alloc(x->dim, n2, x->h, &st);
        if (!R || (st = nl_wk_sample_acf(m, R)))
            cli_die_status(st);
        for (size_t i = 0; i < nl; i++) {
            size_t idx = (size_t)lrint(lag[i] / x->h[axis]), stride = 1;
            for (int a = 0; a < axis; a++)
                stride *= R->n[a];
            out[i] = idx < n2[axis] / 2 ? R->data[idx * stride] : NAN;
        }
        nl_field_free(R);
    } else {
        for (size_t i = 0; i < nl; i++) {
            double v[3] = {0, 0, 0};
            v[axis] = lag[i];
            out[i] = isfinite(lag[i]) ? nl_model_acf(m, x->dim, v) : NAN;
        }
    }
    nl_model_free(m);
}

int cli_cmd_acf(int argc, char **argv)
{
    static const struct option opts[] = {
        {"max-lag", required_argument, 0, 'L'}, {"axis", required_argument, 0, 'a'},
        {"radial", no_argument, 0, 'r'},        {"unbiased", no_argument, 0, 'u'},
        {"mean", required_argument, 0, 'm'},    {"target", required_argument, 0, 't'},
        {"json", no_argument, 0, 'j'},          {"output", required_argument, 0, 'o'},
        {"help", no_argument, 0, 'h'},          {"direct", no_argument, 0, 'D'},
        {"bands", no_argument, 0, 'B'},          {0}};
    const char *out = NULL, *tmp = NULL, *target = NULL, *in;
    double maxlag = NAN, mean = NAN, *lag, *val, *tgt = NULL;
    int c, axis = 0, radial = 0, unbiased = 0, json = 0, st, direct = 0, bands = 0;
    double *blo = NULL, *bhi = NULL;
    size_t nl, *cnt = NULL;
    nl_field *x, *full;

    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'L':
            maxlag = cli_parse_double("--max-lag", optarg);
            if (!(maxlag >= 0))
                cli_die(2, "--max-lag: expected a non-negative lag, got \"%s\"", optarg);
            break;
        case 'a':
            if (strlen(optarg) != 1 || !strchr("xyz", optarg[0]))
                cli_die(2, "--axis: expected x, y or z, got \"%s\"", optarg);
            axis = optarg[0] - 'x';
            break;
        case 'r': radial = 1; break;
        case 'u': unbiased = 1; break;
        case 'm': mean = cli_parse_double("--mean", optarg); break;
        case 't': target = optarg; break;
        case 'j': json = 1; break;
        case 'D': direct = 1; break;
        case 'B': bands = 1; break;
        case 'o': out = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("acf", c, argv);
        }
    }
    if (optind + 1 != argc)
        cli_die(2, "acf: expected one input file, got %d", argc - optind);
    in = argv[optind];
    x = cli_read_field(in, NULL);
    if (axis >= x->dim)
        cli_die(2, "--axis: the field is %dD, got axis \"%c\"", x->dim, 'x' + axis);
    if (radial && x->dim == 1)
        cli_die(2, "--radial: expected a 2D or 3D field, %s is 1D", in);
    if (isnan(maxlag))
        nl = x->n[axis] / 4;
    else if ((nl = (size_t)floor(maxlag / x->h[axis] + 1e-9)) >= x->n[axis])
        cli_die(2, "--max-lag: expected at most %g for %zu samples, got %g", (double)(x->n[axis] - 1) * x->h[axis],
                x->n[axis], maxlag);
    nl += 1;
    if (out)
        tmp = cli_out_begin(out);
    if ((st = nl_acf_full(x, mean, unbiased, &full)))
        cli_die_status(st);
    if (out && cli_has_ext(out, ".exr")) {
        /* the whole ACF, lag 0 at the centre (lags -(n-1) .. n-1 per axis) */
        size_t cn[3] = {1, 1, 1};
        for (int a = 0; a < x->dim; a++)
            cn[a] = 2 * x->n[a] - 1;
        nl_field *C = nl_field_alloc(x->dim, cn, x->h, &st);
        nl_meta meta;
        if (!C)
            cli_die_status(st);
        for (size_t k = 0; k < cn[2]; k++)
            for (size_t j = 0; j < cn[1]; j++)
                for (size_t i = 0; i < cn[0]; i++) {
                    size_t idx[3] = {i, j, k}, src[3];
                    for (int a = 0; a < 3; a++) {
                        long l = a < x->dim ? (long)idx[a] - (long)(x->n[a] - 1) : 0;
                        src[a] = (size_t)(l < 0 ? l + (long)full->n[a] : l);
                    }
                    C->data[(k * cn[1] + j) * cn[0] + i] = full->data[(src[2] * full->n[1] + src[1]) * full->n[0] + src[0]];
                }
        memset(&meta, 0, sizeof meta);
        snprintf(meta.method, sizeof meta.method, "acf %s, lag 0 at the centre", unbiased ? "unbiased" : "biased");
        if ((st = nl_exr_write(tmp, C, &meta)))
            cli_die_status(st);
        cli_out_commit(out);
        nl_field_free(C), nl_field_free(full), nl_field_free(x);
        return 0;
    }
    lag = malloc(nl * sizeof *lag);
    val = malloc(nl * sizeof *val);
    cnt = malloc(nl * sizeof *cnt);
    if (!lag || !val || !cnt)
        cli_die(1, "out of memory");
    if ((direct || bands) && radial)
        cli_die(2, "acf: --direct and --bands go with an axis, not --radial");
    if (bands && (x->dim != 1 || unbiased))
        cli_die(2, "acf: --bands is for the biased estimate of a 1D field");
    if (direct) {
        st = nl_acf_direct(x, mean, unbiased, axis, nl - 1, val);
        for (size_t i = 0; i < nl; i++)
            lag[i] = (double)i * x->h[axis];
    } else if (radial) {
        double step = x->h[0];
        for (int a = 1; a < x->dim; a++)
            step = fmin(step, x->h[a]);
        st = nl_radial(full, NL_GRID_LAG, step, nl, lag, val, cnt);
    } else {
        st = nl_acf_axis(full, axis, nl - 1, lag, val);
    }
    if (st)
        cli_die_status(st);
    if (bands) {
        size_t nc = 4 * (nl - 1) + 1 < x->n[0] ? 4 * (nl - 1) + 1 : x->n[0];
        double *cv = malloc(nc * sizeof *cv), *var = malloc(nl * sizeof *var);
        blo = malloc(nl * sizeof *blo), bhi = malloc(nl * sizeof *bhi);
        if (!cv || !var || !blo || !bhi)
            cli_die(1, "out of memory");
        for (size_t i = 0; i < nc; i++)
            cv[i] = full->data[i];
        if (nc < 2 * (nl - 1) + 1)
            cli_die(2, "--bands: expected a field of at least %zu samples for --max-lag %zu", 2 * (nl - 1) + 1, nl - 1);
        if ((st = nl_acf_bartlett(cv, nc, x->count, nl - 1, var)))
            cli_die_status(st);
        for (size_t i = 0; i < nl; i++)
            blo[i] = val[i] - 1.959964 * sqrt(var[i]), bhi[i] = val[i] + 1.959964 * sqrt(var[i]);
        free(cv), free(var);
    }
    if (target) {
        tgt = malloc(nl * sizeof *tgt);
        if (!tgt)
            cli_die(1, "out of memory");
        target_values(target, x, radial ? 0 : axis, lag, nl, tgt);
    }
    if (json) {
        json_t *o = json_pack("{s:o,s:o}", "lag", cli_json_array(lag, nl), "acf", cli_json_array(val, nl));
        if (tgt)
            json_object_set_new(o, "target", cli_json_array(tgt, nl));
        if (bands) {
            json_object_set_new(o, "band_lo", cli_json_array(blo, nl));
            json_object_set_new(o, "band_hi", cli_json_array(bhi, nl));
        }
        json_object_set_new(o, "estimator", json_string(unbiased ? "unbiased" : "biased"));
        json_object_set_new(o, "direction", json_string(radial ? "radial" : (const char *[]){"x", "y", "z"}[axis]));
        cli_json_print(o);
    }
    if (out || !json) {
        const char *names[5] = {"lag", "acf"};
        const double *cols[5] = {lag, val};
        int ncol = 2;
        if (tgt)
            names[ncol] = "target", cols[ncol++] = tgt;
        if (bands)
            names[ncol] = "lo", cols[ncol++] = blo, names[ncol] = "hi", cols[ncol++] = bhi;
        char comment[256];
        snprintf(comment, sizeof comment, "noiselab acf: %s estimate, %s, lags in spacing units",
                 unbiased ? "unbiased" : "biased", radial ? "radial average" : "along one axis");
        st = cli_write_table(out ? tmp : NULL, comment, ncol, names, nl, cols);
        if (st)
            cli_die_status(st);
    }
    if (out)
        cli_out_commit(out);
    free(lag);
    free(val);
    free(cnt);
    free(tgt), free(blo), free(bhi);
    nl_field_free(full);
    nl_field_free(x);
    return 0;
}
