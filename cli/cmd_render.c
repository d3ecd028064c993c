/* noiselab render: a 2D field as an 8-bit picture, grey levels or shaded relief. */
#include "cli.h"
#include "../analysis/hist.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab render IN (-o OUT.png | --matrix OUT.txt) [--range LO:HI] [--shade AZ,EL]\n"
    "                       [--zscale Z] [--step K]\n\n"
    "Grey levels: values from LO to HI map onto 0..255 (default: mean +- 3 sd).\n"
    "--shade AZ,EL: the field as an obliquely illuminated height field (Lambert),\n"
    "light from azimuth AZ (degrees from +x toward +y) and elevation EL (degrees);\n"
    "heights are multiplied by Z (default 1) in units of the grid spacing.\n"
    "--matrix: the field as a whitespace matrix (gnuplot's `matrix`), every K-th sample\n"
    "(default 1), for perspective views with pm3d.\n";

int cmd_render(int argc, char **argv)
{
    static const struct option opts[] = {{"range", required_argument, 0, 'r'}, {"shade", required_argument, 0, 's'},
                                         {"zscale", required_argument, 0, 'z'}, {"output", required_argument, 0, 'o'},
                                         {"matrix", required_argument, 0, 'm'}, {"step", required_argument, 0, 'k'},
                                         {"help", no_argument, 0, 'h'},         {0}};
    const char *out = NULL, *tmp, *matrix = NULL;
    size_t step = 1;
    double lo = NAN, hi = NAN, az = NAN, el = NAN, zs = 1;
    int c, st;
    nl_field *x;
    opterr = 0;
    while ((c = getopt_long(argc, argv, ":ho:", opts, NULL)) != -1) {
        switch (c) {
        case 'r':
            if (sscanf(optarg, "%lf:%lf", &lo, &hi) != 2 || !(hi > lo) || !isfinite(lo) || !isfinite(hi))
                cli_die(2, "--range: expected LO:HI with LO < HI, got \"%s\"", optarg);
            break;
        case 's':
            if (sscanf(optarg, "%lf,%lf", &az, &el) != 2 || !(el > 0 && el <= 90))
                cli_die(2, "--shade: expected AZ,EL in degrees with 0 < EL <= 90, got \"%s\"", optarg);
            break;
        case 'z':
            zs = cli_parse_double("--zscale", optarg);
            if (!(zs > 0))
                cli_die(2, "--zscale: expected a positive factor, got \"%s\"", optarg);
            break;
        case 'o': out = optarg; break;
        case 'm': matrix = optarg; break;
        case 'k': step = cli_parse_count("--step", optarg, 1); break;
        case 'h': fputs(help, stdout); return 0;
        default: cli_bad_option("render", c, argv);
        }
    }
    if (optind + 1 != argc)
        cli_die(2, "render: expected one input file, got %d", argc - optind);
    if (!out && !matrix)
        cli_die(2, "render: expected -o OUT.png or --matrix OUT.txt");
    if (out && !cli_has_ext(out, ".png"))
        cli_die(2, "render: -o: expected an output file ending in .png, got \"%s\"", out);
    x = cli_read_field(argv[optind], NULL);
    if (x->dim != 2)
        cli_die(2, "render: expected a 2D field, %s is %dD", argv[optind], x->dim);
    if (matrix) {
        const char *mt = cli_out_begin(matrix);
        FILE *fp = fopen(mt, "w");
        if (!fp)
            cli_die(2, "--matrix: cannot write \"%s\"", matrix);
        for (size_t j = 0; j < x->n[1]; j += step)
            for (size_t i = 0; i < x->n[0]; i += step)
                fprintf(fp, "%.6g%c", x->data[j * x->n[0] + i], i + step < x->n[0] ? ' ' : '\n');
        if (fclose(fp))
            cli_die(1, "--matrix: write failed");
        cli_out_commit(matrix);
        if (!out) {
            nl_field_free(x);
            return 0;
        }
    }
    tmp = cli_out_begin(out);
    if (!isnan(az)) {
        size_t nx = x->n[0], ny = x->n[1];
        nl_field *s = nl_field_alloc(2, x->n, x->h, &st);
        double l[3] = {cos(el * M_PI / 180) * cos(az * M_PI / 180), cos(el * M_PI / 180) * sin(az * M_PI / 180),
                       sin(el * M_PI / 180)};
        if (!s)
            cli_die_status(st);
        for (size_t j = 0; j < ny; j++)
            for (size_t i = 0; i < nx; i++) {
                /* central differences, one-sided at the edges */
                size_t i0 = i ? i - 1 : i, i1 = i + 1 < nx ? i + 1 : i, j0 = j ? j - 1 : j, j1 = j + 1 < ny ? j + 1 : j;
                double gx = zs * (x->data[j * nx + i1] - x->data[j * nx + i0]) / ((double)(i1 - i0) * x->h[0]);
                double gy = zs * (x->data[j1 * nx + i] - x->data[j0 * nx + i]) / ((double)(j1 - j0) * x->h[1]);
                double n = sqrt(gx * gx + gy * gy + 1);
                s->data[j * nx + i] = fmax(0, (-gx * l[0] - gy * l[1] + l[2]) / n);
            }
        st = nl_png_write_field(tmp, s, 0, 1);
        nl_field_free(s);
    } else {
        if (isnan(lo)) {
            an_moments m;
            if ((st = an_moments_compute(x, &m)))
                cli_die_status(st);
            lo = m.mean - 3 * sqrt(m.variance), hi = m.mean + 3 * sqrt(m.variance);
            if (!(hi > lo))
                hi = lo + 1;
        }
        st = nl_png_write_field(tmp, x, lo, hi);
    }
    if (st)
        cli_die_status(st);
    cli_out_commit(out);
    nl_field_free(x);
    return 0;
}
