"""fit's likelihood with a drift from Python: the CLI's numbers (its JSON
has 10 significant digits: 1e-9 relative), covariates that span the same
space as the linear drift give the same ML optimum, and refusals."""
import json

import numpy as np
import pytest

import noiselab


@pytest.fixture(scope="module")
def data():
    rng = np.random.default_rng(11)
    pts = rng.uniform(0, 100, size=(70, 2))
    f = noiselab.synth("fft", acf="markov:scale=15", size=(128, 128), seed=4)
    val = np.asarray(noiselab.sample(f, pts), dtype=float).reshape(-1) + 0.02 * pts[:, 0]
    return pts, val


@pytest.mark.heavy
def test_linear_drift_equals_cli(cli, tmp_path, data):
    pts, val = data
    path = tmp_path / "p.tsv"
    np.savetxt(path, np.column_stack([pts, val]), delimiter="\t", header="x\ty\tvalue", comments="", fmt="%.17g")
    for method in ("ml", "reml"):
        j = json.loads(cli("fit", str(path), "--model", "markov", "--nugget", "--method", method, "--drift", "linear",
                           "--json").stdout)
        r = noiselab.fit(pts, val, model="markov", nugget=True, method=method, drift="linear")
        assert r["spec"] == j["model"]
        np.testing.assert_allclose(r["objective"], j["objective"], rtol=1e-9)
        np.testing.assert_allclose(r["drift"], [t["value"] for t in j["drift"]], rtol=1e-9)
        np.testing.assert_allclose(r["drift_se"], [t["se"] for t in j["drift"]], rtol=1e-9)
        assert len(r["drift"]) == 3 and r["starts"] >= 1


def test_covariates_spanning_the_linear_drift(data):
    # the ML likelihood does not depend on how the drift's space is spanned:
    # the coordinates as covariates give the linear drift's optimum (the
    # search's tolerances: 1e-6 relative on -2 log L)
    pts, val = data
    a = noiselab.fit(pts, val, model="markov", nugget=True, method="ml", drift="linear")
    b = noiselab.fit(pts, val, model="markov", nugget=True, method="ml", covariates=pts)
    np.testing.assert_allclose(b["objective"], a["objective"], rtol=1e-6)
    assert len(b["drift"]) == 3
    c = noiselab.fit(pts, val, model="markov", nugget=True, method="ml")
    assert c["objective"] > a["objective"] + 1  # the drift is there: 0.02 per unit over 100 units


def test_wls_fits_the_residual_variogram(cli, tmp_path, data):
    # as fit --drift with wls: the variogram of the drift's residuals
    pts, val = data
    path = tmp_path / "p.tsv"
    c = np.sin(pts[:, 1] / 30)
    np.savetxt(path, np.column_stack([pts, val, c]), delimiter="\t", header="x\ty\tvalue\tc", comments="",
               fmt="%.17g")
    for drift, kw in (("linear", dict(drift="linear")), ("c", dict(covariates=c)),
                      ("linear,c", dict(drift="linear", covariates=c))):
        j = json.loads(cli("fit", str(path), "--model", "markov", "--nugget", "--drift", drift, "--json").stdout)
        r = noiselab.fit(pts, val, model="markov", nugget=True, **kw)
        assert r["spec"] == j["model"]
        np.testing.assert_allclose(r["objective"], j["objective"], rtol=1e-9)
    assert noiselab.fit(pts, val, model="markov", nugget=True, drift="linear")["spec"] != \
        noiselab.fit(pts, val, model="markov", nugget=True)["spec"]


def test_variogram_with_covariates_equals_cli(cli, tmp_path, data):
    pts, val = data
    c = np.sin(pts[:, 1] / 30)
    path = tmp_path / "p.tsv"
    np.savetxt(path, np.column_stack([pts, val, c]), delimiter="\t", header="x\ty\tvalue\tc", comments="",
               fmt="%.17g")
    j = json.loads(cli("variogram", str(path), "--drift", "linear,c", "--json").stdout)
    d, g, n = noiselab.variogram(pts, val, drift="linear", covariates=c)
    np.testing.assert_allclose(g, j["gamma"], rtol=1e-9)
    np.testing.assert_array_equal(n, j["pairs"])
    _, g0, _ = noiselab.variogram(pts, val, drift="linear")
    assert not np.allclose(g, g0, rtol=1e-6)  # the covariate is in the drift


def test_refusals(data):
    pts, val = data
    with pytest.raises(noiselab.Error, match="^drift"):
        noiselab.fit(pts, val, model="markov", method="ml", drift="cubic")
    with pytest.raises(noiselab.Error, match="^covariates"):
        noiselab.fit(pts, val, model="markov", method="ml", covariates=np.ones((5, 1)))
