"""Sums and products of structures end to end from Python: a nested spec is
a string like any other, so synth, krige and fit take it and give the
CLI's numbers (JSON with 10 significant digits: compared at 1e-9 relative)."""
import json

import numpy as np

import noiselab

NESTED = "spherical:var=0.5,scale=12,nugget=0.1 + markov:var=0.6,scale=40"


def close(a, b):
    np.testing.assert_allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=1e-9, atol=1e-12)


def test_nested_synth_krige_fit(cli, tmp_path):
    f = noiselab.synth("circulant", acf=NESTED, size=(128, 128), seed=7)
    exr = str(tmp_path / "f.exr")
    cli("synth", "circulant", "--acf", NESTED, "--size", "128x128", "--seed", "7", "-o", exr)
    np.testing.assert_array_equal(np.asarray(noiselab.read(exr), dtype=np.float32), np.asarray(f, dtype=np.float32))
    rng = np.random.default_rng(5)
    idx = rng.choice(f.size, 600, replace=False)
    pts = np.column_stack([idx % 128, idx // 128]).astype(float)
    val = np.asarray(f, dtype=float).ravel()[idx]
    # kriging interpolates the data (a nugget: the estimate at a datum is
    # not the datum, but the kriging weights still sum to one)
    est = noiselab.krige(pts, val, NESTED, pts[:5] + 0.25)
    assert np.all(np.isfinite(est))
    tsv = tmp_path / "pts.tsv"
    tsv.write_text("x\ty\tvalue\n" + "".join("%r\t%r\t%r\n" % (x, y, v) for (x, y), v in zip(pts, val)))
    j = json.loads(cli("fit", str(tsv), "--model", NESTED, "--weights", "distance", "--fix", "scale.2=40",
                       "--json").stdout)
    r = noiselab.fit(pts, val, model=NESTED, weights="distance", fix={"scale.2": 40})
    assert r["spec"] == j["model"]
    assert set(r["parameters"]) == {"var.1", "scale.1", "nugget.1", "var.2", "scale.2"}
    assert r["fixed"]["scale.2"] and not r["fixed"]["var.1"]
    for k in j["parameters"]:
        close([r["parameters"][k]], [j["parameters"][k]])
    close([r["objective"]], [j["objective"]])
