"""A law's density, CDF and quantile (core/dist.h), and the chi-square
bands of spectrum estimates (analysis/bands.h)."""
import numpy as np

from ._args import Error, _real, as_float, as_int, as_size, refuse
from ._ffi import Dist as _CDist, check, ffi, lib, planner


class Dist:
    """A distribution spec, as shape's `to` and hist's `against`: gauss[:mean=,sd=],
    uniform[:a=,b=], laplace[:a=], hyperbolic, lognormal[:zeta=,sigma=],
    chi2-1, power:p=P, table:FILE (core/dist.h); expr:G is a nonlinearity,
    not a law, and is refused.  Values are in the law's own units; pdf is a
    density per unit of y.

        >>> d = noiselab.Dist("laplace:a=2")
        >>> d.pdf([0, 1]), d.cdf(0.0), d.quantile(0.975), d.mean, d.variance

    function=True also takes expr:G (y = G(x), a memoryless map of a
    standardised Gaussian input, as nonlin's and shape's g), which has only
    transform.

    Attributes: spec (as parsed), mean, variance (NaN where not finite or
    not known), function (an expr: map)."""

    def __init__(self, spec, function=False):
        try:
            self._d = _CDist(spec, "spec")
        except Error as e:
            msg = str(e)
            raise Error(msg if msg.startswith("spec:") else "spec: " + msg, e.code) from None
        self.function = bool(lib.nl_dist_is_function(self._d.ptr))
        if self.function and not function:
            raise Error("spec: expected a distribution (gauss, laplace, ...), got the nonlinearity %r, which has "
                        "no density" % spec)
        self.spec = ffi.string(lib.nl_dist_spec(self._d.ptr)).decode()
        self.mean = float(lib.nl_dist_mean(self._d.ptr))
        self.variance = float(lib.nl_dist_variance(self._d.ptr))

    def __repr__(self):
        return "noiselab.Dist(%r)" % self.spec

    def _map(self, fn, name, values, lo=-np.inf, hi=np.inf):
        a = _real(name, values)
        flat = np.array(a, dtype=np.float64).reshape(-1)
        if np.isnan(flat).any() or (flat < lo).any() or (flat > hi).any():
            bad = int(np.flatnonzero(np.isnan(flat) | (flat < lo) | (flat > hi))[0])
            refuse(name, "numbers from %g to %g" % (lo, hi) if np.isfinite(lo) else "numbers (not NaN)",
                   float(flat[bad]))
        p = self._d.ptr
        out = np.array([fn(p, float(y)) for y in flat])
        return float(out[0]) if a.ndim == 0 else out.reshape(a.shape)

    def _law(self, what):
        if self.function:
            raise Error("%s: %s is a nonlinearity, not a law: it has no %s" % (what, self.spec, what))

    def pdf(self, y):
        """The density at y (a number or an array; per unit of y).  NaN for
        table: laws (a quantile table has no density in closed form)."""
        self._law("pdf")
        return self._map(lib.nl_dist_pdf, "y", y)

    def cdf(self, y):
        """P(Y <= y) at y (a number or an array)."""
        self._law("cdf")
        return self._map(lib.nl_dist_cdf, "y", y)

    def transform(self, x):
        """The memoryless map of a standard Gaussian input x (nl_dist_transform;
        Lewis 1986, section 4): F^-1(Phi(x)) for a law, G(x) for expr:G.  x
        a number or an array (standardised: mean 0, variance 1)."""
        with planner:  # an expression is not reentrant (core/dist.h)
            return self._map(lib.nl_dist_transform, "x", x)

    def quantile(self, u):
        """The quantile at u in [0, 1] (infinite tails at 0 and 1 where the
        support is)."""
        self._law("quantile")
        return self._map(lib.nl_dist_quantile, "u", u, 0.0, 1.0)


def band_chisq(nu):
    """The 95% band of an estimate distributed as S chi-square_nu / nu
    (nl_band_chisq, analysis/bands.h): (lo, hi) = (q(0.025), q(0.975)) / nu,
    so that the estimate falls in [S lo, S hi] with probability 0.95.  One
    periodogram ordinate (0 < f < Nyquist) has nu = 2, the mean of K
    independent ones 2K, Welch's estimate welch_edf's nu.  nu: a positive
    number."""
    nu = as_float("nu", nu, 0.0, np.inf, lo_open=True)
    if not np.isfinite(nu):
        refuse("nu", "a finite positive number", nu)
    lo, hi = ffi.new("double *"), ffi.new("double *")
    check(lib.nl_band_chisq(nu, lo, hi))
    return lo[0], hi[0]


def welch_edf(size, segment, segments=False):
    """The equivalent degrees of freedom nu of Welch's estimate (Hann
    segments of `segment` samples per axis every segment/2, as
    noiselab.psd(..., welch=segment)) of a 1D or 2D field of `size` samples
    (N or (ny, nx)), at frequencies away from 0 and Nyquist for a spectrum
    flat over the window's main lobe (nl_welch_edf; Welch 1967, eq. 5;
    Percival and Walden 1993, eq. 292b): nu = 2 K^2 / sum rho(i - j) over
    the K segments.  segments=True: (nu, K), K counted as noiselab.psd's
    Welch estimate places them (analysis/welch.c: every segment/2 samples
    while a whole segment fits, per axis)."""
    shape = as_size("size", size)
    if len(shape) > 2:
        raise Error("size: Welch's estimate is 1D or 2D, got %dD" % len(shape))
    s = as_int("segment", segment, 4, min(shape), "an integer from 4 to the smallest axis, %d" % min(shape))
    n = ffi.new("size_t[2]", [int(x) for x in reversed(shape)] + [1] * (2 - len(shape)))
    nu = ffi.new("double *")
    check(lib.nl_welch_edf(len(shape), n, s, nu))
    if not segments:
        return nu[0]
    K = 1
    for m in shape:
        K *= (m - s) // (s // 2) + 1
    return nu[0], K

