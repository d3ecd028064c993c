/* Field file formats: one constant descriptor each, one registration list,
 * one write call and one read call.
 *
 * A format is one file under core/formats/ holding its descriptor plus one
 * line in core/formats/list.h.  The descriptor says what the format is and
 * can hold: its name (as --format and Python's format= take it), the
 * extensions that select it, the dimensions and value types it stores, the
 * metadata it carries, the signature that identifies its files, and its
 * read and write functions.  nl_field_write and nl_field_read (core/io.h)
 * dispatch through the registry; `noiselab formats`, the CLI's messages,
 * Python's formats() and docs/formats.md list it.
 *
 * HDF5 is a descriptor of the registry whose functions live in
 * libnoiselab_mpi (mpi/h5.h), which this library does not link: its
 * descriptor has the flag NL_FORMAT_EXTERNAL and NULL read and write, and
 * nl_field_write / nl_field_read refuse it with NL_EINVAL naming
 * libnoiselab_mpi; callers that load that library (cli/ through cli_h5,
 * Python through h5lib) test the flag and call nl_mpi_h5_* themselves,
 * then nl_xdmf_write for the sidecar.  The georeferenced formats (GeoTIFF,
 * COG, NetCDF-CF) go through GDAL (core/formats/gdal_io.h) when it was found
 * at build time, else their descriptors carry NL_FORMAT_OFF.
 *
 * Samples are x fastest (core/field.h), row j = 0 first: in the image
 * formats that row is the image's top.  Descriptors are constant and live
 * for the program; every function here is thread-safe as long as two
 * threads do not write one path. */
#ifndef NL_FORMAT_H
#define NL_FORMAT_H

#include "field.h"
#include "io.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Value types a format stores (nl_format.types). */
enum {
    NL_FORMAT_F32 = 1 << 0, /* IEEE float32: nl_write_options.precision 32 */
    NL_FORMAT_F64 = 1 << 1, /* IEEE float64: precision 64 */
    NL_FORMAT_U16 = 1 << 2, /* 0..65535 mapped linearly from a value range */
    NL_FORMAT_U8 = 1 << 3   /* 0..255 mapped linearly from a value range */
};

/* Metadata a format carries (nl_format.meta; 0: none, the samples alone). */
enum {
    NL_FORMAT_META_PROVENANCE = 1 << 0, /* nl_meta's strings (model, method, seed, ...) */
    NL_FORMAT_META_SPACING = 1 << 1,    /* the grid spacing (else read as 1) */
    NL_FORMAT_META_ORIGIN = 1 << 2,     /* a window's first sample (nl_meta.origin) */
    NL_FORMAT_META_RANGE = 1 << 3,      /* the value range of integer samples, to map back */
    NL_FORMAT_META_CRS = 1 << 4,        /* a coordinate reference system (nl_meta.crs) */
    NL_FORMAT_META_NODATA = 1 << 5      /* a missing-value marker: NaN samples declared missing */
};

/* Descriptor flags. */
enum {
    NL_FORMAT_EXTERNAL = 1 << 0, /* read and written by libnoiselab_mpi (mpi/h5.h): read, write NULL */
    NL_FORMAT_FALLBACK = 1 << 1, /* what nl_field_read takes a file that nothing else claims for */
    NL_FORMAT_SIZED = 1 << 2,    /* no header: reading needs the size (nl_read_options.n), or
                                    takes a square 2D field when the length is one */
    NL_FORMAT_OFF = 1 << 3       /* not built in (e.g. no GDAL or OpenVDB at build time): read and write
                                    NULL, the summary says why; nl_field_write / _read refuse it */
};

/* How a field is written (NULL: all defaults). */
typedef struct {
    const char *format; /* a registered name (nl_format_find), or NULL: by the path's extension */
    int precision;      /* 32 or 64 for float formats; 0: the format's default
                           (nl_format.precision); ignored by integer formats */
    double lo, hi;      /* integer formats: the values mapped to 0 and to the largest code;
                           lo == hi (e.g. both 0): the field's min and max */
    const char *sidecar; /* headerless raw formats (.r16, .raw, .f32): where their JSON sidecar
                            of size, range, spacing, origin and byte order goes; NULL: the
                            path plus ".json" (height.r16.json); "": none */
} nl_write_options;

/* How a field is read (NULL: all defaults). */
typedef struct {
    const char *format; /* a registered name, or NULL: by content, then extension, then TSV */
    int dim;            /* NL_FORMAT_SIZED formats: the size, n[0] (x) first; 0: none given */
    size_t n[3];
    double lo, hi;      /* headerless integer formats (.r16): the values of codes 0 and 65535;
                           lo == hi: 0 and 1 */
} nl_read_options;

typedef struct nl_format {
    const char *name;       /* as --format and format= take it, e.g. "npy" */
    const char *extensions; /* ".npy" or ".raw .r16": the names that select it, space separated,
                               lower case (matched ignoring case) */
    const char *summary;    /* one line for `noiselab formats` */
    unsigned dims;          /* the dimensions it holds: bit d set for dD (1 << 2 for 2D) */
    unsigned types;         /* NL_FORMAT_F32 ... */
    int precision;          /* float formats: the default precision, 32 or 64 */
    unsigned meta;          /* NL_FORMAT_META_* */
    unsigned flags;         /* NL_FORMAT_EXTERNAL, _FALLBACK, _SIZED, _OFF */
    const char *magic;      /* the file's first bytes, or NULL: none (told by extension) */
    size_t magic_len;       /* at most 8 */
    /* A field from the len bytes of a file at buf (path names it in
     * messages; o may be NULL): the readers' contract of core/io.h. */
    int (*read)(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o,
                nl_field **out, nl_meta *meta);
    /* The same from a stream read once, front to back (NULL: read from a
     * copy in memory): for text formats that need not hold the file. */
    int (*read_stream)(FILE *fp, const char *path, nl_field **out, nl_meta *meta);
    /* Write f (dimension and precision already checked against the
     * descriptor; o not NULL): the writers' contract of core/io.h. */
    int (*write)(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o);
} nl_format;

/* The registered formats: i < nl_format_count(), in the order of
 * `noiselab formats`; NULL for a bad i. */
size_t nl_format_count(void);
const nl_format *nl_format_get(size_t i);

/* The format named `name` (exact, lower case), or NULL. */
const nl_format *nl_format_find(const char *name);

/* The format that path's extension selects (ignoring case), or NULL. */
const nl_format *nl_format_for_path(const char *path);

/* The names, "exr, tsv, ..." (what), or the extensions, ".exr, .tsv, ..."
 * (!what), into buf of len bytes (truncated to fit, NUL-terminated).  For
 * messages that list what is expected. */
void nl_format_list(int names, char *buf, size_t len);

/* The format a write of path with options o uses: o->format by name, else
 * by path's extension.  NL_EINVAL with a message naming the format or the
 * path and listing the registry otherwise. */
int nl_format_resolve(const char *path, const char *format, const nl_format **out);

/* Write f to path in the format of o->format or of path's extension, with
 * the provenance of meta (may be NULL; written where the format carries
 * it).  Checks first, writing nothing on failure: NL_EINVAL for an unknown
 * format or extension, a dimension or precision the format does not hold,
 * a range with lo > hi, an infinite sample, a sample beyond float32 in a
 * float32 format, a NaN (a missing value, which float formats keep) in an
 * integer format, or an NL_FORMAT_EXTERNAL format (HDF5: nl_mpi_h5_write_field
 * in libnoiselab_mpi); then what the format's writer returns (NL_OK,
 * NL_EIO, NL_ETOOBIG, NL_ENOMEM).  Integer formats map [lo, hi] linearly
 * onto their codes, rounding to nearest and clamping.  An NL_FORMAT_OFF
 * format is NL_EINVAL with its summary as the reason. */
int nl_field_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o);

/* A kriged map and its variance in one NumPy .npz (numpy.savez's layout:
 * a zip of uncompressed members "field.npy" and "variance.npy", which
 * numpy.load gives as arrays "field" and "variance", axes slowest first);
 * variance may be NULL (then "field" alone, as nl_field_write of an .npz
 * path) and must otherwise have field's shape.  precision 32 or 64 (0:
 * 64).  The checks of nl_field_write on each (NL_EINVAL, nothing written),
 * then NL_OK, NL_EIO or NL_ENOMEM.  No metadata: the format holds none. */
int nl_npz_write(const char *path, const nl_field *field, const nl_field *variance, int precision);

/* nl_field_read (core/io.h) with options: o->format forces a format; a
 * headerless one (NL_FORMAT_SIZED) takes its size and value range from o.
 * NL_EINVAL for an unknown name or an NL_FORMAT_EXTERNAL format, and for a
 * file of an NL_FORMAT_OFF format (named by its signature or extension). */
int nl_field_read_opts(const char *path, const nl_read_options *o, nl_field **out, nl_meta *meta);

/* NL_OK when crs is a coordinate reference system GDAL knows ("EPSG:N",
 * WKT or PROJ text), as nl_meta.crs takes it for the georeferenced formats;
 * NL_EINVAL with a message naming it otherwise, and always in a build
 * without GDAL. */
int nl_format_crs_check(const char *crs);

/* Write the XDMF 3 sidecar xmf_path describing the dataset /field of the
 * HDF5 file h5_name (as the sidecar refers to it: a name relative to the
 * sidecar's folder) holding a dim-D field of n[0..dim-1] samples (x first)
 * at spacing h (x first; NULL: 1), first sample at origin (x first, in
 * length units; NULL: 0), in float64 when dbl, else float32: a
 * 2DCoRectMesh or 3DCoRectMesh topology (XDMF lists axes slowest first)
 * with ORIGIN_DXDYDZ geometry, one node-centred scalar "field".  A 1D field
 * is described as a 2D mesh one sample high.  ParaView opens the sidecar.
 * NL_OK, NL_EINVAL (dim, n or h), NL_EIO. */
int nl_xdmf_write(const char *xmf_path, const char *h5_name, int dim, const size_t *n, const double *h,
                  const double *origin, int dbl);

#ifdef __cplusplus
}
#endif

#endif
