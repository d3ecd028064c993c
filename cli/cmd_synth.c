/* noiselab synth: synthesise a field with a prescribed model. */
#include "cli.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../synth/fft.h"

#include <getopt.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab synth METHOD (--acf SPEC | --spectrum SPEC) --size N[xM[xK]]\n"
    "                      [--seed S] [--spacing H[,H...]] [--clamp] [--preview P.png]\n"
    "                      [--json] -o OUT.exr|OUT.tsv\n\n"
    "METHOD\n"
    "  fft      periodic Fourier synthesis: white noise filtered by the square root of\n"
    "           the model's spectrum on the periodic grid; Gaussian, zero ensemble mean,\n"
    "           variance R(0), covariance exactly the model's R sampled on the torus.\n"
    "           The same seed and size give the same white noise for every model.\n\n"
    "  --acf SPEC       autocorrelation model (see noiselab models)\n"
    "  --spectrum SPEC  spectrum model: power:d=..., spectrum:EXPR, or a bare EXPR in f/fx/fy/k\n"
    "  --size           samples per axis, each >= 2 (1D, 2D or 3D)\n"
    "  --seed           64-bit seed (default 1)\n"
    "  --spacing        grid spacing, one value or one per axis (default 1)\n"
    "  --clamp          accept a spectrum with negative values by zeroing them\n"
    "  --preview        8-bit PNG of a 2D field (the first slice of 3D), mean +- 3 sd\n"
    "  --json           print the synthesis report (variance, spectrum range) as JSON\n"
    "  -o               EXR (any dimension) or TSV (1D: columns t, value)\n";

static const char *const methods_planned[] = {"subdiv", "midpoint", "circulant", "cholesky", "sparse",
                                              "faulting", "lattice", "rank1"};

/* The spec for --spectrum: a bare expression means spectrum:EXPR. */
static const char *spectrum_spec(const char *s, char *buf, size_t len)
{
    if (strncmp(s, "power", 5) == 0 || strncmp(s, "spectrum:", 9) == 0)
        return s;
    snprintf(buf, len, "spectrum:%s", s);
    return buf;
}

static void write_tsv(const char *path, const nl_field *f)
{
    static const char *const names[] = {"t", "value"};
    double *t = malloc(f->count * sizeof *t);
    const double *cols[2];
    int st;
    if (!t)
        cli_die(1, "out of memory");
    for (size_t i = 0; i < f->count; i++)
        t[i] = (double)i * f->h[0];
    cols[0] = t;
    cols[1] = f->data;
    st = nl_tsv_write(path, NULL, 2, names, f->count, cols);
    free(t);
    if (st)
        cli_die_status(st);
}

int cmd_synth(int argc, char **argv)
{
    static const struct option opts[] = {
        {"acf", required_argument, 0, 'a'},     {"spectrum", required_argument, 0, 'S'},
        {"size", required_argument, 0, 'n'},    {"seed", required_argument, 0, 's'},
        {"spacing", required_argument, 0, 'H'}, {"clamp", no_argument, 0, 'c'},
        {"preview", required_argument, 0, 'p'}, {"json", no_argument, 0, 'j'},
        {"output", required_argument, 0, 'o'},  {"help", no_argument, 0, 'h'},
        {0}};
    const char *acf = NULL, *spec = NULL, *size = NULL, *spacing = NULL, *out = NULL, *preview = NULL;
    const char *method, *tmp, *ptmp = NULL;
    char sbuf[1100];
    uint64_t seed = 1;
    unsigned flags = 0;
    int c, dim, json = 0, st;
    size_t n[3] = {1, 1, 1};
    double h[3] = {1, 1, 1};
    nl_model *m;
    synth_fft_plan *plan;
    synth_fft_info info;
    nl_field *f;
    nl_meta meta;

    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'a': acf = optarg; break;
        case 'S': spec = optarg; break;
        case 'n': size = optarg; break;
        case 's': seed = cli_parse_u64("--seed", optarg); break;
        case 'H': spacing = optarg; break;
        case 'c': flags |= SYNTH_FFT_CLAMP; break;
        case 'p': preview = optarg; break;
        case 'j': json = 1; break;
        case 'o': out = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("synth", c, argv);
        }
    }
    if (optind >= argc)
        cli_die(2, "synth: expected a METHOD (fft), see noiselab synth --help");
    method = argv[optind];
    if (optind + 1 < argc)
        cli_die(2, "synth: unexpected argument \"%s\"", argv[optind + 1]);
    if (strcmp(method, "fft") != 0) {
        for (size_t i = 0; i < sizeof methods_planned / sizeof *methods_planned; i++)
            if (strcmp(method, methods_planned[i]) == 0)
                cli_die(2, "synth: method \"%s\" is not available in this version (available: fft)", method);
        cli_die(2, "synth: unknown method \"%s\" (expected fft)", method);
    }
    if (!acf == !spec)
        cli_die(2, "synth: expected exactly one of --acf SPEC or --spectrum SPEC");
    if (!size)
        cli_die(2, "synth: --size: expected N, NxM or NxMxK");
    if (!out)
        cli_die(2, "synth: -o: expected an output file (.exr or .tsv)");
    dim = cli_parse_size("--size", size, n, 2);
    if (spacing)
        cli_parse_spacing("--spacing", spacing, dim, h);
    if (!cli_has_ext(out, ".exr") && !cli_has_ext(out, ".tsv"))
        cli_die(2, "-o: expected a file name ending in .exr or .tsv, got \"%s\"", out);
    if (cli_has_ext(out, ".tsv") && dim != 1)
        cli_die(2, "-o: TSV holds 1D fields; use .exr for a %dD field, got \"%s\"", dim, out);
    if (preview && dim == 1)
        cli_die(2, "--preview: expected a 2D or 3D field, got --size \"%s\"", size);
    if (preview && !cli_has_ext(preview, ".png"))
        cli_die(2, "--preview: expected a file name ending in .png, got \"%s\"", preview);
    if ((st = nl_model_parse(acf ? acf : spectrum_spec(spec, sbuf, sizeof sbuf), &m)))
        cli_die_status(st);
    if (acf && nl_model_is_spectral(m))
        cli_die(2, "--acf: \"%s\" is a spectrum model; pass it with --spectrum", acf);
    if (spec && !nl_model_is_spectral(m))
        cli_die(2, "--spectrum: \"%s\" is an autocorrelation model; pass it with --acf", spec);
    tmp = cli_out_begin(out);
    if (preview)
        ptmp = cli_out_begin(preview);
    if ((st = synth_fft_plan_alloc(m, dim, n, h, flags, &plan)))
        cli_die_status(st);
    synth_fft_plan_info(plan, &info);
    f = nl_field_alloc(dim, n, h, &st);
    if (!f)
        cli_die_status(st);
    if ((st = synth_fft_execute(plan, seed, f)))
        cli_die_status(st);

    memset(&meta, 0, sizeof meta);
    snprintf(meta.model, sizeof meta.model, "%s", nl_model_spec(m));
    snprintf(meta.method, sizeof meta.method, "fft%s", (flags & SYNTH_FFT_CLAMP) ? " clamp" : "");
    snprintf(meta.seed, sizeof meta.seed, "%" PRIu64, seed);
    snprintf(meta.version, sizeof meta.version, "%s", NL_VERSION);
    for (int a = 0, k = 0, l = 0; a < dim; a++) {
        k += snprintf(meta.spacing + k, sizeof meta.spacing - (size_t)k, "%s%.17g", a ? "," : "", h[a]);
        l += snprintf(meta.size + l, sizeof meta.size - (size_t)l, "%s%zu", a ? "x" : "", n[a]);
    }
    st = cli_has_ext(out, ".exr") ? nl_exr_write(tmp, f, &meta) : NL_OK;
    if (st)
        cli_die_status(st);
    if (cli_has_ext(out, ".tsv"))
        write_tsv(tmp, f);
    if (preview) {
        double sd = sqrt(info.variance);
        if ((st = nl_png_write_field(ptmp, f, -3 * sd, 3 * sd)))
            cli_die_status(st);
    }
    cli_out_commit(out);
    if (preview)
        cli_out_commit(preview);
    if (json)
        cli_json_print(json_pack("{s:s,s:s,s:I,s:s,s:f,s:f,s:f,s:I,s:f}", "model", nl_model_spec(m), "method",
                                 meta.method, "seed", (json_int_t)seed, "size", meta.size, "variance",
                                 info.variance, "min_spectrum", info.min_lambda, "max_spectrum",
                                 info.max_lambda, "clamped", (json_int_t)info.negatives, "clamp_error",
                                 info.clamp_error));
    nl_field_free(f);
    synth_fft_plan_free(plan);
    nl_model_free(m);
    return 0;
}
