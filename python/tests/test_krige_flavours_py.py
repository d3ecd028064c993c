"""noiselab.Krige's block=, transform= and indicator= and noiselab.fit's
variogram= give the CLI's numbers (krige --block, --transform,
--indicator; fit --variogram).

Data: Meuse (zinc at 155 points, from R's sp package) when Rscript and sp
are installed, else 155 generated positive values over the same box.
Grids go through the CLI's EXR (float32): the Python doubles rounded to
float32 are the file's samples exactly (the same library calls on the same
doubles and the same cell centres).  Cross-validation tables are TSV of 10
significant digits and the summaries JSON of 10 digits: compared at a
relative 1e-9 (and 1e-15 absolute for probabilities printed near 0).  The
fit of a table reads the same file (or the same decimal strings) as the
CLI: its JSON's 10 digits, relative 1e-9."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import noiselab

LOGSPEC = "nugget:var=0.05 + spherical:var=0.59,scale=897"  # log(zinc), gstat's example
ISPEC = "nugget:var=0.03 + spherical:var=0.17,scale=900"     # an indicator's, any threshold
ISPECS = ["nugget:var=0.02 + spherical:var=0.1,scale=700", ISPEC, "nugget:var=0.04 + spherical:var=0.12,scale=1100"]
THR = (200.0, 400.0, 800.0)
EXTENT = ((178440.0, 181560.0), (329600.0, 333760.0))
EXT = "178440:181560,329600:333760"
SHAPE = (13, 10)  # (ny, nx): --grid 10x13


@pytest.fixture(scope="module")
def meuse(tmp_path_factory):
    """(points, zinc, path of the TSV of zinc, path of the TSV of log zinc)."""
    d = tmp_path_factory.mktemp("meuse")
    tsv, ltsv = d / "zinc.tsv", d / "logzinc.tsv"
    r = None
    if shutil.which("Rscript"):
        r = subprocess.run(["Rscript", "-e", 'suppressMessages(library(sp)); data(meuse); write.table(data.frame('
                            'x=meuse$x, y=meuse$y, value=meuse$zinc), "%s", sep="\\t", row.names=FALSE, '
                            'quote=FALSE)' % tsv], capture_output=True)
    if r is None or r.returncode != 0:
        rng = np.random.default_rng(155)
        p = np.column_stack([rng.uniform(178605, 181390, 155), rng.uniform(329714, 333611, 155)])
        v = np.exp(5.9 + 0.8 * np.sin(p[:, 0] / 700) * np.cos(p[:, 1] / 900) + rng.normal(0, 0.2, 155))
        tsv.write_text("x\ty\tvalue\n" + "".join("%.17g\t%.17g\t%.17g\n" % (a, b, c) for (a, b), c in zip(p, v)))
    t = np.loadtxt(tsv, skiprows=1)
    p, z = np.ascontiguousarray(t[:, :2]), np.ascontiguousarray(t[:, 2])
    ltsv.write_text("x\ty\tvalue\n" + "".join("%.17g\t%.17g\t%.17g\n" % (a, b, c)
                                               for (a, b), c in zip(p, np.log(z))))
    return p, z, str(tsv), str(ltsv)


def table(path):
    rows = [ln.split("\t") for ln in open(path).read().splitlines() if ln and not ln.startswith("#")]
    return {name: np.array([float(r[i]) for r in rows[1:]]) for i, name in enumerate(rows[0])}


def f32(a):
    return np.asarray(a, dtype=np.float32).astype(np.float64)


def grid_args():
    return ["--grid", "%dx%d" % SHAPE[::-1], "--extent", EXT]


@pytest.mark.parametrize("extra,kw", [
    (["--block", "40x40"], dict(block=(40, 40))),
    (["--block", "100x50", "--block-points", "5", "--nmax", "20"], dict(block=(100, 50), block_points=5, nmax=20)),
    (["--block", "40x40", "--mean", "6"], dict(block=(40, 40), mean=6)),
    (["--block", "60x60", "--drift", "linear", "--nmax", "40"], dict(block=(60, 60), drift="linear", nmax=40)),
])
def test_block_grid_is_the_cli_grid(cli, tmp_path, meuse, extra, kw):
    p, z, _, ltsv = meuse
    e, v = str(tmp_path / "e.exr"), str(tmp_path / "v.exr")
    j = json.loads(cli("krige", "--data", ltsv, "--acf", LOGSPEC, *grid_args(), "-o", e, "--variance", v, "--json",
                       *extra).stdout)
    k = noiselab.Krige(p, np.log(z), LOGSPEC, **kw)
    est, var = k.grid(EXTENT, SHAPE)
    assert np.array_equal(f32(est), noiselab.read(e)) and np.array_equal(f32(var), noiselab.read(v))
    assert k.kind == j["kind"] == "block" and k.terms == j["terms"]
    # predict at the cell centres: the grid's bits
    ny, nx = SHAPE
    X, Y = np.meshgrid(EXTENT[0][0] + (np.arange(nx) + 0.5) * 3120.0 / nx,
                       EXTENT[1][0] + (np.arange(ny) + 0.5) * 4160.0 / ny)
    pe, pv = k.predict(np.column_stack([X.ravel(), Y.ravel()]))
    assert np.array_equal(pe, est.ravel()) and np.array_equal(pv, var.ravel())


@pytest.mark.parametrize("extra,kw", [
    (["--transform", "log"], dict(transform="log")),
    (["--transform", "boxcox:0.25", "--nmax", "30"], dict(transform=("boxcox", 0.25), nmax=30)),
    (["--transform", "log", "--block", "50x50", "--radius", "2500"], dict(transform="log", block=(50, 50),
                                                                         radius=2500)),
])
def test_transform_grid_is_the_cli_grid(cli, tmp_path, meuse, extra, kw):
    p, z, tsv, _ = meuse
    spec = LOGSPEC if kw["transform"] == "log" else "nugget:var=0.3 + spherical:var=3.5,scale=900"
    e, v = str(tmp_path / "e.exr"), str(tmp_path / "v.exr")
    j = json.loads(cli("krige", "--data", tsv, "--acf", spec, *grid_args(), "-o", e, "--variance", v, "--json",
                       *extra).stdout)
    k = noiselab.Krige(p, z, spec, **kw)
    est, var = k.grid(EXT, SHAPE)
    assert np.array_equal(f32(est), noiselab.read(e)) and np.array_equal(f32(var), noiselab.read(v))
    assert k.kind == j["kind"] == "trans-gaussian"
    assert k.grid(EXT, SHAPE, variance=False).tobytes() == est.tobytes()


@pytest.mark.parametrize("extra,kw", [([], {}), (["--nmax", "25"], dict(nmax=25))])
def test_transform_cross_validation_is_the_cli(cli, tmp_path, meuse, extra, kw):
    p, z, tsv, _ = meuse
    out = str(tmp_path / "cv.tsv")
    j = json.loads(cli("krige", "--data", tsv, "--acf", LOGSPEC, "--transform", "log", "--cross-validate", "-o", out,
                       "--json", *extra).stdout)
    c = noiselab.Krige(p, z, LOGSPEC, transform="log", **kw).cross_validate()
    t = table(out)
    for col in ("observed", "predicted", "variance", "error", "zscore"):
        np.testing.assert_allclose(c[col], t[col], rtol=1e-9, err_msg=col)
    for key in ("mean_error", "var_error", "mean_zscore", "var_zscore", "rmse"):
        np.testing.assert_allclose(c[key], j[key], rtol=1e-9, err_msg=key)
    assert c["kind"] == j["kind"] and c["points"] == j["points"]


@pytest.mark.parametrize("extra,kw", [
    (["--acf", ISPEC], {}),
    ([a for s in ISPECS for a in ("--indicator-acf", s)] + ["--nmax", "30"], dict(nmax=30)),
    (["--acf", ISPEC, "--block", "80x80", "--drift", "linear", "--nmax", "40"], dict(block=(80, 80), drift="linear",
                                                                                   nmax=40)),
])
def test_indicator_grid_is_the_cli_grid(cli, tmp_path, meuse, extra, kw):
    p, z, tsv, _ = meuse
    out = tmp_path / "i.exr"
    j = json.loads(cli("krige", "--data", tsv, "--indicator", ",".join("%g" % t for t in THR), *grid_args(), "-o",
                       out, "--json", *extra).stdout)
    acf = ISPEC if "--acf" in extra else ISPECS
    k = noiselab.Krige(p, z, acf, indicator=THR, **kw)
    P, nc = k.grid(EXTENT, SHAPE)
    assert P.shape == (3,) + SHAPE and nc == j["corrected"] and k.kind == j["kind"]
    for q in range(3):
        assert np.array_equal(f32(P[q]), noiselab.read(str(tmp_path / ("i.%d.exr" % (q + 1))))), q
    assert (np.diff(P, axis=0) >= 0).all() and (P >= 0).all() and (P <= 1).all()


@pytest.mark.parametrize("extra,kw", [(["--nmax", "40"], dict(nmax=40)), (["--nmax", "12"], dict(nmax=12))])
def test_indicator_cross_validation_is_the_cli(cli, tmp_path, meuse, extra, kw):
    p, z, tsv, _ = meuse
    out = str(tmp_path / "cv.tsv")
    # nmax: leave-one-out of every datum with the other 154 costs 3 x 155 solves of 154 (a second)
    j = json.loads(cli("krige", "--data", tsv, "--acf", ISPEC, "--indicator", "200,400,800", "--cross-validate",
                       "-o", out, "--json", *extra).stdout)
    c = noiselab.Krige(p, z, ISPEC, indicator=THR, **kw).cross_validate()
    t = table(out)
    for q in range(3):
        np.testing.assert_allclose(c["probabilities"][:, q], t["p%d" % (q + 1)], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(c["brier"], j["brier"], rtol=1e-9)
    assert c["corrected"] == j["corrected"] and list(c["thresholds"]) == j["thresholds"]


def test_holes_are_nan(meuse):
    """With a radius, locations with no datum within it are NaN (the CLI
    refuses the grid); the others are what they are alone."""
    p, z, _, _ = meuse
    for kw in (dict(block=(40, 40)), dict(transform="log"), dict(indicator=THR)):
        k = noiselab.Krige(p, z if "block" not in kw else np.log(z), ISPEC if "indicator" in kw else LOGSPEC,
                           radius=250, **kw)
        x = np.array([[178500.0, 333700.0], [179500.0, 331000.0], [181000.0, 333000.0], [180000.0, 332000.0]])
        r = k.predict(x)
        a = r[0] if r[0].ndim == 1 else r[0][:, 0]
        hole = np.isnan(a)
        assert 0 < hole.sum() < len(x), kw
        for i in np.flatnonzero(~hole):
            alone = k.predict(x[i:i + 1])
            assert np.array_equal(alone[0], r[0][i:i + 1]), kw


@pytest.mark.parametrize("weights", [None, "ols", 1])
def test_fit_of_a_table_is_the_cli(cli, tmp_path, meuse, weights):
    p, z, _, ltsv = meuse
    vg = str(tmp_path / "vg.tsv")
    cli("variogram", ltsv, "-o", vg)
    w = [] if weights is None else ["--weights", {"ols": "ols", 1: "1"}[weights]]
    j = json.loads(cli("fit", "--variogram", vg, "--model", "spherical", "--nugget", "--json", *w).stdout)
    kw = dict(model="spherical", nugget=True, weights=weights)
    a = noiselab.fit(variogram=vg, **kw)
    t = table(vg)
    b = noiselab.fit(variogram=(t["distance"], t["gamma"], t["pairs"]), **kw)
    for r in (a, b):
        assert r["spec"] == j["model"] and r["n"] == j["n"]
        for name, value in j["parameters"].items():
            np.testing.assert_allclose(r["parameters"][name], value, rtol=1e-9, err_msg=name)
        np.testing.assert_allclose(r["objective"], j["objective"], rtol=1e-9)


@pytest.mark.parametrize("kw,name,shown", [
    (dict(block=(40,)), "block", "(40,)"),
    (dict(block=(40, -1)), "block", "-1"),
    (dict(block=(40, float("inf"))), "block", "inf"),
    (dict(block="40x40"), "block", "'40x40'"),
    (dict(block=(40, 40), block_points=1), "block_points", "1"),
    (dict(block=(40, 40), block_points=65), "block_points", "65"),
    (dict(block_points=4), "block_points", "4"),
    (dict(transform="sqrt"), "transform", "'sqrt'"),
    (dict(transform=("boxcox", 6)), "transform", "('boxcox', 6)"),
    (dict(transform="boxcox:x"), "transform", "'boxcox:x'"),
    (dict(transform="log", mean=6), "transform", "mean=6"),
    (dict(transform="log", drift="linear"), "transform", "drift='linear'"),
    (dict(transform="log", indicator=THR), "transform", "transform='log'"),
    (dict(indicator=(400, 200)), "indicator", "(400, 200)"),
    (dict(indicator=[]), "indicator", "[]"),
    (dict(indicator=(200, float("nan"))), "indicator", "nan"),
    (dict(indicator="200,400"), "indicator", "'200,400'"),
    (dict(indicator=THR, mean=0.5), "mean", "mean=0.5"),
    (dict(indicator=THR, acf=[ISPEC, ISPEC]), "acf", "got 2 specs"),
    (dict(block=(40, 40), strict=True), "strict", "strict=True"),
])
def test_bad_arguments(meuse, kw, name, shown):
    """Refused before any kriging, with the argument's name and value."""
    p, z, _, _ = meuse
    acf = kw.pop("acf", LOGSPEC)
    with pytest.raises(ValueError) as e:
        noiselab.Krige(p, z, acf, **kw)
    assert str(e.value).startswith(name + ":") and shown in str(e.value), str(e.value)


PTS1 = [[0.0, 0.0], [1.0, 1.0]]


def test_bad_calls(cli, tmp_path, meuse):
    p, z, tsv, _ = meuse
    with pytest.raises(ValueError, match="^block: .*cross_validate"):
        noiselab.Krige(p, z, LOGSPEC, block=(40, 40)).cross_validate()
    r = cli("krige", "--data", tsv, "--acf", LOGSPEC, "--block", "40x40", "--cross-validate", check=False)
    assert r.returncode == 2 and "--block" in r.stderr
    with pytest.raises(ValueError, match=r"^values: .*point 2 is -1"):
        noiselab.Krige(p[:3], [1.0, -1.0, 2.0], LOGSPEC, transform="log")
    k = noiselab.Krige(p, z, ISPEC, indicator=THR)
    with pytest.raises(ValueError, match="^variance: .*True"):
        k.predict(p[:2], variance=True)
    with pytest.raises(ValueError, match="^krige: conditional simulation"):
        k.simulator("fft", (8, 8), EXT)
    for kw, name in ((dict(variogram=([1, 2], [0.1, 0.2], [3, 4]), method="ml"), "method"),
                     (dict(variogram=([1, -2], [0.1, 0.2], [3, 4])), "variogram: distance of bin 2 is -2"),
                     (dict(variogram=([1, 2], [0.1, 0.2], [3, 4.5])), "variogram: pairs of bin 2 is 4.5"),
                     (dict(variogram=([1, 2], [0.1, 0.2])), "variogram: expected"),
                     (dict(variogram=([1, 2], [0.1, 0.2], [3, 4]), cutoff=5), "variogram: .*got cutoff"),
                     (dict(variogram=([1, 2], [0.1, 0.2], [3, 4]), points=PTS1), "variogram: .*got points"),
                     (dict(variogram=str(tmp_path / "none.tsv")), ".*none.tsv")):
        with pytest.raises(ValueError, match="^" + name):
            noiselab.fit(model="spherical", **kw)


def test_one_dimension_is_the_cli(cli, tmp_path):
    """1D: block=W (one edge), the CLI's TSV of cell centres and values
    (10 digits); the indicator's table of columns x, p1 .. pK."""
    rng = np.random.default_rng(2)
    x = np.sort(rng.uniform(0, 100, 40))
    v = np.exp(np.sin(x / 15) + rng.normal(0, 0.3, 40))
    tsv = tmp_path / "d1.tsv"
    tsv.write_text("x\tvalue\n" + "".join("%.17g\t%.17g\n" % (a, c) for a, c in zip(x, v)))
    b, i = str(tmp_path / "b.tsv"), str(tmp_path / "i.tsv")
    cli("krige", "--data", tsv, "--acf", "spherical:scale=30", "--block", "5", "--block-points", "3", "--grid", "6",
        "--extent", "0:100", "-o", b)
    r = cli("krige", "--data", tsv, "--acf", "spherical:scale=30", "--indicator", "0.7,1.5", "--grid", "6",
            "--extent", "0:100", "-o", i)
    est = noiselab.Krige(x, v, "spherical:scale=30", block=5, block_points=3).grid((0, 100), 6, variance=False)
    np.testing.assert_allclose(est, table(b)["value"], rtol=1e-9)
    P, nc = noiselab.Krige(x, v, "spherical:scale=30", indicator=(0.7, 1.5)).grid("0:100", 6)
    t = table(i)
    np.testing.assert_allclose(P, [t["p1"], t["p2"]], rtol=1e-9, atol=1e-15)
    assert "corrected at %d of 6 cells" % nc in r.stderr
