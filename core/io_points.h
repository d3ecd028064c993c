/* Scattered data points from a TSV file: a header line of 2 to 4
 * tab-separated column names, x [y [z]] and value in any order (the columns
 * are found by name: "y x value" reads the first column as y), then one row
 * of as many tab-separated finite numbers per point; lines starting with '#'
 * and empty lines are skipped, a UTF-8 byte order mark and CR before line
 * ends are ignored (lines are read up to 4095 characters).  Any other name,
 * an empty one or one given twice is refused: there is no extra column to
 * drop silently, and no table without a header. */
#ifndef NL_IO_POINTS_H
#define NL_IO_POINTS_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

typedef struct {
    int dim;      /* coordinates per point, 1 to 3 */
    size_t n;     /* points, >= 1 */
    double *pts;  /* n * dim coordinates, point i at pts[i * dim] */
    double *val;  /* n values */
} nl_points;

/* Read path into a new nl_points (*out; NULL on failure), released by
 * nl_points_free.  Errors: NL_EINPUT when the file cannot be opened, the
 * header is not the names above (the message names the column: unknown,
 * empty, twice, or x, y before z, or value missing), a row is not that many finite numbers, or there is no row
 * (the message names file and line); NL_ETOOBIG when the rows outgrow the
 * memory available (core/field.h); NL_ENOMEM.  Thread-safe. */
int nl_points_read(const char *path, nl_points **out);

/* Free p and its arrays (NULL is a no-op). */
void nl_points_free(nl_points *p);

#ifdef __cplusplus
}
#endif

#endif
