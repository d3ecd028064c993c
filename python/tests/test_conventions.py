"""gstat's conventions from Python: variogram's bins and drift and fit's
weights give the CLI's numbers (its JSON has 10 significant digits: 1e-9
relative), and the boundary rule on distances known exactly."""
import json

import numpy as np

import noiselab


def js(cli, *args):
    return json.loads(cli(*args, "--json").stdout)


def test_bins_on_exact_distances():
    # points at 0, 1, 2, 3 and a duplicate of 0, width 1, cutoff 2: gstat's
    # bins [0, 1], (1, 2] hold 5 and 3 pairs; floor's [0, 1), [1, 2) 1 and 4
    p, v = np.array([[0.0], [1], [2], [3], [0]]), np.array([0.3, 1.7, 0.2, 2.9, 1.1])
    _, _, n = noiselab.variogram(p, v, width=1, cutoff=2)
    assert list(n) == [5, 3]
    _, _, n = noiselab.variogram(p, v, width=1, cutoff=2, bins="floor")
    assert list(n) == [1, 4]


def test_drift_and_weights_equal_cli(cli, tmp_path):
    rng = np.random.default_rng(7)
    pts = rng.uniform(0, 50, size=(120, 2))
    val = 0.05 * pts[:, 0] - 0.02 * pts[:, 1] + np.sin(pts[:, 0] / 7) + rng.normal(0, 0.3, 120)
    path = tmp_path / "p.tsv"
    np.savetxt(path, np.column_stack([pts, val]), delimiter="\t", header="x\ty\tvalue", comments="", fmt="%.17g")
    for drift in ("linear", "quadratic"):
        j = js(cli, "variogram", str(path), "--drift", drift)
        d, g, n = noiselab.variogram(pts, val, drift=drift)
        np.testing.assert_allclose(g, j["gamma"], rtol=1e-9)
        np.testing.assert_allclose(n, j["pairs"], rtol=0)
    for w, name in ((7, "distance"), (6, "ols"), (1, "pairs")):
        j = js(cli, "fit", str(path), "--model", "markov", "--nugget", "--weights", str(w))
        r = noiselab.fit(pts, val, model="markov", nugget=True, weights=w)
        assert r["spec"] == j["model"]
        assert noiselab.fit(pts, val, model="markov", nugget=True, weights=name)["spec"] == j["model"]
    # the default is gstat's 7
    assert noiselab.fit(pts, val, model="markov", nugget=True)["spec"] == js(
        cli, "fit", str(path), "--model", "markov", "--nugget", "--weights", "7")["model"]
