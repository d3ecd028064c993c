/* Fields written where users open them: --format and --range, the check of
 * an output's name against the format registry (core/format.h) before a
 * run, and the write itself (HDF5 through cli_h5, with its XDMF sidecar). */
#include "cli.h"
#include "../core/format.h"
#include "../core/provenance.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

const char *cli_field_format;
const char *cli_field_crs;
int cli_field_single;
double cli_field_range[2];

void cli_opt_format(void *obj, const char *label, const char *arg)
{
    char list[256];
    (void)obj;
    if (arg && nl_format_find(arg)) {
        cli_field_format = arg;
        return;
    }
    nl_format_list(1, list, sizeof list);
    cli_die(2, "%s: expected a format, one of %s, got \"%s\"", label, list, arg ? arg : "");
}

/* LO:HI, as render's --range */
void cli_opt_range(void *obj, const char *label, const char *arg)
{
    double lo, hi;
    char junk;
    (void)obj;
    if (!arg || sscanf(arg, "%lf:%lf%c", &lo, &hi, &junk) != 2 || !(lo < hi) || !isfinite(lo) || !isfinite(hi) ||
        !isfinite(hi - lo))
        cli_die(2, "%s: expected LO:HI with LO < HI, both finite and HI - LO finite, got \"%s\"", label,
                arg ? arg : "");
    cli_field_range[0] = lo, cli_field_range[1] = hi;
}

void cli_opt_crs(void *obj, const char *label, const char *arg)
{
    const nl_format *tif = nl_format_find("geotiff");
    (void)obj;
    if (tif && (tif->flags & NL_FORMAT_OFF))
        cli_die(2, "%s: no format of this build carries a CRS (%s), got \"%s\"", label, tif->summary,
                arg ? arg : "");
    if (!arg || nl_format_crs_check(arg))
        cli_die(2, "%s: expected a coordinate reference system GDAL knows, e.g. EPSG:28992, got \"%s\"", label,
                arg ? arg : "");
    cli_field_crs = arg;
}

void cli_opt_cog(void *obj, const char *label, const char *arg)
{
    (void)obj;
    if (arg)
        cli_die(2, "%s: takes no value, got \"%s\"", label, arg);
    cli_opt_format(NULL, "--format", "cog");
}

const nl_format *cli_field_out_check(const char *label, const char *path, int dim)
{
    const nl_format *t = cli_field_format ? nl_format_find(cli_field_format) : nl_format_for_path(path);
    char list[256];
    if (!t) {
        nl_format_list(0, list, sizeof list);
        cli_die(2, "%s: expected a file name ending in one of %s (or --format NAME), got \"%s\"", label, list, path);
    }
    if (dim >= 1 && dim <= 3 && !(t->dims & (1u << dim)))
        cli_die(2, "%s: format %s does not hold %dD fields (noiselab formats lists what each holds), got \"%s\"",
                label, t->name, dim, path);
    if (cli_h5_double && !(t->types & NL_FORMAT_F64))
        cli_die(2, "--precision double: format %s stores no float64; expected %s", t->name,
                "an .h5 or .npy output (or .tif, .nc)");
    if (cli_field_range[0] < cli_field_range[1] && (t->types & (NL_FORMAT_F32 | NL_FORMAT_F64)))
        cli_die(2, "--range: format %s stores floats, not codes of a range; expected png16 or r16", t->name);
    if (cli_field_crs && !(t->meta & NL_FORMAT_META_CRS))
        cli_die(2, "--crs: format %s carries no CRS; expected a .tif, .nc or --format cog output, got \"%s\"",
                t->name, path);
    if (t->flags & NL_FORMAT_OFF)
        cli_die(2, "%s: format %s: %s", label, t->name, t->summary);
    return t;
}

int cli_field_is_float32(const char *path)
{
    const nl_format *t = cli_field_format ? nl_format_find(cli_field_format) : nl_format_for_path(path);
    return t && (t->types & NL_FORMAT_F32) && !(cli_h5_double && (t->types & NL_FORMAT_F64)) &&
           !((t->types & NL_FORMAT_F64) && t->precision == 64 && !cli_field_single);
}

void cli_write_xdmf(const char *path, int dim, const size_t *n, const double *h, const nl_meta *meta)
{
    char xmf[4096];
    const char *base = strrchr(path, '/');
    double origin[3], hh[3] = {h[0], dim > 1 ? h[1] : 1, dim > 2 ? h[2] : 1};
    size_t k = strlen(path) - 3; /* the name without ".h5" */
    if (snprintf(xmf, sizeof xmf, "%.*s.xmf", (int)k, path) >= (int)sizeof xmf)
        cli_die(2, "-o: path too long: \"%s\"", path);
    cli_check(nl_meta_origin(meta, dim, n, hh, origin));
    const char *tmp = cli_out_begin(xmf);
    cli_check(nl_xdmf_write(tmp, base ? base + 1 : path, dim, n, hh, origin, cli_h5_double));
    cli_out_commit(xmf);
}

void cli_meta_extent(nl_meta *m, int dim, const double *lo, const double *hi, const size_t *n)
{
    double h[3], origin[3];
    for (int a = 0; a < dim; a++)
        h[a] = (hi[a] - lo[a]) / (double)n[a], origin[a] = lo[a] + 0.5 * h[a];
    cli_check(nl_meta_set_origin(m, dim, h, origin));
}

void cli_write_field(const char *path, const char *tmp, const nl_field *f, const nl_meta *meta)
{
    const nl_format *t = cli_field_out_check("-o", path, f->dim);
    if (t->flags & NL_FORMAT_EXTERNAL) {
        if (!cli_h5)
            cli_die(2, "%s: HDF5 files are read and written by noiselab-mpi", path);
        cli_check(cli_h5->write(tmp, f, meta, cli_h5_double));
        cli_write_xdmf(path, f->dim, f->n, f->h, meta);
        return;
    }
    nl_meta m = {0};
    if (meta)
        m = *meta;
    if (cli_field_crs)
        snprintf(m.crs, sizeof m.crs, "%s", cli_field_crs);
    meta = &m;
    int prec = cli_h5_double ? 64 : cli_field_single && (t->types & NL_FORMAT_F32) ? 32 : 0;
    char side[4096];
    nl_write_options o = {.format = t->name, .precision = prec, .lo = cli_field_range[0], .hi = cli_field_range[1]};
    if (t->flags & NL_FORMAT_SIZED) { /* the raw formats' JSON sidecar, an output of its own */
        if (snprintf(side, sizeof side, "%s.json", path) >= (int)sizeof side)
            cli_die(2, "-o: path too long: \"%s\"", path);
        o.sidecar = cli_out_begin(side);
    }
    cli_check(nl_field_write(tmp, f, meta, &o));
    if (o.sidecar)
        cli_out_commit(side);
}
