/* PNG read (exemplars) and 8-bit grey write (previews) through libpng. */
#include "io.h"
#include "io_read_internal.h"
#include "nl_error.h"

#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

int nl_png_read(const char *path, nl_field **out)
{
    unsigned char *file;
    size_t len;
    int st;
    *out = NULL;
    if ((st = nl_io_slurp(path, &file, &len)))
        return st;
    st = nl_png_read_mem(path, file, len, out);
    free(file);
    return st;
}

int nl_png_read_mem(const char *path, const unsigned char *file, size_t len, nl_field **out)
{
    png_image img;
    png_bytep buf;
    size_t n[2];
    nl_field *f;
    int st;

    *out = NULL;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&img, file, len))
        return NL_ERROR(NL_EINPUT, "%s: not a readable PNG file: %s", path, img.message);
    /* Sample values are taken as stored, without gamma decoding: 16-bit
     * files are read as 16-bit grey, 8-bit files as 8-bit grey; colour is
     * reduced to grey by libpng's Rec. 709 weights. */
    int wide = (img.format & PNG_FORMAT_FLAG_LINEAR) != 0;
    img.format = wide ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY;
    n[0] = img.width;
    n[1] = img.height;
    f = nl_field_alloc(2, n, NULL, &st);
    if (!f) {
        png_image_free(&img);
        return st;
    }
    buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf) {
        png_image_free(&img);
        nl_field_free(f);
        return NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    }
    if (!png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        st = NL_ERROR(NL_EINPUT, "%s: corrupt PNG: %s", path, img.message);
        free(buf);
        nl_field_free(f);
        png_image_free(&img);
        return st;
    }
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = wide ? ((const png_uint_16 *)buf)[i] / 65535.0 : buf[i] / 255.0;
    free(buf);
    *out = f;
    return NL_OK;
}

/* 8-bit rows of w pixels in `format` (PNG_FORMAT_GRAY or _RGB), top row first. */
static int write8(const char *path, size_t w, size_t h, const uint8_t *pix, png_uint_32 format)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (w > 0x7fffffff || h > 0x7fffffff)
        return NL_ERROR(NL_ETOOBIG, "PNG: %zu x %zu is too large", w, h);
    img.width = (png_uint_32)w;
    img.height = (png_uint_32)h;
    img.format = format;
    if (!png_image_write_to_file(&img, path, 0, pix, 0, NULL))
        return NL_ERROR(NL_EIO, "%s: cannot write PNG: %s", path, img.message);
    return NL_OK;
}

int nl_png_write_gray8(const char *path, size_t w, size_t h, const uint8_t *pix)
{
    return write8(path, w, h, pix, PNG_FORMAT_GRAY);
}

int nl_png_write_field(const char *path, const nl_field *f, double lo, double hi)
{
    size_t w = f->n[0], h = f->dim >= 2 ? f->n[1] : 1;
    uint8_t *pix;
    int st;
    if (!(hi > lo))
        return NL_ERROR(NL_EINVAL, "preview: expected a range lo < hi, got %g..%g", lo, hi);
    pix = malloc(w * h);
    if (!pix)
        return NL_ERROR(NL_ENOMEM, "out of memory for the preview");
    for (size_t i = 0; i < w * h; i++) {
        double v = (f->data[i] - lo) / (hi - lo) * 255.0;
        pix[i] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : lrint(v));
    }
    st = nl_png_write_gray8(path, w, h, pix);
    free(pix);
    return st;
}

int nl_png_write_rgb8(const char *path, size_t w, size_t h, const uint8_t *rgb)
{
    return write8(path, w, h, rgb, PNG_FORMAT_RGB);
}
