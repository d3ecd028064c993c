/* noiselab card: one picture of a 1D or 2D field in the manner of Lagae et
 * al.'s survey of procedural noise: the field, its ACF against the target,
 * its spectrum (2D: as a map with frequency axes and a colour scale, and
 * radially averaged) and its histogram.  The data go to a temporary folder
 * (cli/card_data.c) and gnuplot draws them. */
#include "cli.h"
#include "opt.h"
#include "card.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/welch.h"
#include "../core/model.h"
#include "../core/nl_error.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab card FIELD -o CARD.png [--acf SPEC | --spectrum SPEC]\n\n"
    "One picture of a 1D or 2D field, drawn by gnuplot:\n"
    "  field          2D: grey levels, mean -+ 3 sd, with its colour bar and axes in\n"
    "                 length units (row 0 at the top); 1D: the series against t\n"
    "  ACF            the biased estimate along x (and y), lags in length units,\n"
    "                 against the model's R (when given); 1D: with Bartlett's 95% band\n"
    "  spectrum       2D: the periodogram and the Welch average over segments of a\n"
    "                 quarter of the side, log10 of the density on frequency axes\n"
    "                 (cycles per unit) with a colour bar, and the radial average of\n"
    "                 the Welch estimate against the model's; 1D: periodogram, Welch\n"
    "                 (segments of n/16) and the model's spectrum on log-log axes\n"
    "  histogram      a density against the Gaussian of the same mean and variance\n"
    "Fields larger than 512 samples a side are shown every k-th sample (the field)\n"
    "or as k x k block means (the periodogram); the estimates use every sample.\n";

/* The command's options. */
typedef struct {
    const char *out, *spec; /* -o, --acf or --spectrum */
} opts_t;

static const cli_opt rows[] = {
    CLI_OPT_OUTPUT(opts_t, out), CLI_OPT_MODEL(opts_t, spec), {0}};

static const char *parse(int argc, char **argv, const char **spec)
{
    opts_t a = {0};
    if (cli_opt_parse("card", help, rows, &a, argc, argv))
        exit(0);
    const char *out = a.out;
    *spec = a.spec;
    cli_one_operand("card", "field file", argc, argv);
    if (!out || !cli_has_ext(out, ".png"))
        cli_die(2, "card: -o: expected an output file ending in .png");
    return out;
}

/* gnuplot's settings for a log10 spectrum map with its colour bar. */
static void map_style(FILE *fp, double top)
{
    fprintf(fp, "set palette defined (0 '#000004', 1 '#3b0f70', 2 '#8c2981', 3 '#de4968', 4 '#fe9f6d', "
                "5 '#fcfdbf')\nset cbrange [%.6g:%.6g]\nset cblabel 'log_{10} S' offset 1,0\nset colorbox\n"
                "unset key\nset autoscale xfix\nset autoscale yfix\n"
                "set size ratio -1\nset xlabel 'f_x (cycles per unit)'\nset ylabel 'f_y'\n",
            top - 6, top);
}

static void script_2d(FILE *fp, const cli_card *c)
{
    fprintf(fp, "set terminal pngcairo size 1500,920 font 'DejaVu Sans,10'\nset output '%s'\n"
                "set multiplot layout 2,3 title '%s%s%s'\n",
            c->out, c->name, c->spec ? " against " : "", c->spec ? c->spec : "");
    fprintf(fp, "set title 'field'\nset palette gray\nset cbrange [%.8g:%.8g]\nset cblabel 'value' offset 1,0\n"
                "set size ratio -1\nset xlabel 'x'\nset ylabel 'y'\nunset key\nset tics out\n"
                "set xrange [%.8g:%.8g]\nset yrange [%.8g:%.8g]\n"
                "plot '%s/field.bin' binary array=(%zu,%zu) format='%%float64' dx=%.10g dy=%.10g with image\n",
            c->lo, c->hi, -0.5 * c->fdx, (double)c->fn[0] * c->fdx - 0.5 * c->fdx,
            (double)c->fn[1] * c->fdy - 0.5 * c->fdy, -0.5 * c->fdy, c->dir, c->fn[0], c->fn[1], c->fdx, c->fdy);
    fprintf(fp, "set autoscale\nset size noratio\nunset colorbox\nset key top right\nset title 'ACF'\n"
                "set xlabel 'lag (length units)'\nset ylabel 'R'\nset yrange [*:*]\nset xzeroaxis\n"
                "plot '%s/acf.tsv' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'along x', "
                "'' using 6:3 with lines lw 2 lc rgb '#c0392b' title 'along y'%s\n",
            c->dir, c->spec ? ", '' using 1:4 with lines dt 2 lw 2 lc rgb 'black' title 'model, x', "
                              "'' using 6:5 with lines dt 3 lw 2 lc rgb '#555555' title 'model, y'" : "");
    fprintf(fp, "unset xzeroaxis\nset title 'histogram'\nset xlabel 'value'\nset ylabel 'density'\n"
                "plot '%s/hist.tsv' using 1:2 with boxes lc rgb '#9fb6cd' title 'field', "
                "'' using 1:3 with lines lw 2 lc rgb 'black' title 'Gaussian'\n", c->dir);
    map_style(fp, c->top);
    fprintf(fp, "set title 'periodogram%s'\nplot '%s/per.bin' binary array=(%zu,%zu) format='%%float64' "
                "dx=%.10g dy=%.10g origin=(%.10g,%.10g) with image\n",
            c->block > 1 ? " (block means)" : "", c->dir, c->pn[0], c->pn[1], c->pdx, c->pdy, c->px0, c->py0);
    fprintf(fp, "set title 'Welch, %zu segments of %zu'\nplot '%s/welch.bin' binary array=(%zu,%zu) "
                "format='%%float64' dx=%.10g dy=%.10g origin=(%.10g,%.10g) with image\n",
            c->nseg, c->seg, c->dir, c->seg, c->seg, c->wdx, c->wdy, c->wx0, c->wy0);
    fprintf(fp, "unset colorbox\nset size noratio\nset autoscale\nset logscale xy\nset format y '10^{%%L}'\n"
                "set key bottom left\nset title 'radial spectrum (Welch)'\nset xlabel 'cycles per unit'\n"
                "set ylabel 'S'\nplot '%s/radial.tsv' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'measured'%s\n"
                "unset multiplot\n",
            c->dir, c->spec ? ", '' using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'model'" : "");
}

static void script_1d(FILE *fp, const cli_card *c)
{
    fprintf(fp, "set terminal pngcairo size 1200,820 font 'DejaVu Sans,10'\nset output '%s'\n"
                "set multiplot layout 2,2 title '%s%s%s'\nset tics out\n",
            c->out, c->name, c->spec ? " against " : "", c->spec ? c->spec : "");
    fprintf(fp, "set title 'field'\nunset key\nset autoscale xfix\nset xlabel 't'\nset ylabel 'value'\n"
                "plot '%s/field.tsv' using 1:2 with lines lc rgb '#1f4e99'\n", c->dir);
    fprintf(fp, "set autoscale x\nset key top right\nset title 'ACF with Bartlett 95%% band'\nset xlabel 'lag (length units)'\n"
                "set ylabel 'R'\nset xzeroaxis\n"
                "plot '%s/acf.tsv' using 1:3:4 with filledcurves lc rgb '#cfdcec' title '95%% band', "
                "'' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'measured'%s\n",
            c->dir, c->spec ? ", '' using 1:5 with lines dt 2 lw 2 lc rgb 'black' title 'model'" : "");
    fprintf(fp, "unset xzeroaxis\nset logscale xy\nset format y '10^{%%L}'\nset key bottom left\n"
                "set title 'spectrum'\nset xlabel 'cycles per unit'\nset ylabel 'S (two-sided density)'\n"
                "plot '%s/per.tsv' using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'periodogram', "
                "'%s/welch.tsv' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'Welch, %zu segments of %zu'",
            c->dir, c->dir, c->nseg, c->seg);
    if (c->spec)
        fprintf(fp, ", '%s/per.tsv' using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'model'", c->dir);
    fprintf(fp, "\n");
    fprintf(fp, "unset logscale\nset format y '%%g'\nset key top right\nset title 'histogram'\n"
                "set xlabel 'value'\nset ylabel 'density'\n"
                "plot '%s/hist.tsv' using 1:2 with boxes lc rgb '#9fb6cd' title 'field', "
                "'' using 1:3 with lines lw 2 lc rgb 'black' title 'Gaussian'\nunset multiplot\n", c->dir);
}

static void run_gnuplot(const cli_card *c)
{
    char path[4200];
    FILE *fp;
    snprintf(path, sizeof path, "%s/card.gp", c->dir);
    if (!(fp = fopen(path, "w")))
        cli_die(1, "card: cannot write %s", path);
    if (c->dim == 2)
        script_2d(fp, c);
    else
        script_1d(fp, c);
    if (fclose(fp))
        cli_die(1, "card: cannot write %s", path);
    snprintf(path, sizeof path, "gnuplot '%s/card.gp' 2>&1", c->dir);
    if (system(path) != 0)
        cli_die(1, "card: gnuplot failed");
}

int cli_cmd_card(int argc, char **argv)
{
    cli_card c = {0};
    char dir[] = "/tmp/noiselab-card-XXXXXX", cmd[4200];
    const char *out = parse(argc, argv, &c.spec);
    nl_field *x = cli_read_field(argv[optind], NULL);
    nl_model *m = NULL;
    int st;
    c.name = argv[optind];
    c.dim = x->dim;
    if (!((x->dim == 2 && x->n[0] >= 32 && x->n[1] >= 32) || (x->dim == 1 && x->n[0] >= 64)))
        cli_die(2, "card: expected a 1D field of at least 64 samples or a 2D field of at least 32 x 32, %s is not",
                c.name);
    if (c.spec && (st = nl_model_parse(c.spec, &m)))
        cli_die_status(st);
    if (m && (st = nl_model_check_dim(m, x->dim)))
        cli_die(2, "--acf: %s", nl_errmsg());
    cli_card_prepare(&c, x);
    c.out = cli_out_begin(out);
    if (!cli_out_tmpdir(dir))
        cli_die(1, "card: cannot create a temporary directory");
    c.dir = dir;
    cli_card_write(&c, x, m);
    run_gnuplot(&c);
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        cli_die(1, "card: cannot remove %s", dir);
    cli_out_commit(out);
    nl_field_free(x);
    nl_model_free(m);
    return 0;
}
