"""Files noiselab writes, opened by readers that are not noiselab's:
h5py and xml.etree for HDF5 and its XDMF sidecar, PIL for the 16-bit PNG,
numpy.load for .npy and .npz.  Each checks the shape, the axis order (row 0
of every array is row 0 of noiselab.read's, j = 0: the image's top row,
which is the grid's smallest y, so "north" is down when y grows north) and
the values to the format's precision, and the grid's origin and spacing
where the format holds them."""
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import noiselab

WINDOW = ["synth", "subdiv", "--acf", "markov:scale=6", "--size", "24x10", "--nonperiodic", "--origin", "20,12",
          "--spacing", "0.5", "--seed", "4"]


def test_h5_and_xdmf_by_h5py_and_etree(cli, tmp_path):
    """A window at (20, 12) samples of spacing 0.5: h5py's array is
    noiselab.read's bit for bit (float32 both), the origin attribute says
    20,12, and the sidecar's Origin and Spacing (slowest axis first) put
    sample 0 at (y, x) = (6, 10)."""
    h5py = pytest.importorskip("h5py", reason="python3-h5py is not installed")
    cli(*WINDOW, "-o", tmp_path / "w.h5")
    with h5py.File(tmp_path / "w.h5", "r") as f:
        d = f["field"]
        a = d[...]
        origin = d.attrs["origin"]
    origin = origin.decode() if isinstance(origin, bytes) else origin
    assert a.shape == (10, 24) and a.dtype == np.float32
    assert np.array_equal(a.astype(np.float64), noiselab.read(tmp_path / "w.h5"))
    assert origin == "20,12"
    root = ET.parse(tmp_path / "w.xmf").getroot()
    assert root.find("./Domain/Grid/Topology").get("Dimensions") == "10 24"
    o, h = root.findall("./Domain/Grid/Geometry/DataItem")
    assert [float(v) for v in o.text.split()] == [6.0, 10.0]
    assert [float(v) for v in h.text.split()] == [0.5, 0.5]


def test_krige_map_origin_in_the_xdmf(cli, tmp_path):
    """A kriged map's sidecar: Origin is the first cell centre, a + h / 2."""
    (tmp_path / "d.tsv").write_text("x\ty\tvalue\n11\t-3\t0.5\n14\t-1\t1.5\n17\t-0.5\t-0.3\n")
    cli("krige", "--data", tmp_path / "d.tsv", "--acf", "markov:scale=3", "--grid", "16x8", "--extent",
        "10:18,-4:0", "-o", tmp_path / "k.h5")
    o, h = ET.parse(tmp_path / "k.xmf").getroot().findall("./Domain/Grid/Geometry/DataItem")
    assert [float(v) for v in o.text.split()] == [-3.75, 10.25]
    assert [float(v) for v in h.text.split()] == [0.5, 0.5]


def test_png16_by_pil(cli, tmp_path):
    """PIL reads the heightmap as 16-bit grey: shape (rows, columns), row 0
    the field's row 0, and each code the nearest of 65536 levels of the
    field's min..max to the same window written as EXR: within half a code,
    plus 0.02 for the EXR's float32 rounding (2^-24 of values under 2, over
    a range above 2: under 1e-7 of the range, 0.007 codes)."""
    Image = pytest.importorskip("PIL.Image", reason="python3-pil is not installed")
    cli(*WINDOW, "-o", tmp_path / "w.png")
    cli(*WINDOW, "-o", tmp_path / "w.exr")
    im = Image.open(tmp_path / "w.png")
    assert im.mode in ("I;16", "I;16B", "I")
    codes = np.array(im, dtype=np.float64)
    e = noiselab.read(tmp_path / "w.exr")
    assert codes.shape == e.shape == (10, 24)
    lo, hi = e.min(), e.max()
    assert np.abs(codes - (e - lo) / (hi - lo) * 65535).max() <= 0.52
    v, m = noiselab.read(tmp_path / "w.png", meta=True)
    assert m["origin"] == "20,12"


def test_npy_and_npz_by_numpy(cli, tmp_path):
    """numpy.load: the .npy as noiselab.read gives it (float64, bit for
    bit); krige -o map.npz holds "field" and "variance", the same as the
    EXR map and variance of the same run to float32 rounding (2^-24
    relative), and noiselab reads the .npz's field."""
    cli(*WINDOW, "-o", tmp_path / "w.npy")
    a = np.load(tmp_path / "w.npy")
    assert a.shape == (10, 24) and a.dtype == np.float64
    assert np.array_equal(a, noiselab.read(tmp_path / "w.npy"))
    (tmp_path / "d.tsv").write_text("x\ty\tvalue\n11\t-3\t0.5\n14\t-1\t1.5\n17\t-0.5\t-0.3\n")
    k = ["krige", "--data", tmp_path / "d.tsv", "--acf", "markov:scale=3", "--grid", "16x8", "--extent", "10:18,-4:0"]
    cli(*k, "-o", tmp_path / "k.npz")
    cli(*k, "-o", tmp_path / "k.exr", "--variance", tmp_path / "v.exr")
    z = np.load(tmp_path / "k.npz")
    assert sorted(z.files) == ["field", "variance"]
    f, v = z["field"], z["variance"]
    assert f.shape == v.shape == (8, 16) and f.dtype == np.float64
    tol = 2.0 ** -24
    assert np.allclose(f, noiselab.read(tmp_path / "k.exr"), rtol=tol, atol=tol * np.abs(f).max())
    assert np.allclose(v, noiselab.read(tmp_path / "v.exr"), rtol=tol, atol=tol * np.abs(v).max())
    assert np.array_equal(noiselab.read(tmp_path / "k.npz"), f)
    assert (v >= 0).all() and v.max() > 0


def test_raw_sidecar_round_trip(tmp_path):
    """Python's write and read of .r16 and .f32 through the sidecar: the
    shape (not square) comes back without size=, and r16 values within half
    a step of the range."""
    a = np.linspace(-2, 5, 21).reshape(3, 7)
    noiselab.write(tmp_path / "a.r16", a)
    b, m = noiselab.read(tmp_path / "a.r16", meta=True)
    assert b.shape == (3, 7) and np.abs(a - b).max() <= 7 / 65535 / 2 * (1 + 1e-9)
    noiselab.write(tmp_path / "a.f32", a, spacing=0.25)
    assert np.array_equal(noiselab.read(tmp_path / "a.f32"), a.astype(np.float32))
    (tmp_path / "a.f32.json").write_text('{"size": [4, 4]}')
    with pytest.raises(noiselab.Error, match="a.f32.json: size makes 16 samples; the file holds 21"):
        noiselab.read(tmp_path / "a.f32")
