/* Field files: OpenEXR (through the OpenEXRCore C API), PNG, TSV; the
 * format registry over them and the other formats is core/format.h.
 *
 * EXR: one FLOAT channel "Y", uncompressed scanlines: random fields do not
 * compress (PIZ saved 0% on white-ish noise and 9% on a smooth Gaussian
 * field, at half the run time of a 4096^2 synthesis), and OpenEXRCore 3.1.5
 * corrupts ZIP chunks that do not compress (tests/test_io.c); a 1D field is one
 * row, a 3D field of n0 x n1 x n2 is stored as an image n0 wide and n1*n2
 * high (slice k is rows k*n1 .. k*n1+n1-1), with noiselab.size saying so.
 * String attributes record how the field was made (nl_meta).
 *
 * Writers write exactly the path given; making outputs appear atomically is
 * the caller's job (cli/ writes to a temporary name and renames).
 *
 * Common contract.  Readers put a new field in *out (NULL on failure),
 * released by nl_field_free, and return NL_OK, NL_EINPUT (missing,
 * unreadable or malformed file, named in the message), NL_ETOOBIG (the size
 * the file declares does not fit: nl_size_check, honouring
 * NOISELAB_MEMORY_LIMIT) or NL_ENOMEM.  Writers return NL_OK, NL_EIO (the
 * path cannot be created or written), NL_ETOOBIG (the image is too large for
 * the format) or NL_ENOMEM, and never modify their inputs.  Every function is
 * thread-safe (no shared state; OpenEXRCore and libpng's simplified API keep
 * theirs per call), as long as two threads do not write one path. */
#ifndef NL_IO_H
#define NL_IO_H

#ifdef __cplusplus
extern "C" {
#endif

#include "field.h"

#include <stdint.h>
#include <stdio.h>

/* Provenance stored with a field, as key/value text; empty strings are not
 * written.  core/provenance.h formats and parses it (nl_provenance). */
typedef struct {
    char model[1024];   /* noiselab.model: the model spec */
    char method[256];   /* noiselab.method: synthesis method and its parameters */
    char seed[32];      /* noiselab.seed: decimal seed */
    char spacing[128];  /* noiselab.spacing: "h0[,h1[,h2]]" */
    char size[64];      /* noiselab.size: "N[xM[xK]]" */
    char version[32];   /* noiselab.version */
    char flags[256];    /* noiselab.flags: comma-separated detector flags */
    char origin[64];    /* noiselab.origin: where sample 0 sits, "X[,Y[,Z]]" in samples (nl_meta_origin) */
    /* Georeferencing, carried by the GDAL formats (geotiff, cog, netcdf)
     * alone; the others neither write nor read it. */
    char crs[1024];     /* coordinate reference system: "EPSG:N", or WKT; "": none */
    char extent[192];   /* the grid's outer extent in CRS units, cell edges,
                           "x0:x1,y0:y1" (%.17g), y0 the south edge; "": none */
} nl_meta;

/* Write `f` as EXR with the attributes of `meta` (may be NULL).  Samples
 * are stored as 32-bit floats (rounded to nearest).  Returns NL_OK, NL_EIO,
 * NL_ETOOBIG (n0 or n1 n2 over 2^31 - 1) or NL_ENOMEM. */
int nl_exr_write(const char *path, const nl_field *f, const nl_meta *meta);

/* Read the "Y" channel (or the only channel) of an EXR into a new field;
 * noiselab.size and noiselab.spacing are honoured when present.  `meta`
 * (may be NULL) receives the attributes found.  Samples are widened to
 * double exactly (they may be non-finite: nl_field_read checks).  NL_EINPUT
 * on a bad file (not EXR, tiled or deep, no "Y" channel and several others,
 * subsampled, empty window, noiselab.size or .spacing inconsistent, a
 * noiselab.* attribute that is not a string, is longer than its nl_meta
 * capacity less one, or holds a NUL or control character). */
int nl_exr_read(const char *path, nl_field **out, nl_meta *meta);

/* Read an 8- or 16-bit PNG (grey, or colour converted to grey by the
 * Rec. 709 weights) into a new 2D field with values in [0, 1] (stored value
 * over 255 or 65535, no gamma decoding), unit spacing, top row first (row
 * j = 0 is the image's top).  NL_EINPUT on a file that is not a readable
 * PNG. */
int nl_png_read(const char *path, nl_field **out);

/* Write an 8-bit grey PNG of a w x h row-major image (w h bytes, top row
 * first).  NL_ETOOBIG beyond 2^31 - 1 pixels a side. */
int nl_png_write_gray8(const char *path, size_t w, size_t h, const uint8_t *pix);

/* Write an 8-bit RGB PNG of a w x h image (3 bytes per pixel, row-major,
 * top row first).  NL_ETOOBIG beyond 2^31 - 1 pixels a side. */
int nl_png_write_rgb8(const char *path, size_t w, size_t h, const uint8_t *rgb);

/* 8-bit preview of a 2D field (the first z slice of a 3D one): values from
 * lo to hi map linearly onto 0..255 and are clamped.  NL_EINVAL unless
 * lo < hi. */
int nl_png_write_field(const char *path, const nl_field *f, double lo, double hi);

/* Write a TSV table: `comment` (may be NULL) as a '#' line, a header line of
 * the ncols names, then nrows rows of the columns cols[0..ncols-1] (each of
 * nrows doubles, printed with %.10g; a NaN, a missing value, as "NA", as R
 * writes it).  NL_EIO when the file cannot be created or a write fails. */
int nl_tsv_write(const char *path, const char *comment, int ncols, const char *const *names,
                 size_t nrows, const double *const *cols);

/* The same, to an open stream (e.g. stdout); the stream is not closed.
 * NL_EIO when the stream reports an error. */
int nl_tsv_fwrite(FILE *fp, const char *comment, int ncols, const char *const *names, size_t nrows,
                  const double *const *cols);

/* Write a 1D field as a TSV table: the non-empty fields of `meta` (may be
 * NULL) as comment lines "# key: value" (model, method, seed, spacing,
 * size, version, flags, origin: the EXR attributes without "noiselab."),
 * then the header "COORD<TAB>value" (coord NULL: "t") and one row per
 * sample, both columns printed with %.10g (a NaN sample, a missing value,
 * as "NA", as R writes it).  The coordinates are t[0..n-1]
 * when t is not NULL, else t_i = (X + i) h with X the first number of
 * meta->origin (0 when empty) and h = f->h[0].  NL_EINVAL for a field that
 * is not 1D or an origin that is not an integer (nothing written); NL_EIO
 * as nl_tsv_write. */
int nl_tsv_write_field(const char *path, const nl_field *f, const nl_meta *meta, const char *coord,
                       const double *t);

/* Read a 1D field from a TSV table with a header line: the column named
 * "value", and at most one other, a first column named "t" or "x" that
 * gives the spacing (t1 - t0) and must be finite, increasing and regular
 * (each t within a thousandth of a step of t0 + i step).  Lines starting
 * with '#' are skipped; those before the header of the form "# key: value"
 * with a key of nl_meta fill it (nl_field_read), and a "spacing" within
 * 1e-6 of t1 - t0 is taken as the spacing (t0 need not be 0).  NL_EINPUT: no file, no header, no "value" column,
 * more than two columns (scattered points are not a series), a row with a
 * different column count, a value or coordinate that is not a finite
 * number, a coordinate column that is constant, decreasing or irregular, a
 * line longer than 4095 characters, fewer than 2 samples, or a "# key:"
 * line given twice, longer than its nl_meta capacity less one, or holding a
 * control character; NL_ETOOBIG or
 * NL_ENOMEM when the samples do not fit in memory. */
int nl_tsv_read_field(const char *path, nl_field **out);

/* Read any field through the format registry (core/format.h): by content
 * where a format has a signature (EXR, PNG, .npy), else by the extension
 * (.r16, .raw, .f32), else TSV.  The file is read once, front to back
 * (core/io_read_internal.h), so a pipe, a FIFO or /dev/stdin works as well
 * as a file; NL_ETOOBIG when it grows beyond the memory available,
 * NL_EINPUT for a folder or an HDF5 file (libnoiselab_mpi reads those:
 * NL_EINVAL).  Samples must be finite (NL_EINPUT names the first that is
 * not).  `meta` (may be NULL) is zeroed, then filled from what the format
 * records (EXR attributes, TSV comment lines, PNG text chunks). */
int nl_field_read(const char *path, nl_field **out, nl_meta *meta);

#ifdef __cplusplus
}
#endif

#endif
