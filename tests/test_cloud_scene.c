/* Cloud scenes read from JSON (render/cloud_scene.h): values and defaults
 * land in the scene exactly (they are copied, not computed, so equality is
 * exact), every NL_E* code of the header is triggered, and a failed read
 * leaves no pointers behind. */
#include "../core/nl_error.h"
#include "../render/cloud.h"
#include "../render/cloud_scene.h"
#include "starve.h"
#include "util.h"

#include <criterion/criterion.h>
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BASE                                                                                                        \
    "\"size\": [32, 24], \"box\": [[-1,-2,-3],[1,2,3]], \"points\": [[0.25,0,0,1.5],[0,0.5,0,-2]], "                \
    "\"acf\": \"gauss:scale=0.6\", \"noise\": {\"acf\": \"markov:scale=0.1\", \"period\": 2.385}, "                 \
    "\"camera\": {\"position\": [0,0,-4], \"look_at\": [0,0.125,0]}, \"sun\": [0.3,1,-0.5]"

Test(cloud_scene, values_and_defaults)
{
    nl_cloud_scene s;
    cr_assert_eq(nl_cloud_scene_read(scratch_file("ok.json", "{" BASE ", \"threshold\": 0.3}"), &s), NL_OK, "%s",
                 nl_errmsg());
    cr_expect_eq(s.width, 32);
    cr_expect_eq(s.height, 24);
    cr_expect_eq(s.lo[1], -2);
    cr_expect_eq(s.hi[2], 3);
    cr_assert_eq(s.npoints, 2);
    cr_expect_eq(s.points[0], 0.25);
    cr_expect_eq(s.points[7], -2);
    cr_expect_str_eq(nl_model_spec(s.shape), "gauss:scale=0.6");
    cr_expect_str_eq(nl_model_spec(s.noise), "markov:scale=0.1");
    cr_expect_eq(s.period, 2.385);
    cr_expect_eq(s.threshold, 0.3);
    cr_expect_eq(s.look[1], 0.125);
    cr_expect_eq(s.sun[2], -0.5);
    /* the header's defaults */
    cr_expect_eq(s.amplitude, 0.3);
    cr_expect_eq(s.noise_grid, 64);
    cr_expect_eq(s.seed, 1);
    cr_expect_eq(s.extinction, 8);
    cr_expect_eq(s.grid, 64);
    cr_expect_eq(s.fov, 40);
    nl_cloud_scene_free(&s);
    cr_expect_null(s.points);
    cr_expect_null(s.shape);
    nl_cloud_scene_free(&s); /* twice is harmless */
}

static void refused(const char *text, int code, const char *needle)
{
    nl_cloud_scene s;
    int st = nl_cloud_scene_read(scratch_file("bad.json", text), &s);
    cr_expect_eq(st, code, "%s: status %d, message %s", text, st, nl_errmsg());
    cr_expect(strstr(nl_errmsg(), needle) != NULL, "\"%s\" should name \"%s\"", nl_errmsg(), needle);
    cr_expect(s.points == NULL && s.shape == NULL && s.noise == NULL, "%s: left pointers", text);
}

Test(cloud_scene, error_paths)
{
    refused("{" BASE, NL_EINPUT, "not valid JSON");
    refused("[1, 2]", NL_EINPUT, "JSON object");
    refused("{\"size\": [0, 3]}", NL_EINPUT, "\"size\"");
    refused("{\"size\": [3, 3], \"box\": [[0,0,0],[1,1]]}", NL_EINPUT, "\"hi\"");
    refused("{\"size\": [3, 3], \"box\": [[0,0,0],[1,0,1]]}", NL_EINPUT, "\"box\"");
    refused("{\"size\": [3, 3], \"box\": [[0,0,0],[1,1,1]], \"points\": [[1,2,3,4],[1]]}", NL_EINPUT, "\"points\"[1]");
    refused("{" BASE ", \"grid\": 7}", NL_EINPUT, "\"grid\"");
    refused("{" BASE ", \"extinction\": \"thick\"}", NL_EINPUT, "\"extinction\"");
    refused("{" BASE ", \"acf\": 3}", NL_EINPUT, "\"acf\"");
    refused("{" BASE ", \"sun\": [0, 0, 0]}", NL_EINPUT, "\"sun\"");
    /* a model that fails to parse keeps the model parser's code, after
     * the shape model has already been built (and must be freed) */
    refused("{" BASE ", \"noise\": {\"acf\": \"nosuch\"}}", NL_EINVAL, "nosuch");
}

/* The points array (32 bytes a point) is the one allocation of the reader
 * itself.  With every allocation served from the heap and the heap capped
 * a little higher each time, some cap lets the JSON parse through but not
 * the points: that read must be NL_ENOMEM with nothing left allocated.
 * Caps that stop the parse itself give NL_EINPUT and are stepped over. */
Test(cloud_scene, out_of_memory)
{
    enum { NP = 20000 };
    char *text = malloc(NP * 16 + 1024), *p = text;
    nl_cloud_scene s;
    int st = NL_EINPUT;
    p += sprintf(p, "{\"size\": [3, 3], \"box\": [[0,0,0],[1,1,1]], \"points\": [");
    for (int i = 0; i < NP; i++)
        p += sprintf(p, "%s[0,0,0,%d]", i ? "," : "", i % 10);
    sprintf(p, "]}");
    const char *path = scratch_file("big.json", text);
    free(text);
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    for (size_t leave = 1 << 20; leave < (size_t)256 << 20 && st == NL_EINPUT; leave += 128 << 10) {
        if (!starve_begin_leaving(leave))
            cr_skip_test("allocation failure cannot be forced in this build");
        st = nl_cloud_scene_read(path, &s);
        starve_end();
    }
    cr_expect_eq(st, NL_ENOMEM, "status %d: %s", st, nl_errmsg());
    cr_expect_null(s.points);
}

/* The work of a render is bounded before it starts: more points than krige
 * takes at once (2000), or a grid whose shape and light volumes cost over
 * 1e9 covariance evaluations (G^3 (points + 7 G): 1.9e9 at G = 128), are
 * refused at once; a singular shape system (each point given twice) is
 * rendered by the pseudo-inverse and says so in the info, as krige does. */
Test(cloud_scene, work_refused_and_singular_flagged)
{
    nl_cloud_scene s;
    nl_krige_info info;
    unsigned char rgb[8 * 6 * 3];
    char *text;
    size_t len;
    FILE *f = open_memstream(&text, &len);
    fprintf(f, "{\"size\": [8, 6], \"box\": [[-1,-2,-3],[1,2,3]], \"acf\": \"gauss:scale=0.6\", \"grid\": 8, "
               "\"noise\": {\"acf\": \"markov:scale=0.1\", \"period\": 2.385, \"grid\": 8}, \"camera\": "
               "{\"position\": [0,0,-4], \"look_at\": [0,0.125,0]}, \"sun\": [0.3,1,-0.5], \"points\": [");
    for (int i = 0; i < 2001; i++)
        fprintf(f, "%s[%.4f, %.4f, %.4f, 1]", i ? ", " : "", 0.001 * i - 1, 0.5, 0.25);
    fprintf(f, "]}");
    fclose(f);
    cr_assert_eq(nl_cloud_scene_read(scratch_file("many.json", text), &s), NL_OK, "%s", nl_errmsg());
    cr_expect_eq(nl_render_cloud_info(&s, rgb, NULL, NULL, &info), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "at most 2000") != NULL, "%s", nl_errmsg());
    nl_cloud_scene_free(&s);
    free(text);
    cr_assert_eq(nl_cloud_scene_read(scratch_file("grid.json", "{" BASE ", \"grid\": 128}"), &s), NL_OK, "%s",
                 nl_errmsg());
    cr_expect_eq(nl_render_cloud(&s, rgb, NULL, NULL), NL_EINVAL);
    cr_expect(strstr(nl_errmsg(), "\"grid\" 128") != NULL, "%s", nl_errmsg());
    nl_cloud_scene_free(&s);
    cr_assert_eq(nl_cloud_scene_read(scratch_file("dup.json",
                                                  "{\"size\": [8, 6], \"box\": [[-1,-2,-3],[1,2,3]], \"points\": "
                                                  "[[0.25,0,0,1.5],[0.25,0,0,1.5],[0,0.5,0,-2]], \"acf\": "
                                                  "\"gauss:scale=0.6\", \"grid\": 8, \"noise\": {\"acf\": "
                                                  "\"markov:scale=0.1\", \"period\": 2.385, \"grid\": 8}, \"camera\": "
                                                  "{\"position\": [0,0,-4], \"look_at\": [0,0.125,0]}, \"sun\": "
                                                  "[0.3,1,-0.5]}"),
                                     &s),
                 NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_render_cloud_info(&s, rgb, NULL, NULL, &info), NL_OK, "%s", nl_errmsg());
    cr_expect(info.pseudo_inverse, "a duplicated point: expected the pseudo-inverse flagged");
    cr_expect(info.rcond < NL_KRIGE_RCOND_MIN, "rcond %g", info.rcond);
    nl_cloud_scene_free(&s);
}
