/* noiselab card: one picture of a 2D field in the manner of Lagae et al.'s
 * survey of procedural noise. */
#include "cli.h"
#include "../analysis/fftshift.h"
#include "../analysis/hist.h"
#include "../analysis/psd.h"
#include "../analysis/radial.h"
#include "../analysis/welch.h"
#include "../core/model.h"
#include "../core/nl_error.h"
#include "../core/wk.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab card FIELD -o CARD.png [--acf SPEC | --spectrum SPEC]\n\n"
    "One picture of a 2D field: the field; one periodogram and the Welch average over\n"
    "segments of a quarter of the side (log scale, zero frequency at the centre); the\n"
    "radial spectrum against the model's (when given); the histogram against the\n"
    "Gaussian of the same mean and variance.  Drawn by gnuplot.\n";

/* A spectrum, centred, as a log-scale picture spanning 7 decades. */
static void write_log_picture(const char *path, const nl_field *P)
{
    nl_field *C;
    double mx;
    cli_check(nl_fftshift_alloc(P, &C));
    mx = log10(nl_fftshift_log10_floor(C, 1e-8));
    nl_png_write_field(path, C, mx - 7, mx);
    nl_field_free(C);
}

/* The model's spectrum on the Welch grid, finite everywhere. */
static nl_field *model_spectrum(const nl_field *W, const nl_model *m, const char *spec)
{
    int st;
    nl_field *S = nl_field_alloc(2, W->n, W->h, &st);
    if (!S)
        cli_die_status(st);
    if ((st = nl_wk_sample_spectrum(m, S))) {
        nl_field_free(S);
        cli_die(nl_error_is_input(st) ? 2 : 1, "--acf: %s", nl_errmsg());
    }
    for (size_t i = 0; i < S->count; i++)
        if (!isfinite(S->data[i])) {
            double bad = S->data[i];
            nl_field_free(S);
            cli_die(2, "--acf: %s has a spectrum of %g at a frequency of the card's grid; expected a finite "
                    "spectrum", spec, bad);
        }
    return S;
}

/* Radial spectra on the Welch grid: measured and (with the model's spectrum S) the model's. */
static void write_radial(const char *path, const nl_field *W, const nl_field *S, size_t seg)
{
    size_t nb = seg / 2 + 1, *cnt = cli_malloc(nb * sizeof *cnt);
    double *r = cli_malloc(nb * sizeof *r), *v = cli_malloc(nb * sizeof *v), *t = cli_malloc(nb * sizeof *t);
    double step = 1.0 / ((double)seg * W->h[0]);
    nl_radial(W, NL_GRID_FREQ, step, nb, r, v, cnt);
    for (size_t b = 0; b < nb; b++)
        t[b] = NAN;
    if (S) {
        double *rr = cli_malloc(nb * sizeof *rr);
        nl_radial(S, NL_GRID_FREQ, step, nb, rr, t, cnt);
        free(rr);
    }
    FILE *fp = fopen(path, "w");
    fprintf(fp, "f\twelch\ttarget\n");
    for (size_t b = 1; b < nb; b++)
        fprintf(fp, "%.8g\t%.8g\t%.8g\n", r[b], v[b], t[b]);
    fclose(fp);
    free(cnt), free(r), free(v), free(t);
}

/* The histogram as a density against the Gaussian of the same moments. */
static void write_hist(const char *path, const nl_field *x, const nl_moments *mo)
{
    double mid[40], dens[40], gauss[40];
    FILE *fp;
    nl_hist_density(x, mo, 40, mid, dens, gauss);
    fp = fopen(path, "w");
    fprintf(fp, "x\tdensity\tgauss\n");
    for (int b = 0; b < 40; b++)
        fprintf(fp, "%.8g\t%.8g\t%.8g\n", mid[b], dens[b], gauss[b]);
    fclose(fp);
}

static void write_script(const char *path, const char *dir, const char *tmp, const char *name, const char *spec,
                         size_t nseg)
{
    FILE *fp = fopen(path, "w");
    fprintf(fp, "set terminal pngcairo size 1500,360 font 'DejaVu Sans,10'\nset output '%s'\n"
                "set multiplot layout 1,5 title '%s%s%s'\nunset key\nunset tics\nunset border\nset size ratio -1\n"
                "set title 'field'\nplot '%s/field.png' binary filetype=png with rgbimage\n"
                "set title 'periodogram (log)'\nplot '%s/periodogram.png' binary filetype=png with rgbimage\n"
                "set title 'Welch, %zu segments (log)'\nplot '%s/welch.png' binary filetype=png with rgbimage\n"
                "set size noratio\nset border\nset tics\nset key bottom left\nset logscale xy\nset format y '10^{%%L}'\n"
                "set title 'radial spectrum'\nset xlabel 'cycles per unit'\n"
                "plot '%s/radial.tsv' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'measured'%s\n"
                "unset logscale\nset format y '%%g'\nset xlabel 'value'\nset key top right\n"
                "set title 'histogram'\nplot '%s/hist.tsv' using 1:2 with boxes lc rgb '#9fb6cd' title 'field', "
                "'' using 1:3 with lines lw 2 lc rgb 'black' title 'Gaussian'\nunset multiplot\n",
            tmp, name, spec ? " against " : "", spec ? spec : "", dir, dir, nseg, dir, dir,
            spec ? ", '' using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'model'" : "", dir);
    fclose(fp);
}

static const char *parse(int argc, char **argv, const char **spec)
{
    static const struct option opts[] = {{"output", required_argument, 0, 'o'}, {"acf", required_argument, 0, 'a'},
                                         {"spectrum", required_argument, 0, 'a'}, {"help", no_argument, 0, 'h'},
                                         {0}};
    const char *out = NULL;
    int c;
    while ((c = cli_getopt(argc, argv, ":ho:", opts, "card")) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 'a': *spec = optarg; break;
        case 'h': fputs(help, stdout); exit(0);
        }
    }
    cli_one_operand("card", "field file", argc, argv);
    if (!out || !cli_has_ext(out, ".png"))
        cli_die(2, "card: -o: expected an output file ending in .png");
    return out;
}

int cli_cmd_card(int argc, char **argv)
{
    const char *spec = NULL, *out = parse(argc, argv, &spec);
    int st;
    nl_field *x = cli_read_field(argv[optind], NULL), *P, *W;
    if (x->dim != 2 || x->n[0] < 32 || x->n[1] < 32)
        cli_die(2, "card: expected a 2D field of at least 32 x 32, %s is not", argv[optind]);
    nl_model *m = NULL;
    if (spec && (st = nl_model_parse(spec, &m)))
        cli_die_status(st);
    nl_moments mo;
    size_t seg = (x->n[0] < x->n[1] ? x->n[0] : x->n[1]) / 4, nseg;
    if ((st = nl_moments_compute(x, &mo)) || (st = nl_psd_periodogram(x, NAN, &P)) ||
        (st = nl_psd_welch(x, seg, NAN, &W, &nseg)))
        cli_die_status(st);
    if (!(mo.variance > 0))
        cli_die(2, "card: %s is constant (%g everywhere); expected a field that varies", argv[optind], mo.mean);
    nl_field *S = m ? model_spectrum(W, m, spec) : NULL;
    const char *tmp = cli_out_begin(out);
    char dir[] = "/tmp/noiselab-card-XXXXXX", path[4200];
    if (!cli_out_tmpdir(dir))
        cli_die(1, "card: cannot create a temporary directory");
    snprintf(path, sizeof path, "%s/field.png", dir);
    double sd = sqrt(mo.variance);
    cli_check(nl_png_write_field(path, x, mo.mean - 3 * sd, mo.mean + 3 * sd));
    snprintf(path, sizeof path, "%s/periodogram.png", dir);
    write_log_picture(path, P);
    snprintf(path, sizeof path, "%s/welch.png", dir);
    write_log_picture(path, W);
    snprintf(path, sizeof path, "%s/radial.tsv", dir);
    write_radial(path, W, S, seg);
    snprintf(path, sizeof path, "%s/hist.tsv", dir);
    write_hist(path, x, &mo);
    snprintf(path, sizeof path, "%s/card.gp", dir);
    write_script(path, dir, tmp, argv[optind], m ? spec : NULL, nseg);
    snprintf(path, sizeof path, "gnuplot '%s/card.gp' 2>&1", dir);
    if (system(path) != 0)
        cli_die(1, "card: gnuplot failed");
    snprintf(path, sizeof path, "rm -rf '%s'", dir);
    if (system(path) != 0)
        cli_die(1, "card: cannot remove %s", dir);
    cli_out_commit(out);
    nl_field_free(P), nl_field_free(W), nl_field_free(x), nl_field_free(S), nl_model_free(m);
    return 0;
}
