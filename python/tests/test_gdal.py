"""GeoTIFF, COG and NetCDF-CF (core/formats/gdal_io.h) opened by their own
readers: GDAL's Python bindings for the .tif, netCDF4 for the .nc, and
gdallocationinfo for a kriging map of the Meuse data.  The convention under
test: sample (i, j) is the cell centre (x0 + i h0, y0 + j h1), j = 0 the
southernmost row; the file is north-up, its geotransform the outer corner
(x0 - h0/2, h0, 0, y0 + (n1 - 1/2) h1, 0, -h1)."""
import os
import shutil
import subprocess

import numpy as np
import pytest

import noiselab

gdal = pytest.importorskip("osgeo.gdal")
osr = pytest.importorskip("osgeo.osr")

H = 25.0
X0, Y0 = 155012.5, 463012.5  # the first sample's centre: extent 155000:155100,463000:463075
EXTENT = "155000:155100,463000:463075"
RNG = np.random.default_rng(8112)


def field():
    return RNG.normal(size=(3, 4)) * 2.5  # (ny, nx): row 0 the south


def test_geotiff_by_gdal(tmp_path):
    a = field()
    p = str(tmp_path / "a.tif")
    noiselab.write(p, a, spacing=H, crs="EPSG:28992", extent=EXTENT, model="gauss:scale=2", seed=7)
    ds = gdal.Open(p)
    b = ds.GetRasterBand(1)
    assert (ds.RasterXSize, ds.RasterYSize, ds.RasterCount) == (4, 3, 1)
    # north-up: the file's row 0 is the field's last (northernmost) row; float32 samples
    assert np.array_equal(b.ReadAsArray(), a[::-1].astype(np.float32))
    assert ds.GetGeoTransform() == (X0 - H / 2, H, 0.0, Y0 + (3 - 0.5) * H, 0.0, -H)
    s = osr.SpatialReference(wkt=ds.GetProjection())
    assert s.GetAuthorityCode(None) == "28992"
    assert np.isnan(b.GetNoDataValue())
    assert ds.GetMetadataItem("noiselab_model") == "gauss:scale=2" and ds.GetMetadataItem("noiselab_seed") == "7"
    # and back through the library: the same values (float32), spacing, extent and CRS
    c, m = noiselab.read(p, meta=True)
    assert np.array_equal(c, a.astype(np.float32)) and m["spacing_array"] == (H, H)
    assert m["extent"] == EXTENT and m["crs"] == "EPSG:28992"


def test_geotiff_float64_and_cog(tmp_path, cli):
    a = field()
    p = str(tmp_path / "d.tif")
    noiselab.write(p, a, spacing=H, precision="double", extent=EXTENT)
    assert np.array_equal(gdal.Open(p).ReadAsArray(), a[::-1])  # float64: exact
    cog = str(tmp_path / "c.tif")
    cli("synth", "fft", "--acf", "gauss:scale=3", "--size", "64x64", "--seed", "5", "--spacing", "2", "--cog",
        "--crs", "EPSG:32631", "-o", cog)
    ds = gdal.Open(cog)
    assert ds.GetMetadataItem("LAYOUT", "IMAGE_STRUCTURE") == "COG"
    assert ds.GetGeoTransform() == (-1.0, 2.0, 0.0, 127.0, 0.0, -2.0)  # x0 = y0 = 0, h = 2, n1 = 64


def test_tiff_without_georeferencing(tmp_path):
    p = str(tmp_path / "plain.tif")
    ds = gdal.GetDriverByName("GTiff").Create(p, 3, 2, 1, gdal.GDT_Float32)
    v = np.array([[1, 2, 3], [4, 5, 6]], dtype=np.float32)
    ds.GetRasterBand(1).WriteArray(v)
    ds = None
    a, m = noiselab.read(p, meta=True)
    # no geotransform: spacing 1, image row 0 is array row 0, and the flags say so
    assert np.array_equal(a, v) and m["spacing_array"] == (1.0, 1.0)
    assert m["flags"] == "ungeoreferenced" and m["extent"] == "" and m["crs"] == ""


def test_netcdf_by_netcdf4(tmp_path):
    nc4 = pytest.importorskip("netCDF4")
    a = field()
    p = str(tmp_path / "a.nc")
    noiselab.write(p, a, spacing=H, crs="EPSG:28992", extent=EXTENT, model="gauss:scale=2", method="fft")
    with nc4.Dataset(p) as d:
        v = d.variables["Band1"]
        # CF: y ascending, so the array's row 0 is the south, as the field's
        assert np.array_equal(np.asarray(v[:]), a.astype(np.float32))
        assert np.array_equal(d.variables["x"][:], X0 + H * np.arange(4))
        assert np.array_equal(d.variables["y"][:], Y0 + H * np.arange(3))
        assert d.variables["x"].units == "m" and np.isnan(v._FillValue)
        gm = d.variables[v.grid_mapping]
        assert 'AUTHORITY["EPSG","28992"]' in gm.crs_wkt
        assert d.noiselab_model == "gauss:scale=2" and d.noiselab_method == "fft"
    c, m = noiselab.read(p, meta=True)
    assert np.array_equal(c, a.astype(np.float32)) and m["extent"] == EXTENT and m["crs"] == "EPSG:28992"


def test_netcdf_geographic_lon_lat(tmp_path):
    nc4 = pytest.importorskip("netCDF4")
    p = str(tmp_path / "g.nc")
    noiselab.write(p, field(), spacing=0.5, crs="EPSG:4326", extent="5:7,50:51.5")
    with nc4.Dataset(p) as d:
        assert np.array_equal(d.variables["lon"][:], [5.25, 5.75, 6.25, 6.75])
        assert np.array_equal(d.variables["lat"][:], [50.25, 50.75, 51.25])


@pytest.fixture(scope="module")
def meuse(tmp_path_factory):
    """The Meuse points (x, y, log zinc) as a TSV, from R's sp."""
    if not shutil.which("Rscript"):
        pytest.skip("Rscript is not installed (Meuse comes from R's sp)")
    path = tmp_path_factory.mktemp("meuse") / "meuse.tsv"
    r = subprocess.run(["Rscript", "-e", "suppressMessages(library(sp)); data(meuse); d <- data.frame(x = meuse$x, "
                        "y = meuse$y, value = log(meuse$zinc)); write.table(format(d, digits = 17), '%s', "
                        "sep = '\\t', quote = FALSE, row.names = FALSE)" % path], capture_output=True)
    if r.returncode != 0:
        pytest.skip("R's sp package is not installed")
    return str(path), np.loadtxt(path, skiprows=1)


def test_krige_map_honours_datum_where_crs_puts_it(tmp_path, cli, meuse):
    if not shutil.which("gdallocationinfo"):
        pytest.skip("gdallocationinfo (gdal-bin) is not installed")
    path, t = meuse
    x, y, z = t[0]  # 181072, 333611: made a cell centre of a 40 m grid
    a, c = x - 20 - 40 * 70, y - 20 - 40 * 99
    out = str(tmp_path / "map.tif")
    cli("krige", "--data", path, "--acf", "spherical:scale=900", "--grid", "80x100", "--extent",
        "%g:%g,%g:%g" % (a, a + 3200, c, c + 4000), "--crs", "EPSG:28992", "-o", out)
    r = subprocess.run(["gdallocationinfo", "-valonly", "-geoloc", out, "%g" % x, "%g" % y], capture_output=True,
                       text=True, check=True)
    # ordinary kriging without nugget honours the datum: the solve's rounding
    # (~1e-12 relative) is far below float32's half ulp, 2^-24 relative
    assert abs(float(r.stdout) - z) <= 2.0 ** -23 * abs(z)
    # a neighbouring cell centre is not the datum
    r = subprocess.run(["gdallocationinfo", "-valonly", "-geoloc", out, "%g" % (x + 40), "%g" % y],
                       capture_output=True, text=True, check=True)
    assert abs(float(r.stdout) - z) > 1e-4
    # the map lies where EPSG:28992 puts the Meuse: by Stein, Limburg (about 50.97 N, 5.74 E)
    ds = gdal.Open(out)
    s = osr.SpatialReference(wkt=ds.GetProjection())
    g = osr.SpatialReference()
    g.ImportFromEPSG(4326)
    g.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    lon, lat, _ = osr.CoordinateTransformation(s, g).TransformPoint(x, y)
    assert 5.70 < lon < 5.78 and 50.95 < lat < 51.0


def test_missing_cells_are_nodata_and_crs_carries_over(tmp_path, cli):
    pts = tmp_path / "p.tsv"
    pts.write_text("x\ty\tvalue\n181050\t333050\t6.9\n180650\t332650\t5.2\n")
    grid = ("--grid", "20x20", "--extent", "180000:182000,332000:334000")
    out = str(tmp_path / "m.tif")
    # a 150 m radius reaches the cells whose centres lie within it of a datum: 2 x 9 of 400
    cli("krige", "--data", pts, "--acf", "spherical:scale=900", *grid, "--radius", "150", "--crs", "EPSG:28992",
        "-o", out)
    ds = gdal.Open(out)
    a = ds.GetRasterBand(1).ReadAsArray()
    assert np.isnan(ds.GetRasterBand(1).GetNoDataValue())
    assert np.count_nonzero(~np.isnan(a)) == 18 and a[9, 10] == np.float32(6.9)  # row 9 from the top: y 333050
    # a command that reads the map and writes a field keeps its CRS and place
    m2 = str(tmp_path / "m2.tif")
    full = str(tmp_path / "full.tif")
    cli("krige", "--data", pts, "--acf", "spherical:scale=900", *grid, "--crs", "EPSG:28992", "-o", full)
    cli("shape", "--to", "uniform", full, "-o", m2)
    d2 = gdal.Open(m2)
    assert d2.GetGeoTransform() == gdal.Open(full).GetGeoTransform()
    assert osr.SpatialReference(wkt=d2.GetProjection()).GetAuthorityCode(None) == "28992"
