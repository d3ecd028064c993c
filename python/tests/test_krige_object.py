"""noiselab.Krige, CondSim, condsim and sample give the CLI's numbers.

Data: Meuse (log zinc at 155 points, from R's sp package) when Rscript and
sp are installed, else 155 generated points over the same box.  Grids go
through the CLI's EXR (float32): the Python estimates rounded to float32
are the file's samples exactly (the same library calls on the same doubles:
any difference in the double is at worst a float32 rounding flip, which the
exact comparison would catch, and does not occur).  Cross-validation
tables are TSV of 10 significant digits and the summaries JSON of 10
digits: compared at a relative 1e-9.  Conditional realizations go through
.h5 files of doubles: compared bit for bit."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import noiselab

SPEC = "nugget:var=0.05 + spherical:var=0.59,scale=897"
EXTENT = ((178440.0, 181560.0), (329600.0, 333760.0))
EXT = "178440:181560,329600:333760"
SHAPE = (26, 20)  # (ny, nx): --grid 20x26


@pytest.fixture(scope="module")
def meuse(tmp_path_factory):
    """(points, values, path of the TSV)."""
    d = tmp_path_factory.mktemp("meuse")
    tsv = d / "meuse.tsv"
    r = None
    if shutil.which("Rscript"):
        r = subprocess.run(["Rscript", "-e", 'suppressMessages(library(sp)); data(meuse); write.table(data.frame('
                            'x=meuse$x, y=meuse$y, value=log(meuse$zinc)), "%s", sep="\\t", row.names=FALSE, '
                            'quote=FALSE)' % tsv], capture_output=True)
    if r is None or r.returncode != 0:
        rng = np.random.default_rng(155)
        p = np.column_stack([rng.uniform(178605, 181390, 155), rng.uniform(329714, 333611, 155)])
        v = 5.9 + 0.8 * np.sin(p[:, 0] / 700) * np.cos(p[:, 1] / 900) + rng.normal(0, 0.2, 155)
        tsv.write_text("x\ty\tvalue\n" + "".join("%.17g\t%.17g\t%.17g\n" % (a, b, c) for (a, b), c in zip(p, v)))
    t = np.loadtxt(tsv, skiprows=1)
    return np.ascontiguousarray(t[:, :2]), np.ascontiguousarray(t[:, 2]), str(tsv)


def table(path):
    """A TSV of the CLI: '#' lines, a header, rows; columns by name."""
    rows = [ln.split("\t") for ln in open(path).read().splitlines() if ln and not ln.startswith("#")]
    return {name: np.array([float(r[i]) for r in rows[1:]]) for i, name in enumerate(rows[0])}


def f32(a):
    return np.asarray(a, dtype=np.float32).astype(np.float64)


def cli_grid(cli, tmp_path, tsv, *extra):
    e, v = str(tmp_path / "e.exr"), str(tmp_path / "v.exr")
    r = cli("krige", "--data", tsv, "--acf", SPEC, "--grid", "%dx%d" % SHAPE[::-1], "--extent", EXT, "-o", e,
            "--variance", v, "--json", *extra)
    return noiselab.read(e), noiselab.read(v), json.loads(r.stdout)


@pytest.mark.parametrize("extra,kw", [
    ([], {}),
    (["--mean", "6"], dict(mean=6)),
    (["--nmax", "20"], dict(nmax=20)),
    (["--nmax", "30", "--radius", "2000"], dict(nmax=30, radius=2000)),
    (["--drift", "linear", "--nmax", "40"], dict(drift="linear", nmax=40)),
    (["--drift", "quadratic"], dict(drift="quadratic")),
    (["--mean", "6", "--nmax", "10"], dict(mean=6, nmax=10)),
])
def test_grid_is_the_cli_grid(cli, tmp_path, meuse, extra, kw):
    p, v, tsv = meuse
    E, V, j = cli_grid(cli, tmp_path, tsv, *extra)
    k = noiselab.Krige(p, v, SPEC, **kw)
    e, var = k.grid(EXTENT, SHAPE)
    assert e.shape == SHAPE and var.shape == SHAPE
    assert np.array_equal(f32(e), E) and np.array_equal(f32(var), V)
    assert k.grid(EXT, SHAPE, variance=False).tobytes() == e.tobytes()
    if not k.local:  # the global plan's figures are the CLI's report
        np.testing.assert_allclose([k.mean, k.rcond], [j["mean"], j["rcond"]], rtol=1e-9)
        assert k.pseudo_inverse is False and k.kind == j["kind"]
    else:
        assert k.terms == j["terms"] and k.kind == j["kind"]


@pytest.mark.parametrize("kw", [{}, dict(nmax=12), dict(drift="linear", radius=900)])
def test_points_are_the_grid_cells(meuse, kw):
    """predict at the cell centres gives the grid's bits; at more points
    than one thread takes (blocks of 256 on threads), the bits of one
    block at a time."""
    p, v, _ = meuse
    k = noiselab.Krige(p, v, SPEC, **kw)
    e, var = k.grid(EXTENT, SHAPE)
    ny, nx = SHAPE
    hx, hy = (EXTENT[0][1] - EXTENT[0][0]) / nx, (EXTENT[1][1] - EXTENT[1][0]) / ny
    X, Y = np.meshgrid(EXTENT[0][0] + (np.arange(nx) + 0.5) * hx, EXTENT[1][0] + (np.arange(ny) + 0.5) * hy)
    x = np.column_stack([X.ravel(), Y.ravel()])
    pe, pv = k.predict(x)
    ok = ~np.isnan(e.ravel())
    assert ok.sum() > ok.size // 2
    assert np.array_equal(pe[ok], e.ravel()[ok]) and np.array_equal(pv[ok], var.ravel()[ok])
    if not kw:
        many = np.tile(x, (10, 1))[:5000] + 0.125
        one, onev = k.predict(many)
        for a in range(0, 5000, 256):  # below the threaded size: one call, one block
            sl = slice(a, min(a + 256, 5000))
            assert np.array_equal(k.predict(many[sl], variance=False), one[sl])
            assert np.array_equal(k.predict(many[sl])[1], onev[sl])


def test_empty_neighbourhoods_are_nan(cli, tmp_path, meuse):
    """With a radius, cells with no datum within it are NaN (as the CLI
    writes them, counting them), the others the estimates at those points."""
    p, v, tsv = meuse
    r = 250.0
    k = noiselab.Krige(p, v, SPEC, radius=r)
    e, var = k.grid(EXTENT, SHAPE)
    ny, nx = SHAPE
    hx, hy = (EXTENT[0][1] - EXTENT[0][0]) / nx, (EXTENT[1][1] - EXTENT[1][0]) / ny
    X, Y = np.meshgrid(EXTENT[0][0] + (np.arange(nx) + 0.5) * hx, EXTENT[1][0] + (np.arange(ny) + 0.5) * hy)
    x = np.column_stack([X.ravel(), Y.ravel()])
    d = np.sqrt(((x[:, None, :] - p[None, :, :]) ** 2).sum(-1)).min(1)
    far = d > r * (1 + 1e-9)
    assert far.any() and (~far).any()
    assert np.array_equal(np.isnan(e.ravel()), far) and np.array_equal(np.isnan(var.ravel()), far)
    pe, pv = k.predict(x)
    assert np.array_equal(np.isnan(pe), far)
    assert np.array_equal(pe[~far], e.ravel()[~far]) and np.array_equal(pv[~far], var.ravel()[~far])
    run = cli("krige", "--data", tsv, "--acf", SPEC, "--grid", "20x26", "--extent", EXT, "--radius", str(r),
              "-o", str(tmp_path / "x.exr"), "--json", check=False)
    assert run.returncode == 0 and json.loads(run.stdout)["missing"] == int(far.sum()), run.stderr
    # a drift needs 3 data: cells with 1 or 2 within the radius are NaN too
    kd = noiselab.Krige(p, v, SPEC, radius=r, drift="linear")
    within = (np.sqrt(((x[:, None, :] - p[None, :, :]) ** 2).sum(-1)) <= r).sum(1)
    assert np.array_equal(np.isnan(kd.predict(x, variance=False)), within < 3)


@pytest.mark.parametrize("extra,kw", [([], {}), (["--nmax", "15"], dict(nmax=15)),
                                      (["--mean", "6", "--radius", "1000"], dict(mean=6, radius=1000)),
                                      (["--drift", "linear", "--nmax", "25"], dict(drift="linear", nmax=25))])
def test_cross_validation_is_the_cli(cli, tmp_path, meuse, extra, kw):
    p, v, tsv = meuse
    out = tmp_path / "cv.tsv"
    j = json.loads(cli("krige", "--data", tsv, "--acf", SPEC, "--cross-validate", "-o", str(out), "--json",
                       *extra).stdout)
    t = table(out)
    cv = noiselab.Krige(p, v, SPEC, **kw).cross_validate()
    for c in ("observed", "predicted", "variance", "error", "zscore"):
        np.testing.assert_allclose(cv[c], t[c], rtol=1e-9, atol=1e-12, err_msg=c)
    for c in ("mean_error", "var_error", "mean_zscore", "var_zscore", "rmse"):
        np.testing.assert_allclose(cv[c], j[c], rtol=1e-9, atol=1e-12, err_msg=c)
    assert cv["points"] == j["points"] and cv["kind"] == j["kind"]


def test_cross_validation_holes(meuse):
    """A datum with no other within the radius: NaN, the summary over the
    rest (the same as from the data that have a neighbour, for the errors)."""
    p, v, _ = meuse
    d = np.sqrt(((p[:, None, :] - p[None, :, :]) ** 2).sum(-1))
    np.fill_diagonal(d, np.inf)
    r = float(np.sort(d.min(1))[-3]) * 0.999  # the 3 most isolated data have none
    cv = noiselab.Krige(p, v, SPEC, radius=r).cross_validate()
    alone = d.min(1) > r
    assert alone.sum() == 3
    assert np.array_equal(np.isnan(cv["predicted"]), alone)
    e = cv["error"][~alone]
    np.testing.assert_allclose(cv["rmse"], np.sqrt(np.mean(e * e)), rtol=1e-12)
    np.testing.assert_allclose(cv["mean_error"], e.mean(), rtol=1e-12)


@pytest.mark.parametrize("method,extra,kw", [
    ("circulant", [], {}),
    ("fft", ["--nmax", "12"], dict(nmax=12)),
    ("subdiv", ["--mean", "6"], dict(mean=6)),
])
def test_condsim_is_the_cli(cli, tmp_path, meuse, method, extra, kw):
    """Two realizations, seeds 7 and 8, bit for bit the CLI's .h5 doubles."""
    p, v, tsv = meuse
    out = tmp_path / "c.h5"
    # subdivision: one spacing on both axes, no nugget
    shape, ext, spec = (SHAPE, EXT, SPEC) if method != "subdiv" else \
        ((32, 32), "177900:182060,329600:333760", "markov:var=0.6,scale=500")
    r = cli("synth", method, "--acf", spec, "--size", "%dx%d" % shape[::-1], "--condition", tsv, "--extent", ext,
            "--seed", "7",
            "--realizations", "2", "-o", str(out), "--precision", "double", *extra, check=False)
    if r.returncode != 0 and "HDF5" in r.stderr + r.stdout:
        pytest.skip("no HDF5 support")
    assert r.returncode == 0, r.stderr
    fields = noiselab.condsim(p, v, spec, method, shape, ext, seed=7, realizations=2, **kw)
    assert fields.shape == (2,) + shape
    for k in range(2):
        assert np.array_equal(fields[k], noiselab.read(tmp_path / ("c-%d.h5" % (k + 1))))
    sim = noiselab.Krige(p, v, spec, **kw).simulator(method, shape, ext)
    assert np.array_equal(sim(8), fields[1])
    assert sim.info["n"] == 155 and sim.info["sites"] + sim.info["on_samples"] == 155


def test_condsim_at_points(meuse):
    """Points on cell centres take the realization's value there; others
    are drawn with it (honouring a datum they sit on)."""
    p, v, _ = meuse
    ny, nx = SHAPE
    hx, hy = (EXTENT[0][1] - EXTENT[0][0]) / nx, (EXTENT[1][1] - EXTENT[1][0]) / ny
    cells = [(3, 4), (10, 7), (19, 25)]
    at = np.array([[EXTENT[0][0] + (i + 0.5) * hx, EXTENT[1][0] + (j + 0.5) * hy] for i, j in cells])
    at = np.vstack([at, p[5] + [1.0, 0.0]])
    k = noiselab.Krige(p, v, SPEC)
    f, z = k.simulate("circulant", SHAPE, EXTENT, seed=3, realizations=2, at=at)
    assert f.shape == (2,) + SHAPE and z.shape == (2, 4)
    for r in range(2):
        np.testing.assert_allclose(z[r, :3], [f[r, j, i] for i, j in cells], rtol=0, atol=1e-9)
    # 1 m from a datum, with a spherical range of 897 m: close to it
    assert np.all(np.abs(z[:, 3] - v[5]) < 0.5)
    assert not np.array_equal(z[0], z[1])


def test_sample_is_the_cli(cli, tmp_path, meuse):
    p, v, _ = meuse
    f = noiselab.synth("circulant", acf="markov:scale=2", size=(24, 32), seed=4, spacing=0.5)
    path = tmp_path / "f.h5"
    noiselab.write(path, f, precision="double", spacing=(0.5, 0.5))
    pts = np.array([[0.3, 0.2], [15.5, 11.5], [7.123, 3.9], [0.0, 11.5]])
    (tmp_path / "p.tsv").write_text("x\ty\n" + "".join("%r\t%r\n" % tuple(q) for q in pts))
    for interp in ("bilinear", "nearest"):
        out = tmp_path / ("s-%s.tsv" % interp)
        cli("sample", str(path), "--points", str(tmp_path / "p.tsv"), "--interpolation", interp, "-o", str(out))
        t = table(out)
        np.testing.assert_allclose(noiselab.sample(f, pts, spacing=0.5, interpolation=interp), t["value"],
                                   rtol=1e-9, atol=1e-12)
    out = tmp_path / "r.tsv"
    cli("sample", str(path), "--random", "5", "--seed", "9", "-o", str(out))
    t = table(out)
    q, s = noiselab.sample(f, random=5, seed=9, spacing=0.5)
    np.testing.assert_allclose(q, np.column_stack([t["x"], t["y"]]), rtol=1e-9)
    np.testing.assert_allclose(s, t["value"], rtol=1e-8, atol=1e-9)  # the CLI's points rounded to 10 digits
    # a conditional realization on an extent: the cell centres, as the CLI reads its record
    c = tmp_path / "c.h5"
    cli("synth", "circulant", "--acf", SPEC, "--size", "20x26", "--condition", meuse[2], "--extent", EXT,
        "--seed", "2", "-o", str(c), "--precision", "double")
    (tmp_path / "m.tsv").write_text("x\ty\n" + "".join("%r\t%r\n" % tuple(q) for q in p[:20]))
    cli("sample", str(c), "--points", str(tmp_path / "m.tsv"), "-o", str(out))
    t = table(out)
    np.testing.assert_allclose(noiselab.sample(noiselab.read(c), p[:20], extent=EXTENT), t["value"], rtol=1e-9)


P2 = np.array([[0.0, 0.0], [3.0, 1.0], [1.0, 4.0], [5.0, 5.0], [2.5, 2.0]])
V2 = np.array([1.0, 2.0, 0.5, 1.5, -0.25])


@pytest.mark.parametrize("call,name", [
    (lambda: noiselab.Krige(P2, V2, "markov", nmax=0), "nmax"),
    (lambda: noiselab.Krige(P2, V2, "markov", nmax=2.5), "nmax"),
    (lambda: noiselab.Krige(P2, V2, "markov", radius=-1), "radius"),
    (lambda: noiselab.Krige(P2, V2, "markov", drift="cubic"), "drift"),
    (lambda: noiselab.Krige(P2, V2, "markov", drift="linear", mean=1), "mean"),
    (lambda: noiselab.Krige(P2, V2, "markov", nmax=3, strict=True), "strict"),
    (lambda: noiselab.Krige(P2, V2, "markov", mean="x"), "mean"),
    (lambda: noiselab.Krige(P2, V2[:4], "markov"), "values"),
    (lambda: noiselab.Krige(P2, V2, "nosuchmodel"), "nosuchmodel"),
    (lambda: noiselab.Krige(P2, V2, "markov").grid("0:1", (2, 2)), "extent"),
    (lambda: noiselab.Krige(P2, V2, "markov").grid(((1, 0), (0, 1)), (2, 2)), "extent"),
    (lambda: noiselab.Krige(P2, V2, "markov").grid(((0, 1), (0, 1)), (2, 0)), "shape"),
    (lambda: noiselab.Krige(P2, V2, "markov").grid(((0, 1), (0, 1)), 4), "shape"),
    (lambda: noiselab.Krige(P2, V2, "markov").grid(((0, 1, 2), (0, 1)), (2, 2)), "extent"),
    (lambda: noiselab.Krige(P2, V2, "markov").grid(((0, 1), (0, 1)), (1 << 40, 1 << 40)), "shape"),
    (lambda: noiselab.CondSim("x", "fft", (8, 8), "0:6,0:6"), "krige"),
    (lambda: noiselab.Krige(P2, V2, "markov").simulate("fft", (8, 8), "0:6,0:6", at=[[1, 2, 3]]), "at"),
    (lambda: noiselab.Krige(P2, V2, "markov").predict(np.zeros((2, 3))), "points"),
    (lambda: noiselab.Krige(P2, V2, "markov").predict(P2, variance="yes"), "variance"),
    (lambda: noiselab.Krige(P2, V2, "markov", radius=2).simulate("fft", (8, 8), "0:6,0:6"), "radius"),
    (lambda: noiselab.Krige(P2, V2, "markov").simulate("cholesky", (8, 8), "0:6,0:6"), "method"),
    (lambda: noiselab.Krige(P2, V2, "markov").simulate("fft", (8, 8), "0:6,0:6", seed=-1), "seed"),
    (lambda: noiselab.Krige(P2, V2, "markov").simulate("fft", (8, 8), "0:6,0:6", realizations=0), "realizations"),
    (lambda: noiselab.Krige(P2, V2, "markov").simulate("fft", (8, 8), "0:6,0:6", hood=17), "hood"),
    (lambda: noiselab.Krige(P2, V2, "markov").simulate("fft", (8, 8), "0:4,0:4"), "datum 4"),
    (lambda: noiselab.sample(np.zeros((4, 4)), P2, interpolation="cubic"), "interpolation"),
    (lambda: noiselab.sample(np.zeros((4, 4)), P2, random=3), "random"),
    (lambda: noiselab.sample(np.zeros((4, 4)), [[9.0, 0.0]]), "outside"),
])
def test_bad_arguments_name_themselves(call, name):
    with pytest.raises(ValueError, match=name):
        call()
