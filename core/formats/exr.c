/* OpenEXR (core/io_exr.c): float32, 1D to 3D, with the provenance. */
#include "formats_internal.h"
#include "../io_read_internal.h"

static int exr_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    (void)o;
    return nl_exr_write(path, f, meta);
}

static int exr_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                    nl_meta *meta)
{
    (void)o;
    return nl_exr_read_mem(path, buf, len, out, meta);
}

const nl_format nl_format_exr = {
    .name = "exr",
    .extensions = ".exr",
    .summary = "OpenEXR, one float32 channel Y; a 3D field's slices stacked, noiselab.size says so",
    .dims = 1 << 1 | 1 << 2 | 1 << 3,
    .types = NL_FORMAT_F32,
    .precision = 32,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN,
    .magic = "\x76\x2f\x31\x01",
    .magic_len = 4,
    .read = exr_read,
    .write = exr_write,
};
