/* NumPy .npy, format version 1.0 written (1.0 to 3.0 read): a header of a
 * Python dict literal {'descr': '<f8', 'fortran_order': False, 'shape': (nz, ny, nx), }
 * padded with spaces to a multiple of 64 bytes, then the samples in C order
 * (numpy/lib/format.py, NEP 1).  The array's axes are the field's, slowest
 * first, as noiselab.read returns them; no metadata: spacing is read as 1
 * and the provenance is not written. */
#include "formats_internal.h"
#include "../nl_error.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One little-endian sample of `size` bytes (4 or 8) at p. */
static double get_le(const unsigned char *p, size_t size)
{
    uint64_t u = 0;
    for (size_t b = 0; b < size; b++)
        u |= (uint64_t)p[b] << (8 * b);
    if (size == 8) {
        double d;
        memcpy(&d, &u, 8);
        return d;
    }
    uint32_t w = (uint32_t)u;
    float x;
    memcpy(&x, &w, 4);
    return x;
}

static void put_le(unsigned char *p, double v, size_t size)
{
    uint64_t u;
    if (size == 8) {
        memcpy(&u, &v, 8);
    } else {
        float x = (float)v;
        uint32_t w;
        memcpy(&w, &x, 4);
        u = w;
    }
    for (size_t b = 0; b < size; b++)
        p[b] = (unsigned char)(u >> (8 * b));
}

size_t nl_npy_header(const nl_field *f, size_t size, char *head)
{
    int len = snprintf(head + 10, 246, "{'descr': '<f%zu', 'fortran_order': False, 'shape': (", size);
    for (int a = f->dim - 1; a >= 0; a--)
        len += snprintf(head + 10 + len, 246 - (size_t)len, "%zu,%s", f->n[a], a ? " " : "");
    if (f->dim > 1) /* (5,) but (3, 4) */
        len--;
    len += snprintf(head + 10 + len, 246 - (size_t)len, "), }");
    while ((10 + len + 1) % 64)
        head[10 + len++] = ' ';
    head[10 + len++] = '\n';
    memcpy(head, "\x93NUMPY\x01\x00", 8);
    head[8] = (char)(len & 0xff), head[9] = (char)(len >> 8);
    return (size_t)(10 + len);
}

void nl_npy_samples(const nl_field *f, size_t size, size_t i0, size_t k, unsigned char *buf)
{
    for (size_t j = 0; j < k; j++)
        put_le(buf + j * size, f->data[i0 + j], size);
}

static int npy_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    char head[256];
    size_t size = o->precision == 32 ? 4 : 8, chunk = 4096, k, hl;
    unsigned char buf[4096 * 8];
    int st = NL_OK;
    FILE *fp;
    (void)meta;
    hl = nl_npy_header(f, size, head);
    if (!(fp = fopen(path, "wb")))
        return NL_ERROR(NL_EIO, "cannot create %s: %s", path, strerror(errno));
    if (fwrite(head, 1, hl, fp) != hl)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    for (size_t i = 0; i < f->count && !st; i += k) {
        k = f->count - i < chunk ? f->count - i : chunk;
        nl_npy_samples(f, size, i, k, buf);
        if (fwrite(buf, size, k, fp) != k)
            st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    }
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    return st;
}

/* The header's text: the dict's three keys, each once. */
typedef struct {
    const char *p, *end; /* the header text not yet read */
    size_t size;         /* from descr: 4 or 8 */
    int fortran, dim;    /* fortran_order; the shape's axes */
    size_t shape[3];     /* slowest first */
} npy_head;

static void skip(npy_head *h)
{
    while (h->p < h->end && (*h->p == ' ' || *h->p == '\n' || *h->p == '\t'))
        h->p++;
}

static int expect(npy_head *h, char c)
{
    skip(h);
    if (h->p < h->end && *h->p == c)
        return h->p++, 1;
    return 0;
}

/* A quoted word into w (at most 31 bytes). */
static int quoted(npy_head *h, char *w)
{
    size_t k = 0;
    char q;
    skip(h);
    if (h->p >= h->end || (*h->p != '\'' && *h->p != '"'))
        return 0;
    q = *h->p++;
    while (h->p < h->end && *h->p != q && k < 31)
        w[k++] = *h->p++;
    w[k] = 0;
    return h->p < h->end && *h->p++ == q;
}

/* (n0, n1, ...): 1 to 3 positive integers. */
static int shape(const char *path, npy_head *h)
{
    h->dim = 0;
    if (!expect(h, '('))
        return NL_ERROR(NL_EINPUT, "%s: .npy header: shape: expected a tuple", path);
    while (!expect(h, ')')) {
        char *e;
        unsigned long long v;
        skip(h);
        if (h->dim == 3)
            return NL_ERROR(NL_EINPUT, "%s: .npy header: shape: expected 1 to 3 axes", path);
        errno = 0;
        v = h->p < h->end && *h->p >= '0' && *h->p <= '9' ? strtoull(h->p, &e, 10) : 0;
        if (!v || errno || e > h->end || v > SIZE_MAX)
            return NL_ERROR(NL_EINPUT, "%s: .npy header: shape: expected positive integers", path);
        h->shape[h->dim++] = (size_t)v, h->p = e;
        if (!expect(h, ',') && !(skip(h), h->p < h->end && *h->p == ')'))
            return NL_ERROR(NL_EINPUT, "%s: .npy header: shape: expected ',' or ')'", path);
    }
    return h->dim ? NL_OK : NL_ERROR(NL_EINPUT, "%s: .npy header: shape (): expected 1 to 3 axes", path);
}

/* The value of key `key`. */
static int value(const char *path, npy_head *h, const char *key)
{
    char w[32];
    if (strcmp(key, "descr") == 0) {
        if (!quoted(h, w) || (strcmp(w, "<f8") && strcmp(w, "<f4")))
            return NL_ERROR(NL_EINPUT, "%s: .npy header: descr: expected '<f8' or '<f4' (little-endian float), "
                            "got '%s'", path, w);
        h->size = w[2] == '8' ? 8 : 4;
        return NL_OK;
    }
    if (strcmp(key, "fortran_order") == 0) {
        skip(h);
        if (h->end - h->p >= 5 && strncmp(h->p, "False", 5) == 0)
            return h->p += 5, NL_OK;
        return NL_ERROR(NL_EINPUT, "%s: .npy header: fortran_order: expected False (C order)", path);
    }
    if (strcmp(key, "shape") == 0)
        return shape(path, h);
    return NL_ERROR(NL_EINPUT, "%s: .npy header: unknown key '%s'; expected descr, fortran_order, shape", path, key);
}

static int parse_head(const char *path, npy_head *h)
{
    unsigned seen = 0;
    char key[32];
    int st;
    if (!expect(h, '{'))
        return NL_ERROR(NL_EINPUT, "%s: .npy header: expected a dict", path);
    while (!expect(h, '}')) {
        int bit = 0;
        if (!quoted(h, key) || !expect(h, ':'))
            return NL_ERROR(NL_EINPUT, "%s: .npy header: expected 'key': value", path);
        bit = strcmp(key, "descr") == 0 ? 1 : strcmp(key, "fortran_order") == 0 ? 2 : strcmp(key, "shape") == 0 ? 4 : 0;
        if (seen & (unsigned)bit)
            return NL_ERROR(NL_EINPUT, "%s: .npy header: %s given twice", path, key);
        if ((st = value(path, h, key)))
            return st;
        seen |= (unsigned)bit;
        if (!expect(h, ',') && !(skip(h), h->p < h->end && *h->p == '}'))
            return NL_ERROR(NL_EINPUT, "%s: .npy header: expected ',' or '}'", path);
    }
    return seen == 7 ? NL_OK : NL_ERROR(NL_EINPUT, "%s: .npy header: expected descr, fortran_order and shape", path);
}

int nl_npy_decode(const char *path, const unsigned char *buf, size_t len, nl_field **out)
{
    npy_head h = {0};
    size_t n[3], hlen, at, count, need;
    nl_field *f;
    int st;
    *out = NULL;
    if (len < 10 || memcmp(buf, "\x93NUMPY", 6) || buf[6] < 1 || buf[6] > 3)
        return NL_ERROR(NL_EINPUT, "%s: not a .npy file of version 1 to 3", path);
    hlen = buf[6] == 1 ? (size_t)buf[8] | (size_t)buf[9] << 8
                       : len < 12 ? SIZE_MAX : (size_t)buf[8] | (size_t)buf[9] << 8 | (size_t)buf[10] << 16 |
                                                   (size_t)buf[11] << 24;
    at = buf[6] == 1 ? 10 : 12;
    if (hlen > len - at)
        return NL_ERROR(NL_EINPUT, "%s: .npy header of %zu bytes is truncated (the file has %zu)", path, hlen, len);
    h.p = (const char *)buf + at, h.end = h.p + hlen;
    if ((st = parse_head(path, &h)))
        return st;
    for (int a = 0; a < h.dim; a++)
        n[a] = h.shape[h.dim - 1 - a];
    if ((st = nl_size_check(h.dim, n, sizeof(double), 1, &count)))
        return st;
    need = count * h.size; /* no overflow: count doubles fit */
    if (len - at - hlen != need)
        return NL_ERROR(NL_EINPUT, "%s: .npy data of %zu bytes; its header's shape and descr make %zu", path,
                        len - at - hlen, need);
    if (!(f = nl_field_alloc(h.dim, n, NULL, &st)))
        return st;
    for (size_t i = 0; i < count; i++)
        f->data[i] = get_le(buf + at + hlen + i * h.size, h.size);
    *out = f;
    return NL_OK;
}

static int npy_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                    nl_meta *meta)
{
    (void)o, (void)meta;
    return nl_npy_decode(path, buf, len, out);
}

const nl_format nl_format_npy = {
    .name = "npy",
    .extensions = ".npy",
    .summary = "NumPy array, float64 (or float32), C order, axes slowest first; no metadata",
    .dims = 1 << 1 | 1 << 2 | 1 << 3,
    .types = NL_FORMAT_F64 | NL_FORMAT_F32,
    .precision = 64,
    .meta = 0,
    .magic = "\x93NUMPY",
    .magic_len = 6,
    .read = npy_read,
    .write = npy_write,
};
