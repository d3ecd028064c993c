/* A grey-level picture with its colour bar (render/colorbar.h). */
#include "colorbar.h"
#include "../core/field.h"
#include "../core/nl_error.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { GAP = 8, BAR = 16, TICK = 4, SCALE = 2, ADVANCE = 4 * SCALE, MARGIN = 6 };

/* 3 x 5 glyphs, one row per 3 bits (top row first). */
static const struct {
    char c;               /* the character */
    unsigned char row[5]; /* its rows, bit 2 leftmost */
} glyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'-', {0, 0, 7, 0, 0}}, {'+', {0, 2, 7, 2, 0}},
    {'.', {0, 0, 0, 0, 2}}, {'e', {0, 7, 7, 4, 7}},
};

static void put(uint8_t *pix, size_t w, size_t h, long x, long y, uint8_t v)
{
    if (x >= 0 && y >= 0 && (size_t)x < w && (size_t)y < h)
        pix[(size_t)y * w + (size_t)x] = v;
}

/* The text s in black with its top-left corner at (x, y). */
static void text(uint8_t *pix, size_t w, size_t h, long x, long y, const char *s)
{
    for (; *s; s++, x += ADVANCE)
        for (size_t g = 0; g < sizeof glyphs / sizeof *glyphs; g++) {
            if (glyphs[g].c != *s)
                continue;
            for (int r = 0; r < 5 * SCALE; r++)
                for (int c = 0; c < 3 * SCALE; c++)
                    if (glyphs[g].row[r / SCALE] >> (2 - c / SCALE) & 1)
                        put(pix, w, h, x + c, y + r, 0);
        }
}

/* The ramp, its frame, and ticks with numbers, in columns x0.. of pix. */
static void draw_bar(uint8_t *pix, size_t w, size_t h, size_t x0, double lo, double hi)
{
    long top = MARGIN, bot = (long)h - 1 - MARGIN, bx = (long)x0 + GAP;
    int nt = h >= 64 ? 3 : 2;
    for (long y = top; y <= bot; y++) {
        double u = bot > top ? (double)(bot - y) / (double)(bot - top) : 0.5;
        for (long x = bx; x < bx + BAR; x++)
            put(pix, w, h, x, y, (uint8_t)lrint(255 * u));
        put(pix, w, h, bx - 1, y, 0), put(pix, w, h, bx + BAR, y, 0);
    }
    for (long x = bx - 1; x <= bx + BAR; x++)
        put(pix, w, h, x, top - 1, 0), put(pix, w, h, x, bot + 1, 0);
    for (int t = 0; t < nt; t++) {
        double u = (double)t / (nt - 1);
        long y = lrint((double)bot - u * (double)(bot - top));
        char s[32];
        double v = lo + u * (hi - lo);
        snprintf(s, sizeof s, "%.3g", fabs(v) < 1e-9 * (hi - lo) ? 0.0 : v); /* 0, not -1.2e-12 */
        for (long x = bx + BAR; x < bx + BAR + TICK; x++)
            put(pix, w, h, x, y, 0);
        text(pix, w, h, bx + BAR + TICK + 2, y - 5 * SCALE / 2, s);
    }
}

int nl_render_grey_colorbar(const nl_field *f, double lo, double hi, uint8_t **pix, size_t *w, size_t *h)
{
    size_t n0, n1, dims[2];
    int st;
    *pix = NULL;
    if (f->dim < 2 || !(hi > lo) || !isfinite(lo) || !isfinite(hi))
        return NL_ERROR(NL_EINVAL, "colour bar: expected a 2D field and a finite range lo < hi, got %dD and %g..%g",
                        f->dim, lo, hi);
    n0 = f->n[0], n1 = f->n[1];
    dims[0] = n0 + NL_COLORBAR_WIDTH, dims[1] = n1;
    if ((st = nl_size_check(2, dims, 1, 1, NULL)))
        return st;
    if (!(*pix = malloc(dims[0] * n1)))
        return NL_ERROR(NL_ENOMEM, "out of memory for a %zu x %zu picture", dims[0], n1);
    memset(*pix, 255, dims[0] * n1);
    for (size_t j = 0; j < n1; j++)
        for (size_t i = 0; i < n0; i++) { /* as nl_png_write_field */
            double v = (f->data[j * n0 + i] - lo) / (hi - lo) * 255.0;
            (*pix)[j * dims[0] + i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : lrint(v));
        }
    draw_bar(*pix, dims[0], n1, n0, lo, hi);
    *w = dims[0], *h = n1;
    return NL_OK;
}
