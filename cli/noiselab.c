/* noiselab: synthesise random fields with a prescribed autocorrelation or
 * spectrum, and measure what was produced. */
#include "cli.h"
#include "../core/fftw_plan.h"
#include "../core/version.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const struct {
    const char *name;
    int (*run)(int, char **);
    const char *summary;
} commands[] = {
    {"models", cli_cmd_models, "list the autocorrelation and spectrum models with their parameters"},
    {"formats", cli_cmd_formats, "list the field file formats (-o, --format) with what each holds"},
    {"validate", cli_cmd_validate, "check a model and test every method on it: a report with a verdict"},
    {"check", cli_cmd_check, "is a model positive definite, how smooth, where singular"},
    {"coeffs", cli_cmd_coeffs, "subdivision coefficients, variances and flags per level"},
    {"synth", cli_cmd_synth, "synthesise a field by one of the methods fft, subdiv, midpoint,\n"
                               "           circulant, cholesky, faulting, sparse, lattice, intrinsic"},
    {"acf", cli_cmd_acf, "estimate the autocorrelation of a field"},
    {"psd", cli_cmd_psd, "estimate the power spectral density of a field (periodogram)"},
    {"hist", cli_cmd_hist, "histogram, moments and goodness of fit of a field"},
    {"nonlin", cli_cmd_nonlin, "predicted ACF and spectrum after a memoryless nonlinearity"},
    {"shape", cli_cmd_shape, "memoryless distribution shaping of a field"},
    {"lattice", cli_cmd_lattice, "rank-1 lattices, wave vectors, one-FFT random fields (Keller)"},
    {"cloud", cli_cmd_cloud, "render a cloud: kriged shape plus noise, ray-marched"},
    {"krige", cli_cmd_krige, "kriging of scattered data onto a grid (Stam and Fiume)"},
    {"variogram", cli_cmd_variogram, "empirical variogram of scattered points or a field (as gstat)"},
    {"fit", cli_cmd_fit, "fit a covariance model to scattered data or a field (variogram WLS, ML, REML)"},
    {"sample", cli_cmd_sample, "a field's values at given or random points (a data table)"},
    {"ocean", cli_cmd_ocean, "Tessendorf ocean waves on a Fibonacci lattice or a grid"},
    {"card", cli_cmd_card, "one picture of a field (1D or 2D): field, ACF, spectra, histogram"},
    {"render", cli_cmd_render, "a 2D field as a picture: grey levels, shaded relief or landscape"},
    {"detect", cli_cmd_detect, "creases and aliasing in a subdivision field"},
    {"bench", cli_cmd_bench, "speed of the methods against this machine's floor (TSV)"},
};

static void usage(FILE *fp)
{
    fprintf(fp, "usage: noiselab COMMAND [OPTIONS]\n\n"
                "Synthesise random fields with a prescribed autocorrelation or spectrum,\n"
                "and measure what was produced.\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        fprintf(fp, "  %-8s %s\n", commands[i].name, commands[i].summary);
    fprintf(fp, "\n`noiselab COMMAND --help` describes each; `noiselab --version` prints the version.\n");
}

int cli_main(int argc, char **argv)
{
    static int saving;
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("noiselab %s\n", nl_version());
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
        if (strcmp(argv[1], commands[i].name) == 0) {
            int rc;
            if (!saving++)
                atexit(nl_fftw_save); /* commands may exit() from deep inside */
            cli_out_start(argc, argv);
            cli_limits();
            rc = commands[i].run(argc - 1, argv + 1);
            /* the standard output is an output too: flushed before the files are committed */
            if (rc == 0 && (fflush(stdout) || ferror(stdout)))
                cli_die(1, "standard output: write failed: %s", strerror(errno));
            cli_out_finish(rc == 0);
            return rc;
        }
    cli_die(2, "unknown command \"%s\" (expected one of: models, formats, validate, check, coeffs, synth, acf, psd, hist, nonlin, shape, krige, variogram, fit, sample, cloud, lattice, ocean, card, render, detect, bench; see noiselab --help)",
            argv[1]);
}
