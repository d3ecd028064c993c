"""Hostile arguments to every public function raise noiselab.Error (a
ValueError) naming the argument, before C sees them: not TypeError,
OverflowError, UnicodeEncodeError, numpy's errors or a silent conversion
(2.7 truncated to 2, "no" taken as True, a complex array's imaginary part
dropped).  Estimators refuse data whose sums would overflow instead of
returning inf or NaN.  Each case of HOSTILE was let through or raised
something else before the binding checked its arguments in one place
(_args.py)."""
import numpy as np
import pytest

import noiselab

SUR = "\ud800"  # a lone surrogate: no UTF-8 encoding
X = np.random.default_rng(7).normal(size=32)
X2 = np.random.default_rng(7).normal(size=(8, 8))
PTS = np.random.default_rng(3).uniform(0, 10, size=(12, 2))
VALS = np.random.default_rng(4).normal(size=12)
AT = PTS[:2] + 0.25
BIG = 2 ** 64
SYNTH = dict(acf="markov:scale=3", size=16)
SUB = dict(acf="markov:scale=2", size=(16, 16))


def fields():
    return [X, X + 1.0]


# (id, call, a word the message must hold: the argument's name, or what overflowed)
HOSTILE = [
    # synth and Plan
    ("synth-size-2**64", lambda p: noiselab.synth("fft", acf="markov", size=BIG), "size"),
    ("synth-size-axis-2**64", lambda p: noiselab.synth("fft", acf="markov", size=(BIG, 8)), "size"),
    ("synth-size-float", lambda p: noiselab.synth("fft", acf="markov", size=(8, 8.0)), "size"),
    ("synth-spacing-None", lambda p: noiselab.synth("fft", spacing=None, **SYNTH), "spacing"),
    ("synth-spacing-str", lambda p: noiselab.synth("fft", spacing="1", **SYNTH), "spacing"),
    ("synth-spacing-2**2000", lambda p: noiselab.synth("fft", spacing=2 ** 2000, **SYNTH), "spacing"),
    ("synth-spacing-axis-None", lambda p: noiselab.synth("fft", acf="markov", size=(8, 8), spacing=(1, None)),
     "spacing"),
    ("synth-clamp-str", lambda p: noiselab.synth("fft", clamp="no", **SYNTH), "clamp"),
    ("synth-method-list", lambda p: noiselab.synth(["fft"], **SYNTH), "method"),
    ("synth-acf-surrogate", lambda p: noiselab.synth("fft", acf="markov" + SUR, size=16), "acf"),
    ("synth-spectrum-surrogate", lambda p: noiselab.synth("fft", spectrum="power:d=2" + SUR, size=16), "spectrum"),
    ("synth-tol-2**2000", lambda p: noiselab.synth("subdiv", tol=2 ** 2000, **SUB), "tol"),
    ("synth-flag-str", lambda p: noiselab.synth("subdiv", nonperiodic="no", **SUB), "nonperiodic"),
    ("synth-double-2**2000", lambda p: noiselab.synth("faulting", size=(8, 8), density=2 ** 2000), "density"),
    ("plan-provenance-seed-2.5", lambda p: noiselab.Plan("fft", **SYNTH).provenance(2.5), "seed"),
    # read
    ("read-None", lambda p: noiselab.read(None), "path"),
    ("read-int", lambda p: noiselab.read(3), "path"),
    ("read-surrogate", lambda p: noiselab.read(str(p / ("f" + SUR + ".exr"))), "path"),
    ("read-bytes-missing", lambda p: noiselab.read(b"/nonexistent/f.exr"), "nonexistent"),
    ("read-meta-str", lambda p: noiselab.read(_tsv(p), meta="no"), "meta"),
    # write
    ("write-None", lambda p: noiselab.write(None, X), "path"),
    ("write-surrogate", lambda p: noiselab.write(str(p / ("f" + SUR + ".exr")), X), "path"),
    ("write-spacing-None", lambda p: noiselab.write(str(p / "f.tsv"), X, spacing=None), "spacing"),
    ("write-model-surrogate", lambda p: noiselab.write(str(p / "f.tsv"), X, model="m" + SUR), "model"),
    ("write-model-int", lambda p: noiselab.write(str(p / "f.tsv"), X, model=3), "model"),
    ("write-complex", lambda p: noiselab.write(str(p / "f.tsv"), X + 1j), "array"),
    ("write-strings", lambda p: noiselab.write(str(p / "f.tsv"), ["a", "b"]), "array"),
    # acf
    ("acf-mean-str", lambda p: noiselab.acf(X, mean="x"), "mean"),
    ("acf-mean-bool", lambda p: noiselab.acf(X, mean=True), "mean"),
    ("acf-max_lag-str", lambda p: noiselab.acf(X, max_lag="2"), "max_lag"),
    ("acf-max_lag-list", lambda p: noiselab.acf(X, max_lag=[2]), "max_lag"),
    ("acf-axis-list", lambda p: noiselab.acf(X, axis=["x"]), "axis"),
    ("acf-radial-str", lambda p: noiselab.acf(X2, radial="no"), "radial"),
    ("acf-unbiased-str", lambda p: noiselab.acf(X, unbiased="no"), "unbiased"),
    ("acf-complex", lambda p: noiselab.acf(X + 1j), "field"),
    ("acf-strings", lambda p: noiselab.acf(["a", "b"]), "field"),
    ("acf-bools", lambda p: noiselab.acf(np.array([True, False] * 8)), "field"),
    ("acf-spacing-None", lambda p: noiselab.acf(X, spacing=None), "spacing"),
    ("acf-target-surrogate", lambda p: noiselab.acf(X, target="markov" + SUR), "target"),
    ("acf-lags-overflow", lambda p: noiselab.acf(X, spacing=1e308), "spacing"),
    # psd
    ("psd-welch-2**64", lambda p: noiselab.psd(X, welch=BIG), "welch"),
    ("psd-mean-str", lambda p: noiselab.psd(X, mean="x"), "mean"),
    ("psd-spacing-subnormal", lambda p: noiselab.psd(X, spacing=5e-324), "spacing"),
    ("psd-2d-spacing-subnormal", lambda p: noiselab.psd(X2, spacing=5e-324), "spacing"),
    ("psd-spacing-str", lambda p: noiselab.psd(X, spacing="a"), "spacing"),
    # moments, hist
    ("moments-str", lambda p: noiselab.moments("abc"), "field"),
    ("moments-complex", lambda p: noiselab.moments(np.array([[1 + 1j, 2]])), "field"),
    ("hist-bins-2**62", lambda p: noiselab.hist(X, bins=2 ** 62), "bins"),
    ("hist-bins-2**64", lambda p: noiselab.hist(X, bins=BIG), "bins"),
    ("hist-dict", lambda p: noiselab.hist({"a": 1}), "field"),
    # check
    ("check-acf-surrogate", lambda p: noiselab.check(acf="markov" + SUR), "acf"),
    ("check-dim-float", lambda p: noiselab.check(acf="markov", dim=2.0), "dim"),
    ("check-dim-numpy-float", lambda p: noiselab.check(acf="markov", dim=np.float64(1)), "dim"),
    # coeffs
    ("coeffs-neighborhood-2.7", lambda p: noiselab.coeffs("markov:scale=2", neighborhood=2.7), "neighborhood"),
    ("coeffs-neighborhood-bool", lambda p: noiselab.coeffs("markov:scale=2", neighborhood=True), "neighborhood"),
    ("coeffs-neighborhood-str", lambda p: noiselab.coeffs("markov:scale=2", neighborhood="x"), "neighborhood"),
    ("coeffs-neighborhood-empty", lambda p: noiselab.coeffs("markov:scale=2", neighborhood=""), "neighborhood"),
    ("coeffs-tol-empty", lambda p: noiselab.coeffs("markov:scale=2", tol=""), "tol"),
    ("coeffs-tol-None", lambda p: noiselab.coeffs("markov:scale=2", tol=None), "tol"),
    ("coeffs-tol-rule-junk", lambda p: noiselab.coeffs("markov:scale=2", tol="variance:x"), "tol"),
    ("coeffs-dim-float", lambda p: noiselab.coeffs("markov:scale=2", dim=1.0), "dim"),
    ("coeffs-spacing0-str", lambda p: noiselab.coeffs("markov:scale=2", spacing0="1"), "spacing0"),
    ("coeffs-taps-2.5", lambda p: noiselab.coeffs("markov:scale=2", displacements="correlated", taps=2.5), "taps"),
    # nonlin
    ("nonlin-size-2**64", lambda p: noiselab.nonlin("markov:scale=2", "uniform", size=BIG), "size"),
    ("nonlin-size-float", lambda p: noiselab.nonlin("markov:scale=2", "uniform", size=64.0), "size"),
    ("nonlin-spacing-None", lambda p: noiselab.nonlin("markov:scale=2", "uniform", spacing=None), "spacing"),
    ("nonlin-g-surrogate", lambda p: noiselab.nonlin("markov:scale=2", "uniform" + SUR), "g"),
    ("nonlin-overflow", lambda p: noiselab.nonlin("markov:scale=3,var=1e308", "uniform", size=64), "overflow"),
    # shape
    ("shape-empirical-str", lambda p: noiselab.shape(X, "uniform", empirical="no"), "empirical"),
    ("shape-to-surrogate", lambda p: noiselab.shape(X, "uniform" + SUR), "to"),
    ("shape-strings", lambda p: noiselab.shape(["a", "b"], "uniform"), "field"),
    ("shape-overflow", lambda p: noiselab.shape(X * 1e200, "uniform"), "overflow"),
    # krige
    ("krige-mean-str", lambda p: noiselab.krige(PTS, VALS, "markov", AT, mean="x"), "mean"),
    ("krige-values-strings", lambda p: noiselab.krige(PTS, ["a"] * 12, "markov", AT), "values"),
    ("krige-strict-str", lambda p: noiselab.krige(PTS, VALS, "markov", AT, strict="no"), "strict"),
    ("krige-variance-str", lambda p: noiselab.krige(PTS, VALS, "markov", AT, variance="no"), "variance"),
    ("krige-points-complex", lambda p: noiselab.krige(PTS + 1j, VALS, "markov", AT), "points"),
    ("krige-at-strings", lambda p: noiselab.krige(PTS, VALS, "markov", [["a", "b"]]), "at"),
    # variogram
    ("variogram-width-str", lambda p: noiselab.variogram(PTS, VALS, width="1"), "width"),
    ("variogram-cutoff-list", lambda p: noiselab.variogram(PTS, VALS, cutoff=[1]), "cutoff"),
    ("variogram-direction-str", lambda p: noiselab.variogram(PTS, VALS, direction="x", tolerance=10), "direction"),
    ("variogram-field-spacing-None", lambda p: noiselab.variogram(field=X2, spacing=None), "spacing"),
    ("variogram-points-overflow", lambda p: noiselab.variogram(PTS, VALS * 1e200), "overflow"),
    ("variogram-field-overflow", lambda p: noiselab.variogram(field=X2 * 1e300), "overflow"),
    # fit
    ("fit-fix-None", lambda p: noiselab.fit(PTS, VALS, fix={"scale": None}), "fix"),
    ("fit-fix-int", lambda p: noiselab.fit(PTS, VALS, fix=3), "fix"),
    ("fit-nugget-str", lambda p: noiselab.fit(PTS, VALS, nugget="no"), "nugget"),
    ("fit-model-surrogate", lambda p: noiselab.fit(PTS, VALS, model="markov" + SUR), "model"),
    ("fit-width-str", lambda p: noiselab.fit(PTS, VALS, width="1"), "width"),
    # ensembles
    ("ensemble_acf-mean-str", lambda p: noiselab.ensemble_acf(fields(), mean="x"), "mean"),
    ("ensemble_acf-unbiased-str", lambda p: noiselab.ensemble_acf(fields(), unbiased="no"), "unbiased"),
    ("ensemble_acf-dict", lambda p: noiselab.ensemble_acf({"a": X, "b": X}), "fields"),
    ("ensemble_acf-spacing-None", lambda p: noiselab.ensemble_acf(fields(), spacing=None), "spacing"),
    ("ensemble_acf-axis-list", lambda p: noiselab.ensemble_acf(fields(), axis=["x"]), "axis"),
    ("ensemble_psd-welch-2**64", lambda p: noiselab.ensemble_psd(fields(), welch=BIG), "welch"),
    ("ensemble_psd-grid-str", lambda p: noiselab.ensemble_psd(fields(), grid="no"), "grid"),
    ("ensemble_psd-spacing-subnormal", lambda p: noiselab.ensemble_psd(fields(), spacing=5e-324), "spacing"),
    ("ensemble_hist-bins-2**62", lambda p: noiselab.ensemble_hist(fields(), bins=2 ** 62), "bins"),
    ("ensemble_hist-strings", lambda p: noiselab.ensemble_hist([["a", "b"], ["c", "d"]]), "field"),
]


def _tsv(p):
    path = str(p / "ok.tsv")
    noiselab.write(path, X)
    return path


@pytest.mark.parametrize("call,word", [c[1:] for c in HOSTILE], ids=[c[0] for c in HOSTILE])
def test_hostile_argument_raises_error(call, word, tmp_path):
    with pytest.raises(noiselab.Error) as e:
        call(tmp_path)
    assert isinstance(e.value, ValueError)
    assert word in str(e.value), str(e.value)


def test_enough_cases():
    """The issue asks for at least 60 hostile cases over every public function."""
    assert len(HOSTILE) >= 60
    assert len({c[0] for c in HOSTILE}) == len(HOSTILE)


# Files that are folders or missing were refused with the library's message
# already; they stay so.
@pytest.mark.parametrize("call", [
    lambda p: noiselab.read(str(p)),
    lambda p: noiselab.read(str(p / "missing.exr")),
    lambda p: noiselab.read(p / "missing.tsv"),
    lambda p: noiselab.write(str(p), X),
    lambda p: noiselab.write(str(p / "no" / "f.exr"), X2),
    lambda p: noiselab.read(""),
    lambda p: noiselab.write("", X),
], ids=["read-dir", "read-missing", "read-missing-pathlike", "write-dir", "write-missing-dir", "read-empty",
        "write-empty"])
def test_paths_refused(call, tmp_path):
    with pytest.raises(noiselab.Error):
        call(tmp_path)


@pytest.mark.parametrize("value,expected", [
    (2, 2), (np.int64(3), 3), (np.uint8(4), 4)])
def test_integers_pass(value, expected):
    assert noiselab.coeffs("markov:scale=2", neighborhood=value, levels=1)[0]["N"] == expected


def test_numbers_pass():
    """numpy scalars and 0-d arrays are numbers: the converters take them."""
    a = noiselab.acf(X, mean=np.array(0.25), max_lag=np.float32(4), spacing=np.array(1.0))
    b = noiselab.acf(X, mean=0.25, max_lag=4)
    assert np.array_equal(a[1], b[1])


def test_krige_at_no_positions():
    """No positions is not an error: no estimates."""
    assert noiselab.krige(PTS, VALS, "markov", np.zeros((0, 2))).shape == (0,)


def test_message_names_argument_value_and_expectation():
    """As the CLI's: "size: expected ..., got 2.7"."""
    with pytest.raises(noiselab.Error) as e:
        noiselab.nonlin("markov:scale=2", "uniform", size=2.7)
    assert str(e.value) == "size: expected an integer from 2 to 2^24, got 2.7"


def test_variogram_below_the_bound_stays_finite():
    """Values just inside the guard give a finite variogram: the bound
    refuses only what would overflow."""
    v = VALS / np.ptp(VALS) * 1e150
    d, g, n = noiselab.variogram(PTS, v)
    assert np.isfinite(g).all() and g.max() > 1e298
