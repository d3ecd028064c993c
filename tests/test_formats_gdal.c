/* GeoTIFF, COG and NetCDF through the registry (core/formats/gdal_io.h):
 * values, spacing, extent, CRS and provenance come back; a missing sample
 * (NaN) is written as nodata and refused on reading like any non-finite
 * sample (core/io.h); an unknown CRS is refused before anything is written.
 * The formats' own readers check the files in python/tests/test_gdal.py. */
#include "../core/format.h"
#include "../core/nl_error.h"
#include "util.h"

#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

static char path_buf[512];
static const char *path(const char *name)
{
    snprintf(path_buf, sizeof path_buf, "%s/%s", scratch_dir(), name);
    return path_buf;
}

/* Write a 7 x 5 field with spacing 30 and extent, read it back as `name`. */
static void round_trip(const char *name, const char *file, int prec)
{
    size_t n[2] = {7, 5};
    double h[2] = {30, 30};
    nl_field *f = nl_field_alloc(2, n, h, NULL), *g;
    nl_write_options w = {.format = name, .precision = prec};
    nl_meta m = {0}, r;
    for (size_t i = 0; i < f->count; i++)
        f->data[i] = sin(2.385 * (double)i) * 7.25 + 0.125 * (double)i;
    snprintf(m.model, sizeof m.model, "markov:scale=60");
    snprintf(m.method, sizeof m.method, "krige:ordinary,points=3,extent=1:2,3:4"); /* m.extent wins */
    snprintf(m.crs, sizeof m.crs, "EPSG:32631");
    snprintf(m.extent, sizeof m.extent, "500000:500210,5600000:5600150");
    cr_assert_eq(nl_field_write(path(file), f, &m, &w), NL_OK, "%s: %s", name, nl_errmsg());
    cr_assert_eq(nl_field_read(path(file), &g, &r), NL_OK, "%s: %s", name, nl_errmsg());
    cr_assert(g->dim == 2 && g->n[0] == 7 && g->n[1] == 5 && g->h[0] == 30 && g->h[1] == 30, "%s", name);
    /* float64 bit for bit, float32 as (float) rounds: exact comparisons */
    for (size_t i = 0; i < f->count; i++)
        cr_assert_eq(g->data[i], prec == 64 ? f->data[i] : (double)(float)f->data[i], "%s sample %zu", name, i);
    cr_assert_str_eq(r.extent, m.extent, "%s", name);
    cr_assert_str_eq(r.crs, "EPSG:32631", "%s", name);
    cr_assert_str_eq(r.model, m.model, "%s", name);
    cr_assert_str_eq(r.method, m.method, "%s", name);
    nl_field_free(f);
    nl_field_free(g);
}

Test(formats_gdal, round_trips)
{
    if (nl_format_find("geotiff")->flags & NL_FORMAT_OFF)
        cr_skip_test("built without GDAL");
    round_trip("geotiff", "a.tif", 32);
    round_trip("geotiff", "b.tif", 64);
    round_trip("cog", "c.tif", 32);
    round_trip("netcdf", "a.nc", 32);
    round_trip("netcdf", "b.nc", 64);
}

Test(formats_gdal, nodata_and_refusals)
{
    size_t n[2] = {4, 3};
    nl_field *f = nl_field_alloc(2, n, NULL, NULL), *g = NULL;
    nl_meta m = {0};
    if (nl_format_find("geotiff")->flags & NL_FORMAT_OFF)
        cr_skip_test("built without GDAL");
    f->data[5] = NAN;
    cr_assert_eq(nl_field_write(path("nan.tif"), f, NULL, NULL), NL_OK, "%s", nl_errmsg());
    cr_assert_eq(nl_field_read(path("nan.tif"), &g, NULL), NL_EINPUT);
    cr_assert(strstr(nl_errmsg(), "sample 5 is nan"), "%s", nl_errmsg());
    snprintf(m.crs, sizeof m.crs, "EPSG:999999");
    cr_assert_eq(nl_field_write(path("bad.tif"), f, &m, NULL), NL_EINVAL);
    cr_assert(strstr(nl_errmsg(), "EPSG:999999"), "%s", nl_errmsg());
    cr_assert_neq(access(path("bad.tif"), F_OK), 0, "nothing written");
    cr_assert_eq(nl_format_crs_check("EPSG:28992"), NL_OK);
    nl_field_free(f);
}
