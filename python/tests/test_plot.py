"""noiselab.plot: each figure drawn (Agg, small sizes) with its axes
labelled in the given units, its colour bars labelled, its legend naming
the model and clear of the data, and the plotted numbers the very ones the
package's functions return; bad arguments refused with noiselab.Error
naming the argument.  Importing noiselab does not import matplotlib."""
import ast
import os

import numpy as np
import pytest

import noiselab
from conftest import TOP

mpl = pytest.importorskip("matplotlib")
mpl.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

import noiselab.plot as nlp  # noqa: E402

SPEC = "markov:scale=4"
# the plotted numbers are the package's arrays, copied by matplotlib: equal up to float64 rounding
EXACT = dict(rtol=1e-12, atol=0)


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def field(n=256, seed=3, spec=SPEC):
    return noiselab.synth("circulant", acf=spec, size=n, seed=seed)


def labelled(ax, unit=None):
    """Both axis labels set, each with a unit in parentheses; unit in the
    x label when given."""
    for lab in (ax.get_xlabel(), ax.get_ylabel()):
        assert lab.strip() and "(" in lab and lab.endswith(")"), lab
    if unit:
        assert "(%s)" % unit in ax.get_xlabel() or "per %s)" % unit in ax.get_xlabel(), ax.get_xlabel()


def clear(ax, most=0.03):
    """The legend covers at most `most` of the plotted line vertices, or
    lies outside the axes (after the figure's layout)."""
    fig = ax.figure
    fig.canvas.draw()
    leg = ax.get_legend()
    assert leg is not None
    bb, axbb = leg.get_window_extent(), ax.get_window_extent()
    if not bb.overlaps(axbb):
        return
    pts = np.concatenate([ln.get_transform().transform(np.column_stack([ln.get_xdata(), ln.get_ydata()]))
                          for ln in ax.lines])
    pts = pts[np.isfinite(pts).all(axis=1)]
    inside = (pts[:, 0] >= bb.x0) & (pts[:, 0] <= bb.x1) & (pts[:, 1] >= bb.y0) & (pts[:, 1] <= bb.y1)
    assert inside.mean() <= most, "the legend covers %.1f%% of the points" % (100 * inside.mean())


def legend_texts(ax):
    return [t.get_text() for t in ax.get_legend().get_texts()]


def line(ax, label_part):
    found = [ln for ln in ax.lines if label_part in ln.get_label()]
    assert len(found) == 1, [ln.get_label() for ln in ax.lines]
    return found[0]


def band(ax):
    """(x, lower, upper) of the one fill_between of ax: its polygon runs
    (x0, y2[0]), (x, y1)..., (xn, y2[n]), (x, y2) backwards."""
    (pc,) = [c for c in ax.collections if isinstance(c, PolyCollection)]
    v = pc.get_paths()[0].vertices
    n = (len(v) - 3) // 2
    return v[1:n + 1, 0], v[1:n + 1, 1], v[n + 2:2 * n + 2, 1][::-1]


def test_import_noiselab_needs_no_matplotlib():
    """No module imports matplotlib at its top level, and only the plot
    modules mention it (a static check: a fresh interpreter would cost
    seconds)."""
    pkg = os.path.join(TOP, "python", "noiselab")
    for name in sorted(os.listdir(pkg)):
        if not name.endswith(".py"):
            continue
        tree = ast.parse(open(os.path.join(pkg, name)).read())
        for node in tree.body:
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                mods = [a.name for a in node.names] + [getattr(node, "module", None) or ""]
                assert not any(m.startswith("matplotlib") for m in mods), (name, mods)
                assert not any(m in ("plot", "noiselab.plot") for m in mods) or name.startswith(("plot", "_plot")), name
        if not name.startswith(("plot", "_plot")):
            assert "matplotlib" not in open(os.path.join(pkg, name)).read(), name


def test_field():
    f = np.random.default_rng(1).normal(size=(16, 24))
    pts = np.array([[3.0, 4.0], [20.0, 10.0]])
    ax = nlp.field(f, spacing=2.0, origin=(1.0, -3.0), unit="m", label="height", value_unit="mm", points=pts)
    labelled(ax, "m")
    (im,) = ax.images
    np.testing.assert_array_equal(im.get_array(), f)
    # cell centres at origin + i h: edges half a cell beyond
    assert list(im.get_extent()) == [0.0, 1.0 + 23.5 * 2, -4.0, -3.0 + 15.5 * 2]
    cb = im.colorbar
    assert cb is not None and cb.ax.get_ylabel() == "height (mm)"
    np.testing.assert_array_equal(ax.collections[0].get_offsets(), pts)
    # a grid of Krige.grid: cells of (hi - lo) / n over the extent
    assert list(nlp.field(f, extent=((0, 48), (10, 26))).images[0].get_extent()) == [0, 48, 10, 26]
    ax1 = nlp.field(f[0], unit="km")
    labelled(ax1, "km")
    np.testing.assert_array_equal(ax1.lines[0].get_ydata(), f[0])
    assert "samples" in nlp.field(f[0]).get_xlabel()
    ax3 = nlp.field(np.zeros((5, 4, 6)) + np.arange(5)[:, None, None])
    assert "z = 2" in ax3.get_title() and np.all(ax3.images[0].get_array() == 2)


def test_acf_one_field_with_model():
    x = field()
    ax = nlp.acf(x, model=SPEC, max_lag=20, unit="m")
    labelled(ax, "m")
    assert "value^2" in ax.get_ylabel()
    d = noiselab.acf(x, max_lag=20, bands=True, target=SPEC)
    np.testing.assert_allclose(line(ax, "estimate (biased").get_ydata(), d["acf"], **EXACT)
    np.testing.assert_allclose(line(ax, "model R").get_ydata(), d["target"], **EXACT)
    np.testing.assert_allclose(line(ax, "expectation").get_ydata(), d["expected"], **EXACT)
    b = noiselab.Model(SPEC).acf_band(256, max_lag=20)
    lag, lo, hi = band(ax)
    np.testing.assert_allclose(lag, b["lag"], **EXACT)
    np.testing.assert_allclose(lo, b["lo"], **EXACT)
    np.testing.assert_allclose(hi, b["hi"], **EXACT)
    assert any(SPEC in t for t in legend_texts(ax))
    clear(ax)


def test_acf_plugin_band_and_ensemble():
    x = field()
    ax = nlp.acf(x, max_lag=20)
    d = noiselab.acf(x, max_lag=20, bands=True)
    _, lo, hi = band(ax)
    np.testing.assert_allclose(lo, d["plugin_lo"], **EXACT)
    np.testing.assert_allclose(hi, d["plugin_hi"], **EXACT)
    fs = [field(128, s) for s in range(4)]
    ax = nlp.acf(fs, model=SPEC, max_lag=16)
    lag, mean, _ = noiselab.ensemble_acf(fs, max_lag=16)
    np.testing.assert_allclose(line(ax, "mean of 4").get_ydata(), mean, **EXACT)
    b = noiselab.Model(SPEC).acf_band(128, max_lag=16, realizations=4)
    _, lo, hi = band(ax)
    np.testing.assert_allclose(lo, b["lo"], **EXACT)
    np.testing.assert_allclose(hi, b["hi"], **EXACT)
    clear(ax)


def test_spectrum():
    x = field(256)
    ax = nlp.spectrum(x, model=SPEC, unit="m", value_unit="K")
    labelled(ax, "m")
    assert ax.get_xlabel() == "frequency (cycles per m)" and ax.get_ylabel() == "spectral density (K^2 m)"
    f, p = noiselab.psd(x)
    np.testing.assert_allclose(line(ax, "periodogram").get_ydata(), p[1:], **EXACT)  # f = 0 off the log axis
    ft, tgt = noiselab.Model(SPEC).periodogram_target(256)
    lo, hi = noiselab.band_chisq(2)
    fb, blo, bhi = band(ax)
    np.testing.assert_allclose(fb, ft[1:], **EXACT)
    np.testing.assert_allclose(blo, lo * tgt[1:], **EXACT)
    np.testing.assert_allclose(bhi, hi * tgt[1:], **EXACT)
    assert any(SPEC in t for t in legend_texts(ax))
    clear(ax)
    # Welch of a mean of 2: nu = 2 welch_edf
    fs = [field(512, s) for s in (1, 2)]
    ax = nlp.spectrum(fs, model=SPEC, welch=64)
    nu = 2 * noiselab.welch_edf(512, 64)
    _, blo, _ = band(ax)
    _, tw = noiselab.Model(SPEC).welch_target(512, segment=64)
    np.testing.assert_allclose(blo, noiselab.band_chisq(nu)[0] * tw[1:], **EXACT)
    np.testing.assert_allclose(line(ax, "mean of 2").get_ydata(), noiselab.ensemble_psd(fs, welch=64)[1][1:], **EXACT)
    assert ax.get_xlabel() == "frequency (cycles per sample)"
    assert ax.get_ylabel() == "spectral density (value^2 samples)"


def test_spectrum_radial_band():
    # a ring of c ordinates: about c/2 independent periodogram ordinates, nu = c
    # (coverage 0.947 over 200 fields of 64 x 64 and 32 rings, markov:scale=4)
    x = noiselab.synth("fft", acf=SPEC, size=(32, 32), seed=4)
    f, p, c = noiselab.psd(x, counts=True)
    assert c[0] == 1 and c.sum() <= 32 * 32 and np.array_equal(p, noiselab.psd(x)[1], equal_nan=True)
    assert np.all(noiselab.psd(x[0], counts=True)[2] == 1)
    ax = nlp.spectrum(x, model=SPEC)
    _, tgt = noiselab.Model(SPEC).periodogram_target((32, 32))
    keep = (f > 0) & (c > 0)
    _, lo, hi = band(ax)
    np.testing.assert_allclose(lo, [noiselab.band_chisq(k)[0] * t for k, t in zip(c[keep], tgt[keep])], **EXACT)
    np.testing.assert_allclose(hi, [noiselab.band_chisq(k)[1] * t for k, t in zip(c[keep], tgt[keep])], **EXACT)
    assert ax.get_ylabel() == "spectral density (value^2 samples^2)"
    clear(ax)


def test_periodogram_welch():
    x = field(512, spec="markov:scale=2")
    ax = nlp.periodogram_welch(x, model="markov:scale=2", segment=64, unit="m")
    labelled(ax, "m")
    texts = legend_texts(ax)
    assert any("15 segments of 64" in t for t in texts), texts  # (512 - 64) / 32 + 1
    assert any("markov:scale=2" in t for t in texts)
    np.testing.assert_allclose(line(ax, "Welch:").get_ydata(), noiselab.psd(x, welch=64)[1][1:], **EXACT)
    np.testing.assert_allclose(line(ax, "Welch's target").get_ydata(),
                               noiselab.Model("markov:scale=2").welch_target(512, segment=64)[1][1:], **EXACT)
    clear(ax)


def test_histogram():
    x = noiselab.shape(noiselab.synth("fft", acf=SPEC, size=(32, 32), seed=2), "laplace")
    ax = nlp.histogram(x, against="gauss", bins=20, draws=19, label="height", value_unit="m")
    assert ax.get_xlabel() == "height (m)" and "(per m)" in ax.get_ylabel()
    edges, counts, mom, test = noiselab.hist(x, 20, against="gauss", draws=19)
    heights = [r.get_height() for r in ax.patches]
    np.testing.assert_allclose(heights, counts / (mom["n"] * np.diff(edges)), **EXACT)
    law = line(ax, "density of gauss")
    np.testing.assert_allclose(law.get_ydata(), noiselab.Dist("gauss").pdf(law.get_xdata()), **EXACT)
    words = [t for t in legend_texts(ax) if t.startswith("test against gauss")]
    assert words and ("p = %.3g" % test["p"]) in words[0] and test["p_from"] in words[0], legend_texts(ax)
    clear(ax)


def test_nonlinearity():
    ax = nlp.nonlinearity("gauss:scale=6", "expr:x^2", size=1024, unit="m")
    labelled(ax, "m")
    pred = noiselab.nonlin("gauss:scale=6", "expr:x^2", size=1024)
    p = line(ax, "predicted (Hermite, 24 terms)")
    keep = np.isin(pred["freq"], p.get_xdata())
    np.testing.assert_allclose(p.get_ydata(), pred["output_psd"][keep], **EXACT)
    assert line(ax, "measured")
    ax = nlp.nonlinearity("gauss:scale=6", "expr:x^2", size=1024, show="acf")
    np.testing.assert_allclose(line(ax, "predicted").get_ydata(), pred["output_acf"][:len(ax.lines[0].get_xdata())],
                               **EXACT)
    clear(ax)


def test_variogram():
    rng = np.random.default_rng(1)
    pts = rng.uniform(0, 60, (60, 2))
    vals = noiselab.sample(noiselab.synth("fft", acf="spherical:scale=20", size=(61, 61), seed=2), pts)
    ft = noiselab.fit(pts, vals, model="spherical")
    ax = nlp.variogram(pts, vals, fit=ft, unit="m", label="zinc", value_unit="ppm")
    assert ax.get_xlabel() == "distance (m)" and ax.get_ylabel() == "semivariance (ppm^2)"
    d, g, n = noiselab.variogram(pts, vals)
    np.testing.assert_allclose(ax.collections[0].get_offsets(), np.column_stack([d, g]), **EXACT)
    assert [t.get_text() for t in ax.texts] == ["%d" % k for k in n]
    curve = line(ax, "WLS fit")
    np.testing.assert_allclose(curve.get_ydata(), noiselab.Model(ft["spec"]).variogram(curve.get_xdata(), dim=2),
                               **EXACT)
    clear(ax)
    ax = nlp.variogram(pts, vals, model="spherical:scale=20")
    assert any("spherical:scale=20" in t for t in legend_texts(ax))


def _krige_data():
    rng = np.random.default_rng(1)
    pts = rng.uniform(0, 40, (20, 2))
    vals = np.sin(pts[:, 0] / 9) + np.cos(pts[:, 1] / 7)
    k = noiselab.Krige(pts, vals, "spherical:scale=30")
    ext = ((0, 50), (0, 40))
    est, var = k.grid(ext, (8, 10))
    return k, pts, vals, ext, est, var


def test_kriging_and_conditional():
    k, pts, vals, ext, est, var = _krige_data()
    a, b = nlp.kriging(est, var, ext, points=pts, values=vals, unit="m", label="zinc", value_unit="ppm")
    for ax in (a, b):
        labelled(ax, "m")
        assert list(ax.images[0].get_extent()) == [0, 50, 0, 40]
    np.testing.assert_array_equal(a.images[0].get_array(), est)
    np.testing.assert_allclose(b.images[0].get_array(), np.sqrt(var), **EXACT)
    assert a.images[0].colorbar.ax.get_ylabel() == "estimate of zinc (ppm)"
    assert b.images[0].colorbar.ax.get_ylabel() == "kriging standard deviation (ppm)"
    np.testing.assert_array_equal(a.collections[0].get_offsets(), pts)
    r = k.simulate("circulant", (8, 10), ext, seed=1, realizations=3)
    axs = nlp.conditional(r, est, ext, points=pts, n=2, unit="m", label="zinc")
    assert len(axs) == 3
    np.testing.assert_array_equal(axs[0].images[0].get_array(), est)
    for j in (1, 2):
        np.testing.assert_array_equal(axs[j].images[0].get_array(), r[j - 1])
        labelled(axs[j], "m")
    norms = {id(ax.images[0].norm) for ax in axs}
    assert len(norms) == 1  # one colour scale
    cbs = {id(ax.images[0].colorbar) for ax in axs if ax.images[0].colorbar is not None}
    assert len(cbs) == 1 and axs[-1].images[0].colorbar.ax.get_ylabel() == "zinc"
    lo = min(est.min(), r[:2].min())
    assert axs[0].images[0].norm.vmin == lo


def test_on_given_axes():
    fig, (a, b) = plt.subplots(1, 2)
    assert nlp.acf(field(), ax=a) is a
    _, _, _, ext, est, var = _krige_data()
    fig, axs = plt.subplots(1, 2)
    assert nlp.kriging(est, var, ext, axes=axs) == list(axs)


@pytest.mark.parametrize("call, name", [
    (lambda: nlp.field("x"), "f"),
    (lambda: nlp.field(np.zeros((4, 4)), unit=3), "unit"),
    (lambda: nlp.field(np.zeros((4, 4)), label=None), "label"),
    (lambda: nlp.field(np.zeros((4, 4)), origin=(1, 2, 3)), "origin"),
    (lambda: nlp.field(np.zeros((4, 4)), points=np.zeros((3, 3))), "points"),
    (lambda: nlp.field(np.zeros(8), ax="left"), "ax"),
    (lambda: nlp.acf(np.zeros(64) + np.arange(64), model=7), "model"),
    (lambda: nlp.acf([], model=SPEC), "fields"),
    (lambda: nlp.acf(np.arange(64.0), max_lag=100), "max_lag"),
    (lambda: nlp.spectrum(np.arange(64.0), welch=2), "welch"),
    (lambda: nlp.spectrum(np.arange(64.0), loglog="yes"), "loglog"),
    (lambda: nlp.periodogram_welch(np.arange(64.0), segment=128), "segment"),
    (lambda: nlp.periodogram_welch(np.zeros((4, 4, 4)), segment=4), "field"),
    (lambda: nlp.histogram(np.arange(64.0), against="nosuch"), "spec"),
    (lambda: nlp.histogram(np.arange(64.0), bins=0), "bins"),
    (lambda: nlp.nonlinearity(SPEC, "expr:x^2", size=1), "size"),
    (lambda: nlp.nonlinearity(SPEC, "expr:x^2", size=64, show="both"), "show"),
    (lambda: nlp.variogram(np.zeros((5, 2)) + np.arange(5)[:, None], np.arange(5.0), fit={"a": 1}), "fit"),
    (lambda: nlp.kriging(np.zeros((4, 4)), -np.ones((4, 4)), ((0, 1), (0, 1))), "variance"),
    (lambda: nlp.kriging(np.zeros((4, 4)), np.ones((4, 4)), ((0, 1),)), "extent"),
    (lambda: nlp.kriging(np.zeros((4, 4)), np.ones((4, 4)), ((0, 1), (0, 1)), axes=[1, 2]), "axes"),
    (lambda: nlp.conditional(np.zeros((2, 4, 4)), np.zeros((4, 4)), ((0, 1), (0, 1)), n=0), "n"),
    (lambda: nlp.conditional(np.zeros((2, 3, 4)), np.zeros((4, 4)), ((0, 1), (0, 1))), "realizations"),
])
def test_bad_arguments(call, name):
    with pytest.raises(noiselab.Error, match=name):
        call()


def test_python_page_example(tmp_path, monkeypatch):
    """docs/python.md's example of "Figures: noiselab.plot" runs as shown."""
    import re
    monkeypatch.chdir(tmp_path)
    text = open(os.path.join(TOP, "docs", "python.md")).read()
    section = text[text.index("## Figures: noiselab.plot"):]
    code = re.findall(r"^```python\n(.*?)^```", section, re.S | re.M)[0]
    exec(compile(code, "docs/python.md", "exec"), {})
    assert os.path.getsize("acf-band.png") > 0
