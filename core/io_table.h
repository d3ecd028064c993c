/* Tables of named numeric columns from TSV: a header line of tab-separated
 * column names (any names, each once), then one row of as many
 * tab-separated finite numbers per record.  Lines starting with '#' and
 * empty lines are skipped, a UTF-8 byte order mark and CR before line ends
 * are ignored; lines have no length limit.  Unlike nl_points_read
 * (core/io_points.h), which refuses any column but x, y, z and value, every
 * column is kept by name: coordinates, values, covariates, fold ids.  A
 * cell that is not a finite number ("NA", text, "inf", empty) is refused,
 * naming file, line and column: a table is read whole or not at all.
 *
 * The text of each row is kept as read (without its line end) so that a
 * table can be written back with new columns and its cells unchanged
 * (nl_table_write). */
#ifndef NL_IO_TABLE_H
#define NL_IO_TABLE_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stddef.h>

typedef struct {
    size_t n;       /* rows, >= 1 */
    size_t ncols;   /* columns, >= 1 */
    char **names;   /* ncols column names */
    double **cols;  /* ncols columns of n values each */
    char **rows;    /* n rows' text as read, without CR or LF */
    char *header;   /* the header line as read, without CR or LF */
    char *path;     /* the file read (a copy), for messages */
} nl_table;

/* Read path into a new table (*out; NULL on failure), released by
 * nl_table_free.  Errors: NL_EINPUT when the file cannot be opened, has no
 * header or no row, a name is empty or given twice, a row has another
 * number of cells than the header, or a cell is not a finite number (the
 * message names file, line and column); NL_ETOOBIG when the rows outgrow
 * the memory available (core/field.h); NL_ENOMEM.  Thread-safe. */
int nl_table_read(const char *path, nl_table **out);

/* The index of the column called name, or -1. */
long nl_table_column(const nl_table *t, const char *name);

/* The coordinates of the table: the columns x [y [z]] (x required; y when
 * z is present) as *dim (1 to 3) and a new array *pts of n * dim numbers
 * (row-major), released by free; when value is not NULL, the column of
 * that name as a new array *val of n numbers (else *val is not touched).
 * Errors: NL_EINPUT naming the missing column; NL_ENOMEM. */
int nl_table_points(const nl_table *t, const char *value, int *dim, double **pts, double **val);

/* Write path: the table's header and rows as read, each followed by the
 * nextra columns extra[0..nextra-1] (n numbers each) called names[...],
 * printed with 17 significant digits (exact in double), "NA" for a NaN (as
 * R writes a missing value).  NL_EIO when the file cannot be created or a
 * write fails. */
int nl_table_write(const char *path, const nl_table *t, size_t nextra, const char *const *names,
                   const double *const *extra);

/* Free t and its arrays (NULL is a no-op). */
void nl_table_free(nl_table *t);

#ifdef __cplusplus
}
#endif

#endif
