/* The perspective renderer: projection, occlusion, shadows and refusals,
 * checked on fields whose pictures are known. */
#include "../core/field.h"
#include "../render/shade.h"
#include "../render/terrain.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

static nl_field *flat(size_t n)
{
    size_t nn[2] = {n, n};
    nl_field *f = nl_field_alloc(2, nn, NULL, NULL);
    cr_assert_not_null(f);
    return f;
}

static const uint8_t *px(const uint8_t *rgb, const nl_render_view *v, size_t x, size_t y)
{
    return rgb + 3 * (y * v->width + x);
}

/* A flat plain seen level (pitch 0): the horizon is the middle row.  Rows
 * clearly above it are sky (blue over red), rows clearly below are ground
 * (green over blue); a ray at depression angle a meets the plain at
 * distance H / tan(a), so every ground row is inside a 4096-sample tiled
 * plain long before the haze limit. */
Test(render, flat_plain_horizon_in_the_middle)
{
    nl_field *f = flat(64);
    nl_render_view v;
    nl_render_view_default(f, &v);
    v.width = 64, v.height = 48, v.pitch = 0, v.cam[2] = 10, v.tile = 1, v.zscale = 1, v.haze = 1e6;
    uint8_t *rgb = malloc(v.width * v.height * 3);
    cr_assert_eq(nl_render_terrain(f, &v, rgb), 0);
    for (size_t x = 0; x < v.width; x += 7) {
        for (size_t y = 0; y < 20; y++)
            cr_expect_gt(px(rgb, &v, x, y)[2], px(rgb, &v, x, y)[0], "sky at (%zu, %zu)", x, y);
        for (size_t y = 28; y < v.height; y++)
            cr_expect_gt(px(rgb, &v, x, y)[1], px(rgb, &v, x, y)[2], "ground at (%zu, %zu)", x, y);
    }
    free(rgb), nl_field_free(f);
}

/* A wall across the field hides what lies behind it: with the wall, the
 * rows just above the plain's horizon show the wall (ground, not sky). */
Test(render, a_wall_occludes_the_sky_behind_it)
{
    nl_field *f = flat(64);
    nl_render_view v;
    for (size_t i = 0; i < 64; i++)
        for (size_t j = 30; j < 34; j++)
            f->data[j * 64 + i] = 1;
    nl_render_view_default(f, &v);
    v.width = 64, v.height = 48, v.pitch = 0, v.cam[0] = 32, v.cam[1] = 0, v.cam[2] = 5, v.zscale = 12, v.haze = 1e6;
    uint8_t *rgb = malloc(v.width * v.height * 3);
    cr_assert_eq(nl_render_terrain(f, &v, rgb), 0);
    /* the wall top is 7 samples above the camera at distance 30..34: 12-13
     * degrees up, 0.21 focal = 12 pixels above the middle row (focal = 55
     * pixels on a 64-pixel-wide, 60-degree view); row 16 (8 pixels above)
     * is wall, row 2 (22 pixels above, 22 degrees) is sky */
    cr_expect_gt(px(rgb, &v, 32, 16)[1], px(rgb, &v, 32, 16)[2], "wall at the middle column");
    cr_expect_gt(px(rgb, &v, 32, 2)[2], px(rgb, &v, 32, 2)[0], "sky above the wall");
    free(rgb), nl_field_free(f);
}

/* A ridge casts a shadow toward the side away from the sun: a ridge 30
 * samples high at x = 40..43, sun 20 degrees high, shades the plain for
 * 30 / tan(20) = 82 samples on its far side.  The camera, 10 samples above
 * x = 20 behind the field, looking along +y and 10 degrees down, sees the
 * plain x = 0..20 in the lower left quarter of the picture and the ridge on
 * the right.  With the sun in +x the plain there is in shadow; with the sun
 * in -x it is not (same terrain, same palette, same Lambert term on flat
 * ground): the shadowed sum has only the ambient 0.32 of 0.32 + 0.78 sin 20
 * = 0.59, a ratio of 0.54, so below 0.8 of the lit one. */
Test(render, ridges_cast_shadows_away_from_the_sun)
{
    nl_field *f = flat(64);
    nl_render_view v;
    uint8_t *lit, *shaded;
    double a = 0, b = 0;
    for (size_t j = 0; j < 64; j++)
        for (size_t i = 40; i < 44; i++)
            f->data[j * 64 + i] = 30;
    nl_render_view_default(f, &v);
    v.width = 64, v.height = 48, v.pitch = 10, v.cam[0] = 20, v.cam[1] = -5, v.cam[2] = 10, v.zscale = 1;
    v.sun[1] = 20, v.haze = 1e6, v.azimuth = 90, v.fov = 40;
    lit = malloc(v.width * v.height * 3), shaded = malloc(v.width * v.height * 3);
    v.sun[0] = 180;
    cr_assert_eq(nl_render_terrain(f, &v, lit), 0);
    v.sun[0] = 0;
    cr_assert_eq(nl_render_terrain(f, &v, shaded), 0);
    for (size_t y = 24; y < v.height; y++)
        for (size_t x = 0; x < v.width / 4; x++)
            for (int k = 0; k < 3; k++)
                a += px(lit, &v, x, y)[k], b += px(shaded, &v, x, y)[k];
    cr_expect_lt(b, 0.8 * a, "lower left: shadowed %g vs lit %g", b, a);
    /* the ridge (x = 40..43, right of the camera) is on the right: high up
     * at the right edge there is terrain, at the left edge sky */
    cr_expect_lt(px(lit, &v, 62, 6)[2], 150, "ridge at the right");
    cr_expect_gt(px(lit, &v, 1, 6)[2], px(lit, &v, 1, 6)[0], "sky at the left");
    free(lit), free(shaded), nl_field_free(f);
}

Test(render, refuses_bad_views)
{
    nl_field *f = flat(16);
    nl_render_view v;
    uint8_t rgb[3 * 4 * 4];
    size_t n1[1] = {16};
    nl_field *g = nl_field_alloc(1, n1, NULL, NULL);
    nl_render_view_default(f, &v);
    v.width = v.height = 4;
    v.fov = 175;
    cr_expect_neq(nl_render_terrain(f, &v, rgb), 0);
    nl_render_view_default(f, &v);
    v.width = v.height = 4;
    v.sun[1] = 0;
    cr_expect_neq(nl_render_terrain(f, &v, rgb), 0);
    cr_expect_neq(nl_render_terrain(g, &v, rgb), 0);
    nl_field_free(f), nl_field_free(g);
}

/* Lambert's law on gradients: a level surface returns ambient plus the
 * light's cosine to the vertical; a face turned toward the light returns
 * 1 and one turned away returns the ambient.  Exact up to a few ulps. */
Test(render, shade_gradients_lambert)
{
    const double l[3] = {-0.74, -0.43, 0.5}, ln = sqrt(0.74 * 0.74 + 0.43 * 0.43 + 0.25);
    /* the gradient whose normal is l / |l|: (-l0 / l2, -l1 / l2) */
    double gx[3] = {0, -l[0] / l[2], l[0] / l[2] * 40}, gy[3] = {0, -l[1] / l[2], l[1] / l[2] * 40}, out[3];
    nl_render_shade_gradients(3, gx, gy, l, 0.1, out);
    cr_assert_float_eq(out[0], 0.1 + 0.9 * l[2] / ln, 1e-15);
    cr_assert_float_eq(out[1], 1, 1e-15);
    cr_assert_eq(out[2], 0.1);
}

/* Relief of the tilted plane z = a x: central and one-sided differences
 * both give the gradient a zscale / h exactly, so every sample is
 * max(0, (-g cos el cos az + sin el) / sqrt(g^2 + 1)); to 1e-15. */
Test(render, relief_of_a_plane)
{
    size_t n[2] = {7, 5};
    double h[2] = {0.5, 2}, a = 0.3, zs = 1.7, az = 20, el = 35;
    nl_field *x = nl_field_alloc(2, n, h, NULL), *s = nl_field_alloc(2, n, h, NULL);
    for (size_t j = 0; j < 5; j++)
        for (size_t i = 0; i < 7; i++)
            x->data[j * 7 + i] = a * (double)i * h[0];
    cr_assert_eq(nl_render_relief(x, az, el, zs, s), 0);
    double g = a * zs, r = M_PI / 180;
    double want = fmax(0, (-g * cos(el * r) * cos(az * r) + sin(el * r)) / sqrt(g * g + 1));
    for (size_t q = 0; q < 35; q++)
        cr_assert_float_eq(s->data[q], want, 1e-15, "sample %zu", q);
    nl_field_free(x), nl_field_free(s);
}

/* Nearest-sample resampling to twice the size repeats every sample in a
 * 2 x 2 block; to the same size it copies. */
Test(render, nearest_resampling)
{
    double src[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9}, dst[36], same[9];
    nl_render_nearest(3, src, 6, dst);
    for (size_t y = 0; y < 6; y++)
        for (size_t x = 0; x < 6; x++)
            cr_assert_eq(dst[y * 6 + x], src[(y / 2) * 3 + x / 2]);
    nl_render_nearest(3, src, 3, same);
    cr_assert_arr_eq(same, src, sizeof src);
}

/* The default grey range is the mean -+ 3 sd, the sample sd (divisor
 * n - 1): for the samples -1, 1, 1, -1 that is -+ 3 sqrt(4/3). */
Test(render, grey_range)
{
    size_t n[2] = {2, 2};
    nl_field *x = nl_field_alloc(2, n, NULL, NULL);
    double lo, hi;
    x->data[0] = x->data[3] = -1, x->data[1] = x->data[2] = 1;
    cr_assert_eq(nl_render_grey_range(x, &lo, &hi), 0);
    cr_assert_float_eq(hi - lo, 6 * sqrt(4.0 / 3.0), 1e-12, "%g", hi - lo);
    cr_assert_float_eq(lo + hi, 0, 1e-15);
    nl_field_free(x);
}
