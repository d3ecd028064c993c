/* Raw 16-bit heightmaps (.raw, .r16), as Unity's and Unreal's terrain
 * importers read them: little-endian uint16 codes, rows top to bottom (row
 * j = 0 first), no header.  Writing maps the range (default: the field's
 * min..max) onto 0..65535; the file cannot record it, nor the size, so a
 * JSON sidecar beside it (height.r16.json: raw_sidecar.c) says both, with
 * the spacing and origin.  Reading takes the size and range from
 * nl_read_options (Python's size=, range=) where given, else from the
 * sidecar when there is one, else a square (as Unity does) and 0..1. */
#include "formats_internal.h"
#include "../nl_error.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int r16_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    enum { CHUNK = 4096 };
    unsigned char buf[2 * CHUNK];
    double lo, hi;
    int st = NL_OK;
    FILE *fp;
    (void)meta;
    nl_format_range(f, o, &lo, &hi);
    if (!(fp = fopen(path, "wb")))
        return NL_ERROR(NL_EIO, "cannot create %s: %s", path, strerror(errno));
    for (size_t i = 0, k; i < f->count && !st; i += k) {
        k = f->count - i < CHUNK ? f->count - i : CHUNK;
        for (size_t j = 0; j < k; j++) {
            uint32_t c = nl_format_code(f->data[i + j], lo, hi, 65535);
            buf[2 * j] = (unsigned char)(c & 0xff), buf[2 * j + 1] = (unsigned char)(c >> 8);
        }
        if (fwrite(buf, 2, k, fp) != k)
            st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    }
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    double range[2] = {lo, hi};
    return st ? st : nl_raw_sidecar_write(path, "r16", f, meta, o, range);
}

static int r16_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                    nl_meta *meta)
{
    nl_read_options r = {0};
    double lo = 0, hi = 1, h[3], origin[3];
    size_t n[3];
    nl_field *f;
    int dim, st, side, sdim;
    *out = NULL;
    if (len % 2)
        return NL_ERROR(NL_EINPUT, "%s: %zu bytes; a 16-bit raw file holds an even count", path, len);
    if ((st = nl_raw_sidecar_read(path, "r16", len / 2, &r, h, origin, &side)))
        return st;
    if (side)
        lo = r.lo, hi = r.hi;
    sdim = r.dim;
    if (o && o->dim) /* what the caller says wins */
        r.dim = o->dim, memcpy(r.n, o->n, sizeof r.n);
    if (o && o->lo < o->hi)
        lo = o->lo, hi = o->hi;
    if ((st = nl_format_raw_size(path, len / 2, &r, &dim, n)))
        return st;
    if (!(f = nl_field_alloc(dim, n, NULL, &st)))
        return st;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = lo + (hi - lo) * (buf[2 * i] | buf[2 * i + 1] << 8) / 65535.0;
    if (side && dim == sdim && (st = nl_raw_sidecar_apply(f, meta, h, origin))) {
        nl_field_free(f);
        return st;
    }
    *out = f;
    return NL_OK;
}

const nl_format nl_format_r16 = {
    .name = "r16",
    .extensions = ".r16 .raw",
    .summary = "raw 16-bit heightmap (Unity, Unreal): little-endian uint16, top row first, no header; "
               "size, range, spacing and origin in a sidecar NAME.r16.json",
    .dims = 1 << 1 | 1 << 2 | 1 << 3,
    .types = NL_FORMAT_U16,
    .meta = NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN | NL_FORMAT_META_RANGE, /* in the sidecar */
    .flags = NL_FORMAT_SIZED,
    .read = r16_read,
    .write = r16_write,
};
