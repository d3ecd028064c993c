/* noiselab render: a 2D field as an 8-bit picture, grey levels or shaded relief. */
#include "cli.h"
#include "opt.h"
#include "render_axes.h"
#include "../core/nl_error.h"
#include "../render/colorbar.h"
#include "../render/shade.h"
#include "../render/terrain.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const char help[] =
    "usage: noiselab render IN (-o OUT.png | --matrix OUT.txt) [--range LO:HI] [--shade AZ,EL]\n"
    "                       [--zscale Z] [--step K] [--colorbar] [--axes grid|lags]\n\n"
    "Grey levels: values from LO to HI map onto 0..255 (default: mean +- 3 sd);\n"
    "--colorbar adds the scale to the right: a ramp from LO to HI with their values\n"
    "and the middle one (112 more columns).\n"
    "--axes grid|lags: drawn by gnuplot with axes in length units (the field's\n"
    "spacing), its name as the title and a colour bar: grid puts sample (0, 0) at\n"
    "the origin, row 0 at the top; lags puts the centre sample at lag (0, 0), lag y\n"
    "up, for the map of noiselab acf --max-lag L -o ACF.exr or a centred spectrum.\n"
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

static void perspective(const char *in, const nl_field *x, const char *tmp, nl_render_view *v)
{
    size_t n[2] = {v->width, v->height};
    int st = nl_size_check(2, n, 3, 1, NULL);
    uint8_t *rgb = st ? NULL : malloc(v->width * v->height * 3);
    if (st)
        cli_die_status(st);
    if (!rgb)
        cli_die(1, "render: out of memory for a %zu x %zu picture", v->width, v->height);
    cli_phase("render", in);
    if ((st = nl_render_terrain(x, v, rgb)) || (st = nl_png_write_rgb8(tmp, v->width, v->height, rgb)))
        cli_die_status(st);
    cli_progress_done();
    free(rgb);
}

/* The command's options. */
typedef struct {
    const char *out, *matrix, *size, *camera, *look, *clouds;  /* as given, or NULL */
    double plane[2];                                           /* --cloud-plane */
    size_t step;                                               /* --step */
    double lo, hi, az, el, zs, fov, sun[2], haze, water;       /* NAN: not given */
    int persp, tile, sea, given_zs, view_opts, colorbar;       /* flags; view options given */
    int given_step;                                            /* --step given */
    int axes, given_axes;                                      /* --axes: CLI_AXES_* */
} opts_t;

static void range_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    char junk;
    if (sscanf(arg, "%lf:%lf%c", &a->lo, &a->hi, &junk) != 2 || !(a->hi > a->lo) || !isfinite(a->lo) ||
        !isfinite(a->hi) || !isfinite(a->hi - a->lo))
        cli_die(2, "%s: expected LO:HI with LO < HI, both finite and HI - LO finite, got \"%s\"", label, arg);
}

static void shade_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    char junk;
    if (sscanf(arg, "%lf,%lf%c", &a->az, &a->el, &junk) != 2 || !(a->el > 0 && a->el <= 90) ||
        !(fabs(a->az) <= 360))
        cli_die(2, "%s: expected AZ,EL in degrees with -360 <= AZ <= 360 and 0 < EL <= 90, got \"%s\"", label,
                arg);
}

static void plane_option(void *obj, const char *label, const char *arg)
{
    opts_t *a = obj;
    cli_parse_pair(label, arg, &a->plane[0], &a->plane[1]);
    if (!(a->plane[0] > 0 && a->plane[1] > 0))
        cli_die(2, "%s: expected a positive height and scale, got \"%s\"", label, arg);
}

/* A view option: it needs --perspective. */
#define VIEW CLI_GIVEN(opts_t, view_opts)

static const char *const axes_choices[] = {"grid", "lags", NULL};

static const cli_opt rows[] = {
    CLI_CALL("range", range_option), CLI_CALL("shade", shade_option),
    CLI_POSITIVE("zscale", opts_t, zs, CLI_GIVEN(opts_t, given_zs), .what = "factor"), CLI_OPT_OUTPUT(opts_t, out),
    CLI_STRING("matrix", opts_t, matrix), CLI_COUNT("step", opts_t, step, .lo = 1, CLI_GIVEN(opts_t, given_step)),
    CLI_FLAG("perspective", opts_t, persp), CLI_STRING("size", opts_t, size, VIEW),
    CLI_STRING("camera", opts_t, camera, VIEW), CLI_STRING("look", opts_t, look, VIEW),
    CLI_DOUBLE("fov", opts_t, fov, VIEW), CLI_PAIR("sun", opts_t, sun, VIEW), CLI_DOUBLE("haze", opts_t, haze, VIEW),
    CLI_DOUBLE("water", opts_t, water, VIEW), CLI_FLAG("tile", opts_t, tile, VIEW),
    CLI_FLAG("sea", opts_t, sea, VIEW), CLI_STRING("clouds", opts_t, clouds, VIEW),
    CLI_CALL("cloud-plane", plane_option, VIEW), CLI_FLAG("colorbar", opts_t, colorbar),
    CLI_CHOICE("axes", opts_t, axes, .choices = axes_choices, CLI_GIVEN(opts_t, given_axes)), {0}};

static void check(int argc, char **argv, const opts_t *a)
{
    cli_one_operand("render", "input file", argc, argv);
    if (!a->out && !a->matrix)
        cli_die(2, "render: expected -o OUT.png or --matrix OUT.txt");
    if (a->out && !cli_has_ext(a->out, ".png"))
        cli_die(2, "render: -o: expected an output file ending in .png, got \"%s\"", a->out);
    if (a->view_opts && !a->persp)
        cli_die(2, "render: --size, --camera, --look, --fov, --sun, --haze, --water, --tile, --sea and --clouds "
                "need --perspective");
    if (a->persp && (a->matrix || !isnan(a->az) || !isnan(a->lo)))
        cli_die(2, "render: --perspective takes none of --matrix, --shade, --range");
    if (a->persp && !a->out)
        cli_die(2, "render: --perspective: expected -o OUT.png");
    if (a->given_zs && !a->persp && isnan(a->az))
        cli_die(2, "render: --zscale %g: expected --shade or --perspective (it scales the heights they draw)", a->zs);
    if (a->given_step && !a->matrix)
        cli_die(2, "render: --step %zu: expected --matrix (every K-th sample of it)", a->step);
    if (a->colorbar && (a->persp || !isnan(a->az) || !a->out))
        cli_die(2, "render: --colorbar: goes with grey levels into -o OUT.png (not --shade or --perspective)");
    if (a->given_axes && (a->persp || !isnan(a->az) || !a->out))
        cli_die(2, "render: --axes: goes with grey levels into -o OUT.png (not --shade or --perspective)");
}

/* The view of the options over the defaults for x. */
static void view(const opts_t *a, const nl_field *x, nl_render_view *v)
{
    nl_render_view_default(x, v);
    if (a->size) {
        size_t n[3];
        if (cli_parse_size("--size", a->size, n, 1) != 2 || n[0] > 8192 || n[1] > 8192)
            cli_die(2, "--size: expected WxH of at most 8192x8192 pixels, got \"%s\"", a->size);
        v->width = n[0], v->height = n[1];
    }
    if (a->given_zs)
        v->zscale = a->zs;
    if (a->camera) {
        char c;
        if (sscanf(a->camera, "%lf,%lf,%lf%c", &v->cam[0], &v->cam[1], &v->cam[2], &c) != 3 || !isfinite(v->cam[0]) ||
            !isfinite(v->cam[1]) || !(v->cam[2] > 0))
            cli_die(2, "--camera: expected X,Y,H with H > 0, got \"%s\"", a->camera);
    }
    if (a->look)
        cli_parse_pair("--look", a->look, &v->azimuth, &v->pitch);
    if (!isnan(a->fov))
        v->fov = a->fov;
    if (!isnan(a->sun[0]))
        v->sun[0] = a->sun[0], v->sun[1] = a->sun[1];
    if (!isnan(a->haze))
        v->haze = a->haze;
    v->water = a->water;
    v->tile = a->tile;
    v->palette = a->sea ? NL_RENDER_SEA : NL_RENDER_LAND;
}

static void write_matrix(const char *matrix, const nl_field *x, size_t step)
{
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
}

/* Grey levels or, with --shade, the relief. */
static void write_picture(const opts_t *a, const nl_field *x, const char *name)
{
    const char *tmp = cli_out_begin(a->out);
    double lo = a->lo, hi = a->hi;
    int st;
    if (!isnan(a->az)) {
        nl_field *s = cli_field_alloc(2, x->n, x->h);
        cli_check(nl_render_relief(x, a->az, a->el, a->zs, s));
        st = nl_png_write_field(tmp, s, 0, 1);
        nl_field_free(s);
    } else {
        if (isnan(lo) && (st = nl_render_grey_range(x, &lo, &hi)))
            cli_die_status(st);
        if (a->given_axes) {
            cli_render_axes(x, lo, hi, a->axes, name, tmp);
            st = NL_OK;
        } else if (a->colorbar) {
            uint8_t *pix;
            size_t w, h;
            if (!(st = nl_render_grey_colorbar(x, lo, hi, &pix, &w, &h)))
                st = nl_png_write_gray8(tmp, w, h, pix);
            free(pix);
        } else
            st = nl_png_write_field(tmp, x, lo, hi);
    }
    cli_check(st);
    cli_out_commit(a->out);
}

int cli_cmd_render(int argc, char **argv)
{
    opts_t a = {.plane = {200, 4}, .step = 1, .lo = NAN, .hi = NAN, .az = NAN, .el = NAN, .zs = 1, .fov = NAN,
                .sun = {NAN, NAN}, .haze = NAN, .water = NAN};
    nl_field *x;
    if (cli_opt_parse("render", help, rows, &a, argc, argv))
        exit(0);
    check(argc, argv, &a);
    x = cli_read_field(argv[optind], NULL);
    if (x->dim != 2)
        cli_die(2, "render: expected a 2D field, %s is %dD", argv[optind], x->dim);
    if (a.persp) {
        nl_render_view v;
        nl_field *cf = NULL;
        view(&a, x, &v);
        if (a.clouds) {
            cf = cli_read_field(a.clouds, NULL);
            if (cf->dim != 2)
                cli_die(2, "--clouds: expected a 2D field, %s is %dD", a.clouds, cf->dim);
            v.clouds = cf, v.cloud_height = a.plane[0], v.cloud_scale = a.plane[1];
        }
        perspective(argv[optind], x, cli_out_begin(a.out), &v);
        cli_out_commit(a.out);
        nl_field_free(cf);
    } else {
        if (a.matrix)
            write_matrix(a.matrix, x, a.step);
        if (a.out)
            write_picture(&a, x, argv[optind]);
    }
    nl_field_free(x);
    return 0;
}
