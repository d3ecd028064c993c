"""noiselab.Model: R and S against closed forms, the grid spectrum's
Parseval sum and aliasing, the estimators' targets against the CLI's, the
ACF band's coverage over independent fields, and bad input."""
import json
import math

import numpy as np
import pytest

import noiselab

# every Model.spectrum value off its closed form is a Hankel quadrature
# (core/model_hankel.c) of int R J r^(d/2) dr to 1e-9 relative or 1e-14 R(0)
# absolute, whichever is larger, scaled by 2 pi w^(1 - d/2): a factor 10 on each
HANKEL_RTOL = 1e-8


def hankel_close(got, want, f, d, r0):
    f = np.maximum(np.abs(np.asarray(f, dtype=float)), 1e-3)
    atol = 10 * 2 * np.pi * f ** (1 - d / 2) * 1e-14 * r0
    assert np.all(np.abs(got - want) <= HANKEL_RTOL * np.abs(want) + atol), (got, want)


def markov_density(f, s, d, var=1.0):
    """The d-dimensional Fourier transform of var exp(-|x|/s) (cycles per
    unit): var 2^d pi^((d-1)/2) Gamma((d+1)/2) s^d / (1 + (2 pi f s)^2)^((d+1)/2)."""
    q = 2 * np.pi * np.asarray(f) * s
    return var * 2 ** d * np.pi ** ((d - 1) / 2) * math.gamma((d + 1) / 2) * s ** d / (1 + q * q) ** ((d + 1) / 2)


def test_acf_closed_forms():
    m = noiselab.Model("markov:scale=3.7,var=2.385")
    t = np.array([0, 0.5, 1.7, 3.7, 11.2])
    np.testing.assert_allclose(m.acf(t), 2.385 * np.exp(-t / 3.7), rtol=1e-14)
    g = noiselab.Model("gauss:scale=2.3")
    np.testing.assert_allclose(g.acf(t), np.exp(-(t / 2.3) ** 2), rtol=1e-14)
    assert g.acf(1.1) == pytest.approx(math.exp(-(1.1 / 2.3) ** 2), rel=1e-14)
    # lag vectors: an isotropic model is a function of |v| in 2D and 3D
    rng = np.random.default_rng(3)
    for d in (2, 3):
        v = rng.normal(0, 3, (20, d))
        np.testing.assert_allclose(m.acf(v), 2.385 * np.exp(-np.linalg.norm(v, axis=1) / 3.7), rtol=1e-14)
    # the nugget only where every component is exactly 0
    n = noiselab.Model("markov:scale=2,nugget=0.25")
    np.testing.assert_allclose(n.acf(np.array([[0, 0], [0, 1e-300], [1, 0]])), [1.25, 1, math.exp(-0.5)], rtol=1e-14)


def test_acf_anisotropic():
    """Stam and Fiume's ellipsoid as core/model.h states it: the lag turned
    by -angle, then y and z shrunk by ratio and zratio; sep the product of
    the axes' profiles."""
    rng = np.random.default_rng(5)
    a, r, z = math.radians(30), 0.5, 0.25
    v = rng.normal(0, 4, (30, 3))
    u = math.cos(a) * v[:, 0] + math.sin(a) * v[:, 1]
    w = (-math.sin(a) * v[:, 0] + math.cos(a) * v[:, 1]) / r
    m2 = noiselab.Model("markov:scale=4,angle=30,ratio=0.5")
    np.testing.assert_allclose(m2.acf(v[:, :2]), np.exp(-np.hypot(u, w) / 4), rtol=1e-13)
    m3 = noiselab.Model("markov:scale=4,angle=30,ratio=0.5,zratio=0.25")
    np.testing.assert_allclose(m3.acf(v), np.exp(-np.sqrt(u * u + w * w + (v[:, 2] / z) ** 2) / 4), rtol=1e-13)
    s3 = noiselab.Model("gauss:scale=3,sep,ratio=0.5,zratio=0.25")
    np.testing.assert_allclose(s3.acf(v), np.exp(-(v[:, 0] / 3) ** 2 - (v[:, 1] / 1.5) ** 2 - (v[:, 2] / 0.75) ** 2),
                               rtol=1e-13)
    assert not m2.isotropic and noiselab.Model("markov").isotropic
    # a 1D array of lags in dim dimensions: vectors along x
    np.testing.assert_array_equal(m3.acf([1.5, -2.0], dim=3), m3.acf(np.array([[1.5, 0, 0], [-2.0, 0, 0]])))


@pytest.mark.parametrize("d", [1, 2, 3])
def test_spectrum_markov(d):
    """The closed form in every dimension (2D and 3D through the Hankel
    transform of the profile), and its integral over R^d is R(0)."""
    m = noiselab.Model("markov:scale=2.5,var=1.7")
    f = np.array([0, 0.003, 0.05, 0.2, 0.7, 3.0])
    hankel_close(m.spectrum(f, dim=d), markov_density(f, 2.5, d, 1.7), f, d, 1.7)
    # the same at vectors of those lengths in other directions: isotropic
    rng = np.random.default_rng(d)
    dirs = rng.normal(size=(f.size, d))
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]
    hankel_close(m.spectrum(dirs * f[:, None]), markov_density(f, 2.5, d, 1.7), f, d, 1.7)
    # int S = R(0): the radial integral of the density on a log grid
    # (trapezoid on 200 points per decade: error ~ (dlog)^2/12 ~ 1e-5
    # relative) from 1e-4 to 1e3, and the tail beyond, where the integrand
    # falls as f^-2, as F g(F); the part below 1e-4 as g(1e-4) * 1e-4 / d
    k = np.logspace(-4, 3, 1401)
    area = [2, 2 * np.pi, 4 * np.pi][d - 1]
    g = area * k ** (d - 1) * (markov_density(k, 2.5, d, 1.7) if d > 1 else m.spectrum(k))
    if d > 1:  # the Hankel route at a few of those points up to 10 (beyond, its quadrature
        # slows, 0.9 s at 100 in 3D, then fails: thousands of Bessel periods over R's decay)
        hankel_close(m.spectrum(k[:1001:200], dim=d), markov_density(k[:1001:200], 2.5, d, 1.7), k[:1001:200], d, 1.7)
    total = np.trapz(g, k) + k[-1] * g[-1] + g[0] * k[0] / d
    assert total == pytest.approx(1.7, rel=1e-4)


def test_spectrum_anisotropic():
    """The density through the anisotropy against an independent route: the
    forward transform of R sampled on a grid (spectrum_grid), which equals
    the continuous density where aliasing and the grid's truncation are
    below rounding: gauss, scale 5 (2.5 along the short axis), |f| <= 0.2
    so that the nearest alias, at distance >= 0.8, is S ~ exp(-(pi 2.5
    0.8)^2) = exp(-39) of S(0); R(32) along the long axis exp(-41)."""
    for spec in ("gauss:scale=5,angle=30,ratio=0.5", "gauss:scale=5,sep,angle=20,ratio=0.5"):
        m = noiselab.Model(spec)
        G = m.spectrum_grid((64, 64))
        fy, fx = np.meshgrid(np.fft.fftfreq(64), np.fft.fftfreq(64), indexing="ij")
        pick = [(0, 0), (1, 0), (0, 2), (3, 5), (63, 4), (6, 60), (9, 9), (12, 1)]
        f = np.array([[fx[j, i], fy[j, i]] for j, i in pick])
        want = np.array([G[j, i] for j, i in pick])
        hankel_close(m.spectrum(f), want, np.linalg.norm(f, axis=1), 2, 1.0)
        assert np.all(np.abs(m.spectrum(f) - want) < 1e-6 * want.max())
    # sep markov: the product of Lorentzians, stretched (closed forms only)
    m = noiselab.Model("markov:scale=2,sep,ratio=0.5")
    f = np.array([[0.05, 0.1], [0.3, -0.02]])
    want = markov_density(f[:, 0], 2, 1) * 0.5 * markov_density(0.5 * f[:, 1], 2, 1)
    np.testing.assert_allclose(m.spectrum(f), want, rtol=1e-13)


def test_spectrum_grid_parseval_and_aliasing():
    """sum(S_grid) / (n h) = R(0) (the inverse transform at lag 0, to
    rounding), and S_grid is the aliased continuous density
    sum_m S(f + m/h): summed here over |m| <= M, the rest bounded by
    2 sum_{m > M} 2 s / (2 pi s m / h)^2 < 4 s h^2 / ((2 pi s)^2 M)."""
    h, s, n = 0.5, 3.0, 256
    m = noiselab.Model("markov:scale=3")
    S = m.spectrum_grid(n, h)
    assert S.sum() / (n * h) == pytest.approx(1.0, rel=1e-12)
    f = np.fft.fftfreq(n, h)
    M = 4000
    alias = markov_density(f[None, :] + np.arange(-M, M + 1)[:, None] / h, s, 1).sum(axis=0)
    bound = 4 * s * h * h / ((2 * np.pi * s) ** 2 * M) + 1e-12 * S.max()  # R(n h / 2) = exp(-21) < 1e-9: truncation
    assert np.max(np.abs(S - alias)) < bound + 1e-9 * S.max()
    # a 2D grid with a nugget: the nugget's h_1 h_2 at every frequency
    S2 = noiselab.Model("markov:scale=2,nugget=0.3").spectrum_grid((32, 64), (1.0, 0.5))
    assert S2.sum() / (32 * 64 * 0.5) == pytest.approx(1.3, rel=1e-12)
    # a spectral model: its closed form sampled; Riemann sum of the integral
    # sqrt(pi) / 10 (Gaussian tails beyond Nyquist: exp(-25))
    G = noiselab.Model("spectrum:exp(-(f/0.1)^2)").spectrum_grid(512)
    assert G.sum() / 512 == pytest.approx(math.sqrt(math.pi) / 10, rel=1e-12)


def _cli_target(cli, path, *extra):
    return json.loads(cli("psd", path, "--target", "markov:scale=4", "--json", *extra).stdout)


def test_targets_are_the_clis(cli, tmp_path):
    """periodogram_target and welch_target print what `psd --target` prints
    for a field of that size (JSON, 10 significant digits), and psd(target=)
    the same."""
    m = noiselab.Model("markov:scale=4")
    for size, extra, kw in ((200, [], {}), ((48, 64), [], {}), (200, ["--welch", "32"], dict(segment=32)),
                            ((48, 64), ["--welch", "16"], dict(segment=16))):
        p = str(tmp_path / ("f.tsv" if np.ndim(size) == 0 else "f.exr"))
        x = noiselab.synth("fft", acf=m.spec, size=size, seed=2)
        noiselab.write(p, x)
        j = _cli_target(cli, p, *extra)
        fr, t = m.welch_target(size, segment=kw["segment"]) if kw else m.periodogram_target(size)
        np.testing.assert_allclose(t, np.array(j["target"], dtype=float), rtol=1e-9)
        np.testing.assert_allclose(fr, np.array(j["freq"], dtype=float), rtol=1e-9, atol=1e-12)
        f2, p2, t2 = noiselab.psd(x, welch=kw.get("segment"), target=m)
        np.testing.assert_array_equal(t2, t)
        np.testing.assert_array_equal(f2, fr)


def test_acf_band_coverage():
    """Over 400 independent fields (circulant: exact, not periodic) the
    estimate at a lag falls inside the band of acf_band with probability
    0.95 if the band is right: the count is binomial, sd sqrt(0.95 0.05 /
    400) = 1.1%; each lag checked at 3.5 sd (4 lags: a false alarm about 1
    in 1000).  The mean of 400 estimates is expected[k] within 3.5 of its
    standard errors (the band's half-width / 1.96 / sqrt(400))."""
    m = noiselab.Model("markov:scale=6")
    b = m.acf_band(256, max_lag=24)
    plan = noiselab.Plan("circulant", acf=m.spec, size=256)
    est = np.array([noiselab.acf(plan(s), max_lag=24)[1] for s in range(400)])
    lags = [0, 3, 12, 24]
    inside = ((b["lo"] <= est) & (est <= b["hi"])).mean(axis=0)[lags]
    assert np.all(np.abs(inside - 0.95) < 3.5 * math.sqrt(0.95 * 0.05 / 400)), inside
    sd = (b["hi"] - b["expected"]) / 1.959964
    assert np.all(np.abs(est.mean(axis=0) - b["expected"])[lags] < 3.5 * sd[lags] / math.sqrt(400))
    # the band's width: mean z^2 = 1, its standard error sqrt(var(z^2) / 400)
    # from the sample (the estimate is not Gaussian: var(z^2) is about 3, not 2)
    z2 = ((est - b["expected"]) / sd)[:, lags] ** 2
    assert np.all(np.abs(z2.mean(axis=0) - 1) < 3.5 * np.sqrt(z2.var(axis=0) / 400)), z2.mean(axis=0)
    # 2D along y, 100 fields of 48 x 40: 3.5 sd of binomial(100, 0.95)
    m2 = noiselab.Model("gauss:scale=3")
    b2 = m2.acf_band((48, 40), max_lag=6, axis="y")
    p2 = noiselab.Plan("circulant", acf=m2.spec, size=(48, 40))
    e2 = np.array([noiselab.acf(p2(s), max_lag=6, axis="y")[1] for s in range(100)])
    in2 = ((b2["lo"] <= e2) & (e2 <= b2["hi"])).mean(axis=0)[[0, 3, 6]]
    assert np.all(np.abs(in2 - 0.95) < 3.5 * math.sqrt(0.95 * 0.05 / 100)), in2
    # the band of a mean of K: sqrt(K) narrower, same centre
    bk = m.acf_band(256, max_lag=24, realizations=16)
    np.testing.assert_allclose(bk["hi"] - bk["expected"], (b["hi"] - b["expected"]) / 4, rtol=1e-12)
    np.testing.assert_allclose(bk["expected"], b["expected"], rtol=1e-14)


def test_acf_bands_dict(cli, tmp_path):
    """acf(bands=True): the model band is acf_band's; the plug-in band is
    `acf --bands`'s."""
    m = noiselab.Model("markov:scale=5")
    x = noiselab.synth("circulant", acf=m.spec, size=300, seed=4)
    d = noiselab.acf(x, max_lag=20, target=m, bands=True)
    b = m.acf_band(300, max_lag=20)
    assert d["band"] == "model"
    for k, kb in (("target", "target"), ("expected", "expected"), ("model_lo", "lo"), ("model_hi", "hi")):
        np.testing.assert_array_equal(d[k], b[kb])
    p = noiselab.acf(x, max_lag=20, bands=True)
    assert p["band"] == "plug-in" and set(p) == {"lag", "acf", "band", "plugin_lo", "plugin_hi"}
    path = str(tmp_path / "x.tsv")
    noiselab.write(path, x)
    j = json.loads(cli("acf", path, "--max-lag", "20", "--bands", "--json").stdout)
    np.testing.assert_allclose(p["plugin_lo"], np.array(j["band_lo"], dtype=float), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(p["plugin_hi"], np.array(j["band_hi"], dtype=float), rtol=1e-9, atol=1e-12)


def test_spectral_only_and_dims():
    s = noiselab.Model("spectrum:exp(-(f/0.1)^2)")
    assert s.spectral and not s.has_acf
    with pytest.raises(noiselab.Error, match="lags: .*acf_grid"):
        s.acf([0, 1])
    R = s.acf_grid(512)  # R(0) = int S = sqrt(pi)/10, the Riemann sum as above
    assert R[0] == pytest.approx(math.sqrt(math.pi) / 10, rel=1e-12)
    assert noiselab.Model("spherical:scale=4").dims == (1, 2, 3)
    assert noiselab.Model("hyperspherical:dim=2,scale=3").dims == (1, 2)
    assert noiselab.Model("markov").dim_valid(3)


@pytest.mark.parametrize("call, name", [
    (lambda: noiselab.Model("markov:scale=-1"), "scale"),
    (lambda: noiselab.Model("nosuchfamily"), "nosuchfamily"),
    (lambda: noiselab.Model(7), "spec"),
    (lambda: noiselab.Model("markov").acf(np.zeros((3, 4))), "lags"),
    (lambda: noiselab.Model("markov").acf(np.zeros((2, 3, 1))), "lags"),
    (lambda: noiselab.Model("markov").acf([0, np.nan]), "lags"),
    (lambda: noiselab.Model("markov").acf(np.zeros((3, 2)), dim=3), "lags"),
    (lambda: noiselab.Model("markov").acf([1.0], dim=4), "dim"),
    (lambda: noiselab.Model("markov").spectrum("x"), "freqs"),
    (lambda: noiselab.Model("markov*gauss").spectrum([0.1]), "freqs"),
    (lambda: noiselab.Model("markov").spectrum_grid(0), "size"),
    (lambda: noiselab.Model("markov").periodogram_target((0, 8)), "size"),
    (lambda: noiselab.Model("markov").periodogram_target(16, spacing=-1), "spacing"),
    (lambda: noiselab.Model("markov").welch_target(64, segment=128), "segment"),
    (lambda: noiselab.Model("markov").welch_target(64), "segment"),
    (lambda: noiselab.Model("markov").welch_target((8, 8, 8), segment=4), "size"),
    (lambda: noiselab.Model("markov").acf_band(0), "size"),
    (lambda: noiselab.Model("markov").acf_band(64, max_lag=64), "max_lag"),
    (lambda: noiselab.Model("markov").acf_band(64, axis="y"), "axis"),
    (lambda: noiselab.Model("markov").acf_band(64, realizations=0), "realizations"),
    (lambda: noiselab.Model("hyperspherical:dim=2").acf_band((8, 8, 8)), "size"),
    (lambda: noiselab.Model("powvar:alpha=1").acf_band(64), "intrinsic"),
    (lambda: noiselab.acf(np.ones((8, 8)), bands=True), "bands"),
    (lambda: noiselab.acf(np.arange(64.0), bands=True, radial=False, unbiased=True), "bands"),
    (lambda: noiselab.acf(np.arange(64.0), bands=True, realizations=4), "realizations"),
    (lambda: noiselab.psd(np.arange(64.0), target="markov:scale=0"), "scale"),
    (lambda: noiselab.psd(np.arange(64.0), target="markov", grid="wrapped"), "target"),
])
def test_bad_input(call, name):
    with pytest.raises(noiselab.Error, match=name):
        call()


def test_grids_are_nonlins_input():
    """spectrum_grid and acf_grid are what nonlin samples as its input (the
    same library calls on the same grid): bit for bit."""
    d = noiselab.nonlin("matern:nu=1.5,scale=5", "uniform", size=512, spacing=0.5)
    m = noiselab.Model("matern:nu=1.5,scale=5")
    np.testing.assert_array_equal(m.spectrum_grid(512, 0.5)[:257], d["input_psd"])
    np.testing.assert_array_equal(m.acf_grid(512, 0.5)[:257], d["input_acf"])
