/* Fields written and read through GDAL (internal to core/formats/): the
 * shared work of the geotiff, cog and netcdf descriptors.  Compiled only
 * when the build found GDAL (NL_HAVE_GDAL, Makefile).
 *
 * Georeferencing.  Sample (i, j) of a field is the centre of a cell:
 * x = x0 + i h0, y = y0 + j h1, j = 0 the southernmost row, where (x0, y0)
 * is the first sample's centre.  The file is north-up: raster row 0 is the
 * field's last row (the northernmost), and GDAL's geotransform, which names
 * the outer corner of the top-left cell, is
 *     (x0 - h0/2, h0, 0, y0 + (n1 - 1/2) h1, 0, -h1).
 * (x0, y0) comes from nl_meta.extent (its cell edges x0 - h0/2 and
 * y0 - h1/2), else from an "extent=a:b,c:d" of nl_meta.method (what krige
 * records), else from nl_meta.origin (a window's first sample, in samples:
 * x0 = X h0), else (0, 0).  Reading inverts this: a file without a
 * geotransform reads with spacing 1, origin 0 and "ungeoreferenced" added to
 * nl_meta.flags; a rotated one is refused.
 *
 * NaN samples are missing: the band's nodata value (GeoTIFF) or _FillValue
 * (netCDF) is NaN; on reading, samples equal to a declared nodata value
 * become NaN.  The provenance is written as metadata items noiselab_KEY
 * (netCDF global attributes), the CRS as the file's spatial reference. */
#ifndef NL_GDAL_IO_H
#define NL_GDAL_IO_H

#include "../format.h"

/* Write f through GDAL driver `driver` (a MEM copy, then CreateCopy with the
 * creation options copts, NULL-terminated).  NL_EINVAL for a CRS GDAL does
 * not know, NL_EIO when GDAL fails (its message quoted). */
int nl_gdal_write(const char *driver, const char *const *copts, const char *path, const nl_field *f,
                  const nl_meta *meta, const nl_write_options *o);

/* Read path through GDAL driver `driver` (only it).  3D: bands as z when
 * allow3d, else a file of several bands is refused.  NL_EINPUT naming path. */
int nl_gdal_read(const char *driver, int allow3d, const char *path, nl_field **out, nl_meta *meta);

#endif
