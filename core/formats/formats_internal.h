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

#endif
