"""Field formats through the library's registry (core/format.h): numpy
reads the .npy noiselab writes and noiselab reads numpy's, 16-bit PNG
heightmaps map back within half a step, the .xmf sidecar of an .h5 is
valid XML naming the right grid, and unknown names are refused alike by
Python and the command line."""
import json
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import noiselab

RNG = np.random.default_rng(2385)
SHAPES = [(97,), (13, 7), (5, 4, 3)]


@pytest.mark.parametrize("shape", SHAPES)
def test_npy_read_by_numpy_and_back(tmp_path, shape):
    a = RNG.normal(size=shape) * 3.25
    p = tmp_path / "a.npy"
    noiselab.write(p, a)
    b = np.load(p)
    assert b.dtype == np.float64 and b.shape == shape and np.array_equal(a, b)
    noiselab.write(p, a, precision="single")
    assert np.array_equal(np.load(p), a.astype(np.float32))
    for dt in (np.float64, np.float32):  # numpy's own file, read by the library
        np.save(tmp_path / "n.npy", a.astype(dt))
        assert np.array_equal(noiselab.read(tmp_path / "n.npy"), a.astype(dt).astype(np.float64))


def test_npy_numpy_headers_refused_with_a_message(tmp_path):
    np.save(tmp_path / "i.npy", np.arange(6, dtype=np.int32))
    with pytest.raises(noiselab.Error, match="descr: expected '<f8' or '<f4'"):
        noiselab.read(tmp_path / "i.npy")
    np.save(tmp_path / "f.npy", np.asfortranarray(np.ones((3, 4))))
    with pytest.raises(noiselab.Error, match="fortran_order"):
        noiselab.read(tmp_path / "f.npy")


def test_png16_within_half_a_step_and_provenance(tmp_path):
    """Codes round to the nearest of 65536 levels over the range: at most
    half a step, (max - min) / 65535 / 2, from the written value."""
    a = RNG.normal(size=(24, 40)) * 100 + 7
    p = tmp_path / "h.png"
    noiselab.write(p, a, spacing=(2.0, 0.5), seed=11, model="markov:scale=3")
    b, m = noiselab.read(p, meta=True)
    half = (a.max() - a.min()) / 65535 / 2
    assert np.abs(a - b).max() <= half * (1 + 1e-9)
    assert m["seed"] == "11" and m["model"] == "markov:scale=3" and m["spacing_array"] == (2.0, 0.5)
    noiselab.write(p, a, range=(0, 50))  # clamped to the range given
    assert np.abs(np.clip(a, 0, 50) - noiselab.read(p)).max() <= 50 / 65535 / 2 * (1 + 1e-9)


@pytest.mark.parametrize("shape", SHAPES)
def test_raw_formats_with_a_size(tmp_path, shape):
    a = RNG.uniform(-2, 5, size=shape)
    noiselab.write(tmp_path / "a.f32", a)
    assert np.array_equal(noiselab.read(tmp_path / "a.f32", size=shape), a.astype(np.float32))
    assert np.array_equal(np.fromfile(tmp_path / "a.f32", dtype="<f4").reshape(shape), a.astype(np.float32))
    noiselab.write(tmp_path / "a.r16", a, range=(-2, 5))
    codes = np.fromfile(tmp_path / "a.r16", dtype="<u2").reshape(shape)  # as Unity reads it
    assert np.array_equal(codes, np.rint((a + 2) / 7 * 65535).astype(np.uint16))
    b = noiselab.read(tmp_path / "a.r16", size=shape, range=(-2, 5))
    assert np.abs(a - b).max() <= 7 / 65535 / 2 * (1 + 1e-9)


@pytest.mark.parametrize("shape", [(6, 9), (3, 4, 5)])
def test_xdmf_sidecar_parses_and_names_the_grid(cli, tmp_path, shape):
    p = tmp_path / "f.h5"
    size = "x".join(str(n) for n in reversed(shape))
    cli("synth", "fft", "--acf", "markov:scale=2", "--size", size, "--spacing", "0.5", "--clamp", "--seed", "3",
        "-o", p)
    root = ET.parse(tmp_path / "f.xmf").getroot()
    assert root.tag == "Xdmf" and root.get("Version") == "3.0"
    topo = root.find("./Domain/Grid/Topology")
    assert topo.get("TopologyType") == "%dDCoRectMesh" % len(shape)
    assert topo.get("Dimensions") == " ".join(map(str, shape))
    origin, spacing = root.findall("./Domain/Grid/Geometry/DataItem")
    assert origin.get("Name") == "Origin" and [float(v) for v in origin.text.split()] == [0.0] * len(shape)
    assert [float(v) for v in spacing.text.split()] == [0.5] * len(shape)
    data = root.find("./Domain/Grid/Attribute/DataItem")
    assert data.text == "f.h5:/field" and data.get("Precision") == "4"
    assert data.get("Dimensions") == " ".join(map(str, shape))
    noiselab.write(tmp_path / "g.h5", np.ones(shape), precision="double")
    data = ET.parse(tmp_path / "g.xmf").getroot().find("./Domain/Grid/Attribute/DataItem")
    assert data.get("Precision") == "8" and data.text == "g.h5:/field"


def test_unknown_names_refused(cli, tmp_path):
    a = np.zeros((4, 4))
    with pytest.raises(noiselab.Error, match="unknown extension; expected one of .exr, .tsv, .npy"):
        noiselab.write(tmp_path / "a.gif", a)
    with pytest.raises(noiselab.Error, match='format "gif": unknown'):
        noiselab.write(tmp_path / "a.exr", a, format="gif")
    with pytest.raises(noiselab.Error, match="does not hold 3D"):
        noiselab.write(tmp_path / "a.png", np.zeros((2, 3, 4)))
    assert not list(tmp_path.iterdir())
    r = cli("synth", "fft", "--acf", "markov:scale=2", "--size", "16x16", "-o", tmp_path / "a.gif", check=False)
    assert r.returncode == 2 and r.stderr.count("\n") == 1
    assert '-o: expected a file name ending in one of .exr, .tsv, .npy' in r.stderr and "a.gif" in r.stderr
    r = cli("shape", "--to", "uniform", "--format", "gif", "x.exr", "-o", "a.exr", check=False)
    assert r.returncode == 2 and '--format: expected a format, one of exr, tsv, npy' in r.stderr


def test_format_by_name_and_listing(cli, tmp_path):
    a = RNG.normal(size=(8, 8))
    noiselab.write(tmp_path / "a.bin", a, format="npy")
    assert np.array_equal(np.load(tmp_path / "a.bin"), a)
    assert np.array_equal(noiselab.read(tmp_path / "a.bin"), a)  # by content
    listed = json.loads(cli("formats", "--json").stdout)
    ours = noiselab.formats()
    assert [f["name"] for f in listed] == [f["name"] for f in ours]
    assert {"exr", "tsv", "npy", "png16", "r16", "f32", "h5"} <= {f["name"] for f in ours}
    assert next(f for f in ours if f["name"] == "npy")["metadata"] == []
