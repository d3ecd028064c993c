"""noiselab.Dist (a law's density, CDF, quantile and map of a Gaussian
input), band_chisq and welch_edf against closed forms, and bad input."""
import math

import numpy as np
import pytest

import noiselab


def test_densities_closed_forms():
    y = np.array([-2.5, -0.3, 0.0, 1.1, 4.0])
    g = noiselab.Dist("gauss:mean=1,sd=2")
    np.testing.assert_allclose(g.pdf(y), np.exp(-((y - 1) / 2) ** 2 / 2) / (2 * math.sqrt(2 * math.pi)), rtol=1e-13)
    np.testing.assert_allclose(g.cdf(y), [0.5 * math.erfc(-(v - 1) / 2 / math.sqrt(2)) for v in y], rtol=1e-12)
    assert g.mean == pytest.approx(1) and g.variance == pytest.approx(4)
    lap = noiselab.Dist("laplace:a=2")
    np.testing.assert_allclose(lap.pdf(y), np.exp(-np.abs(y) / 2) / 4, rtol=1e-13)
    assert lap.quantile(0.975) == pytest.approx(-2 * math.log(0.05), rel=1e-12)  # 1 - exp(-q/a)/2 = 0.975
    assert lap.pdf(1.1) == pytest.approx(math.exp(-0.55) / 4, rel=1e-13)  # a number gives a number
    h = noiselab.Dist("hyperbolic")
    np.testing.assert_allclose(h.pdf(y), 0.5 / np.cosh(np.pi * y / 2), rtol=1e-13)
    assert noiselab.Dist("uniform:a=0,b=4").pdf(np.array([[1.0, 5.0]])).tolist() == [[0.25, 0.0]]


def test_transform():
    # F^-1(Phi(x)) of the uniform law on [0, 1] is Phi(x); expr:G is G(x)
    x = np.array([-1.0, 0.0, 2.0])
    np.testing.assert_allclose(noiselab.Dist("uniform").transform(x),
                               [0.5 * math.erfc(-v / math.sqrt(2)) for v in x], rtol=1e-12)
    sq = noiselab.Dist("expr:x^2", function=True)
    assert sq.function
    np.testing.assert_allclose(sq.transform(x), x ** 2, rtol=1e-15)


def test_band_chisq_and_welch_edf():
    # nu = 2: the exponential law, quantiles -ln(1 - p)
    lo, hi = noiselab.band_chisq(2)
    assert lo == pytest.approx(-math.log(0.975), rel=1e-10) and hi == pytest.approx(-math.log(0.025), rel=1e-10)
    # large nu: about 1 -+ 1.96 sqrt(2 / nu) (the normal limit; O(1/nu) apart)
    lo, hi = noiselab.band_chisq(20000)
    assert abs(hi - 1 - 1.959964 * math.sqrt(2 / 20000)) < 2 / 20000 * 3
    # 1D Welch, Hann, half overlap: nu = 2K / (1 + (K - 1) / (18 K)), K = (n - S) / (S / 2) + 1
    K = (4096 - 256) // 128 + 1
    assert noiselab.welch_edf(4096, 256) == pytest.approx(2 * K / (1 + (K - 1) / (18 * K)), rel=1e-12)
    assert noiselab.welch_edf(4096, 256, segments=True)[1] == K == 31
    assert noiselab.welch_edf((64, 96), 32, segments=True)[1] == 3 * 5


@pytest.mark.parametrize("call, name", [
    (lambda: noiselab.Dist("nosuch"), "spec"),
    (lambda: noiselab.Dist("expr:x^2"), "spec"),
    (lambda: noiselab.Dist(3), "spec"),
    (lambda: noiselab.Dist("gauss").pdf("a"), "y"),
    (lambda: noiselab.Dist("gauss").cdf([np.nan]), "y"),
    (lambda: noiselab.Dist("gauss").quantile(1.5), "u"),
    (lambda: noiselab.Dist("expr:x^2", function=True).pdf(0.0), "pdf"),
    (lambda: noiselab.band_chisq(0), "nu"),
    (lambda: noiselab.band_chisq(float("inf")), "nu"),
    (lambda: noiselab.band_chisq("2"), "nu"),
    (lambda: noiselab.welch_edf(4096, 2), "segment"),
    (lambda: noiselab.welch_edf(100, 128), "segment"),
    (lambda: noiselab.welch_edf((8, 8, 8), 4), "size"),
])
def test_bad_arguments(call, name):
    with pytest.raises(noiselab.Error, match=name):
        call()
