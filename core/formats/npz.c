/* NumPy .npz: a zip of .npy members, stored uncompressed, as numpy.savez
 * writes it (numpy/lib/npyio.py): "field.npy" and, from nl_npz_write,
 * "variance.npy" (a kriged map and its variance in one file); numpy.load
 * gives them as arrays "field" and "variance".  The zip is libzip's.
 * Reading gives the "field" member (any .npy of npy.c's reader); no
 * metadata, as .npy. */
#include "formats_internal.h"
#include "../nl_error.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <zip.h>

/* The .npy bytes of f (samples of size bytes) in a new buffer. */
static unsigned char *encode(const nl_field *f, size_t size, size_t *len)
{
    char head[256];
    size_t hl = nl_npy_header(f, size, head);
    unsigned char *b;
    if (f->count > (SIZE_MAX - hl) / size || !(b = malloc(hl + f->count * size)))
        return NULL;
    memcpy(b, head, hl);
    nl_npy_samples(f, size, 0, f->count, b + hl);
    *len = hl + f->count * size;
    return b;
}

/* Member name of array f into the open archive z. */
static int add(zip_t *z, const char *path, const char *name, const nl_field *f, size_t size)
{
    size_t len;
    unsigned char *b = encode(f, size, &len);
    zip_source_t *src;
    zip_int64_t i;
    if (!b)
        return NL_ERROR(NL_ENOMEM, "out of memory writing %s", path);
    if (!(src = zip_source_buffer(z, b, len, 1))) { /* 1: libzip frees b */
        free(b);
        return NL_ERROR(NL_ENOMEM, "out of memory writing %s", path);
    }
    if ((i = zip_file_add(z, name, src, ZIP_FL_OVERWRITE)) < 0) {
        zip_source_free(src);
        return NL_ERROR(NL_EIO, "%s: cannot add %s: %s", path, name, zip_strerror(z));
    }
    if (zip_set_file_compression(z, (zip_uint64_t)i, ZIP_CM_STORE, 0))
        return NL_ERROR(NL_EIO, "%s: cannot store %s: %s", path, name, zip_strerror(z));
    return NL_OK;
}

static int write_npz(const char *path, const nl_field *f, const nl_field *var, size_t size)
{
    int err, st;
    zip_t *z = zip_open(path, ZIP_CREATE | ZIP_TRUNCATE, &err);
    if (!z)
        return NL_ERROR(NL_EIO, "cannot create %s (libzip error %d)", path, err);
    st = add(z, path, "field.npy", f, size);
    if (!st && var)
        st = add(z, path, "variance.npy", var, size);
    if (st) {
        zip_discard(z);
        return st;
    }
    if (zip_close(z)) {
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, zip_strerror(z));
        zip_discard(z);
    }
    return st;
}

int nl_npz_write(const char *path, const nl_field *field, const nl_field *variance, int precision)
{
    nl_write_options o = {.format = "npz", .precision = precision};
    const nl_format *t = nl_format_find("npz");
    int st;
    if (variance && (variance->dim != field->dim || memcmp(variance->n, field->n, sizeof field->n)))
        return NL_ERROR(NL_EINVAL, "%s: the variance's shape differs from the field's", path);
    if ((st = nl_format_check(t, field, &o)) || (variance && (st = nl_format_check(t, variance, &o))))
        return st;
    return write_npz(path, field, variance, o.precision == 32 ? 4 : 8);
}

static int npz_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    (void)meta;
    return write_npz(path, f, NULL, o->precision == 32 ? 4 : 8);
}

static int npz_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                    nl_meta *meta)
{
    zip_error_t ze;
    zip_source_t *src;
    zip_t *z;
    zip_stat_t s;
    zip_int64_t i;
    int st;
    (void)o, (void)meta;
    *out = NULL;
    zip_error_init(&ze);
    if (!(src = zip_source_buffer_create(buf, len, 0, &ze)))
        return zip_error_fini(&ze), NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    if (!(z = zip_open_from_source(src, ZIP_RDONLY, &ze))) {
        zip_source_free(src);
        st = NL_ERROR(NL_EINPUT, "%s: not a zip archive (.npz): %s", path, zip_error_strerror(&ze));
        zip_error_fini(&ze);
        return st;
    }
    zip_error_fini(&ze);
    if ((i = zip_name_locate(z, "field.npy", 0)) < 0 || zip_stat_index(z, (zip_uint64_t)i, 0, &s) ||
        !(s.valid & ZIP_STAT_SIZE)) {
        zip_close(z);
        return NL_ERROR(NL_EINPUT, "%s: .npz without an array \"field\" (field.npy); expected noiselab's or "
                        "numpy.savez(path, field=...)'s", path);
    }
    unsigned char *b = s.size <= len * 1032 + 4096 ? malloc(s.size ? s.size : 1) : NULL; /* deflate: at most ~1032:1 */
    zip_file_t *zf = b ? zip_fopen_index(z, (zip_uint64_t)i, 0) : NULL;
    zip_int64_t got = zf ? zip_fread(zf, b, s.size) : -1;
    if (zf)
        zip_fclose(zf);
    zip_close(z);
    if (got < 0 || (zip_uint64_t)got != s.size)
        st = b ? NL_ERROR(NL_EINPUT, "%s: field.npy cannot be read from the archive", path)
               : NL_ERROR(NL_EINPUT, "%s: field.npy claims %llu bytes, beyond what the archive can hold", path,
                          (unsigned long long)s.size);
    else
        st = nl_npy_decode(path, b, s.size, out);
    free(b);
    return st;
}

const nl_format nl_format_npz = {
    .name = "npz",
    .extensions = ".npz",
    .summary = "NumPy .npz (numpy.savez): arrays \"field\" (and, from krige, \"variance\"), stored .npy; "
               "no metadata",
    .dims = 1 << 1 | 1 << 2 | 1 << 3,
    .types = NL_FORMAT_F64 | NL_FORMAT_F32,
    .precision = 64,
    .meta = 0,
    .magic = "PK\x03\x04",
    .magic_len = 4,
    .read = npz_read,
    .write = npz_write,
};
