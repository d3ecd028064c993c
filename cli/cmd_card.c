/* noiselab card: one picture of a 1D or 2D field in the manner of Lagae et
 * al.'s survey of procedural noise: the field, its ACF against the target,
 * its spectrum (2D: as a map with frequency axes and a colour scale, and
 * radially averaged) and its histogram, with the bands where the estimates
 * of a field of the model fall; or the same of the mean of an ensemble of
 * fields.  The data go to a temporary folder (cli/card_data.c,
 * cli/card_ensemble.c) and gnuplot draws them (cli/card_script.c). */
#include "cli.h"
#include "opt.h"
#include "card.h"
#include "inputs.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab card FIELD... -o CARD.png [--acf SPEC | --spectrum SPEC]\n"
    "       noiselab card --realizations K --acf SPEC --size N [--seed S] -o CARD.png\n\n"
    "One picture of a 1D or 2D field, drawn by gnuplot, each panel with its axes\n"
    "in length units and its key below it:\n"
    "  field          2D: grey levels, mean -+ 3 sd, with its colour bar (row 0 at\n"
    "                 the top); 1D: the series against t\n"
    "  ACF            the biased estimate along x (and y) against the model's R, with\n"
    "                 the model's 95% band: where the estimate of a field of the model\n"
    "                 falls (nl_acf_model_band: Bartlett's variance with the model's R,\n"
    "                 around the estimate's expectation); without a model, 1D:\n"
    "                 Bartlett's plug-in band around the estimate\n"
    "  spectrum       1D: periodogram and Welch (segments of n/16) on log-log axes with\n"
    "                 the model's spectrum and its 95% bands (one ordinate: S times\n"
    "                 [0.025, 3.69], chi-square 2; Welch: chi-square with its equivalent\n"
    "                 degrees of freedom); 2D: periodogram and Welch maps (log10 on\n"
    "                 frequency axes, colour bar) and the radial average of the\n"
    "                 periodogram with the model's band for the ordinates averaged\n"
    "  histogram      a density against the model's N(0, R(0)) with the band where a\n"
    "                 field's histogram falls (its correlation widens it), or without\n"
    "                 a model against the Gaussian of the field's mean and variance\n"
    "Several FIELDs (one size and spacing), or --realizations K (K >= 2: the fields\n"
    "of noiselab synth fft --acf SPEC --size N with seeds S (default 1) to S + K - 1),\n"
    "make an ensemble card: the mean of the K estimates with +- 1.96 standard errors\n"
    "against the model and its bands for a mean of K (ACF and histogram: over\n"
    "sqrt(K); periodogram: chi-square with 2K degrees of freedom per ordinate); 2D\n"
    "shows the mean periodogram beside the model's spectrum.\n"
    "Fields larger than 512 samples a side are shown every k-th sample (the field)\n"
    "or as k x k block means (the periodogram); the estimates use every sample.\n";

/* The command's options. */
typedef struct {
    const char *out;  /* -o */
    cli_inputs src;   /* files or realizations; src.spec: --acf or --spectrum */
} opts_t;

static const cli_opt rows[] = {CLI_OPT_OUTPUT(opts_t, out), CLI_STRING("spectrum", opts_t, src.spec),
                               CLI_GROUP(cli_inputs_rows, opts_t, src), {0}};

static void parse(int argc, char **argv, opts_t *a)
{
    const char *spec;
    if (cli_opt_parse("card", help, rows, a, argc, argv))
        exit(0);
    spec = a->src.spec;
    if (!a->src.K)  /* files: --acf is the model to compare with */
        a->src.spec = NULL;
    cli_inputs_operands(&a->src, "card", argc, argv);
    a->src.spec = spec;
    if (!a->out || !cli_has_ext(a->out, ".png"))
        cli_die(2, "card: -o: expected an output file ending in .png");
}

static void run_gnuplot(const cli_card *c, int have_model)
{
    char path[4200];
    FILE *fp;
    snprintf(path, sizeof path, "%s/card.gp", c->dir);
    if (!(fp = fopen(path, "w")))
        cli_die(1, "card: cannot write %s", path);
    cli_card_script(fp, c, have_model);
    if (fclose(fp))
        cli_die(1, "card: cannot write %s", path);
    snprintf(path, sizeof path, "gnuplot '%s/card.gp' 2>&1", c->dir);
    if (system(path) != 0)
        cli_die(1, "card: gnuplot failed");
}

/* NOISELAB_CARD_KEEP=DIR keeps the data and script there (for tests). */
static void finish(const cli_card *c)
{
    char cmd[8500];
    const char *keep = getenv("NOISELAB_CARD_KEEP");
    if (keep && *keep)
        snprintf(cmd, sizeof cmd, "cp '%s'/* '%s'/ && rm -rf '%s'", c->dir, keep, c->dir);
    else
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", c->dir);
    if (system(cmd) != 0)
        cli_die(1, "card: cannot remove %s", c->dir);
}

int cli_cmd_card(int argc, char **argv)
{
    cli_card c = {0};
    opts_t a = {0};
    char dir[] = "/tmp/noiselab-card-XXXXXX";
    nl_model *m = NULL;
    int st;
    parse(argc, argv, &a);
    nl_field *x = cli_inputs_read(&a.src, 0, NULL);
    c.spec = a.src.spec;
    c.name = cli_inputs_name(&a.src, 0);
    c.dim = x->dim;
    if (!((x->dim == 2 && x->n[0] >= 32 && x->n[1] >= 32) || (x->dim == 1 && x->n[0] >= 64)))
        cli_die(2, "card: expected a 1D field of at least 64 samples or a 2D field of at least 32 x 32, %s is not",
                c.name);
    if (c.spec && (st = nl_model_parse(c.spec, &m)))
        cli_die_status(st);
    if (m && (st = nl_model_check_dim(m, x->dim)))
        cli_die(2, "--acf: %s", nl_errmsg());
    cli_card_prepare(&c, x);
    c.out = cli_out_begin(a.out);
    if (!cli_out_tmpdir(dir))
        cli_die(1, "card: cannot create a temporary directory");
    c.dir = dir;
    if (a.src.count > 1)
        cli_card_ensemble_write(&c, &a.src, x, m);
    else
        cli_card_write(&c, x, m);
    run_gnuplot(&c, m != NULL);
    finish(&c);
    cli_out_commit(a.out);
    nl_field_free(x);
    nl_model_free(m);
    cli_inputs_free(&a.src);
    return 0;
}
