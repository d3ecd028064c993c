/* noiselab formats: the field file formats, from the registry (core/format.h). */
#include "cli.h"
#include "opt.h"

#include <stdio.h>
#include <string.h>

static const char help[] =
    "usage: noiselab formats [--json]\n\n"
    "Lists the formats a field is written in (-o, chosen by the extension or by\n"
    "--format NAME) and read from (by content where the format has a signature,\n"
    "else by extension, else TSV): name, extensions, dimensions, value types and\n"
    "the metadata each carries; formats this build lacks (GeoTIFF, COG and NetCDF\n"
    "without GDAL) are listed with \"off\" and why.  Integer formats (png16, r16)\n"
    "map a value range, by default the field's min..max or --range LO:HI, linearly\n"
    "onto their codes.  --crs EPSG:N georeferences .tif, .nc and --cog outputs.\n";

typedef struct {
    int json; /* --json */
} opts_t;

static const cli_opt rows[] = {CLI_OPT_JSON(opts_t, json), {0}};

/* The bits of v named by names[i] for bit i, joined by sep into buf. */
static const char *words(unsigned v, const char *const *names, int n, const char *sep, char *buf, size_t len)
{
    size_t at = 0;
    buf[0] = 0;
    for (int i = 0; i < n; i++)
        if (v & (1u << i)) {
            int w = snprintf(buf + at, len - at, "%s%s", at ? sep : "", names[i]);
            if (w < 0 || (size_t)w >= len - at)
                break;
            at += (size_t)w;
        }
    if (!at)
        snprintf(buf, len, "none");
    return buf;
}

static const char *const dim_names[] = {"0D", "1D", "2D", "3D"};
static const char *const type_names[] = {"float32", "float64", "uint16", "uint8"};
static const char *const meta_names[] = {"provenance", "spacing", "origin", "range", "crs", "nodata"};

/* A list of words as a JSON array. */
static json_t *word_array(const char *s)
{
    json_t *a = json_array();
    for (const char *p = s; *p;) {
        size_t k = strcspn(p, ", ");
        if (k && strcmp(s, "none"))
            json_array_append_new(a, json_stringn(p, k));
        p += k;
        p += strspn(p, ", ");
    }
    return a;
}

int cli_cmd_formats(int argc, char **argv)
{
    opts_t a = {0};
    char d[64], t[64], m[128];
    json_t *all = json_array();
    if (cli_opt_parse("formats", help, rows, &a, argc, argv))
        return 0;
    cli_no_operands("formats", argc, argv);
    if (!a.json)
        printf("%-6s %-10s %-9s %-16s %s\n", "name", "extensions", "dims", "values", "metadata");
    for (size_t i = 0; i < nl_format_count(); i++) {
        const nl_format *f = nl_format_get(i);
        words(f->dims, dim_names, 4, ",", d, sizeof d);
        words(f->types, type_names, 4, ",", t, sizeof t);
        words(f->meta, meta_names, 6, ",", m, sizeof m);
        if (!a.json) {
            printf("%-6s %-10s %-9s %-16s %s%s\n       %s\n", f->name, f->extensions, d, t, m,
                   f->flags & NL_FORMAT_EXTERNAL ? " (noiselab-mpi)" : "", f->summary);
            continue;
        }
        json_t *o = json_object();
        json_object_set_new(o, "name", json_string(f->name));
        json_object_set_new(o, "extensions", word_array(f->extensions));
        json_object_set_new(o, "dims", word_array(d));
        json_object_set_new(o, "values", word_array(t));
        json_object_set_new(o, "metadata", word_array(m));
        json_object_set_new(o, "external", json_boolean(f->flags & NL_FORMAT_EXTERNAL));
        json_object_set_new(o, "off", json_boolean(f->flags & NL_FORMAT_OFF));
        json_object_set_new(o, "summary", json_string(f->summary));
        json_array_append_new(all, o);
    }
    if (a.json)
        cli_json_print(all);
    else
        json_decref(all);
    return 0;
}
