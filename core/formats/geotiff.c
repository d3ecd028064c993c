/* GeoTIFF (.tif, .tiff) and cloud-optimised GeoTIFF (format cog) through
 * GDAL's GTiff and COG drivers: one float32 or float64 band, north-up, the
 * geotransform of the first sample's cell centre as core/formats/gdal_io.h
 * states ((x0 - h0/2, h0, 0, y0 + (n1 - 1/2) h1, 0, -h1): GDAL's corner
 * convention), the CRS as GeoKeys, NaN as the band's nodata, the provenance
 * as GDAL metadata items noiselab_KEY.  A TIFF without a geotransform reads
 * with spacing 1, row 0 the image's top, "ungeoreferenced" in the flags.
 * Without GDAL at build time both descriptors are NL_FORMAT_OFF. */
#include "formats_internal.h"
#include "gdal_io.h"

#ifdef NL_HAVE_GDAL
static int tif_read(const char *path, const unsigned char *buf, size_t len, const nl_read_options *o,
                    nl_field **out, nl_meta *meta)
{
    (void)buf, (void)len, (void)o;
    return nl_gdal_read("GTiff", 0, path, out, meta);
}

static int tif_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    static const char *const copts[] = {"COMPRESS=DEFLATE", "PREDICTOR=3", NULL};
    return nl_gdal_write("GTiff", copts, path, f, meta, o);
}

static int cog_write(const char *path, const nl_field *f, const nl_meta *meta, const nl_write_options *o)
{
    static const char *const copts[] = {"COMPRESS=DEFLATE", "PREDICTOR=YES", NULL};
    return nl_gdal_write("COG", copts, path, f, meta, o);
}
#define NL_GDAL_FNS(r, w) .read = r, .write = w
#define NL_GDAL_OFF(s) s
#else
#define NL_GDAL_FNS(r, w) .flags = NL_FORMAT_OFF
#define NL_GDAL_OFF(s) "off: this build has no GDAL (install libgdal-dev and rebuild)"
#endif

const nl_format nl_format_geotiff = {
    .name = "geotiff",
    .extensions = ".tif .tiff",
    .summary = NL_GDAL_OFF("GeoTIFF, one float32 (or float64) band, north-up, geotransform, CRS, NaN "
                           "nodata; through GDAL"),
    .dims = 1 << 2,
    .types = NL_FORMAT_F32 | NL_FORMAT_F64,
    .precision = 32,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN | NL_FORMAT_META_CRS |
            NL_FORMAT_META_NODATA,
    .magic = "II*\0", /* little-endian TIFF, as GDAL writes it; big-endian ones by extension */
    .magic_len = 4,
    NL_GDAL_FNS(tif_read, tif_write),
};

const nl_format nl_format_cog = {
    .name = "cog",
    .extensions = "",
    .summary = NL_GDAL_OFF("cloud-optimised GeoTIFF (tiled, overviews), as geotiff; --format cog; "
                           "read as geotiff; through GDAL"),
    .dims = 1 << 2,
    .types = NL_FORMAT_F32 | NL_FORMAT_F64,
    .precision = 32,
    .meta = NL_FORMAT_META_PROVENANCE | NL_FORMAT_META_SPACING | NL_FORMAT_META_ORIGIN | NL_FORMAT_META_CRS |
            NL_FORMAT_META_NODATA,
    NL_GDAL_FNS(tif_read, cog_write),
};
