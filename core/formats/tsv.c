/* TSV series (core/io_tsv.c): 1D, printed with 10 digits, with the
 * provenance as comment lines; what a file no other format claims is read as. */
#include "formats_internal.h"
#include "../io_read_internal.h"
#include "../nl_error.h"

#include <stdio.h>

static int tsv_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    (void)o;
    return nl_tsv_write_field(path, f, meta, NULL, NULL);
}

static int tsv_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o, nl_field **out,
                    nl_meta *meta)
{
    FILE *fp;
    int st;
    (void)o;
    *out = NULL;
    if (!len)
        return NL_ERROR(NL_EINPUT, "%s: expected a TSV header line, found none", path);
    if (!(fp = fmemopen((void *)buf, len, "r")))
        return NL_ERROR(NL_ENOMEM, "out of memory reading %s", path);
    st = nl_tsv_read_stream(fp, path, out, meta);
    fclose(fp);
    return st;
}

const nl_format nl_format_tsv = {
    .name = "tsv",
    .extensions = ".tsv",
    .summary = "tab-separated t, value columns (%.10g), provenance as '# key: value' lines",
    .dims = 1 << 1,
    .types = NL_FORMAT_F64, /* ten significant digits: between float32 and float64 */
    .precision = 64,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN,
    .flags = NL_FORMAT_FALLBACK,
    .read = tsv_read,
    .read_stream = nl_tsv_read_stream,
    .write = tsv_write,
};
