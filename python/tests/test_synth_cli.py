"""Synthesis from Python is the CLI's, bit for bit.

The CLI writes 32-bit EXR (samples rounded to nearest) or a TSV (%.10g), so
the comparable quantities are: (1) the CLI's EXR samples, read back exactly
(float32 widened to double), equal the Python field rounded to float32, at
every sample; (2) the EXR the Python package writes with the plan's
provenance is byte-identical to the CLI's file (same samples, same
attributes: model, method, seed, size, spacing, flags, origin, version); for
1D the TSV files are byte-identical too.  (1) cannot see float64 differences
below float32's half ulp, so (3) the float64 fields of Plan(seed) and of
synth() must be identical, and a second seed must differ."""
import numpy as np
import pytest

import noiselab

# (method, model keyword, model, numpy size, CLI options, Python options)
CASES = [
    ("fft", "acf", "markov:scale=4", (60, 64), [], {}),
    ("fft", "acf", "markov:scale=8", (40, 48), ["--clamp"], {"clamp": True}),
    ("fft", "acf", "gauss:scale=3", (96,), [], {}),
    ("fft", "spectrum", "power:d=2.6", (8, 12, 10), [], {}),
    ("fft", "acf", "gauss:scale=1.5", (32, 40), ["--spacing", "0.5,2"], {"spacing": (2.0, 0.5)}),
    ("circulant", "acf", "matern:scale=4,nu=1.5", (30, 34), [], {}),
    ("cholesky", "acf", "markov:scale=3", (12, 10), [], {}),
    ("subdiv", "acf", "gauss:scale=4", (64, 64), ["--neighborhood", "3"], {"neighborhood": 3}),
    ("subdiv", "acf", "markov:scale=6", (128,), ["--nonperiodic", "--origin", "17"],
     {"nonperiodic": True, "origin": 17}),
    ("subdiv", "acf", "markov:scale=6", (64,), ["--displacements", "correlated", "--taps", "3"],
     {"displacements": "correlated", "taps": 3}),
    ("subdiv", "acf", "gauss:scale=4", (128, 128), ["--neighborhood", "auto", "--tol", "variance:1e-3", "--levels", "3"],
     {"neighborhood": "auto", "tol": "variance:1e-3", "levels": 3}),
    ("midpoint", "spectrum", "power:d=2.5", (32, 32), [], {}),
    ("midpoint", None, None, (64,), ["--H", "0.7", "--interpolant", "miller"], {"H": 0.7, "interpolant": "miller"}),
    ("faulting", None, None, (40, 40), ["--density", "2"], {"density": 2.0}),
    ("sparse", "acf", "gauss:scale=3", (40, 36), ["--density", "2"], {"density": 2.0}),
    ("sparse", "acf", "gauss:scale=3", (32, 32), ["--wrap"], {"wrap": True}),
    ("lattice", "spectrum", "power:d=3", (64, 64), [], {}),
    ("lattice", "acf", "gauss:scale=6", (48, 60), ["--interpolant", "wiener", "--cell", "6"],
     {"interpolant": "wiener", "cell": 6}),
]


def cli_args(method, kind, model, size, extra, path, seed):
    args = ["synth", method, "--size", "x".join(str(n) for n in reversed(size)), "--seed", seed, "-o", path]
    if kind:
        args += ["--" + kind, model]
    return args + extra


@pytest.mark.parametrize("method,kind,model,size,extra,opts", CASES, ids=lambda c: str(c) if isinstance(c, str) else None)
def test_synth_equals_cli(cli, tmp_path, method, kind, model, size, extra, opts):
    seed = 12345
    exr = str(tmp_path / "cli.exr")
    cli(*cli_args(method, kind, model, size, extra, exr, seed))
    kw = dict(opts)
    if kind:
        kw[kind] = model
    plan = noiselab.Plan(method, size=size, **kw)
    f = plan(seed)
    assert f.shape == size and f.dtype == np.float64 and f.flags["C_CONTIGUOUS"]
    assert not f.flags["OWNDATA"] and f.base.base is not None  # a view over the library's memory, no copy
    ref, meta = noiselab.read(exr, meta=True)
    assert ref.shape == size
    # (1) every sample, at the CLI's float32 precision
    np.testing.assert_array_equal(ref, f.astype(np.float32).astype(np.float64))
    # (2) the same file
    mine = str(tmp_path / "py.exr")
    noiselab.write(mine, f, **plan.provenance(seed))
    assert open(mine, "rb").read() == open(exr, "rb").read()
    for k in ("model", "method", "seed", "flags", "origin"):
        assert meta[k] == plan.provenance(seed)[k], k
    assert meta["spacing_array"] == plan.spacing
    # (3) float64: plan and one-shot agree bit for bit; seeds differ
    g = noiselab.synth(method, size=size, seed=seed, **kw)
    assert np.array_equal(f, g)
    assert not np.array_equal(f, plan(seed + 1))


def test_tsv_equals_cli(cli, tmp_path):
    tsv = str(tmp_path / "cli.tsv")
    cli("synth", "fft", "--acf", "markov:scale=4", "--size", "50", "--seed", "3", "--spacing", "0.25", "-o", tsv)
    plan = noiselab.Plan("fft", acf="markov:scale=4", size=50, spacing=0.25)
    mine = str(tmp_path / "py.tsv")
    noiselab.write(mine, plan(3), **plan.provenance(3))
    assert open(mine).read() == open(tsv).read()
    back = noiselab.read(mine)
    np.testing.assert_allclose(back, plan(3), rtol=1e-9, atol=0)  # %.10g


def test_read_write_roundtrip_3d(tmp_path):
    f = noiselab.synth("fft", acf="markov:scale=2", size=(3, 5, 7), seed=1)
    p = str(tmp_path / "f.exr")
    noiselab.write(p, f, spacing=(1.0, 2.0, 0.5), model="markov:scale=2")
    g, meta = noiselab.read(p, meta=True)
    assert g.shape == (3, 5, 7)
    assert meta["size"] == "7x5x3" and meta["spacing"] == "0.5,2,1" and meta["model"] == "markov:scale=2"
    assert meta["spacing_array"] == (1.0, 2.0, 0.5)
    np.testing.assert_array_equal(g, f.astype(np.float32))
