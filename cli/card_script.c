/* The gnuplot script of `noiselab card`: every panel with its axes named
 * and their units, a title that says what it shows, and the key below the
 * plot, clear of the data.  The files it reads are written by
 * cli/card_data.c (one field) and cli/card_ensemble.c (an ensemble). */
#include "card.h"

#include <stdio.h>

#define BAND "fs transparent solid 0.35 noborder"
#define KEY "set key below horizontal width 1 samplen 2 height 1.5\n"

/* The field: 2D grey levels with a colour bar, 1D the series. */
static void field_panel(FILE *fp, const cli_card *c)
{
    const char *which = c->K > 1 ? "field 1 of the ensemble" : "the field";
    if (c->dim == 1) {
        fprintf(fp, "set title '%s'\nunset key\nset autoscale xfix\nset xlabel 't (length units)'\n"
                    "set ylabel 'value'\nplot '%s/field.tsv' using 1:2 with lines lc rgb '#1f4e99'\n",
                which, c->dir);
        return;
    }
    fprintf(fp, "set title '%s%s'\nset palette gray\nset cbrange [%.8g:%.8g]\nset cblabel 'value' offset 1,0\n"
                "set colorbox\nset size ratio -1\nset xlabel 'x (length units)'\nset ylabel 'y (length units)'\n"
                "unset key\nset xrange [%.8g:%.8g]\nset yrange [%.8g:%.8g]\n"
                "plot '%s/field.bin' binary array=(%zu,%zu) format='%%float64' dx=%.10g dy=%.10g with image\n",
            which, c->stride > 1 ? " (one sample in k shown)" : "", c->lo, c->hi, -0.5 * c->fdx,
            (double)c->fn[0] * c->fdx - 0.5 * c->fdx, (double)c->fn[1] * c->fdy - 0.5 * c->fdy, -0.5 * c->fdy,
            c->dir, c->fn[0], c->fn[1], c->fdx, c->fdy);
    fprintf(fp, "set autoscale\nset size noratio\nunset colorbox\n");
}

/* The ACF along one axis: columns base+1.. of acf.tsv (lag, estimate, lo,
 * hi, R, E), and the ensemble's se in column se_col. */
static void acf_series(FILE *fp, const cli_card *c, int m, int base, int se_col, const char *axis,
                       const char *col, const char *fill, int first)
{
    char sfx[32] = "";
    if (c->dim == 2)
        snprintf(sfx, sizeof sfx, ", %s", axis);
    if (m || (c->dim == 1 && c->K == 1))
        fprintf(fp, "%s'%s/acf.tsv' using %d:%d:%d with filledcurves %s lc rgb '%s' title '%s%s'", first ? "" : ", ",
                c->dir, base + 1, base + 3, base + 4, BAND, fill,
                m ? (c->K > 1 ? "model band / √K" : "model 95% band") : "95% band (plug-in, around the estimate)",
                sfx), first = 0;
    if (c->K > 1)
        fprintf(fp, "%s'%s/acf.tsv' using %d:%d with lines lw 2 lc rgb '%s' title 'mean%s', "
                    "'' using %d:%d:(1.959964*$%d) every %zu with yerrorbars pt 7 ps 0.4 lc rgb '%s' "
                    "title '+- 1.96 se%s'",
                first ? "" : ", ", c->dir, base + 1, base + 2, col, sfx, base + 1, base + 2, se_col,
                (c->maxlag + 25) / 25, col, sfx);
    else
        fprintf(fp, "%s'%s/acf.tsv' using %d:%d with lines lw 2 lc rgb '%s' title 'estimate%s'", first ? "" : ", ",
                c->dir, base + 1, base + 2, col, sfx);
    if (m)
        fprintf(fp, ", '' using %d:%d with lines dt 2 lw 2 lc rgb '%s' title 'model R%s'", base + 1, base + 5,
                c->dim == 2 && base ? "#555555" : "black", sfx);
}

static void acf_panel(FILE *fp, const cli_card *c, int m)
{
    if (c->K > 1)
        fprintf(fp, "set title 'ACF: mean of %zu biased estimates%s'\n", c->K,
                m ? " against the model" : "");
    else
        fprintf(fp, "set title 'ACF: the biased estimate%s'\n",
                m ? " and where 95% of estimates fall under the model" : (c->dim == 1 ? ", Bartlett band" : ""));
    fprintf(fp, "set xlabel 'lag (length units)'\nset ylabel 'autocovariance (value^2)'\nset xzeroaxis\n"
                "set autoscale\n" KEY "plot ");
    acf_series(fp, c, m, 0, c->dim == 2 ? 13 : 7, "x", "#1f4e99", "#9ecae1", 1);
    if (c->dim == 2)
        acf_series(fp, c, m, 6, 14, "y", "#c0392b", "#f4a582", 0);
    fprintf(fp, "\nunset xzeroaxis\n");
}

static void hist_panel(FILE *fp, const cli_card *c, int m)
{
    fprintf(fp, "set title 'histogram%s'\nset xlabel 'value'\nset ylabel 'density (per unit value)'\n" KEY
                "set style fill solid 0.4 border lc rgb '#7f9fbf'\nset autoscale\nset yrange [0:*]\nplot ",
            m ? " against the model N(0, R(0))"
              : c->K > 1 ? " against the Gaussian of field 1''s mean and variance"
                         : " against the Gaussian of its mean and variance");
    if (m)
        fprintf(fp, "'%s/hist.tsv' using 1:5:6 with filledcurves %s lc rgb '#fdae6b' title '%s', ", c->dir, BAND,
                c->K > 1 ? "model band / √K" : "model 95% band");
    fprintf(fp, "'%s/hist.tsv' using 1:2 with boxes lc rgb '#9fb6cd' title '%s'", c->dir,
            c->K > 1 ? "mean density" : "field");
    if (c->K > 1)
        fprintf(fp, ", '' using 1:2:(1.959964*$7) with yerrorbars pt 0 lc rgb '#1f4e99' title '+- 1.96 se'");
    if (m)
        fprintf(fp, ", '' using 1:4 with lines lw 2 lc rgb 'black' title 'model'");
    else
        fprintf(fp, ", '' using 1:3 with lines lw 2 lc rgb 'black' title 'Gaussian'");
    fprintf(fp, "\nset style fill empty\nset yrange [*:*]\n");
}

/* 1D spectrum: periodogram(s) and Welch with the model's bands. */
static void spectrum_panel_1d(FILE *fp, const cli_card *c, int m)
{
    fprintf(fp, "set logscale xy\nset format y '10^{%%L}'\nset autoscale xfix\n" KEY
                "set xlabel 'frequency (cycles per unit length)'\n"
                "set ylabel 'S, two-sided (value^2·length)'\n");
    if (c->K > 1) {
        fprintf(fp, "set title 'spectrum: mean of %zu periodograms%s'\nplot ", c->K, m ? " against the model" : "");
        if (m)
            fprintf(fp, "'%s/per.tsv' using 1:4:5 with filledcurves %s lc rgb '#9ecae1' title 'model 95%% band "
                        "(chi^2_{2K})', ", c->dir, BAND);
        fprintf(fp, "'%s/per.tsv' using 1:2 with lines lw 1 lc rgb '#1f4e99' title 'mean', '' using "
                    "1:2:($2-1.959964*$6>0?$2-1.959964*$6:$2/10):($2+1.959964*$6) every %zu with yerrorbars pt 7 "
                    "ps 0.4 lc rgb '#1f4e99' title '+- 1.96 se'",
                c->dir, (c->n[0] / 2 + 39) / 40);
    } else {
        fprintf(fp, "set title 'spectrum: periodogram and Welch%s'\nplot ", m ? " with the model bands" : "");
        if (m)
            fprintf(fp, "'%s/per.tsv' using 1:4:5 with filledcurves %s lc rgb '#d9d9d9' title 'periodogram 95%% "
                        "band', '%s/welch.tsv' using 1:4:5 with filledcurves %s lc rgb '#9ecae1' title 'Welch "
                        "95%% band (ν = %.0f)', ",
                    c->dir, BAND, c->dir, BAND, c->welch_nu);
        fprintf(fp, "'%s/per.tsv' using 1:2 with points pt 7 ps 0.2 lc rgb '#808080' title 'periodogram', "
                    "'%s/welch.tsv' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'Welch, %zu segments of %zu'",
                c->dir, c->dir, c->nseg, c->seg);
    }
    if (m)
        fprintf(fp, ", '%s/per.tsv' using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'model'", c->dir);
    fprintf(fp, "\nunset logscale\nset format y '%%g'\n");
}

/* 2D: a log10 spectrum map with frequency axes and a colour bar. */
static void map_panel(FILE *fp, const cli_card *c, const char *title, const char *file, size_t nx, size_t ny,
                      double dx, double dy, double x0, double y0)
{
    fprintf(fp, "set palette defined (0 '#000004', 1 '#3b0f70', 2 '#8c2981', 3 '#de4968', 4 '#fe9f6d', "
                "5 '#fcfdbf')\nset cbrange [%.6g:%.6g]\nset cblabel 'log_{10} S (value^2·length^2)' offset 1,0\n"
                "set colorbox\nunset key\nset autoscale xfix\nset autoscale yfix\nset size ratio -1\n"
                "set xlabel 'f_x (cycles per unit length)'\nset ylabel 'f_y (cycles per unit length)'\n"
                "set title '%s'\nplot '%s/%s' binary array=(%zu,%zu) format='%%float64' dx=%.10g dy=%.10g "
                "origin=(%.10g,%.10g) with image\nunset colorbox\nset size noratio\nset autoscale\n",
            c->top - 6, c->top, title, c->dir, file, nx, ny, dx, dy, x0, y0);
}

static void radial_panel(FILE *fp, const cli_card *c, int m)
{
    fprintf(fp, "set logscale xy\nset format y '10^{%%L}'\nset autoscale xfix\n" KEY
                "set xlabel '|f| (cycles per unit length)'\n"
                "set ylabel 'S (value^2·length^2)'\nset title 'radial spectrum: %s%s'\nplot ",
            c->K > 1 ? "mean radial periodogram" : "radial average of the periodogram",
            m ? " against the model" : "");
    if (m)
        fprintf(fp, "'%s/radial.tsv' using 1:4:5 with filledcurves %s lc rgb '#9ecae1' title 'model 95%% band%s', ",
                c->dir, BAND, c->K > 1 ? " (mean of K)" : "");
    if (c->K > 1)
        fprintf(fp, "'%s/radial.tsv' using 1:2 with lines lw 1 lc rgb '#1f4e99' title 'mean', '' using "
                    "1:2:($2-1.959964*$6>0?$2-1.959964*$6:$2/10):($2+1.959964*$6) every %zu with yerrorbars pt 7 "
                    "ps 0.4 lc rgb '#1f4e99' title '+- 1.96 se'",
                c->dir, (c->n[0] / 2 + 39) / 40);
    else
        fprintf(fp, "'%s/radial.tsv' using 1:2 with lines lw 2 lc rgb '#1f4e99' title 'periodogram'", c->dir);
    if (m)
        fprintf(fp, ", '' using 1:3 with lines dt 2 lw 2 lc rgb 'black' title 'model'");
    fprintf(fp, "\nunset logscale\nset format y '%%g'\n");
}

void cli_card_script(FILE *fp, const cli_card *c, int m)
{
    char title[600];
    if (c->K > 1)
        snprintf(title, sizeof title, "%zu fields%s%s", c->K, m ? " against " : "", m ? c->spec : "");
    else
        snprintf(title, sizeof title, "%s%s%s", c->name, m ? " against " : "", m ? c->spec : "");
    fprintf(fp, "set terminal pngcairo size %s font 'DejaVu Sans,10'\nset output '%s'\n"
                "set multiplot layout 2,%d title '%s' noenhanced\nset tics out\n",
            c->dim == 2 ? "1500,1000" : "1200,900", c->out, c->dim == 2 ? 3 : 2, title);
    field_panel(fp, c);
    acf_panel(fp, c, m);
    if (c->dim == 1) {
        spectrum_panel_1d(fp, c, m);
        hist_panel(fp, c, m);
    } else {
        hist_panel(fp, c, m);
        const char *per = c->K > 1 ? "mean periodogram" : c->block > 1 ? "periodogram (block means)" : "periodogram";
        map_panel(fp, c, per, "per.bin", c->pn[0], c->pn[1], c->pdx, c->pdy, c->px0, c->py0);
        if (c->K > 1)
            map_panel(fp, c, m ? "the model''s spectrum" : "periodogram of field 1", m ? "model.bin" : "first.bin",
                      c->pn[0], c->pn[1], c->pdx, c->pdy, c->px0, c->py0);
        else {
            char t[96];
            snprintf(t, sizeof t, "Welch, %zu segments of %zu", c->nseg, c->seg);
            map_panel(fp, c, t, "welch.bin", c->seg, c->seg, c->wdx, c->wdy, c->wx0, c->wy0);
        }
        radial_panel(fp, c, m);
    }
    fprintf(fp, "unset multiplot\n");
}
