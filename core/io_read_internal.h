/* Reading a file once (internal to core/io_*.c).
 *
 * Inputs are read once, front to back, so that pipes, FIFOs and /dev/stdin
 * work as inputs: nl_field_read takes the whole file into memory, looks at
 * its first bytes and decodes the copy (the EXR reader seeks, which a pipe
 * cannot). */
#ifndef NL_IO_READ_INTERNAL_H
#define NL_IO_READ_INTERNAL_H

#include "io.h"

#include <stddef.h>

/* The whole of `path` (a file, pipe, FIFO or character device) in a new
 * block *buf of *len bytes (plus a NUL after them), released by free.
 * NL_EINPUT when it cannot be opened or read or is a folder (the message
 * names the path), NL_ETOOBIG when it grows beyond the memory available
 * (nl_mem_available), NL_ENOMEM.  Thread-safe. */
int nl_io_slurp(const char *path, unsigned char **buf, size_t *len);

/* One tab-separated row of exactly cols finite numbers into v (ending at
 * the line's end); 0 when the line is not that (core/io_points.c). */
int nl_tsv_row(const char *line, size_t cols, double *v);

/* A line a table skips: a comment ('#' first) or an empty line ("\n" or
 * "\r\n"). */
int nl_tsv_skipped(const char *line);

/* The columns of a point table (core/io_points.h, core/io_coords.h), named
 * by its header line in any order. */
typedef struct {
    size_t cols;  /* columns of the header */
    int dim;      /* coordinates: 1 (x), 2 (x y) or 3 (x y z) */
    int at[4];    /* the columns (0-based) of x, y, z and value; -1 where absent */
} nl_point_columns;

/* Read the header of a point table from fp (skipping comment and empty
 * lines and a UTF-8 byte order mark; a CR before the line end is dropped):
 * tab-separated names, each of x, y, z and value at most once, x present, y
 * when z is, value when need_value.  NL_EINPUT naming the column otherwise
 * (an unknown or empty name, one given twice, one missing), when there is no
 * header or it is longer than 4095 characters.  *lineno counts the lines read
 * (core/io_points_header.c). */
int nl_point_columns_read(FILE *fp, const char *path, int need_value, size_t *lineno, nl_point_columns *c);

/* The readers of io.h on a file already in memory (`path` only names it in
 * messages); same results and codes. */
int nl_exr_read_mem(const char *path, const unsigned char *buf, size_t len, nl_field **out, nl_meta *meta);
int nl_png_read_mem(const char *path, const unsigned char *buf, size_t len, nl_field **out);
int nl_tsv_read_stream(FILE *fp, const char *path, nl_field **out, nl_meta *meta);

#endif
