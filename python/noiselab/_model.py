"""noiselab.Model: a model spec's autocorrelation R(lag), spectral density
S(f), their samples on a grid, and what the estimators of a field of a
given size estimate when the model is true (core/model.h, core/wk.h,
analysis/spectral.h, analysis/acf.h)."""
import math

import numpy as np

from . import _ffi
from ._args import Error, _real, as_bool, as_choice, as_float, as_int, as_size, as_spacing, refuse
from ._ffi import alloc_field, check, ffi, grid_args, lib, owned_field, planner

_AXES = {"x": 0, "y": 1, "z": 2}


def _dptr(a):
    return ffi.cast("double *", ffi.from_buffer(a))


def model_of(value, what):
    """The parsed model (_ffi.Model: .ptr, .spec) of a spec string or a
    noiselab.Model, for arguments such as target=."""
    if isinstance(value, Model):
        return value._m
    return _ffi.Model(value, what)


def _vectors(name, value, dim):
    """(m, d) float64 vectors and d from lags or frequencies: a number, a 1D
    array of m numbers (vectors (t, 0, ...) in `dim` dimensions, default 1)
    or an (m, d) array, d = 1..3.  Also whether the input was a number."""
    a = _real(name, value)
    if dim is not None:
        dim = as_int("dim", dim, 1, 3)
    if a.ndim <= 1:
        t = a.reshape(-1)
        d = dim or 1
        v = np.zeros((t.size, d))
        v[:, 0] = t
    elif a.ndim == 2 and 1 <= a.shape[1] <= 3 and (dim is None or a.shape[1] == dim):
        v, d = np.array(a, dtype=np.float64), a.shape[1]
    else:
        want = "a number, a 1D array or an (m, d) array of vectors with d = %s" % (dim or "1, 2 or 3")
        raise Error("%s: expected %s, got shape %s" % (name, want, a.shape))
    if not np.isfinite(v).all():
        bad = int(np.flatnonzero(~np.isfinite(v).all(axis=1))[0])
        raise Error("%s: entry %d is not finite; expected finite numbers" % (name, bad))
    return np.ascontiguousarray(v), d, a.ndim == 0


def _grid(size, spacing):
    """numpy shape, spacing and the library's (dim, n, h) of a grid."""
    shape = as_size("size", size)
    h = as_spacing("spacing", spacing, len(shape))
    return shape, h, grid_args(shape, h)


class Model:
    """A model spec (``noiselab models``; e.g. "markov:scale=8",
    "gauss:scale=3,ratio=0.5,angle=30", "nugget:var=0.1 + spherical:scale=9",
    "power:d=2.5", "spectrum:exp(-f^2)") and what follows from it.

    Units and conventions (core/model.h, core/wk.h): lags in the spec's
    length units (samples at unit spacing); frequencies in cycles per unit
    length; spectra TWO-SIDED densities in variance per (cycles per unit)^d,
    so that the integral of S over all frequencies is R(0) (the nugget
    excepted, see spectrum), and the sum of a grid spectrum over its
    frequencies times the frequency cell 1/(n_1 h_1 ... n_d h_d) is R(0).
    Grids are numpy arrays in numpy's axis order (x last), wrapped order
    (index j stands for lag j h or frequency j/(n h), j - n from n/2 on:
    numpy.fft.fftfreq's layout).

    Attributes: spec (as parsed), spectral (defined by its spectrum),
    has_acf (R can be evaluated: not for spectrum: models), intrinsic (a
    variogram without covariance: powvar), isotropic, nugget.
    """

    def __init__(self, spec):
        self._m = model_of(spec, "spec")
        p = self._m.ptr
        self.spec = self._m.spec
        self.spectral = bool(lib.nl_model_is_spectral(p))
        self.has_acf = bool(lib.nl_model_has_acf(p))
        self.intrinsic = bool(lib.nl_model_is_intrinsic(p))
        self.isotropic = bool(lib.nl_model_is_isotropic(p))
        self.nugget = float(lib.nl_model_nugget(p))

    def __repr__(self):
        return "noiselab.Model(%r)" % self.spec

    # -- dimensions --------------------------------------------------------

    def dim_valid(self, dim):
        """Can the model be used in dim (1..3) dimensions (nl_model_check_dim:
        e.g. hyperspherical:dim=2 is not positive definite in 3D, image: has
        no 3D table)?"""
        dim = as_int("dim", dim, 1, 3)
        return lib.nl_model_check_dim(self._m.ptr, dim) == 0

    @property
    def dims(self):
        """The dimensions (of 1, 2, 3) in which the model is valid."""
        return tuple(d for d in (1, 2, 3) if self.dim_valid(d))

    def _check_dim(self, name, dim):
        st = lib.nl_model_check_dim(self._m.ptr, dim)
        if st:
            msg = ffi.string(lib.nl_errmsg()).decode("utf-8", "replace")
            raise Error("%s: the model is not valid in %dD: %s" % (name, dim, msg), int(st))

    def _eval(self, fn, name, values, dim):
        v, d, scalar = _vectors(name, values, dim)
        self._check_dim(name, d)
        out = np.empty(v.shape[0])
        p, vp = self._m.ptr, _dptr(v)
        with planner:  # expressions are not reentrant (core/model.h)
            for i in range(v.shape[0]):
                out[i] = fn(p, d, vp + i * d)
        return (out[0] if scalar else out), v, d

    # -- R and S -------------------------------------------------------------

    def acf(self, lags, dim=None):
        """R at the given lags (nl_model_acf): a number or a 1D array of m
        lags (vectors (t, 0, ...) along x in `dim` dimensions, default 1:
        for an isotropic model R(|t|), for an anisotropic one its section
        along x), or an (m, d) array of lag vectors, d = 1, 2 or 3.  In the
        model's variance units; R(0) = var + nugget (the nugget only where
        every component is exactly 0).  Intrinsic models (powvar): the
        generalized covariance -gamma (core/model.h).  power: by quadrature
        (slow).  A model defined by its spectrum alone (spectrum:) has no R
        at arbitrary lags: refused; acf_grid gives R on a periodic grid."""
        if not self.has_acf:
            raise Error("lags: %s is defined by its spectrum and has no R at arbitrary lags; use "
                        "acf_grid(size, spacing) for R on a periodic grid (Wiener-Khinchine, core/wk.h)" % self.spec)
        out, _, _ = self._eval(lib.nl_model_acf, "lags", lags, dim)
        return out

    def variogram(self, lags, dim=None):
        """The semivariogram gamma = R(0) - R(lag) (nugget included; powvar:
        its own), lags as for acf."""
        if not self.has_acf:
            raise Error("lags: %s is defined by its spectrum and has no variogram at arbitrary lags" % self.spec)
        out, _, _ = self._eval(lib.nl_model_variogram, "lags", lags, dim)
        return out

    def spectrum(self, freqs, dim=None):
        """The continuous spectral density S at the given frequencies
        (nl_model_spectral_density): frequencies in cycles per unit length,
        shaped as acf's lags (a number or 1D array: (f, 0, ...) in `dim`
        dimensions, default 1; or (m, d) vectors).  TWO-SIDED, in variance
        per (cycles per unit)^d: the integral of S over R^d is R(0) less the
        nugget (white noise has no density off a grid; spectrum_grid
        includes it).  The family's closed form where it has one, else the
        d-dimensional (Hankel) transform of the radial profile through the
        anisotropy (quadrature: under a millisecond a frequency near the
        band of R's decay, up to a second a thousand times beyond it, where
        it eventually fails and is refused).  Refused
        where there is no such density (products, image:, expressions of
        x, y, z): spectrum_grid gives the spectrum the synthesis samples."""
        out, v, d = self._eval(lib.nl_model_spectral_density, "freqs", freqs, dim)
        bad = np.isnan(np.atleast_1d(out))
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise Error("freqs: no spectral density of %s at f = %s in %dD (no closed form, and the transform "
                        "of its profile is undefined or failed there); use spectrum_grid(size, spacing) for the "
                        "spectrum sampled on a grid" % (self.spec, tuple(float(x) for x in v[i]), d))
        return out

    # -- on a grid -----------------------------------------------------------

    def _sample(self, fn, size, spacing):
        shape, h, (dim, n, hh) = _grid(size, spacing)
        self._check_dim("size", dim)
        f = alloc_field(shape, h)
        try:
            with planner:
                check(fn(self._m.ptr, f))
        except BaseException:
            lib.nl_field_free(f)
            raise
        return owned_field(f)

    def acf_grid(self, size, spacing=1.0):
        """R at the wrapped lags of a periodic grid of `size` samples (N,
        (ny, nx) or (nz, ny, nx)) at `spacing` (nl_wk_sample_acf): index j
        stands for lag j h (j - n from n/2 on).  For spectrum: models the
        inverse transform of the sampled spectrum (the periodic R the
        synthesis realises)."""
        return self._sample(lib.nl_wk_sample_acf, size, spacing)

    def spectrum_grid(self, size, spacing=1.0):
        """The spectrum on the grid as the FFT synthesis samples it
        (nl_wk_sample_spectrum): at the wrapped frequencies j/(n h) (numpy.fft
        .fftfreq(n, h) per axis), the transform of R sampled at the lags of
        that grid, so aliasing is included (S_grid(f) = sum_m S(f + m/h) for
        an R that has decayed within the grid) and the nugget appears as
        the constant nugget h_1...h_d; for spectral models the closed form.
        Two-sided density: sum(S) / (n_1 h_1 ... n_d h_d) = R(0)."""
        return self._sample(lib.nl_wk_sample_spectrum, size, spacing)

    # -- what the estimators estimate ---------------------------------------------

    def _profile(self, dim, n, h):
        """(freq, target): nl_psd_model_profile on the grid (the target of
        ``noiselab psd --target``) and the frequencies of nl_psd_profile."""
        Z = lib.nl_field_alloc(dim, n, h, ffi.new("int *"))
        if Z == ffi.NULL:
            raise Error("size: a grid of %s samples does not fit in memory" % (tuple(n[a] for a in range(dim)),), 6)
        try:
            k = lib.nl_psd_profile_size(Z)
            freq, zero, val = np.empty(k), np.empty(k), np.empty(k)
            cnt, nf = ffi.new("size_t[]", max(k, 1)), ffi.new("size_t *")
            check(lib.nl_psd_profile(Z, _dptr(freq), _dptr(zero), cnt, nf))
            with planner:
                check(lib.nl_psd_model_profile(self._m.ptr, dim, n, h, _dptr(val), nf))
        finally:
            lib.nl_field_free(Z)
        return freq[:nf[0]], val[:nf[0]]

    def periodogram_target(self, size, spacing=1.0):
        """What noiselab.psd of a field of `size` at `spacing` is compared
        with, as ``noiselab psd --target``: the spectrum on the field's grid
        (spectrum_grid, aliasing included) in psd's layout and units.
        Returns (freq, target): 1D f = 0 .. Nyquist (i/(n h)); 2D/3D the
        radial average in bins one frequency step wide (NaN for an empty
        bin), freq the bins' mean |f|.  The periodogram's expectation is this
        spectrum smoothed by the Fejer kernel (analysis/psd.h): equal to it
        where S varies slowly over 1/(n h)."""
        shape, h, (dim, n, hh) = _grid(size, spacing)
        self._check_dim("size", dim)
        return self._profile(dim, n, hh)

    def welch_target(self, size, spacing=1.0, segment=None):
        """The same for noiselab.psd(..., welch=segment): the spectrum on the
        grid of one segment (segment samples per axis, 1D or 2D, 4 <=
        segment <= every axis of size), as ``noiselab psd --welch S
        --target``.  Returns (freq, target) in psd's layout for that grid.
        Welch's expectation is it smoothed by the Hann window's kernel
        (main lobe 4/(segment h))."""
        shape, h, _ = _grid(size, spacing)
        if len(shape) > 2:
            raise Error("size: Welch's estimate is 1D or 2D, got %dD" % len(shape))
        if segment is None:
            refuse("segment", "the segment length in samples (an integer >= 4)", segment)
        s = as_int("segment", segment, 4, min(shape), "an integer from 4 to the smallest axis, %d" % min(shape))
        dim, n, hh = grid_args((s,) * len(shape), h)
        self._check_dim("size", dim)
        return self._profile(dim, n, hh)

    def acf_band(self, size, spacing=1.0, max_lag=None, axis="x", realizations=1, known_mean=False):
        """Where noiselab.acf's (biased) estimate of a field of `size` (N,
        (ny, nx) or (nz, ny, nx)) at `spacing` falls along `axis` when the
        model is true and the field Gaussian (analysis/acf.h
        nl_acf_model_band): its expectation, exact with the sample mean
        removed (acf's default; about (1 - k/n)(R(k) - Var(sample mean))),
        and its 95% band, expectation -+ 1.96 sd, with Bartlett's variance
        (1946) from the model's R summed over the grid's lag vectors with
        the field's pair counts,
            Var c(k) = (1/N^2) sum_v w_k(v) [R(v)^2 + R(v + k) R(v - k)],
        (1/N) sum_v [...] for a field much longer than k and R's decay.
        realizations=K: the band of the mean of K independent estimates
        (noiselab.ensemble_acf's), its half-width over sqrt(K).
        known_mean=True (acf's mean=): the expectation (1 - k/n) R(k); the
        half-width stays the sample mean's, smaller than the known mean's
        by a relative O((Var(sample mean) / R(0))^2).  max_lag in length
        units (default a quarter of the axis, as acf).  Costs O(2^d N
        max_lag) evaluations of a table: 0.2 s for 256 x 256 to lag 64.

        Returns a dict of arrays over lags 0..max_lag/h: lag (length units),
        target (R), expected, lo, hi."""
        shape, h, (dim, n, hh) = _grid(size, spacing)
        ax = _AXES[as_choice("axis", axis, tuple(_AXES))]
        if ax >= dim:
            raise Error('axis: the field is %dD, got axis "%s"' % (dim, axis))
        n_ax, h_ax = int(n[ax]), float(hh[ax])
        if max_lag is None:
            k = n_ax // 4
        else:
            ml = as_float("max_lag", max_lag, 0.0)
            k = int(math.floor(ml / h_ax + 1e-9))
            if k >= n_ax:
                raise Error("max_lag: expected at most %g for %d samples, got %g" % ((n_ax - 1) * h_ax, n_ax, ml))
        K = as_int("realizations", realizations, 1, (1 << 63) - 1)
        known = as_bool("known_mean", known_mean)
        self._check_dim("size", dim)
        mean, lo, hi = np.empty(k + 1), np.empty(k + 1), np.empty(k + 1)
        with planner:
            check(lib.nl_acf_model_band(self._m.ptr, dim, n, hh, ax, k, _dptr(mean), _dptr(lo), _dptr(hi)))
        lag = np.arange(k + 1) * h_ax
        tgt = np.empty(k + 1)
        with planner:
            check(lib.nl_acf_model_values(self._m.ptr, dim, n, hh, ax, _dptr(lag), k + 1, _dptr(tgt)))
        half = (hi - mean) / math.sqrt(K)
        if known:
            mean = (n_ax - np.arange(k + 1)) / n_ax * tgt
        return dict(lag=lag, target=tgt, expected=mean, lo=mean - half, hi=mean + half)
