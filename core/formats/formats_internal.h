/* Helpers shared by the format descriptors (core/formats/, internal). */
#ifndef NL_FORMATS_INTERNAL_H
#define NL_FORMATS_INTERNAL_H

#include "../format.h"

#include <stdint.h>

/* The range [*lo, *hi] an integer format maps onto its codes: o's when
 * o->lo < o->hi, else f's min and max (max = min + 1 for a constant field). */
void nl_format_range(const nl_field *f, const nl_write_options *o, double *lo, double *hi);

/* Sample v as a code 0..top of the range [lo, hi] (rounded to nearest, clamped). */
uint32_t nl_format_code(double v, double lo, double hi, uint32_t top);

/* The dimension and size of a headerless file of `count` samples: o's size
 * when given (its product must be count), else a square 2D field.  NL_EINPUT
 * naming path otherwise. */
int nl_format_raw_size(const char *path, size_t count, const nl_read_options *o, int *dim, size_t *n);

/* nl_field_write's checks of f against t with o (its precision set to
 * the one written), for writers reached another way (nl_npz_write). */
int nl_format_check(const nl_format *t, const nl_field *f, nl_write_options *o);

/* .npy pieces (npy.c) for .npz (npz.c): the version 1.0 header of f with
 * samples of size bytes (4 or 8) into head (256 bytes), its length
 * returned; samples i0 .. i0 + k - 1 of f, little-endian, into buf; and a
 * field from the .npy bytes buf (path names it in messages). */
size_t nl_npy_header(const nl_field *f, size_t size, char *head);
void nl_npy_samples(const nl_field *f, size_t size, size_t i0, size_t k, unsigned char *buf);
int nl_npy_decode(const char *path, const unsigned char *buf, size_t len, nl_field **out);

/* The JSON sidecar of a headerless raw file (.r16, .raw, .f32), written
 * beside it (core/formats/raw_sidecar.c):
 *   {"format": "r16", "size": [nx, ny], "byte_order": "little",
 *    "spacing": [hx, hy], "origin": [x0, y0], "range": [lo, hi]}
 * size x first; origin the coordinate of sample 0 in length units, x first
 * (nl_meta_origin); range for the 16-bit codes only (code 0 and 65535).
 * Written to o->sidecar, or path + ".json" when it is NULL, nowhere when
 * it is "".  NL_OK, NL_EIO, NL_EINVAL (a record nl_meta_origin refuses). */
int nl_raw_sidecar_write(const char *path, const char *format, const nl_field *f, const nl_meta *meta,
                         const nl_write_options *o, const double *range);

/* What path's sidecar (path + ".json") says, when there is one (*found 1;
 * 0 and nothing else set when there is none): the size into r (dim, n),
 * the range into r->lo, r->hi (16-bit codes: range required), the spacing
 * into h and the origin (length units) into origin (x first; 1 and 0 when
 * absent).  count: the samples the file holds, which the size must make.
 * NL_EINPUT with one line naming the sidecar for one that is not JSON, not
 * an object, has a size of other than 1 to 3 positive integers or one
 * that disagrees with count, a byte order other than "little", a range
 * without lo < hi, a spacing not positive or an origin not finite. */
int nl_raw_sidecar_read(const char *path, const char *format, size_t count, nl_read_options *r, double *h,
                        double *origin, int *found);

/* Apply a sidecar's spacing and origin (dim axes) to f and meta (may be NULL). */
int nl_raw_sidecar_apply(nl_field *f, nl_meta *meta, const double *h, const double *origin);

#endif
