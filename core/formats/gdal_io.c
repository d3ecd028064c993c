/* GeoTIFF, COG and NetCDF-CF through GDAL: the conventions are in
 * gdal_io.h.  GDAL's messages go to a quiet handler pushed for each call
 * (thread-local in GDAL), and the last one is quoted in ours. */
#include "gdal_io.h"
#include "../nl_error.h"
#include "../provenance.h"

#ifdef NL_HAVE_GDAL
#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* GDAL's last message, or "unknown error". */
static const char *gdal_msg(void)
{
    const char *m = CPLGetLastErrorMsg();
    return m && *m ? m : "no reason given (truncated, or not this format)";
}

/* The first sample's centre (x0, y0) of f as its record says (nl_meta_origin). */
static void first_centre(const nl_field *f, const nl_meta *meta, double *x0, double *y0)
{
    double h[3] = {f->h[0], f->h[1], f->h[2]}, o[3] = {0, 0, 0};
    if (meta && nl_meta_origin(meta, f->dim, f->n, h, o))
        o[0] = o[1] = 0;
    *x0 = o[0], *y0 = o[1];
}

int nl_format_crs_check(const char *crs)
{
    OGRSpatialReferenceH s = OSRNewSpatialReference(NULL);
    CPLPushErrorHandler(CPLQuietErrorHandler);
    OGRErr e = OSRSetFromUserInput(s, crs);
    CPLPopErrorHandler();
    OSRDestroySpatialReference(s);
    return e == OGRERR_NONE ? NL_OK : NL_ERROR(NL_EINVAL, "CRS \"%s\": unknown; expected EPSG:N, WKT or PROJ text "
                                                          "that GDAL knows", crs);
}

/* The CRS text crs as WKT into *wkt (CPLFree), NULL for "". */
static int crs_wkt(const char *crs, char **wkt)
{
    OGRSpatialReferenceH s;
    OGRErr e;
    *wkt = NULL;
    if (!crs || !*crs)
        return NL_OK;
    s = OSRNewSpatialReference(NULL);
    e = OSRSetFromUserInput(s, crs);
    if (e == OGRERR_NONE)
        e = OSRExportToWkt(s, wkt);
    OSRDestroySpatialReference(s);
    if (e != OGRERR_NONE)
        return NL_ERROR(NL_EINVAL, "CRS \"%s\": unknown; expected EPSG:N, WKT or PROJ text that GDAL knows", crs);
    return NL_OK;
}

/* A MEM dataset holding f north-up (bands = z slices) with its georeferencing,
 * nodata and provenance. */
static GDALDatasetH mem_copy(const nl_field *f, const nl_meta *meta, int dbl, const char *wkt, const char *prefix)
{
    GDALDriverH mem = GDALGetDriverByName("MEM");
    int nx = (int)f->n[0], ny = f->dim > 1 ? (int)f->n[1] : 1, nz = f->dim > 2 ? (int)f->n[2] : 1;
    GDALDataType t = dbl ? GDT_Float64 : GDT_Float32;
    GDALDatasetH ds = mem ? GDALCreate(mem, "", nx, ny, nz, t, NULL) : NULL;
    double x0, y0, gt[6];
    if (!ds)
        return NULL;
    first_centre(f, meta, &x0, &y0);
    gt[0] = x0 - f->h[0] / 2, gt[1] = f->h[0], gt[2] = 0;
    gt[3] = y0 + ((double)ny - 0.5) * f->h[1], gt[4] = 0, gt[5] = -f->h[1];
    GDALSetGeoTransform(ds, gt);
    if (wkt)
        GDALSetProjection(ds, wkt);
    for (int k = 0; meta && k < NL_META_NKEYS; k++) {
        char key[64];
        const char *v = nl_meta_value(meta, k);
        snprintf(key, sizeof key, "%snoiselab_%s", prefix, nl_meta_key(k));
        if (v && *v && *prefix) { /* netCDF splits "key=value" at every '=': quoted, it does not */
            char q[2 * 1024 + 3], *p = q;
            *p++ = '"';
            for (; *v; v++)
                *v == '"' || *v == '\\' ? (void)(*p++ = '\\', *p++ = *v) : (void)(*p++ = *v);
            *p++ = '"', *p = 0;
            GDALSetMetadataItem(ds, key, q, NULL);
        } else if (v && *v)
            GDALSetMetadataItem(ds, key, v, NULL);
    }
    for (int z = 0; z < nz; z++) {
        GDALRasterBandH b = GDALGetRasterBand(ds, z + 1);
        GDALSetRasterNoDataValue(b, NAN);
        for (int r = 0; r < ny; r++) { /* raster row r: the field's row ny - 1 - r */
            const double *row = f->data + ((size_t)z * (size_t)ny + (size_t)(ny - 1 - r)) * (size_t)nx;
            if (GDALRasterIO(b, GF_Write, 0, r, nx, 1, (void *)row, nx, 1, GDT_Float64, 0, 0) != CE_None) {
                GDALClose(ds);
                return NULL;
            }
        }
    }
    return ds;
}

int nl_gdal_write(const char *driver, const char *const *copts, const char *path, const nl_field *f,
                  const nl_meta *meta, const nl_write_options *o)
{
    GDALDriverH drv;
    GDALDatasetH mem, out = NULL;
    char *wkt = NULL;
    int st;
    if (f->n[0] > 0x7fffffff || (f->dim > 1 && f->n[1] > 0x7fffffff) || (f->dim > 2 && f->n[2] > 0x7fffffff))
        return NL_ERROR(NL_ETOOBIG, "%s: more than 2^31 - 1 samples on an axis", path);
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    st = crs_wkt(meta ? meta->crs : NULL, &wkt);
    if (!st && !(drv = GDALGetDriverByName(driver)))
        st = NL_ERROR(NL_EIO, "%s: GDAL has no %s driver", path, driver);
    else if (!st && !(mem = mem_copy(f, meta, o->precision == 64, wkt, strcmp(driver, "netCDF") ? "" : "NC_GLOBAL#")))
        st = NL_ERROR(NL_ENOMEM, "%s: GDAL: %s", path, gdal_msg());
    else if (!st) {
        CPLErrorReset();
        out = GDALCreateCopy(drv, path, mem, FALSE, (char **)copts, NULL, NULL);
        if (out)
            GDALClose(out); /* void in GDAL 3.6: a failed flush shows as the last error */
        if (!out || CPLGetLastErrorType() >= CE_Failure)
            st = NL_ERROR(NL_EIO, "cannot write %s: GDAL: %s", path, gdal_msg());
        GDALClose(mem);
    }
    CPLPopErrorHandler();
    CPLFree(wkt);
    return st;
}

/* The CRS of ds into meta->crs: "EPSG:N" when GDAL identifies it, else WKT. */
static void read_crs(GDALDatasetH ds, nl_meta *meta)
{
    const char *wkt = GDALGetProjectionRef(ds);
    OGRSpatialReferenceH s;
    if (!wkt || !*wkt)
        return;
    s = OSRNewSpatialReference(wkt);
    if (s) {
        OSRAutoIdentifyEPSG(s);
        const char *auth = OSRGetAuthorityName(s, NULL), *code = OSRGetAuthorityCode(s, NULL);
        if (auth && code && strcmp(auth, "EPSG") == 0)
            snprintf(meta->crs, sizeof meta->crs, "EPSG:%s", code);
        OSRDestroySpatialReference(s);
    }
    if (!meta->crs[0] && strlen(wkt) < sizeof meta->crs)
        snprintf(meta->crs, sizeof meta->crs, "%s", wkt);
}

/* The provenance items noiselab_KEY of ds into meta. */
static void read_items(GDALDatasetH ds, nl_meta *meta)
{
    for (int k = 0; k < NL_META_NKEYS; k++) {
        char key[64], nc[80];
        const char *v;
        snprintf(key, sizeof key, "noiselab_%s", nl_meta_key(k));
        snprintf(nc, sizeof nc, "NC_GLOBAL#%s", key);
        if ((v = GDALGetMetadataItem(ds, key, NULL)) || (v = GDALGetMetadataItem(ds, nc, NULL)))
            snprintf(nl_meta_slot(meta, k), nl_meta_capacity(k), "%s", v);
    }
}

/* The samples of ds into a new field with spacing and extent from gt. */
static int read_samples(GDALDatasetH ds, const char *path, const double *gt, int geo, nl_field **out, nl_meta *meta)
{
    int nx = GDALGetRasterXSize(ds), ny = GDALGetRasterYSize(ds), nz = GDALGetRasterCount(ds), st;
    size_t n[3] = {(size_t)nx, (size_t)ny, (size_t)nz};
    double h[3] = {gt[1], fabs(gt[5]), 1};
    nl_field *f = nl_field_alloc(nz > 1 ? 3 : 2, n, h, &st);
    if (!f)
        return st;
    for (int z = 0; z < nz; z++) {
        GDALRasterBandH b = GDALGetRasterBand(ds, z + 1);
        int has = 0;
        double nd = GDALGetRasterNoDataValue(b, &has);
        for (int r = 0; r < ny; r++) { /* north-up: raster row r is the field's row ny - 1 - r */
            size_t j = gt[5] < 0 ? (size_t)(ny - 1 - r) : (size_t)r;
            double *row = f->data + ((size_t)z * (size_t)ny + j) * (size_t)nx;
            if (GDALRasterIO(b, GF_Read, 0, r, nx, 1, row, nx, 1, GDT_Float64, 0, 0) != CE_None) {
                nl_field_free(f);
                return NL_ERROR(NL_EINPUT, "%s: unreadable samples: GDAL: %s", path, gdal_msg());
            }
            for (int i = 0; has && !isnan(nd) && i < nx; i++)
                if (row[i] == nd)
                    row[i] = NAN;
        }
    }
    if (meta && geo) {
        double s = gt[5] < 0 ? gt[3] + ny * gt[5] : gt[3];
        snprintf(meta->extent, sizeof meta->extent, "%.17g:%.17g,%.17g:%.17g", gt[0], gt[0] + nx * gt[1], s,
                 s + ny * fabs(gt[5]));
    }
    *out = f;
    return NL_OK;
}

int nl_gdal_read(const char *driver, int allow3d, const char *path, nl_field **out, nl_meta *meta)
{
    const char *const drivers[] = {driver, NULL};
    double gt[6] = {0, 1, 0, 0, 0, 1};
    GDALDatasetH ds;
    int st, geo;
    *out = NULL;
    GDALAllRegister();
    CPLPushErrorHandler(CPLQuietErrorHandler);
    CPLErrorReset();
    ds = GDALOpenEx(path, GDAL_OF_RASTER | GDAL_OF_READONLY, drivers, NULL, NULL);
    if (!ds) {
        st = NL_ERROR(NL_EINPUT, "%s: not a readable %s file: GDAL: %s", path, driver, gdal_msg());
        CPLPopErrorHandler();
        return st;
    }
    geo = GDALGetGeoTransform(ds, gt) == CE_None;
    if (!geo)
        gt[0] = gt[3] = 0, gt[1] = 1, gt[5] = 1;
    if (GDALGetRasterCount(ds) < 1 || (GDALGetRasterCount(ds) > 1 && !allow3d))
        st = NL_ERROR(NL_EINPUT, "%s: %d bands; expected one (a 2D field)", path, GDALGetRasterCount(ds));
    else if (gt[2] != 0 || gt[4] != 0 || !(gt[1] > 0) || gt[5] == 0 || !isfinite(gt[0]) || !isfinite(gt[3]))
        st = NL_ERROR(NL_EINPUT, "%s: a rotated or degenerate geotransform (%g, %g, %g, %g, %g, %g); expected "
                      "north-up cells", path, gt[0], gt[1], gt[2], gt[3], gt[4], gt[5]);
    else if (!(st = read_samples(ds, path, gt, geo, out, meta)) && meta) {
        read_items(ds, meta);
        read_crs(ds, meta);
        if (!geo)
            snprintf(meta->flags + strlen(meta->flags), sizeof meta->flags - strlen(meta->flags), "%s%s",
                     meta->flags[0] ? "," : "", "ungeoreferenced");
    }
    GDALClose(ds);
    CPLPopErrorHandler();
    return st;
}
#else
int nl_format_crs_check(const char *crs)
{
    return NL_ERROR(NL_EINVAL, "CRS \"%s\": this build has no GDAL (libgdal-dev) to know CRSs", crs ? crs : "");
}
#endif
