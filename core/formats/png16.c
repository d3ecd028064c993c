/* 16-bit grey PNG heightmaps: what terrain tools and game engines (Unity,
 * Unreal, Godot, Blender displacement) import as a heightmap.  A 2D field
 * is mapped linearly from a value range (default: its min..max) onto
 * 0..65535, top row first; the range ("noiselab.range" = "lo,hi") and the
 * provenance ("noiselab.KEY") are tEXt chunks, so the reader maps codes
 * back to within half a step, (hi - lo) / 131070.  A gAMA chunk of 1.0
 * says the codes are linear, so no reader applies a transfer curve.
 *
 * Reading takes any PNG (8 or 16 bits, grey or colour: core/io_png.c):
 * without noiselab chunks, values are code / max in [0, 1]; with any
 * noiselab chunk, noiselab.range must be there and well formed. */
#include "formats_internal.h"
#include "../io_read_internal.h"
#include "../nl_error.h"
#include "../provenance.h"

#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The tEXt chunks of a PNG held in memory: noiselab.range into range
 * (NUL-terminated, at most len - 1 bytes), the provenance into meta; *any
 * set when a noiselab.* chunk was found. */
static int read_text(const char *path, const unsigned char *buf, size_t len, char *range, size_t rlen, nl_meta *meta,
                     int *any)
{
    size_t at = 8;
    *any = 0;
    range[0] = 0;
    while (at + 12 <= len) {
        size_t k = (size_t)buf[at] << 24 | (size_t)buf[at + 1] << 16 | (size_t)buf[at + 2] << 8 | buf[at + 3];
        const char *type = (const char *)buf + at + 4, *d = (const char *)buf + at + 8, *v;
        if (k > len - at - 12)
            break; /* libpng reports the damage */
        if (memcmp(type, "tEXt", 4) == 0 && (v = memchr(d, 0, k)) && strncmp(d, "noiselab.", 9) == 0) {
            size_t vl = k - (size_t)(v + 1 - d), cap = rlen;
            char *slot = NULL;
            *any = 1;
            if (strcmp(d + 9, "range") == 0)
                slot = range;
            for (int i = 0; !slot && i < NL_META_NKEYS; i++)
                if (strcmp(d + 9, nl_meta_key(i)) == 0)
                    slot = nl_meta_slot(meta, i), cap = nl_meta_capacity(i);
            if (slot && vl >= cap)
                return NL_ERROR(NL_EINPUT, "%s: PNG text %s: expected at most %zu bytes, got %zu", path, d, cap - 1,
                                vl);
            for (size_t c = 0; slot && c < vl; c++)
                if ((unsigned char)v[1 + c] < 0x20 || v[1 + c] == 0x7f)
                    return NL_ERROR(NL_EINPUT, "%s: PNG text %s: expected text without control characters", path, d);
            if (slot) {
                memcpy(slot, v + 1, vl);
                slot[vl] = 0;
            }
        }
        if (memcmp(type, "IEND", 4) == 0)
            break;
        at += k + 12;
    }
    return NL_OK;
}

static int png16_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o,
                      nl_field **out, nl_meta *meta)
{
    char range[128], tail;
    double lo, hi, h[2];
    nl_meta m = {0};
    int any, st;
    (void)o;
    *out = NULL;
    if ((st = read_text(path, buf, len, range, sizeof range, &m, &any)))
        return st;
    if (any && (sscanf(range, "%lf,%lf%c", &lo, &hi, &tail) != 2 || !isfinite(lo) || !isfinite(hi) || !(lo < hi)))
        return NL_ERROR(NL_EINPUT, "%s: PNG text noiselab.range: expected \"lo,hi\" with lo < hi (noiselab "
                        "heightmaps record it), got \"%s\"", path, range);
    if ((st = nl_png_read_mem(path, buf, len, out)))
        return st;
    if (!any)
        return NL_OK;
    for (size_t i = 0; i < (*out)->count; i++)
        (*out)->data[i] = lo + (hi - lo) * (*out)->data[i];
    if (sscanf(m.spacing, "%lf,%lf%c", &h[0], &h[1], &tail) == 2 && h[0] > 0 && h[1] > 0 && isfinite(h[0] + h[1]))
        (*out)->h[0] = h[0], (*out)->h[1] = h[1];
    if (meta)
        *meta = m;
    return NL_OK;
}

/* libpng's error callback: back to png16_write through its jmp_buf. */
static void on_error(png_structp png, png_const_charp msg)
{
    (void)msg;
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp msg) { (void)png, (void)msg; }

/* The noiselab text chunks: the range, then the provenance's non-empty keys. */
static void set_text(png_structp png, png_infop info, const nl_meta *meta, char keys[][32], const char *range)
{
    png_text t[1 + NL_META_NKEYS];
    int k = 0;
    memset(t, 0, sizeof t);
    t[k].compression = PNG_TEXT_COMPRESSION_NONE, t[k].key = "noiselab.range", t[k++].text = (char *)range;
    for (int i = 0; meta && i < NL_META_NKEYS; i++)
        if (*nl_meta_value(meta, i)) {
            snprintf(keys[i], 32, "noiselab.%s", nl_meta_key(i));
            t[k].compression = PNG_TEXT_COMPRESSION_NONE, t[k].key = keys[i];
            t[k++].text = (char *)nl_meta_value(meta, i);
        }
    png_set_text(png, info, t, k);
}

/* The image: header, gAMA, text, rows; 1 when libpng failed (it jumps
 * back here, so nothing set after setjmp is read after it). */
static int write_png(png_structp png, png_infop info, FILE *fp, const nl_field *f, const nl_meta *meta,
                     const double *range, png_bytep row)
{
    size_t w = f->n[0], h = f->n[1];
    char text[64], keys[NL_META_NKEYS][32];
    if (setjmp(png_jmpbuf(png)))
        return 1;
    snprintf(text, sizeof text, "%.17g,%.17g", range[0], range[1]);
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_gAMA_fixed(png, info, PNG_GAMMA_LINEAR);
    set_text(png, info, meta, keys, text);
    png_write_info(png, info);
    for (size_t j = 0; j < h; j++) {
        for (size_t i = 0; i < w; i++) { /* PNG samples are big-endian */
            uint32_t c = nl_format_code(f->data[j * w + i], range[0], range[1], 65535);
            row[2 * i] = (png_byte)(c >> 8), row[2 * i + 1] = (png_byte)(c & 0xff);
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    return 0;
}

static int png16_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    double range[2];
    png_structp png = NULL;
    png_infop info = NULL;
    png_bytep row;
    FILE *fp;
    int st = NL_OK;
    if (f->n[0] > 0x7fffffff || f->n[1] > 0x7fffffff)
        return NL_ERROR(NL_ETOOBIG, "PNG: %zu x %zu is too large", f->n[0], f->n[1]);
    nl_format_range(f, o, &range[0], &range[1]);
    if (!(row = malloc(2 * f->n[0])))
        return NL_ERROR(NL_ENOMEM, "out of memory writing %s", path);
    if (!(fp = fopen(path, "wb"))) {
        free(row);
        return NL_ERROR(NL_EIO, "cannot create %s: %s", path, strerror(errno));
    }
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, on_error, on_warning);
    if (!png || !(info = png_create_info_struct(png)) || write_png(png, info, fp, f, meta, range, row))
        st = NL_ERROR(NL_EIO, "%s: cannot write PNG", path);
    png_destroy_write_struct(&png, &info);
    if (fclose(fp) && !st)
        st = NL_ERROR(NL_EIO, "%s: write failed: %s", path, strerror(errno));
    free(row);
    return st;
}

const nl_format nl_format_png16 = {
    .name = "png16",
    .extensions = ".png",
    .summary = "16-bit grey PNG heightmap, 2D, min..max (or --range) onto 0..65535; range and provenance "
               "in tEXt chunks",
    .dims = 1 << 2,
    .types = NL_FORMAT_U16,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN | NL_FORMAT_META_RANGE,
    .magic = "\x89PNG",
    .magic_len = 4,
    .read = png16_read,
    .write = png16_write,
};
