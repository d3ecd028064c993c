/* noiselab cloud: render a cloud scene (kriged shape + noise) to a picture. */
#include "cli.h"
#include "../render/cloud.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static const char help[] =
    "usage: noiselab cloud SCENE.json -o CLOUD.png [--exr CLOUD.exr]\n\n"
    "Stam and Fiume's clouds: the density is the kriged global shape (simple kriging of\n"
    "the scene's points with an ellipsoidal covariance) plus small-scale noise (a periodic\n"
    "3D FFT field), thresholded so that edges thin out; rendered by marching rays with\n"
    "absorption and single scattering toward the sun (a precomputed light volume) over\n"
    "a sky gradient.  SCENE.json:\n"
    "  {\"size\": [W, H], \"box\": [[x0, y0, z0], [x1, y1, z1]],\n"
    "   \"points\": [[x, y, z, value], ...], \"acf\": \"gauss:scale=..,ratio=..,zratio=..\",\n"
    "   \"noise\": {\"acf\": SPEC, \"amplitude\": A, \"period\": P, \"grid\": g, \"seed\": S},\n"
    "   \"threshold\": t, \"extinction\": sigma, \"grid\": G,\n"
    "   \"camera\": {\"position\": [..], \"look_at\": [..], \"fov\": degrees},\n"
    "   \"sun\": [x, y, z]}   (y is up)\n";

static void progress(double f) { cli_progress("cloud", f); }

static double num(json_t *o, const char *key, double def, double lo, double hi, const char *path)
{
    json_t *v = json_object_get(o, key);
    if (!v)
        return def;
    if (!json_is_number(v))
        cli_die(2, "%s: \"%s\": expected a number", path, key);
    double x = json_number_value(v);
    if (!(x >= lo && x <= hi))
        cli_die(2, "%s: \"%s\": expected a value in [%g, %g], got %g", path, key, lo, hi, x);
    return x;
}

static void vec3(json_t *o, const char *key, double *v, const char *path)
{
    json_t *a = json_object_get(o, key);
    if (!json_is_array(a) || json_array_size(a) != 3)
        cli_die(2, "%s: \"%s\": expected an array of 3 numbers", path, key);
    for (int i = 0; i < 3; i++) {
        if (!json_is_number(json_array_get(a, (size_t)i)))
            cli_die(2, "%s: \"%s\": expected an array of 3 numbers", path, key);
        v[i] = json_number_value(json_array_get(a, (size_t)i));
    }
}

/* "size" and "box" of the scene. */
static void scene_frame(json_t *j, const char *path, nl_cloud_scene *s)
{
    json_t *size = json_object_get(j, "size"), *box = json_object_get(j, "box");
    if (!json_is_array(size) || json_array_size(size) != 2 || !json_is_integer(json_array_get(size, 0)) ||
        !json_is_integer(json_array_get(size, 1)))
        cli_die(2, "%s: \"size\": expected [W, H]", path);
    s->width = (size_t)json_integer_value(json_array_get(size, 0));
    s->height = (size_t)json_integer_value(json_array_get(size, 1));
    if (s->width < 1 || s->height < 1 || s->width > 8192 || s->height > 8192)
        cli_die(2, "%s: \"size\": expected 1 to 8192 pixels per side", path);
    if (!json_is_array(box) || json_array_size(box) != 2)
        cli_die(2, "%s: \"box\": expected [[x0, y0, z0], [x1, y1, z1]]", path);
    json_t *b = json_pack("{s:O,s:O}", "lo", json_array_get(box, 0), "hi", json_array_get(box, 1));
    vec3(b, "lo", s->lo, path);
    vec3(b, "hi", s->hi, path);
    json_decref(b);
    for (int a = 0; a < 3; a++)
        if (!(s->hi[a] > s->lo[a]))
            cli_die(2, "%s: \"box\": expected each lower corner coordinate below the upper", path);
}

/* "points": npoints rows of x y z value. */
static void scene_points(json_t *j, const char *path, nl_cloud_scene *s)
{
    json_t *pts = json_object_get(j, "points");
    if (!json_is_array(pts) || json_array_size(pts) < 1)
        cli_die(2, "%s: \"points\": expected an array of [x, y, z, value]", path);
    s->npoints = json_array_size(pts);
    s->points = cli_malloc(s->npoints * 4 * sizeof *s->points);
    for (size_t i = 0; i < s->npoints; i++) {
        json_t *p = json_array_get(pts, i);
        if (!json_is_array(p) || json_array_size(p) != 4)
            cli_die(2, "%s: \"points\"[%zu]: expected [x, y, z, value]", path, i);
        for (int a = 0; a < 4; a++) {
            if (!json_is_number(json_array_get(p, (size_t)a)))
                cli_die(2, "%s: \"points\"[%zu]: expected numbers", path, i);
            s->points[4 * i + a] = json_number_value(json_array_get(p, (size_t)a));
        }
    }
}

/* The models, the noise, the medium, the camera and the sun; returns the
 * shape's model string. */
static const char *scene_rest(json_t *j, const char *path, nl_cloud_scene *s)
{
    const char *acf = json_string_value(json_object_get(j, "acf"));
    json_t *noise = json_object_get(j, "noise"), *cam = json_object_get(j, "camera");
    int st;
    if (!acf)
        cli_die(2, "%s: \"acf\": expected a model string", path);
    if (!json_is_object(noise) || !json_string_value(json_object_get(noise, "acf")))
        cli_die(2, "%s: \"noise\": expected an object with \"acf\"", path);
    if (!json_is_object(cam))
        cli_die(2, "%s: \"camera\": expected an object", path);
    if ((st = nl_model_parse(acf, &s->shape)) ||
        (st = nl_model_parse(json_string_value(json_object_get(noise, "acf")), &s->noise)))
        cli_die_status(st);
    s->amplitude = num(noise, "amplitude", 0.3, 0, 100, path);
    s->period = num(noise, "period", 1, 1e-6, 1e6, path);
    s->noise_grid = (size_t)num(noise, "grid", 64, 8, 256, path);
    s->seed = (uint64_t)num(noise, "seed", 1, 0, 1e15, path);
    s->threshold = num(j, "threshold", 0.2, 0, 0.99, path);
    s->extinction = num(j, "extinction", 8, 0, 1e6, path);
    s->grid = (size_t)num(j, "grid", 64, 8, 256, path);
    vec3(cam, "position", s->cam, path);
    vec3(cam, "look_at", s->look, path);
    s->fov = num(cam, "fov", 40, 1, 170, path);
    vec3(j, "sun", s->sun, path);
    if (s->sun[0] == 0 && s->sun[1] == 0 && s->sun[2] == 0)
        cli_die(2, "%s: \"sun\": expected a non-zero direction", path);
    return acf;
}

/* The luminance as an EXR field. */
static void write_lum(const char *etmp, const nl_cloud_scene *s, const double *lum, const char *acf, const char *path)
{
    size_t n[2] = {s->width, s->height};
    int st;
    nl_field *f = nl_field_alloc(2, n, NULL, &st);
    nl_meta meta;
    if (!f)
        cli_die_status(st);
    memcpy(f->data, lum, s->width * s->height * sizeof *lum);
    memset(&meta, 0, sizeof meta);
    snprintf(meta.model, sizeof meta.model, "%s", acf);
    snprintf(meta.method, sizeof meta.method, "cloud:%s", path);
    cli_check(nl_exr_write(etmp, f, &meta));
    nl_field_free(f);
}

int cli_cmd_cloud(int argc, char **argv)
{
    static const struct option opts[] = {{"output", required_argument, 0, 'o'}, {"exr", required_argument, 0, 'e'},
                                         {"help", no_argument, 0, 'h'},         {0}};
    const char *out = NULL, *exr = NULL, *path, *tmp, *etmp = NULL, *acf;
    int c;
    json_error_t je;
    nl_cloud_scene s;
    while ((c = cli_getopt(argc, argv, ":ho:", opts, "cloud")) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 'e': exr = optarg; break;
        case 'h': fputs(help, stdout); return 0;
        }
    }
    path = cli_one_operand("cloud", "scene file", argc, argv);
    if (!out || !cli_has_ext(out, ".png"))
        cli_die(2, "cloud: -o: expected an output file ending in .png");
    if (exr && !cli_has_ext(exr, ".exr"))
        cli_die(2, "--exr: expected a file ending in .exr, got \"%s\"", exr);
    json_t *j = json_load_file(path, 0, &je);
    if (!j)
        cli_die(2, "%s:%d: not valid JSON: %s", path, je.line, je.text);
    if (!json_is_object(j))
        cli_die(2, "%s: expected a JSON object", path);
    memset(&s, 0, sizeof s);
    scene_frame(j, path, &s);
    scene_points(j, path, &s);
    acf = scene_rest(j, path, &s);
    tmp = cli_out_begin(out);
    etmp = cli_out_begin(exr);
    unsigned char *rgb = cli_malloc(s.width * s.height * 3);
    double *lum = exr ? cli_malloc(s.width * s.height * sizeof *lum) : NULL;
    cli_progress("cloud", 0);
    cli_check(nl_render_cloud(&s, rgb, lum, progress));
    cli_progress_done();
    cli_check(nl_png_write_rgb8(tmp, s.width, s.height, rgb));
    if (exr) {
        write_lum(etmp, &s, lum, acf, path);
        cli_out_commit(exr);
    }
    cli_out_commit(out);
    free(rgb), free(lum), free(s.points);
    nl_model_free(s.shape), nl_model_free(s.noise);
    json_decref(j);
    return 0;
}
