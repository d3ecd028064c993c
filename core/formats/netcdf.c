/* NetCDF-CF (.nc, netCDF classic) through GDAL's netCDF driver: one float32
 * or float64 variable "Band1" of a 2D field (3D fields are refused: GDAL
 * writes their slices as separate variables that it reads back as
 * subdatasets, not as one field), CF coordinate variables x and y
 * (lon and lat for a geographic CRS) holding the cell centres of
 * core/formats/gdal_io.h, a grid_mapping variable with the CRS's WKT
 * (crs_wkt, spatial_ref), _FillValue NaN, the provenance as global
 * attributes noiselab_KEY.  Without GDAL at build time the descriptor is
 * NL_FORMAT_OFF. */
#include "formats_internal.h"
#include "gdal_io.h"

#ifdef NL_HAVE_GDAL
static int nc_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o,
                   nl_field **out, nl_meta *meta)
{
    (void)buf, (void)len, (void)o;
    return nl_gdal_read("netCDF", 0, path, out, meta);
}

static int nc_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    static const char *const copts[] = {"FORMAT=NC", NULL};
    return nl_gdal_write("netCDF", copts, path, f, meta, o);
}
#define NL_GDAL_FNS .read = nc_read, .write = nc_write
#define NL_GDAL_OFF(s) s
#else
#define NL_GDAL_FNS .flags = NL_FORMAT_OFF
#define NL_GDAL_OFF(s) "off: this build has no GDAL (install libgdal-dev and rebuild)"
#endif

const nl_format nl_format_netcdf = {
    .name = "netcdf",
    .extensions = ".nc",
    .summary = NL_GDAL_OFF("NetCDF-CF, float32 (or float64), x/y coordinate variables, grid_mapping CRS, "
                           "_FillValue NaN; through GDAL"),
    .dims = 1 << 2,
    .types = NL_FORMAT_F32 | NL_FORMAT_F64,
    .precision = 32,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN | NL_FORMAT_META_CRS |
            NL_FORMAT_META_NODATA,
    .magic = "CDF",
    .magic_len = 3,
    NL_GDAL_FNS,
};
