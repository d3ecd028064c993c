"""The ensemble functions (analysis/ensemble.h through cffi) against the
direct computation: each field's estimate by acf, psd, moments and hist,
then numpy's mean and standard error (sample sd, ddof=1, over sqrt K).
numpy's pairwise sums differ from the library's in order, by rounding: the
tolerance is 1e-12 relative.  And the numbers are those noiselab acf|psd
prints for the same files, to the 10 significant digits of its JSON
(relative 5e-10 rounding; 1e-9 allowed)."""
import json
import os
import subprocess

import numpy as np
import pytest

import noiselab

K = 5


def fields(shape=(24, 32)):
    rng = np.random.default_rng(7)
    return [2.385 * k + 1.3 * rng.standard_normal(shape) for k in range(K)]


def mean_se(rows):
    rows = np.asarray(rows)
    return rows.mean(axis=0), rows.std(axis=0, ddof=1) / np.sqrt(len(rows))


def test_ensemble_acf_equals_direct():
    xs = fields()
    for kw in (dict(axis="y", max_lag=6), dict(radial=True, unbiased=True), dict(mean=0.5)):
        lag, m, se = noiselab.ensemble_acf(xs, spacing=(0.5, 0.25), **kw)
        rows = [noiselab.acf(x, spacing=(0.5, 0.25), **kw)[1] for x in xs]
        dm, dse = mean_se(rows)
        np.testing.assert_array_equal(lag, noiselab.acf(xs[0], spacing=(0.5, 0.25), **kw)[0])
        np.testing.assert_allclose(m, dm, rtol=1e-12, atol=1e-14)
        np.testing.assert_allclose(se, dse, rtol=1e-12, atol=1e-14)


def test_ensemble_psd_equals_direct():
    xs = fields()
    freq, m, se, P = noiselab.ensemble_psd(xs, welch=8, grid=True)
    rows = [noiselab.psd(x, welch=8)[1] for x in xs]
    dm, dse = mean_se(rows)
    np.testing.assert_array_equal(freq, noiselab.psd(xs[0], welch=8)[0])
    np.testing.assert_allclose(m, dm, rtol=1e-12)
    np.testing.assert_allclose(se, dse, rtol=1e-12)
    grids = [noiselab.psd(x, welch=8, grid="wrapped") for x in xs]
    np.testing.assert_allclose(P, np.mean(grids, axis=0), rtol=1e-12)


def test_ensemble_hist_equals_direct():
    xs = fields((300,)) + [np.linspace(-1, 1, 77)]  # sizes may differ
    edges, counts, se, mo, mo_se = noiselab.ensemble_hist(xs, bins=9)
    each = [noiselab.moments(x) for x in xs]
    for key in ("mean", "variance", "skewness", "kurtosis"):
        dm, dse = mean_se([e[key] for e in each])
        assert mo[key] == pytest.approx(dm, rel=1e-12) and mo_se[key] == pytest.approx(dse, rel=1e-12)
    assert mo["n"] == sum(x.size for x in xs)
    assert mo["min"] == min(x.min() for x in xs) and mo["max"] == max(x.max() for x in xs)
    np.testing.assert_allclose(edges, np.linspace(mo["min"], mo["max"], 10), rtol=1e-12, atol=1e-12)
    assert counts.sum() == pytest.approx(np.mean([x.size for x in xs]), rel=1e-12)


def test_ensemble_refusals_name_the_field():
    xs = fields()
    with pytest.raises(noiselab.Error, match="ensemble_acf: field 2: ensemble: field 3 differs"):
        noiselab.ensemble_acf(xs[:2] + [np.zeros((24, 31))] + xs[3:])
    with pytest.raises(noiselab.Error, match="ensemble_psd: field 1: .* expected finite"):
        noiselab.ensemble_psd([xs[0], np.full((24, 32), np.nan)])
    with pytest.raises(noiselab.Error, match="at least 2"):
        noiselab.ensemble_acf(xs[:1])
    with pytest.raises(noiselab.Error, match="expected a sequence"):
        noiselab.ensemble_hist(iter(xs))


def test_ensemble_equals_the_command_line(tmp_path):
    exe = os.environ.get("NOISELAB")
    if not exe:
        pytest.skip("NOISELAB not set")
    paths = []
    for seed in (3, 4, 5):
        p = str(tmp_path / ("f%d.tsv" % seed))
        subprocess.run([exe, "synth", "fft", "--acf", "markov:scale=4", "--size", "128", "--seed", str(seed), "-o", p],
                       check=True)
        paths.append(p)
    xs = [noiselab.read(p) for p in paths]
    out = json.loads(subprocess.run([exe, "acf", "--json"] + paths, check=True, capture_output=True).stdout)
    lag, m, se = noiselab.ensemble_acf(xs)
    np.testing.assert_allclose(m, out["acf"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(se, out["se"], rtol=1e-9, atol=1e-15)
    out = json.loads(subprocess.run([exe, "psd", "--json"] + paths, check=True, capture_output=True).stdout)
    freq, m, se = noiselab.ensemble_psd(xs)
    np.testing.assert_allclose(m, out["psd"], rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(se, out["se"], rtol=1e-9, atol=1e-15)
