"""Krige with an external drift and k-fold cross-validation from Python:
the CLI's numbers (krige --at ... --drift NAME, --covariate NAME=FIELD,
--cross-validate K --seed S, --folds COLUMN).  Tables: 17 significant
digits (1e-12 relative); JSON: 10 (1e-9); EXR maps: float32."""
import json

import numpy as np
import pytest

import noiselab

ACF = "markov:var=0.3,scale=20,nugget=0.05"


@pytest.fixture(scope="module")
def data():
    r = np.random.default_rng(5)
    p = r.uniform(0, 100, (60, 2))
    c = np.sin(p[:, 0] / 20) + p[:, 1] / 50
    v = 0.8 * c + r.normal(0, 0.3, 60)
    q = r.uniform(0, 100, (20, 2))
    return p, v, c, q, np.sin(q[:, 0] / 20) + q[:, 1] / 50


def tsv(path, cols, names):
    np.savetxt(path, np.column_stack(cols), delimiter="\t", header="\t".join(names), comments="", fmt="%.17g")
    return str(path)


def test_external_drift_at_points_equals_cli(cli, tmp_path, data):
    p, v, c, q, qc = data
    d = tsv(tmp_path / "d.tsv", [p, v, c], ["x", "y", "value", "c"])
    at = tsv(tmp_path / "q.tsv", [q, qc], ["x", "y", "c"])
    for opts, kw in (([], {}), (["--nmax", "12"], dict(nmax=12)), (["--drift", "linear,c"], dict(drift="linear"))):
        drift = [] if "--drift" in opts else ["--drift", "c"]
        cli("krige", "--data", d, "--acf", ACF, "--at", at, *drift, *opts, "-o", str(tmp_path / "o.tsv"))
        want = np.loadtxt(tmp_path / "o.tsv", skiprows=1)
        k = noiselab.Krige(p, v, ACF, covariates=c, **kw)
        est, var = k.predict(q, covariates=qc)
        np.testing.assert_allclose(est, want[:, 3], rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(var, want[:, 4], rtol=1e-12)
    with pytest.raises(noiselab.Error, match="^covariates"):
        noiselab.Krige(p, v, ACF, covariates=c).predict(q)
    with pytest.raises(noiselab.Error, match="^covariates"):
        noiselab.Krige(p, v, ACF).predict(q, covariates=qc)
    with pytest.raises(noiselab.Error, match="^covariates"):
        noiselab.Krige(p, v, ACF, covariates=c[:10])


def test_external_drift_on_a_grid_equals_cli(cli, tmp_path, data):
    p, v, c, _, _ = data
    d = tsv(tmp_path / "d.tsv", [p, v, c], ["x", "y", "value", "c"])
    shape = (12, 16)  # ny, nx: cells of 100/16 by 100/12
    xs, ys = (np.arange(16) + 0.5) * 100 / 16, (np.arange(12) + 0.5) * 100 / 12
    cov = (np.sin(xs[None, :] / 20) + ys[:, None] / 50).astype(np.float32)  # the EXR's precision
    noiselab.write(str(tmp_path / "c.exr"), cov.astype(np.float64))
    cli("krige", "--data", d, "--acf", ACF, "--grid", "16x12", "--extent", "0:100,0:100", "--drift", "c",
        "--covariate", "c=" + str(tmp_path / "c.exr"), "-o", str(tmp_path / "e.exr"), "--variance",
        str(tmp_path / "v.exr"))
    e, var = noiselab.Krige(p, v, ACF, covariates=c).grid("0:100,0:100", shape, covariates=cov.astype(np.float64))
    np.testing.assert_array_equal(e.astype(np.float32), noiselab.read(str(tmp_path / "e.exr")).astype(np.float32))
    np.testing.assert_array_equal(var.astype(np.float32), noiselab.read(str(tmp_path / "v.exr")).astype(np.float32))


def test_k_fold_equals_cli(cli, tmp_path, data):
    p, v, c, _, _ = data
    fold = np.arange(60) % 4 + 1
    d = tsv(tmp_path / "d.tsv", [p, v, c, fold], ["x", "y", "value", "c", "f"])
    j = json.loads(cli("krige", "--data", d, "--acf", ACF, "--cross-validate", "--folds", "f", "-o",
                       str(tmp_path / "cv.tsv"), "--json").stdout)
    r = noiselab.Krige(p, v, ACF).cross_validate(folds=fold)
    want = np.loadtxt(tmp_path / "cv.tsv", skiprows=1)
    np.testing.assert_allclose(r["predicted"], want[:, 3], rtol=1e-9)
    np.testing.assert_allclose(r["variance"], want[:, 4], rtol=1e-9)
    for key in ("mean_error", "var_error", "mean_zscore", "var_zscore", "rmse"):
        np.testing.assert_allclose(r[key], j[key], rtol=1e-9)
    # folds drawn from a seed, with the external drift: the CLI's folds and numbers
    j = json.loads(cli("krige", "--data", d, "--acf", ACF, "--drift", "c", "--cross-validate", "5", "--seed", "3",
                       "-o", str(tmp_path / "cv5.tsv"), "--json").stdout)
    r = noiselab.Krige(p, v, ACF, covariates=c).cross_validate(folds=5, seed=3)
    want = np.loadtxt(tmp_path / "cv5.tsv", skiprows=1)
    np.testing.assert_array_equal(r["fold"], want[:, 7])
    np.testing.assert_allclose(r["predicted"], want[:, 3], rtol=1e-9)
    np.testing.assert_allclose(r["rmse"], j["rmse"], rtol=1e-9)
    # one fold per datum is leave-one-out
    a = noiselab.Krige(p, v, ACF, nmax=15).cross_validate()
    b = noiselab.Krige(p, v, ACF, nmax=15).cross_validate(folds=np.arange(60))
    np.testing.assert_allclose(b["predicted"], a["predicted"], rtol=1e-12)
    for bad in (1, 61, np.arange(59), np.full(60, 0.5)):
        with pytest.raises(noiselab.Error, match="^folds"):
            noiselab.Krige(p, v, ACF).cross_validate(folds=bad)
