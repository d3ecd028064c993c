/* noiselab cloud: render a cloud scene (kriged shape + noise) to a picture. */
#include "cli.h"
#include "opt.h"
#include "../render/cloud_scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: noiselab cloud SCENE.json -o CLOUD.png [--exr CLOUD.exr]\n\n"
    "Stam and Fiume's clouds: the density is the kriged global shape (ordinary kriging,\n"
    "as in the paper, of the scene's points with an ellipsoidal covariance, fully\n"
    "oriented by three rotation angles) times small-scale noise (a periodic 3D FFT\n"
    "volume, or sparse-convolution noise evaluated at every sample of every ray),\n"
    "thresholded so that edges thin out; rendered by marching rays with absorption\n"
    "and single scattering toward the sun (a precomputed light volume) over a sky\n"
    "gradient.  SCENE.json:\n"
    "  {\"size\": [W, H], \"box\": [[x0, y0, z0], [x1, y1, z1]],\n"
    "   \"points\": [[x, y, z, value], ...], \"acf\": \"gauss:scale=..,ratio=..,zratio=..\",\n"
    "   \"noise\": {\"acf\": SPEC, \"amplitude\": A, \"period\": P, \"grid\": g, \"seed\": S},\n"
    "   \"threshold\": t, \"extinction\": sigma, \"grid\": G,\n"
    "   \"camera\": {\"position\": [..], \"look_at\": [..], \"fov\": degrees},\n"
    "   \"sun\": [x, y, z]}   (y is up)\n"
    "Optional: \"kriging\": \"ordinary\" (default; far from every datum the shape tends to\n"
    "the data's estimated mean, so surround the cloud with points of value <= 0) or\n"
    "\"simple\" (mean 0: scenes made before ordinary kriging render as they did);\n"
    "\"rotation\": [ax, ay, az] degrees about x, y, z (the ellipsoid turned by\n"
    "Rz Ry Rx); in \"noise\": \"kind\": \"grid\" (default) or \"point\" (a gauss: acf;\n"
    "no period or grid) with \"density\": impulses per scale^3 (default 8).\n"
    "The shape kriges with every point: at most 2000 points, and grid^3 (points +\n"
    "7 grid) at most 1e9 (about half a minute); a singular system (duplicate points) is solved by the pseudo-inverse\n"
    "(up to 1000 points), said on stderr and flagged in the EXR.\n";

static void progress(double f) { cli_progress("cloud", f); }

/* The luminance as an EXR field (flagged when the shape's kriging system
 * was singular). */
static void write_lum(const char *etmp, const nl_cloud_scene *s, const double *lum, const char *path,
                      const nl_krige_info *info)
{
    size_t n[2] = {s->width, s->height};
    nl_field *f = cli_field_alloc(2, n, NULL);
    nl_meta meta = {0};
    memcpy(f->data, lum, s->width * s->height * sizeof *lum);
    snprintf(meta.model, sizeof meta.model, "%s", nl_model_spec(s->shape));
    snprintf(meta.method, sizeof meta.method, "cloud:%s", path);
    if (info->pseudo_inverse)
        snprintf(meta.flags, sizeof meta.flags, "singular,pseudo-inverse");
    cli_check(nl_exr_write(etmp, f, &meta));
    nl_field_free(f);
}

/* The command's options. */
typedef struct {
    const char *out, *exr; /* -o, --exr */
} opts_t;

static const cli_opt rows[] = {
    CLI_OPT_OUTPUT(opts_t, out), {.name = "exr", .type = CLI_OPT_STRING, CLI_AT(opts_t, exr)}, {0}};

int cli_cmd_cloud(int argc, char **argv)
{
    opts_t a = {0};
    const char *path, *tmp, *etmp = NULL;
    nl_cloud_scene s;
    nl_krige_info info;
    if (cli_opt_parse("cloud", help, rows, &a, argc, argv))
        return 0;
    path = cli_one_operand("cloud", "scene file", argc, argv);
    if (!a.out || !cli_has_ext(a.out, ".png"))
        cli_die(2, "cloud: -o: expected an output file ending in .png");
    if (a.exr && !cli_has_ext(a.exr, ".exr"))
        cli_die(2, "--exr: expected a file ending in .exr, got \"%s\"", a.exr);
    cli_check(nl_cloud_scene_read(path, &s));
    size_t px[2] = {s.width, s.height};
    cli_check(nl_size_check(2, px, 3 + sizeof(double), 1, NULL));
    tmp = cli_out_begin(a.out);
    etmp = cli_out_begin(a.exr);
    unsigned char *rgb = cli_malloc(s.width * s.height * 3);
    double *lum = a.exr ? cli_malloc(s.width * s.height * sizeof *lum) : NULL;
    cli_progress("cloud", 0);
    cli_check(nl_render_cloud_info(&s, rgb, lum, progress, &info));
    cli_progress_done();
    if (info.pseudo_inverse) /* as krige says it */
        fprintf(stderr, "noiselab: cloud: the shape's kriging system is singular (reciprocal condition %.2g); solved "
                "by the pseudo-inverse%s\n", info.rcond, a.exr ? " (flagged in the EXR)" : "");
    cli_check(nl_png_write_rgb8(tmp, s.width, s.height, rgb));
    if (a.exr) {
        write_lum(etmp, &s, lum, path, &info);
        cli_out_commit(a.exr);
    }
    cli_out_commit(a.out);
    free(rgb), free(lum);
    nl_cloud_scene_free(&s);
    return 0;
}
