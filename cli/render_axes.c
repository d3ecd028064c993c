/* render --axes: the field as gnuplot draws it, with its axes in length
 * units (the field's spacing), a title and a colour bar, so that a picture
 * of a field or of an ACF map can be shown as it is. */
#include "cli.h"
#include "render_axes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* s as a gnuplot single-quoted string body (a quote doubled). */
static void quoted(FILE *fp, const char *s)
{
    for (; *s; s++)
        fputs(*s == '\'' ? "''" : (char[]){*s, 0}, fp);
}

static void script(FILE *fp, const nl_field *x, double lo, double hi, int kind, const char *name, const char *dir,
                   const char *tmp)
{
    double dx = x->h[0], dy = x->h[1], w = (double)x->n[0] * dx, h = (double)x->n[1] * dy;
    double x0 = kind == CLI_AXES_LAGS ? -(double)((x->n[0] - 1) / 2) * dx : 0;
    double y0 = kind == CLI_AXES_LAGS ? -(double)((x->n[1] - 1) / 2) * dy : 0;
    fprintf(fp, "set terminal pngcairo size %d,%d font 'DejaVu Sans,11'\nset output '", 760, 700);
    quoted(fp, tmp);
    fprintf(fp, "'\nset title '");
    quoted(fp, name);
    fprintf(fp, "' noenhanced\nset palette gray\nset cbrange [%.10g:%.10g]\nset cblabel 'value'\nset colorbox\n"
                "set size ratio -1\nunset key\nset tics out\nset xlabel '%s'\nset ylabel '%s'\n"
                "set xrange [%.10g:%.10g]\n",
            lo, hi, kind == CLI_AXES_LAGS ? "lag x (length units)" : "x (length units)",
            kind == CLI_AXES_LAGS ? "lag y (length units)" : "y (length units)", x0 - 0.5 * dx, x0 + w - 0.5 * dx);
    if (kind == CLI_AXES_LAGS)
        fprintf(fp, "set yrange [%.10g:%.10g]\n", y0 - 0.5 * dy, y0 + h - 0.5 * dy);
    else  /* row 0 at the top, as the grey picture */
        fprintf(fp, "set yrange [%.10g:%.10g]\n", h - 0.5 * dy, -0.5 * dy);
    fprintf(fp, "plot '%s/field.bin' binary array=(%zu,%zu) format='%%float64' dx=%.10g dy=%.10g "
                "origin=(%.10g,%.10g) with image\n",
            dir, x->n[0], x->n[1], dx, dy, x0, y0);
}

void cli_render_axes(const nl_field *x, double lo, double hi, int kind, const char *name, const char *tmp)
{
    char dir[] = "/tmp/noiselab-axes-XXXXXX", path[4200];
    FILE *fp;
    if (!cli_out_tmpdir(dir))
        cli_die(1, "render: cannot create a temporary directory");
    snprintf(path, sizeof path, "%s/field.bin", dir);
    if (!(fp = fopen(path, "wb")) || fwrite(x->data, sizeof(double), x->count, fp) != x->count || fclose(fp))
        cli_die(1, "render: cannot write %s", path);
    snprintf(path, sizeof path, "%s/axes.gp", dir);
    if (!(fp = fopen(path, "w")))
        cli_die(1, "render: cannot write %s", path);
    script(fp, x, lo, hi, kind, name, dir, tmp);
    if (fclose(fp))
        cli_die(1, "render: cannot write %s", path);
    snprintf(path, sizeof path, "gnuplot '%s/axes.gp' 2>&1 && rm -rf '%s'", dir, dir);
    if (system(path) != 0)
        cli_die(1, "render: gnuplot failed");
}
