/* Cloud scenes from JSON files. */
#include "cloud_scene.h"
#include "../core/nl_error.h"

#include <errno.h>
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* An optional number in [lo, hi] (def when absent) into *x. */
static int num(json_t *o, const char *key, double def, double lo, double hi, const char *path, double *x)
{
    json_t *v = json_object_get(o, key);
    *x = def;
    if (!v)
        return NL_OK;
    if (!json_is_number(v))
        return NL_ERROR(NL_EINPUT, "%s: \"%s\": expected a number", path, key);
    *x = json_number_value(v);
    if (!(*x >= lo && *x <= hi))
        return NL_ERROR(NL_EINPUT, "%s: \"%s\": expected a value in [%g, %g], got %g", path, key, lo, hi, *x);
    return NL_OK;
}

static int vec3(json_t *o, const char *key, double *v, const char *path)
{
    json_t *a = json_object_get(o, key);
    if (!json_is_array(a) || json_array_size(a) != 3)
        return NL_ERROR(NL_EINPUT, "%s: \"%s\": expected an array of 3 numbers", path, key);
    for (int i = 0; i < 3; i++) {
        if (!json_is_number(json_array_get(a, (size_t)i)))
            return NL_ERROR(NL_EINPUT, "%s: \"%s\": expected an array of 3 numbers", path, key);
        v[i] = json_number_value(json_array_get(a, (size_t)i));
    }
    return NL_OK;
}

/* "size" and "box". */
static int scene_frame(json_t *j, const char *path, nl_cloud_scene *s)
{
    json_t *size = json_object_get(j, "size"), *box = json_object_get(j, "box"), *b;
    int st;
    if (!json_is_array(size) || json_array_size(size) != 2 || !json_is_integer(json_array_get(size, 0)) ||
        !json_is_integer(json_array_get(size, 1)))
        return NL_ERROR(NL_EINPUT, "%s: \"size\": expected [W, H]", path);
    s->width = (size_t)json_integer_value(json_array_get(size, 0));
    s->height = (size_t)json_integer_value(json_array_get(size, 1));
    if (s->width < 1 || s->height < 1 || s->width > 8192 || s->height > 8192)
        return NL_ERROR(NL_EINPUT, "%s: \"size\": expected 1 to 8192 pixels per side", path);
    if (!json_is_array(box) || json_array_size(box) != 2)
        return NL_ERROR(NL_EINPUT, "%s: \"box\": expected [[x0, y0, z0], [x1, y1, z1]]", path);
    b = json_pack("{s:O,s:O}", "lo", json_array_get(box, 0), "hi", json_array_get(box, 1));
    if (!(st = vec3(b, "lo", s->lo, path)))
        st = vec3(b, "hi", s->hi, path);
    json_decref(b);
    if (st)
        return st;
    for (int a = 0; a < 3; a++)
        if (!(s->hi[a] > s->lo[a]))
            return NL_ERROR(NL_EINPUT, "%s: \"box\": expected each lower corner coordinate below the upper", path);
    return NL_OK;
}

/* "points": npoints rows of x y z value. */
static int scene_points(json_t *j, const char *path, nl_cloud_scene *s)
{
    json_t *pts = json_object_get(j, "points");
    if (!json_is_array(pts) || json_array_size(pts) < 1)
        return NL_ERROR(NL_EINPUT, "%s: \"points\": expected an array of [x, y, z, value]", path);
    s->npoints = json_array_size(pts);
    if (!(s->points = malloc(s->npoints * 4 * sizeof *s->points)))
        return NL_ERROR(NL_ENOMEM, "out of memory");
    for (size_t i = 0; i < s->npoints; i++) {
        json_t *p = json_array_get(pts, i);
        if (!json_is_array(p) || json_array_size(p) != 4)
            return NL_ERROR(NL_EINPUT, "%s: \"points\"[%zu]: expected [x, y, z, value]", path, i);
        for (int a = 0; a < 4; a++) {
            if (!json_is_number(json_array_get(p, (size_t)a)))
                return NL_ERROR(NL_EINPUT, "%s: \"points\"[%zu]: expected numbers", path, i);
            s->points[4 * i + a] = json_number_value(json_array_get(p, (size_t)a));
        }
    }
    return NL_OK;
}

/* The noise's and the medium's numbers. */
static int scene_numbers(json_t *j, json_t *noise, const char *path, nl_cloud_scene *s)
{
    double g, seed, grid;
    int st;
    if ((st = num(noise, "amplitude", 0.3, 0, 100, path, &s->amplitude)) ||
        (st = num(noise, "period", 1, 1e-6, 1e6, path, &s->period)) ||
        (st = num(noise, "grid", 64, 8, 256, path, &g)) || (st = num(noise, "seed", 1, 0, 1e15, path, &seed)) ||
        (st = num(j, "threshold", 0.2, 0, 0.99, path, &s->threshold)) ||
        (st = num(j, "extinction", 8, 0, 1e6, path, &s->extinction)) || (st = num(j, "grid", 64, 8, 256, path, &grid)))
        return st;
    s->noise_grid = (size_t)g, s->seed = (uint64_t)seed, s->grid = (size_t)grid;
    return NL_OK;
}

/* The optional keys of Stam and Fiume's primitive: "kriging", "rotation",
 * and the noise's "kind" and "density". */
static int scene_options(json_t *j, json_t *noise, const char *path, nl_cloud_scene *s)
{
    json_t *kr = json_object_get(j, "kriging"), *kind = json_object_get(noise, "kind");
    int st;
    if (kr && (!json_is_string(kr) || (strcmp(json_string_value(kr), "ordinary") &&
                                       strcmp(json_string_value(kr), "simple"))))
        return NL_ERROR(NL_EINPUT, "%s: \"kriging\": expected \"ordinary\" or \"simple\"", path);
    s->kriging = kr && !strcmp(json_string_value(kr), "simple") ? NL_CLOUD_SIMPLE : NL_CLOUD_ORDINARY;
    if (json_object_get(j, "rotation")) {
        if ((st = vec3(j, "rotation", s->rotation, path)))
            return st;
        for (int a = 0; a < 3; a++)
            if (!(fabs(s->rotation[a]) <= 360))
                return NL_ERROR(NL_EINPUT, "%s: \"rotation\": expected angles in degrees within +-360, got %g", path,
                                s->rotation[a]);
    }
    if (kind && (!json_is_string(kind) || (strcmp(json_string_value(kind), "grid") &&
                                           strcmp(json_string_value(kind), "point"))))
        return NL_ERROR(NL_EINPUT, "%s: \"noise\": \"kind\": expected \"grid\" or \"point\"", path);
    s->noise_kind = kind && !strcmp(json_string_value(kind), "point") ? NL_CLOUD_NOISE_POINT : NL_CLOUD_NOISE_GRID;
    return num(noise, "density", 8, 0.5, 1000, path, &s->noise_density);
}

/* The models, the noise, the medium, the camera and the sun. */
static int scene_rest(json_t *j, const char *path, nl_cloud_scene *s)
{
    const char *acf = json_string_value(json_object_get(j, "acf"));
    json_t *noise = json_object_get(j, "noise"), *cam = json_object_get(j, "camera");
    int st;
    if (!acf)
        return NL_ERROR(NL_EINPUT, "%s: \"acf\": expected a model string", path);
    if (!json_is_object(noise) || !json_string_value(json_object_get(noise, "acf")))
        return NL_ERROR(NL_EINPUT, "%s: \"noise\": expected an object with \"acf\"", path);
    if (!json_is_object(cam))
        return NL_ERROR(NL_EINPUT, "%s: \"camera\": expected an object", path);
    if ((st = nl_model_parse(acf, &s->shape)) ||
        (st = nl_model_parse(json_string_value(json_object_get(noise, "acf")), &s->noise)) ||
        (st = scene_numbers(j, noise, path, s)) || (st = scene_options(j, noise, path, s)) || (st = vec3(cam, "position", s->cam, path)) ||
        (st = vec3(cam, "look_at", s->look, path)) || (st = num(cam, "fov", 40, 1, 170, path, &s->fov)) ||
        (st = vec3(j, "sun", s->sun, path)))
        return st;
    if (s->sun[0] == 0 && s->sun[1] == 0 && s->sun[2] == 0)
        return NL_ERROR(NL_EINPUT, "%s: \"sun\": expected a non-zero direction", path);
    return NL_OK;
}

int nl_cloud_scene_read(const char *path, nl_cloud_scene *s)
{
    json_error_t je;
    FILE *fp = fopen(path, "r");
    json_t *j;
    struct stat sb;
    int st;
    memset(s, 0, sizeof *s);
    if (!fp)
        return NL_ERROR(NL_EINPUT, "cannot open %s: %s", path, strerror(errno));
    if (fstat(fileno(fp), &sb) == 0 && S_ISDIR(sb.st_mode)) {
        fclose(fp);
        return NL_ERROR(NL_EINPUT, "%s: is a folder; expected a file", path);
    }
    j = json_loadf(fp, 0, &je);
    fclose(fp);
    if (!j)
        return NL_ERROR(NL_EINPUT, "%s:%d: not valid JSON: %s", path, je.line, je.text);
    if (!json_is_object(j))
        st = NL_ERROR(NL_EINPUT, "%s: expected a JSON object", path);
    else if (!(st = scene_frame(j, path, s)) && !(st = scene_points(j, path, s)))
        st = scene_rest(j, path, s);
    json_decref(j);
    if (st)
        nl_cloud_scene_free(s);
    return st;
}

void nl_cloud_scene_free(nl_cloud_scene *s)
{
    free(s->points);
    nl_model_free(s->shape);
    nl_model_free(s->noise);
    s->points = NULL, s->shape = s->noise = NULL;
}
