"""The analysis verbs give the CLI's numbers.

The CLI prints JSON with 10 significant digits (JSON_REAL_PRECISION(10)), so
the Python results are compared at a relative 1e-9 (plus 1e-12 absolute for
values that are zero to rounding); fields go through the CLI's EXR, so the
Python side reads the same float32 samples back with noiselab.read."""
import json

import numpy as np
import pytest

import noiselab


@pytest.fixture(scope="module")
def field(tmp_path_factory, cli):
    p = str(tmp_path_factory.mktemp("an") / "f.exr")
    cli("synth", "fft", "--acf", "markov:scale=4", "--size", "64x48", "--seed", "5", "-o", p)
    return p, noiselab.read(p)


def js(cli, *args):
    return json.loads(cli(*args, "--json").stdout)


def close(a, b):
    b = np.array([np.nan if v is None else v for v in b], dtype=float)
    np.testing.assert_allclose(np.asarray(a, dtype=float), b, rtol=1e-9, atol=1e-12)


def test_acf(cli, field):
    path, f = field
    for extra, kw in (([], {}), (["--axis", "y", "--unbiased"], dict(axis="y", unbiased=True)),
                      (["--radial"], dict(radial=True)), (["--mean", "0.25"], dict(mean=0.25))):
        j = js(cli, "acf", path, "--max-lag", "6", "--target", "markov:scale=4", *extra)
        lag, r, t = noiselab.acf(f, max_lag=6, target="markov:scale=4", **kw)
        close(lag, j["lag"]), close(r, j["acf"]), close(t, j["target"])


def test_acf_grid(cli, field, tmp_path):
    path, f = field
    out = str(tmp_path / "c.exr")
    cli("acf", path, "-o", out)
    np.testing.assert_array_equal(noiselab.read(out), noiselab.acf(f, grid="centred").astype(np.float32))
    w = noiselab.acf(f, grid="wrapped")
    assert w.shape == (96, 128) and w[0, 0] == noiselab.acf(f, max_lag=0)[1][0]


def test_psd(cli, field):
    path, f = field
    for extra, kw in (([], {}), (["--welch", "16"], dict(welch=16)), (["--mean", "0"], dict(mean=0.0))):
        j = js(cli, "psd", path, *extra)
        fr, p = noiselab.psd(f, **kw)
        close(fr, j["freq"]), close(p, j["psd"])
    g = noiselab.read(path)[0]  # 1D: f = 0 .. Nyquist
    fr, p = noiselab.psd(g)
    assert fr.shape == (33,) and fr[-1] == 0.5


def test_hist(cli, field):
    path, f = field
    j = js(cli, "hist", path, "--bins", "7")
    edges, counts, mo = noiselab.hist(f, bins=7)
    close(edges, j["edges"]), close(counts, j["counts"])
    for k in ("mean", "variance", "skewness", "kurtosis", "min", "max"):
        close([mo[k]], [j[k]])


def test_hist_against(cli, field):
    """The bootstrap test of hist --against: the same numbers as the CLI's."""
    path, f = field
    j = js(cli, "hist", path, "--bins", "7", "--against", "laplace", "--draws", "19", "--draw-seed", "3")
    b = j["against"]["bootstrap"]
    t = noiselab.hist(f, bins=7, against="laplace", draws=19, draw_seed=3)[3]
    close([t["p"]], [b["verdict_p"]])
    assert t["p_from"] == b["verdict_from"] and t["draws"] == 19
    assert sorted(t["tests"]) == sorted(b["tests"])
    for k, v in t["tests"].items():
        close([v["statistic"], v["p"], v["p_rank"], v["null_sd"]],
              [b["tests"][k]["statistic"], b["tests"][k]["p"], b["tests"][k]["p_rank"], b["tests"][k]["null_sd"]])
    close(t["detectable"]["variance_ratio"], b["detectable"]["variance_ratio"])
    with pytest.raises(noiselab.Error):
        noiselab.hist(f, against="expr:x^2")
    with pytest.raises(noiselab.Error):
        noiselab.hist(f, against="gauss", draws=1)


@pytest.mark.heavy
def test_check(cli):
    j = js(cli, "check", "--acf", "oscillatory:scale=4,omega=2", "--dim", "2")
    c = noiselab.check(acf="oscillatory:scale=4,omega=2", dim=2)
    # R decays over 4 units but oscillates within 0.5: judged on the tapered spectrum
    assert c["positive_definite"] is False and c["why"] == j["why"] == "negative-tapered-spectrum"
    for k in ("variance", "min_spectrum", "min_spectrum_k", "min_eigenvalue", "min_r", "spectral_decay"):
        close([c[k]], [j[k]])
    assert c["neighbours"].split("\n")[0] in j["neighbours"] or j["neighbours"][0] in c["neighbours"]
    assert noiselab.check(acf="gauss:scale=3", dim=3)["positive_definite"] is True


def test_coeffs(cli):
    j = js(cli, "coeffs", "--acf", "gauss:scale=2", "--dim", "2", "--levels", "3")
    c = noiselab.coeffs("gauss:scale=2", dim=2, levels=3)
    assert len(c) == 3
    for lv, jl in zip(c, j["levels"]):
        assert lv["N"] == jl["N"]
        close([lv["spacing"]], [jl["spacing"]])
        for cl, jc in zip(lv["classes"], jl["classes"]):
            assert cl["cls"] == jc["class"]
            close(cl["coefficients"], jc["coefficients"])
            close([cl["variance"], cl["condition"]], [jc["variance"], jc["condition"]])


def test_nonlin(cli):
    j = js(cli, "nonlin", "--acf", "markov:scale=4", "--g", "uniform", "--size", "64", "--spacing", "0.5")
    r = noiselab.nonlin("markov:scale=4", "uniform", size=64, spacing=0.5)
    for k in ("lag", "input_acf", "output_acf", "freq", "input_psd", "output_psd", "hermite_coefficients"):
        close(r[k], j[k])
    close([r["output_variance"], r["truncation"]], [j["output_variance"], j["truncation"]])


def test_shape(cli, field, tmp_path):
    path, f = field
    for extra, kw in (([], {}), (["--empirical"], dict(empirical=True))):
        out = str(tmp_path / "s.exr")
        cli("shape", "--to", "uniform", path, "-o", out, *extra)
        before = f.copy()
        g = noiselab.shape(f, "uniform", **kw)
        assert np.array_equal(f, before)  # the input is not changed
        np.testing.assert_array_equal(noiselab.read(out), g.astype(np.float32))


def test_krige(cli, tmp_path):
    pts = np.array([[0, 0], [3, 1], [1, 4], [5, 5], [2.5, 2.0]])
    val = np.array([1.0, 2.0, 0.5, 1.5, -0.25])
    tsv = tmp_path / "pts.tsv"
    tsv.write_text("x\ty\tvalue\n" + "".join("%r\t%r\t%r\n" % (x, y, v) for (x, y), v in zip(pts, val)))
    for extra, kw in (([], {}), (["--mean", "0.5"], dict(mean=0.5))):
        est, var = str(tmp_path / "k.exr"), str(tmp_path / "v.exr")
        cli("krige", "--data", str(tsv), "--acf", "markov:scale=3", "--grid", "4x3", "--extent", "0:6,0:6",
            "-o", est, "--variance", var, *extra)
        xs, ys = (np.arange(4) + 0.5) * 6 / 4, (np.arange(3) + 0.5) * 6 / 3
        X, Y = np.meshgrid(xs, ys)
        e, v = noiselab.krige(pts, val, "markov:scale=3", np.column_stack([X.ravel(), Y.ravel()]), variance=True,
                              **kw)
        # float32 files; the grid path and the block path agree to rounding
        np.testing.assert_allclose(noiselab.read(est), e.reshape(3, 4), rtol=1e-6, atol=1e-7)
        np.testing.assert_allclose(noiselab.read(var), v.reshape(3, 4), rtol=1e-6, atol=1e-7)
    # the data are honoured exactly (ordinary kriging interpolates)
    np.testing.assert_allclose(noiselab.krige(pts, val, "markov:scale=3", pts), val, atol=1e-9)


def test_variogram_and_fit(cli, field):
    path, f = field
    j = js(cli, "variogram", path)
    d, g, n = noiselab.variogram(field=f)
    close(d, j["distance"]), close(g, j["gamma"]), close(n, j["pairs"])
    j = js(cli, "fit", path, "--model", "markov")
    r = noiselab.fit(field=f, model="markov")
    assert r["spec"] == j["model"]
    close([r["parameters"]["var"], r["parameters"]["scale"], r["aic"]],
          [j["parameters"]["var"], j["parameters"]["scale"], j["aic"]])
    # points in, the same: the field's samples at index * spacing, x first
    ys, xs = np.indices(f.shape)
    d2, g2, n2 = noiselab.variogram(np.column_stack([xs.ravel(), ys.ravel()]), f.ravel())
    np.testing.assert_allclose(d, d2, rtol=1e-12), np.testing.assert_allclose(g, g2, rtol=1e-12)


def test_models(cli):
    names = [m["name"] for m in noiselab.models()]
    out = cli("models").stdout
    assert "markov" in names and "matern" in names
    for n in names:
        assert n in out


@pytest.mark.heavy
def test_fit_ml_points(cli, tmp_path):
    f = noiselab.synth("fft", acf="markov:scale=6", size=(64, 64), seed=11)
    rng = np.random.default_rng(3)
    idx = rng.choice(f.size, 80, replace=False)
    pts = np.column_stack([idx % 64, idx // 64]).astype(float)
    val = f.ravel()[idx]
    tsv = tmp_path / "pts.tsv"
    tsv.write_text("x\ty\tvalue\n" + "".join("%r\t%r\t%r\n" % (x, y, v) for (x, y), v in zip(pts, val)))
    for method in ("wls", "ml"):
        j = js(cli, "fit", str(tsv), "--model", "markov", "--nugget", "--method", method)
        r = noiselab.fit(pts, val, model="markov", nugget=True, method=method)
        assert r["spec"] == j["model"]
        for k in j["parameters"]:
            close([r["parameters"][k]], [j["parameters"][k]])
        close([r["objective"], r["aic"]], [j["objective"], j["aic"]])
        if method == "ml":
            close([r["mean"]], [j["mean"]])
            for k, (lo, hi) in j["intervals"].items():
                close([r["intervals"][k][0]], [lo])


def test_fit_status_as_cli(cli, tmp_path):
    """A matern fit whose nu runs to an end of its fit range (0.2 to 30) says
    so, as the CLI's JSON does, with no standard error; two data at one
    place with different values are refused without a nugget."""
    rng = np.random.default_rng(3)
    pts = rng.random((40, 2))
    val = rng.random(40)
    tsv = tmp_path / "pts.tsv"
    tsv.write_text("x\ty\tvalue\n" + "".join("%r\t%r\t%r\n" % (x, y, v) for (x, y), v in zip(pts, val)))
    j = js(cli, "fit", str(tsv), "--model", "matern")
    r = noiselab.fit(pts, val, model="matern")
    assert r["status"] == j["status"]
    assert r["status"]["nu"] == "at bound" and r["parameters"]["nu"] in (0.2, 30)
    assert np.isnan(r["standard_errors"]["nu"]) and j["standard_errors"]["nu"] is None
    close([r["rcond"]], [j["rcond"]])
    pts[1] = pts[0]
    with pytest.raises(noiselab.Error, match="nugget"):
        noiselab.fit(pts, val, model="markov", method="ml")
