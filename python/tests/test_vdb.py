"""OpenVDB volumes (core/formats/vdb.c) through Python, and read by an
independent reader: OpenVDB's own Python module (Debian's python3-openvdb,
pyopenvdb), skipped with the reason when it is absent."""
import numpy as np
import pytest

import noiselab

RNG = np.random.default_rng(11)


def _built():
    f = next((f for f in noiselab.formats() if f["name"] == "openvdb"), None)
    return f is not None and not f.get("off")


pytestmark = pytest.mark.skipif(not _built(), reason="this build has no OpenVDB (the format openvdb is off)")


def _pyopenvdb():
    try:
        import pyopenvdb
    except ImportError as e:
        pytest.skip("OpenVDB's Python module (python3-openvdb) is absent: %s" % e)
    return pyopenvdb


def test_write_read_back_float32(tmp_path):
    a = RNG.normal(size=(3, 5, 7))  # z, y, x: slowest first, as read() returns it
    a[:, :, 0] = 0  # a plane of zeros stays in the box
    noiselab.write(tmp_path / "a.vdb", a, spacing=(2.0, 0.5, 0.25))
    b, meta = noiselab.read(tmp_path / "a.vdb", meta=True)
    assert b.shape == a.shape
    assert np.array_equal(b, a.astype(np.float32).astype(np.float64))  # tolerance 0: float32 storage only
    assert [float(h) for h in meta["spacing"].split(",")] == [0.25, 0.5, 2.0]  # x first


def test_openvdb_reads_what_we_write(cli, tmp_path):
    """The command line's volume, opened by OpenVDB itself: the grid
    "density", its voxel size the spacing, the world position of voxel
    (0, 0, 0) the origin, values at a few voxels those of the same field
    written as float32 .npy, and the provenance as string metadata."""
    vdb = _pyopenvdb()
    args = ["synth", "fft", "--acf", "markov:scale=3", "--size", "8x6x4", "--spacing", "0.5", "--seed", "3",
            "--clamp"]
    cli(*args, "-o", tmp_path / "a.vdb")
    cli(*args, "-o", tmp_path / "a.npy")
    ref = np.load(tmp_path / "a.npy")  # (z, y, x), float64
    g = vdb.read(str(tmp_path / "a.vdb"), "density")
    assert isinstance(g, vdb.FloatGrid)
    assert g.transform.voxelSize() == (0.5, 0.5, 0.5)
    assert g.transform.indexToWorld((0, 0, 0)) == (0.0, 0.0, 0.0)
    assert g.evalActiveVoxelBoundingBox() == ((0, 0, 0), (7, 5, 3))
    acc = g.getConstAccessor()
    for i, j, k in [(0, 0, 0), (7, 5, 3), (3, 1, 2), (6, 4, 0)]:
        assert acc.getValue((i, j, k)) == float(np.float32(ref[k, j, i])), (i, j, k)
    assert g["noiselab.seed"] == "3"
    assert g["noiselab.model"].startswith("markov")
    assert g.gridClass == vdb.GridClass.FOG_VOLUME


def test_origin_is_the_translation(tmp_path):
    vdb = _pyopenvdb()
    a = RNG.normal(size=(2, 3, 4))
    noiselab.write(tmp_path / "o.vdb", a, spacing=0.5, origin="6,-4")
    g = vdb.read(str(tmp_path / "o.vdb"), "density")
    assert g.transform.indexToWorld((0, 0, 0)) == (3.0, -2.0, 0.0)
    _, meta = noiselab.read(tmp_path / "o.vdb", meta=True)
    assert meta["origin"] == "6,-4"


def test_refusals(tmp_path):
    vdb = _pyopenvdb()
    with pytest.raises(noiselab.Error, match="does not hold 2D fields"):
        noiselab.write(tmp_path / "p.vdb", np.zeros((4, 4)))
    g = vdb.BoolGrid()
    g.name = "labels"
    g.getAccessor().setValueOn((1, 2, 3), True)
    vdb.write(str(tmp_path / "i.vdb"), grids=[g])
    with pytest.raises(noiselab.Error, match="no float grid among its 1 grids"):
        noiselab.read(tmp_path / "i.vdb")
    (tmp_path / "t.vdb").write_bytes((tmp_path / "i.vdb").read_bytes()[:100])
    with pytest.raises(noiselab.Error, match="not a readable OpenVDB file"):
        noiselab.read(tmp_path / "t.vdb")
