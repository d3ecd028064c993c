/* Point coordinates from a TSV file (where to sample a field): a header
 * line of 1 to 3 tab-separated column names (x [y [z]]) and optionally a
 * column named "value" that is read and dropped (so a data table,
 * core/io_points.h, names its own points), in any order and read by name
 * with the rules of core/io_points.h, then one row of as many
 * tab-separated finite numbers per point; lines starting with '#' and
 * empty lines are skipped (lines are read up to 4095 characters). */
#ifndef NL_IO_COORDS_H
#define NL_IO_COORDS_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

/* Read path: *dim (1..3) coordinates per point, *n (>= 1) points, *pts
 * (n * dim doubles, point i at pts[i * dim], released by free()).  *pts is
 * NULL on failure.  Errors: NL_EINPUT when the file cannot be opened, the
 * header is not those names (named in the message as in core/io_points.h), a row is not that many
 * finite numbers, or there is no row (the message names file and line);
 * NL_ETOOBIG when the rows outgrow the memory available (core/field.h);
 * NL_ENOMEM.  Thread-safe. */
int nl_coords_read(const char *path, int *dim, size_t *n, double **pts);

#ifdef __cplusplus
}
#endif

#endif
