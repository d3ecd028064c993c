/* noiselab render: a 2D field as an 8-bit picture, grey levels or shaded relief. */
#include "cli.h"
#include "../analysis/hist.h"
#include "../render/terrain.h"

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
    "(default 1), for perspective views with pm3d.\n\n"
    "--perspective: a landscape view (RGB): the terrain lit by the sun with cast\n"
    "shadows, coloured by height and slope, in distance haze under a sky:\n"
    "  --size WxH          picture size (default 960x540)\n"
    "  --zscale Z          heights in samples per field unit (default: the rms slope\n"
    "                      between neighbouring samples is 0.5)\n"
    "  --camera X,Y,H      position in samples and height above the terrain there\n"
    "                      (outside the field: above its mean height)\n"
    "                      (default: behind the middle of the y = 0 edge, 0.15 n high)\n"
    "  --look AZ,PITCH     direction (degrees from +x toward +y; default 90) and\n"
    "                      degrees below the horizon (default 10, at most 30)\n"
    "  --fov F             horizontal field of view, degrees (default 60)\n"
    "  --sun AZ,EL         sun direction, degrees (default 210,35: from the left, behind)\n"
    "  --haze D            distance in samples at which haze hides 63% (default 2.5 n)\n"
    "  --water LEVEL       water below this height (field units)\n"
    "  --tile              repeat the (periodic) field to the horizon\n"
    "  --sea               a sea palette (blue by height) instead of the land one\n"
    "  --clouds FIELD      a 2D field as clouds on a plane above the camera, white\n"
    "                      where it exceeds its mean by 0.5 to 2 sd (GI '86 Fig. 5)\n"
    "  --cloud-plane Z,S   the plane's height above the camera and terrain samples per\n"
    "                      cloud sample (default 200,4)\n";

/* "A,B" with both finite, or exit 2 naming the option. */
static void pair(const char *opt, const char *s, double *a, double *b)
{
    char c;
    if (sscanf(s, "%lf,%lf%c", a, b, &c) != 2 || !isfinite(*a) || !isfinite(*b))
        cli_die(2, "%s: expected two numbers A,B, got \"%s\"", opt, s);
}

static void perspective(const char *in, const nl_field *x, const char *tmp, nl_render_view *v)
{
    uint8_t *rgb = malloc(v->width * v->height * 3);
    int st;
    if (!rgb)
        cli_die(1, "render: out of memory for a %zu x %zu picture", v->width, v->height);
    cli_phase("render", in);
    if ((st = nl_render_terrain(x, v, rgb)) || (st = nl_png_write_rgb8(tmp, v->width, v->height, rgb)))
        cli_die_status(st);
    cli_progress_done();
    free(rgb);
}

int cli_cmd_render(int argc, char **argv)
{
    static const struct option opts[] = {{"range", required_argument, 0, 'r'}, {"shade", required_argument, 0, 's'},
                                         {"zscale", required_argument, 0, 'z'}, {"output", required_argument, 0, 'o'},
                                         {"matrix", required_argument, 0, 'm'}, {"step", required_argument, 0, 'k'},
                                         {"perspective", no_argument, 0, 'P'},  {"size", required_argument, 0, 'S'},
                                         {"camera", required_argument, 0, 'c'}, {"look", required_argument, 0, 'l'},
                                         {"fov", required_argument, 0, 'f'},    {"sun", required_argument, 0, 'u'},
                                         {"haze", required_argument, 0, 'H'},   {"water", required_argument, 0, 'w'},
                                         {"tile", no_argument, 0, 't'},         {"sea", no_argument, 0, 'e'},
                                         {"clouds", required_argument, 0, 'C'}, {"cloud-plane", required_argument, 0, 'Z'},
                                         {"help", no_argument, 0, 'h'},         {0}};
    const char *out = NULL, *tmp, *matrix = NULL, *size = NULL, *camera = NULL, *look = NULL, *clouds = NULL;
    double plane[2] = {200, 4};
    size_t step = 1;
    double lo = NAN, hi = NAN, az = NAN, el = NAN, zs = 1, fov = NAN, sun[2] = {NAN, NAN}, haze = NAN, water = NAN;
    int persp = 0, tile = 0, sea = 0, given_zs = 0, view_opts = 0;
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
            given_zs = 1;
            break;
        case 'P': persp = 1; break;
        case 'S': size = optarg, view_opts++; break;
        case 'c': camera = optarg, view_opts++; break;
        case 'l': look = optarg, view_opts++; break;
        case 'f': fov = cli_parse_double("--fov", optarg), view_opts++; break;
        case 'u': pair("--sun", optarg, &sun[0], &sun[1]), view_opts++; break;
        case 'H': haze = cli_parse_double("--haze", optarg), view_opts++; break;
        case 'w': water = cli_parse_double("--water", optarg), view_opts++; break;
        case 't': tile = 1, view_opts++; break;
        case 'e': sea = 1, view_opts++; break;
        case 'C': clouds = optarg, view_opts++; break;
        case 'Z':
            pair("--cloud-plane", optarg, &plane[0], &plane[1]), view_opts++;
            if (!(plane[0] > 0 && plane[1] > 0))
                cli_die(2, "--cloud-plane: expected a positive height and scale, got \"%s\"", optarg);
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
    if (view_opts && !persp)
        cli_die(2, "render: --size, --camera, --look, --fov, --sun, --haze, --water, --tile, --sea and --clouds "
                "need --perspective");
    if (persp && (matrix || !isnan(az) || !isnan(lo)))
        cli_die(2, "render: --perspective takes none of --matrix, --shade, --range");
    if (persp && !out)
        cli_die(2, "render: --perspective: expected -o OUT.png");
    x = cli_read_field(argv[optind], NULL);
    if (x->dim != 2)
        cli_die(2, "render: expected a 2D field, %s is %dD", argv[optind], x->dim);
    if (persp) {
        nl_render_view v;
        nl_render_view_default(x, &v);
        if (size) {
            size_t n[3];
            if (cli_parse_size("--size", size, n, 1) != 2 || n[0] > 8192 || n[1] > 8192)
                cli_die(2, "--size: expected WxH of at most 8192x8192 pixels, got \"%s\"", size);
            v.width = n[0], v.height = n[1];
        }
        if (given_zs)
            v.zscale = zs;
        if (camera) {
            char c;
            if (sscanf(camera, "%lf,%lf,%lf%c", &v.cam[0], &v.cam[1], &v.cam[2], &c) != 3 || !isfinite(v.cam[0]) ||
                !isfinite(v.cam[1]) || !(v.cam[2] > 0))
                cli_die(2, "--camera: expected X,Y,H with H > 0, got \"%s\"", camera);
        }
        if (look)
            pair("--look", look, &v.azimuth, &v.pitch);
        if (!isnan(fov))
            v.fov = fov;
        if (!isnan(sun[0]))
            v.sun[0] = sun[0], v.sun[1] = sun[1];
        if (!isnan(haze))
            v.haze = haze;
        v.water = water;
        v.tile = tile;
        v.palette = sea ? NL_RENDER_SEA : NL_RENDER_LAND;
        nl_field *cf = NULL;
        if (clouds) {
            cf = cli_read_field(clouds, NULL);
            if (cf->dim != 2)
                cli_die(2, "--clouds: expected a 2D field, %s is %dD", clouds, cf->dim);
            v.clouds = cf, v.cloud_height = plane[0], v.cloud_scale = plane[1];
        }
        tmp = cli_out_begin(out);
        perspective(argv[optind], x, tmp, &v);
        cli_out_commit(out);
        nl_field_free(x);
        nl_field_free(cf);
        return 0;
    }
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
            nl_moments m;
            if ((st = nl_moments_compute(x, &m)))
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
