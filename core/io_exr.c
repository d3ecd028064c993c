/* OpenEXR read (from a file in memory: read once) and write through the
 * OpenEXRCore C API. */
#include "io.h"
#include "io_read_internal.h"
#include "provenance.h"
#include "nl_error.h"

#include <math.h>
#include <openexr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static _Thread_local char exr_msg[256];

static void quiet_handler(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    (void)ctxt;
    (void)code;
    snprintf(exr_msg, sizeof exr_msg, "%s", msg ? msg : "");
}

/* The EXR attribute of provenance field i: "noiselab." and its key. */
static const char *attr_name(int i, char *buf, size_t len)
{
    snprintf(buf, len, "noiselab.%s", nl_meta_key(i));
    return buf;
}

/* Image layout of a field: width n0, height n1 * n2. */
static int image_size(const nl_field *f, int32_t *w, int32_t *h)
{
    size_t hh = f->n[1] * f->n[2];
    if (f->n[0] > INT32_MAX || hh > INT32_MAX || f->n[1] > INT32_MAX)
        return NL_ERROR(NL_ETOOBIG, "EXR: a %zu x %zu image is too large for the format", f->n[0], hh);
    *w = (int32_t)f->n[0];
    *h = (int32_t)hh;
    return NL_OK;
}

int nl_exr_write(const char *path, const nl_field *f, const nl_meta *meta)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_context_t ctx = NULL;
    exr_encode_pipeline_t enc;
    int part, st = NL_OK, have_enc = 0;
    int32_t w = 0, h = 0, lpc = 1;
    float *buf = NULL;
    exr_result_t rv;

    if ((st = image_size(f, &w, &h)))
        return st;
    buf = malloc(f->count * sizeof *buf);
    if (!buf)
        return NL_ERROR(NL_ENOMEM, "out of memory for the EXR buffer");
    for (size_t i = 0; i < f->count; i++)
        buf[i] = (float)f->data[i];

    init.error_handler_fn = quiet_handler;
    rv = exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv != EXR_ERR_SUCCESS) {
        free(buf);
        return NL_ERROR(NL_EIO, "%s: cannot write EXR: %s", path, exr_msg);
    }
    rv = exr_add_part(ctx, "main", EXR_STORAGE_SCANLINE, &part);
    if (!rv)
        rv = exr_initialize_required_attr_simple(ctx, part, w, h, EXR_COMPRESSION_NONE);
    if (!rv)
        rv = exr_add_channel(ctx, part, "Y", EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1);
    for (int i = 0; meta && i < NL_META_NKEYS && !rv; i++) {
        const char *s = nl_meta_value(meta, i);
        char name[64];
        if (*s)
            rv = exr_attr_set_string(ctx, part, attr_name(i, name, sizeof name), s);
    }
    if (!rv)
        rv = exr_write_header(ctx);
    if (!rv)
        rv = exr_get_scanlines_per_chunk(ctx, part, &lpc);
    for (int32_t y = 0; !rv && y < h; y += lpc) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(ctx, part, y, &ci);
        if (rv)
            break;
        rv = have_enc ? exr_encoding_update(ctx, part, &ci, &enc) : exr_encoding_initialize(ctx, part, &ci, &enc);
        if (rv)
            break;
        enc.channels[0].encode_from_ptr = (const uint8_t *)(buf + (size_t)y * (size_t)w);
        enc.channels[0].user_pixel_stride = sizeof(float);
        enc.channels[0].user_line_stride = (int32_t)(sizeof(float) * (size_t)w);
        enc.channels[0].user_data_type = EXR_PIXEL_FLOAT;
        enc.channels[0].user_bytes_per_element = sizeof(float);
        if (!have_enc)
            rv = exr_encoding_choose_default_routines(ctx, part, &enc);
        have_enc = 1;
        if (!rv)
            rv = exr_encoding_run(ctx, part, &enc);
    }
    if (rv)
        st = NL_ERROR(NL_EIO, "%s: writing EXR failed: %s", path, exr_msg);
    if (have_enc)
        exr_encoding_destroy(ctx, &enc);
    if (exr_finish(&ctx) != EXR_ERR_SUCCESS && !st)
        st = NL_ERROR(NL_EIO, "%s: finishing EXR failed: %s", path, exr_msg);
    free(buf);
    return st;
}

static int parse_dims(const char *s, size_t *n, int *dim)
{
    char *end;
    *dim = 0;
    while (*dim < 3) {
        unsigned long long v = strtoull(s, &end, 10);
        if (end == s || v == 0)
            return -1;
        n[(*dim)++] = (size_t)v;
        if (*end == 0)
            return 0;
        if (*end != 'x')
            return -1;
        s = end + 1;
    }
    return -1;
}

static int read_pixels(exr_context_t ctx, const char *path, float *buf, int32_t w, const exr_attr_box2i_t *dw)
{
    const exr_attr_chlist_t *chl;
    exr_decode_pipeline_t dec;
    int32_t lpc;
    int have_dec = 0, chan = -1;
    exr_result_t rv = exr_get_channels(ctx, 0, &chl);
    if (rv)
        return NL_ERROR(NL_EINPUT, "%s: cannot read the channel list: %s", path, exr_msg);
    for (int c = 0; c < chl->num_channels; c++)
        if (strcmp(chl->entries[c].name.str, "Y") == 0)
            chan = c;
    if (chan < 0 && chl->num_channels == 1)
        chan = 0;
    if (chan < 0)
        return NL_ERROR(NL_EINPUT, "%s: expected a channel \"Y\" or a single channel, found %d channels", path,
                        chl->num_channels);
    if (chl->entries[chan].x_sampling != 1 || chl->entries[chan].y_sampling != 1)
        return NL_ERROR(NL_EINPUT, "%s: subsampled channels are not supported", path);
    rv = exr_get_scanlines_per_chunk(ctx, 0, &lpc);
    for (int32_t y = dw->min.y; !rv && y <= dw->max.y; y += lpc) {
        exr_chunk_info_t ci;
        rv = exr_read_scanline_chunk_info(ctx, 0, y, &ci);
        if (rv)
            break;
        rv = have_dec ? exr_decoding_update(ctx, 0, &ci, &dec) : exr_decoding_initialize(ctx, 0, &ci, &dec);
        if (rv)
            break;
        for (int c = 0; c < dec.channel_count; c++) {
            exr_coding_channel_info_t *ch = &dec.channels[c];
            if (strcmp(ch->channel_name, chl->entries[chan].name.str) != 0) {
                ch->decode_to_ptr = NULL;
                continue;
            }
            ch->decode_to_ptr = (uint8_t *)(buf + (size_t)(ci.start_y - dw->min.y) * (size_t)w);
            ch->user_pixel_stride = sizeof(float);
            ch->user_line_stride = (int32_t)(sizeof(float) * (size_t)w);
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = sizeof(float);
        }
        if (!have_dec)
            rv = exr_decoding_choose_default_routines(ctx, 0, &dec);
        have_dec = 1;
        if (!rv)
            rv = exr_decoding_run(ctx, 0, &dec);
    }
    if (have_dec)
        exr_decoding_destroy(ctx, &dec);
    if (rv)
        return NL_ERROR(NL_EINPUT, "%s: reading EXR pixels failed: %s", path, exr_msg);
    return NL_OK;
}

/* The field's dimension, size and spacing from the w x hh image and the
 * noiselab.size and noiselab.spacing attributes, when present. */
static int layout(const char *path, const nl_meta *m, int32_t w, int32_t hh, int *dim, size_t *n, double *h)
{
    n[0] = (size_t)w;
    n[1] = (size_t)hh;
    n[2] = 1;
    *dim = hh == 1 ? 1 : 2;
    if (m->size[0]) {
        size_t nn[3] = {1, 1, 1};
        int d;
        if (parse_dims(m->size, nn, &d) || nn[0] != (size_t)w || nn[1] > (size_t)hh || nn[2] > (size_t)hh ||
            nn[1] * nn[2] != (size_t)hh)
            return NL_ERROR(NL_EINPUT, "%s: noiselab.size \"%s\" does not match the %dx%d image", path, m->size, w,
                            hh);
        memcpy(n, nn, sizeof nn);
        *dim = d;
    }
    if (m->spacing[0]) {
        const char *p = m->spacing;
        char *end;
        for (int a = 0; a < *dim; a++) {
            h[a] = *p == '-' || *p == '+' || (*p >= '0' && *p <= '9') || *p == '.' ? strtod(p, &end) : 0;
            if (!(h[a] > 0) || !isfinite(h[a]) || *end != (a + 1 < *dim ? ',' : 0))
                return NL_ERROR(NL_EINPUT, "%s: noiselab.spacing \"%s\": expected %d positive finite numbers "
                                "separated by commas", path, m->spacing, *dim);
            p = end + 1;
        }
    }
    return NL_OK;
}

/* The attribute noiselab.KEY of provenance key i, when present, into m: a
 * string of at most its capacity - 1 bytes, with no NUL or control
 * character inside (what the writer records), or refused. */
static int read_attr(exr_context_t ctx, const char *path, int i, nl_meta *m)
{
    const exr_attribute_t *a = NULL;
    char name[64];
    size_t cap = nl_meta_capacity(i), len;
    exr_result_t rv = exr_get_attribute_by_name(ctx, 0, attr_name(i, name, sizeof name), &a);
    if (rv == EXR_ERR_NO_ATTR_BY_NAME)
        return NL_OK;
    if (rv || !a)
        return NL_ERROR(NL_EINPUT, "%s: %s cannot be read: %s", path, name, exr_msg);
    if (a->type != EXR_ATTR_STRING || !a->string || a->string->length < 0 || (a->string->length && !a->string->str))
        return NL_ERROR(NL_EINPUT, "%s: %s: expected a string attribute, got type \"%.32s\"", path, name,
                        a->type_name ? a->type_name : "?");
    len = (size_t)a->string->length;
    if (len >= cap)
        return NL_ERROR(NL_EINPUT, "%s: %s: expected at most %zu bytes, got %zu", path, name, cap - 1, len);
    for (size_t k = 0; k < len; k++) {
        unsigned char c = (unsigned char)a->string->str[k];
        if (c < 0x20 || c == 0x7f)
            return NL_ERROR(NL_EINPUT, "%s: %s: expected text without control characters or NUL, got byte 0x%02x "
                            "at %zu", path, name, c, k);
    }
    memcpy(nl_meta_slot(m, i), a->string->str, len);
    nl_meta_slot(m, i)[len] = 0;
    return NL_OK;
}

/* The file in memory, read through OpenEXRCore's custom stream (pread
 * semantics: a short count at the end). */
typedef struct {
    const unsigned char *buf;
    size_t len;
} membuf;

static int64_t mem_read(exr_const_context_t ctxt, void *user, void *dst, uint64_t sz, uint64_t off,
                        exr_stream_error_func_ptr_t error_cb)
{
    const membuf *m = user;
    (void)ctxt;
    (void)error_cb;
    if (off >= m->len)
        return 0;
    if (sz > m->len - off)
        sz = m->len - off;
    memcpy(dst, m->buf + off, sz);
    return (int64_t)sz;
}

static int64_t mem_size(exr_const_context_t ctxt, void *user)
{
    (void)ctxt;
    return (int64_t)((const membuf *)user)->len;
}

int nl_exr_read(const char *path, nl_field **out, nl_meta *meta)
{
    unsigned char *buf;
    size_t len;
    int st;
    *out = NULL;
    if ((st = nl_io_slurp(path, &buf, &len)))
        return st;
    st = nl_exr_read_mem(path, buf, len, out, meta);
    free(buf);
    return st;
}

int nl_exr_read_mem(const char *path, const unsigned char *file, size_t len, nl_field **out, nl_meta *meta)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    membuf mb = {file, len};
    exr_context_t ctx = NULL;
    exr_attr_box2i_t dw;
    exr_storage_t storage;
    nl_meta m;
    nl_field *f = NULL;
    float *buf = NULL;
    size_t n[3];
    double h[3] = {1, 1, 1};
    int dim, st = NL_OK;
    int32_t w, hh;

    *out = NULL;
    memset(&m, 0, sizeof m);
    init.error_handler_fn = quiet_handler;
    init.user_data = &mb;
    init.read_fn = mem_read;
    init.size_fn = mem_size;
    if (exr_start_read(&ctx, path, &init) != EXR_ERR_SUCCESS)
        return NL_ERROR(NL_EINPUT, "%s: not a readable EXR file: %s", path, exr_msg);
    if (exr_get_storage(ctx, 0, &storage) || storage != EXR_STORAGE_SCANLINE) {
        exr_finish(&ctx);
        return NL_ERROR(NL_EINPUT, "%s: expected a scanline EXR image (tiled and deep files are not read)", path);
    }
    if (exr_get_data_window(ctx, 0, &dw)) {
        exr_finish(&ctx);
        return NL_ERROR(NL_EINPUT, "%s: EXR has no data window", path);
    }
    w = dw.max.x - dw.min.x + 1;
    hh = dw.max.y - dw.min.y + 1;
    if (w < 1 || hh < 1) {
        exr_finish(&ctx);
        return NL_ERROR(NL_EINPUT, "%s: EXR data window is empty", path);
    }
    for (int i = 0; i < NL_META_NKEYS && !st; i++)
        st = read_attr(ctx, path, i, &m);
    if (st || (st = layout(path, &m, w, hh, &dim, n, h))) {
        exr_finish(&ctx);
        return st;
    }
    f = nl_field_alloc(dim, n, h, &st);
    if (f)
        buf = malloc(f->count * sizeof *buf);
    if (f && !buf)
        st = NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    if (!st)
        st = read_pixels(ctx, path, buf, w, &dw);
    exr_finish(&ctx);
    if (st) {
        free(buf);
        nl_field_free(f);
        return st;
    }
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = buf[i];
    free(buf);
    if (meta)
        *meta = m;
    *out = f;
    return NL_OK;
}
