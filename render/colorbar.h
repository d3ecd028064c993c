/* A grey-level picture of a 2D field with its colour bar: the field's
 * grey levels (as nl_png_write_field maps them) and, to its right, a ramp
 * from hi (top) to lo (bottom) framed in black, with ticks and numbers at
 * lo, the middle and hi (a 3 x 5 pixel font drawn twice as large; only lo
 * and hi on pictures shorter than 64 rows), on white.
 *
 * Thread safety: reentrant (no shared state). */
#ifndef NL_RENDER_COLORBAR_H
#define NL_RENDER_COLORBAR_H

#ifdef __cplusplus
extern "C" {
#endif

#include "../core/field.h"

#include <stddef.h>
#include <stdint.h>

/* Columns the bar adds to the right of the field: room for numbers of
 * ten characters ("-1.23e+04", %.3g). */
#define NL_COLORBAR_WIDTH 112

/* *pix (released by free) receives a (*w) x (*h) 8-bit grey image, row-major,
 * top row first: the first slice of f (n0 x n1) mapped linearly from lo..hi
 * onto 0..255 and clamped, then the bar; *w = n0 + NL_COLORBAR_WIDTH,
 * *h = n1.  Returns NL_OK, NL_EINVAL (f not 2D or 3D, or not lo < hi, both
 * finite), NL_ETOOBIG (the picture does not fit: nl_size_check) or
 * NL_ENOMEM; *pix is NULL on failure. */
int nl_render_grey_colorbar(const nl_field *f, double lo, double hi, uint8_t **pix, size_t *w, size_t *h);

#ifdef __cplusplus
}
#endif

#endif
