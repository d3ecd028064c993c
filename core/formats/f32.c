/* Raw float32 (.f32): little-endian IEEE float32 samples, x fastest, row
 * j = 0 first, no header (World Machine's and Gaea's raw float heightmaps,
 * numpy's tofile).  A JSON sidecar beside it (NAME.f32.json: raw_sidecar.c)
 * says the size, spacing and origin.  Reading takes the size from
 * nl_read_options (Python's size=) where given, else from the sidecar, else
 * a square. */
#include "formats_internal.h"
#include "../nl_error.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int f32_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    enum { CHUNK = 4096 };
    unsigned char buf[4 * CHUNK];
    int st = NL_OK;
    FILE *fp;
    if (!(fp = fopen(path, "wb")))
        return NL_ERROR(NL_EIO, "cannot create %s: %s", path, strerror(errno));
    for (size_t i = 0, k; i < f->count && !st; i += k) {
        k = f->count - i < CHUNK ? f->count - i : CHUNK;
        for (size_t j = 0; j < k; j++) {
            float x = (float)f->data[i + j];
            uint32_t u;
            memcpy(&u, &x, 4);
            for (int b = 0; b < 4; b++)
                buf[4 * j + (size_t)b] = (unsigned char)(u >> (8 * b));
        }
        if (fwrite(buf, 4, k, fp) != k)
            st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    }
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    return st ? st : nl_raw_sidecar_write(path, "f32", f, meta, o, NULL);
}

static int f32_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                    nl_meta *meta)
{
    nl_read_options r = {0};
    double h[3], origin[3];
    size_t n[3];
    nl_field *f;
    int dim, st, side, sdim;
    *out = NULL;
    if (len % 4)
        return NL_ERROR(NL_EINPUT, "%s: %zu bytes; a float32 raw file holds a multiple of 4", path, len);
    if ((st = nl_raw_sidecar_read(path, "f32", len / 4, &r, h, origin, &side)))
        return st;
    sdim = r.dim;
    if (o && o->dim) /* what the caller says wins */
        r.dim = o->dim, memcpy(r.n, o->n, sizeof r.n);
    if ((st = nl_format_raw_size(path, len / 4, &r, &dim, n)))
        return st;
    if (!(f = nl_field_alloc(dim, n, NULL, &st)))
        return st;
    for (size_t i = 0; i < f->count; i++) {
        const unsigned char *p = buf + 4 * i;
        uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
        float x;
        memcpy(&x, &u, 4);
        f->data[i] = x;
    }
    if (side && dim == sdim && (st = nl_raw_sidecar_apply(f, meta, h, origin))) {
        nl_field_free(f);
        return st;
    }
    *out = f;
    return NL_OK;
}

const nl_format nl_format_f32 = {
    .name = "f32",
    .extensions = ".f32",
    .summary = "raw float32, little-endian, x fastest, top row first, no header; size, spacing and "
               "origin in a sidecar NAME.f32.json",
    .dims = 1 << 1 | 1 << 2 | 1 << 3,
    .types = NL_FORMAT_F32,
    .precision = 32,
    .meta = NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN, /* in the sidecar */
    .flags = NL_FORMAT_SIZED,
    .read = f32_read,
    .write = f32_write,
};
