"""Block, trans-Gaussian and indicator kriging, and the fit of a given
variogram: noiselab.Krige's block=, transform= and indicator= and
noiselab.fit's variogram=, as the CLI's ``krige --block, --transform,
--indicator`` and ``fit --variogram`` (analysis/krige_flavours.h,
analysis/variogram.h, analysis/fit.h): every number comes from the same
library calls."""
import math
import os

import numpy as np

from . import _analysis, _krige
from ._args import Error, as_bool, as_coords, as_float, as_int, as_path, as_values, refuse
from ._ffi import Model, check, ffi, lib, planner
from ._krige import _DBL_MAX, _DRIFTS, _EMPTY, _dptr, _extent, _shape

_NK_MAX = 256      # thresholds at most (nl_krige_indicator's)
_AXIS_MAX = 64     # NL_KRIGE_BLOCK_AXIS_MAX: block points per axis at most


def _msg():
    return ffi.string(lib.nl_errmsg()).decode("utf-8", "replace")


def _block(block, points, dim):
    """nl_krige_block of block=(W, H[, D]) (one positive edge per axis of
    the data, as --block WxH[xD]) and block_points (None: gstat's 4-point
    Gauss-Legendre rule; N in 2..64 regular points per axis)."""
    want = "%d positive edge%s (one per axis of the data)" % (dim, "s" if dim > 1 else "")
    items = (block,) if np.ndim(block) == 0 and not isinstance(block, (str, bytes)) else block
    try:
        items = tuple(items)
    except TypeError:
        refuse("block", want, block)
    if isinstance(block, (str, bytes)) or len(items) != dim:
        refuse("block", want, block)
    b = ffi.new("nl_krige_block *")
    for a, w in enumerate(items):
        b.size[a] = as_float("block", w, 0.0, lo_open=True)
    b.points = 0 if points is None else as_int("block_points", points, 2, _AXIS_MAX)
    return b


def _lambda(transform):
    """Box-Cox lambda of "log", ("boxcox", L) or "boxcox:L", L in [-5, 5]."""
    want = '"log", ("boxcox", LAMBDA) or "boxcox:LAMBDA" with LAMBDA in [-5, 5]'
    if isinstance(transform, str) and transform == "log":
        return 0.0
    if isinstance(transform, str) and transform.startswith("boxcox:"):
        try:
            lam = float(transform[7:])
        except ValueError:
            refuse("transform", want, transform)
    elif isinstance(transform, (tuple, list)) and len(transform) == 2 and transform[0] == "boxcox":
        lam = transform[1]
    else:
        refuse("transform", want, transform)
    try:
        return as_float("transform", lam, -5.0, 5.0)
    except Error:
        refuse("transform", want, transform)


def _thresholds(t):
    """1 to 256 finite thresholds in increasing order, float64."""
    want = "1 to %d finite thresholds in increasing order" % _NK_MAX
    try:
        a = np.array(t, dtype=np.float64, ndmin=1) if not isinstance(t, (str, bytes, bool)) else None
    except (TypeError, ValueError):
        a = None
    if a is None or a.ndim != 1 or not 1 <= a.size <= _NK_MAX or not np.isfinite(a).all() or (np.diff(a) <= 0).any():
        refuse("indicator", want, t)
    return np.ascontiguousarray(a)


class Krige(_krige.Krige):
    """noiselab.Krige (see there) with the flavours of ``noiselab krige``,
    all on local plans (analysis/krige_flavours.h), as the CLI's:

    block         (W, H[, D]): block kriging (gstat's krige(..., block =)):
                  estimates of the mean over the block of those edges
                  centred at each location, and their kriging variances
                  (--block WxH); with any mean, drift, nmax, radius.
    block_points  N regular points per axis (2..64; gstat's nblockdiscr);
                  default gstat's 4-point Gauss-Legendre rule per axis.
    transform     "log", ("boxcox", L) or "boxcox:L" (L in [-5, 5]):
                  trans-Gaussian kriging (gstat's krigeTg; --transform):
                  ordinary kriging of the Box-Cox transforms of the data
                  (all > 0), estimates and variances back in the data's
                  units with Cressie's bias correction; not with mean or a
                  drift; with block, of blocks.
    indicator     thresholds t_1 < ... < t_K (--indicator): indicator
                  kriging of P(value <= t_k), acf one spec for every
                  threshold or a list of K specs (--indicator-acf), GSLIB's
                  order-relation correction; not with mean; with block,
                  of blocks.

    With block or transform, predict and grid give (estimate, variance) as
    without; with indicator, (probabilities, corrected): an (m, K) array
    from predict, (K,) + shape from grid (probability field k of
    threshold k, as the CLI's OUT.k.exr), and the number of locations the
    correction changed.  cross_validate: trans-Gaussian in the data's
    units; indicator {observed, probabilities (n, K), thresholds, brier
    (K: mean squared difference of indicator and probability), corrected,
    points, kind}; block refused (the data are points, as the CLI).
    Locations whose neighbourhood is too small get NaN (rows of NaN).
    Attributes besides Krige's: block, block_points, transform (lambda or
    None), thresholds, models (the specs, one per threshold)."""

    def __init__(self, points, values, acf, *, mean=None, nmax=None, radius=None, drift=None, strict=False,
                 covariates=None, block=None, block_points=None, transform=None, indicator=None):
        p = as_coords("points", points)
        v = as_values("values", values, p.shape[0])
        self._b = self._lam = self._thr = self._y = None
        self.block = self.block_points = self.transform = self.thresholds = None
        if block_points is not None and block is None:
            raise Error("block_points: expected block=(W, H[, D]) with it, got block_points=%r alone" % (block_points,))
        if block is not None:
            self._b = _block(block, block_points, p.shape[1])
            self.block = tuple(self._b.size[a] for a in range(p.shape[1]))
            self.block_points = self._b.points or None
        if transform is not None and indicator is not None:
            raise Error("transform: expected no indicator with it (one flavour), got transform=%r" % (transform,))
        if transform is not None:
            self._lam = self.transform = _lambda(transform)
            if mean is not None or drift not in (None, "constant"):
                raise Error("transform: expected ordinary kriging (no mean, no drift; as gstat's krigeTg), got %s"
                            % ("mean=%r" % (mean,) if mean is not None else "drift=%r" % (drift,)))
            self._y = np.empty_like(v)
            if lib.nl_krige_tg_transform(self._lam, v.size, _dptr(v), _dptr(self._y)):
                raise Error("values: " + _msg())
        acfs = [acf]
        if indicator is not None:
            self._thr = self.thresholds = _thresholds(indicator)
            if mean is not None:
                raise Error("mean: expected no mean with indicator (each indicator has its own mean, the CDF at its "
                            "threshold: ordinary indicator kriging estimates it), got mean=%r" % (mean,))
            if isinstance(acf, (list, tuple)):
                if len(acf) != self._thr.size:
                    raise Error("acf: expected one spec, or one per threshold (%d), got %d specs"
                                % (self._thr.size, len(acf)))
                acfs = list(acf)
        self._flavour = self._b is not None or self._lam is not None or self._thr is not None
        if self._flavour and strict:
            raise Error("strict: applies to global kriging (no block, transform or indicator), got strict=True")
        if self._flavour and covariates is not None:
            raise Error("covariates: expected no external drift with block, transform or indicator kriging (as the "
                        "CLI), got covariates")
        super().__init__(p, v, acfs[0], mean=mean, nmax=nmax, radius=radius, drift=drift, strict=strict,
                         covariates=covariates)
        if self._thr is not None:
            self._ms = [self._m] + [Model(s, "acf") for s in acfs[1:]]
            self.models = [m.spec for m in self._ms]
            ptrs = [self._ms[j if len(acfs) > 1 else 0].ptr for j in range(self._thr.size)]
            self._mp = ffi.new("const nl_model *[]", ptrs)
            self._reentrant = all(lib.nl_model_is_reentrant(m.ptr) for m in self._ms)
        else:
            self.models = [self.model]

    # -- plans: the flavours krige on local plans, as the CLI's -------------

    def _global_plan(self):
        if not self._flavour:
            return super()._global_plan()
        self.local = True
        self._local = self._local_plan(0, 0.0)  # every datum in every neighbourhood

    def _local_plan(self, nmax, radius, pts=None, val=None, **kw):
        if val is None and self._y is not None:
            val = self._y  # trans-Gaussian: the plan of the transforms
        return super()._local_plan(nmax, radius, pts, val, **kw)

    def _options(self):
        o = ffi.new("nl_krige_local_options *")
        o.nmax, o.radius = self.nmax or 0, self.radius or 0.0
        o.drift = _DRIFTS.index(self.drift or "constant")
        return o

    @property
    def kind(self):
        if self._thr is not None:
            return "indicator"
        if self._lam is not None:
            return "trans-gaussian"
        return "block" if self._b is not None else super().kind

    # -- estimates ----------------------------------------------------------

    def _run(self, x, est, var):
        """Block or trans-Gaussian kriging at the m locations x: status."""
        b = self._b if self._b is not None else ffi.NULL
        vp = _dptr(var) if var is not None else ffi.NULL
        if self._lam is not None:
            return self._call(lib.nl_krige_tg_eval, self._local, b, self._lam, x.shape[0], _dptr(x), _dptr(est), vp)
        return self._call(lib.nl_krige_block_eval, self._local, b, x.shape[0], _dptr(x), _dptr(est), vp)

    def _eval(self, x, variance, where):
        m = x.shape[0]
        est = np.full(m, np.nan)
        var = np.full(m, np.nan) if variance else None
        if m:
            st = self._run(x, est, var)
            if st:
                def one(t):
                    e, v = np.full(1, np.nan), np.full(1, np.nan)
                    s = self._run(x[t:t + 1], e, v)
                    return s, e[0], v[0]
                est[:] = np.nan
                self._holes(st, est, var, where, one)
        return est, var

    def _indicator(self, x, where):
        """Corrected probabilities at x ((m, K)), or at the data each left
        out (x None), and the count of corrected locations."""
        k = self._thr.size
        count = self.n if x is None else x.shape[0]
        cdf = np.full((count, k), np.nan)
        if count == 0:
            return cdf, 0
        nc = ffi.new("size_t *")
        b = self._b if self._b is not None else ffi.NULL
        call = lambda c, xp, out: self._call(lib.nl_krige_indicator, self._mp, k, _dptr(self._thr), self.dim, self.n,
                                             _dptr(self._p), _dptr(self._v), self._options(), b, c, xp, ffi.NULL,
                                             _dptr(out), nc)
        st = call(count, _dptr(x) if x is not None else ffi.NULL, cdf)
        if st == 0:
            return cdf, int(nc[0])
        if x is None or st != 1 or _EMPTY not in _msg():
            raise Error(_msg(), int(st))
        cdf[:] = np.nan
        total = 0
        for t in range(count):  # location by location: those with too few data stay NaN
            row = np.full((1, k), np.nan)
            s = call(1, _dptr(x[t:t + 1]), row)
            if s == 0:
                cdf[t], total = row[0], total + int(nc[0])
            elif s != 1 or _EMPTY not in _msg():
                raise Error(_msg() + " (%s)" % where(t), int(s))
        return cdf, total

    def predict(self, points, variance=None, covariates=None):
        """Estimates at points ((m, d), x first): see Krige.predict; with
        indicator (probabilities (m, K), corrected locations), and variance
        refused."""
        if not self._flavour:
            return super().predict(points, True if variance is None else variance, covariates)
        if covariates is not None:
            raise Error("covariates: expected none with block, transform or indicator kriging, got an array")
        x = as_coords("points", points, self.dim, least=0)
        if self._thr is not None:
            if variance is not None:
                refuse("variance", "no variance with indicator kriging (it gives probabilities)", variance)
            return self._indicator(x, lambda t: "point %d" % (t + 1))
        variance = as_bool("variance", True if variance is None else variance)
        est, var = self._eval(x, variance, lambda t: "point %d" % (t + 1))
        return (est, var) if variance else est

    def grid(self, extent, shape, variance=None, covariates=None):
        """Estimates at the cell centres of a grid: see Krige.grid; with
        indicator (probabilities (K,) + shape, corrected cells)."""
        if not self._flavour:
            return super().grid(extent, shape, True if variance is None else variance, covariates)
        if covariates is not None:
            raise Error("covariates: expected none with block, transform or indicator kriging, got an array")
        lo, hi = _extent(extent, self.dim)
        shape = _shape(shape, self.dim)
        for a in range(self.dim):  # the grid and the data span finite distances (the CLI's check)
            c = self._p[:, a]
            l, h = min(lo[a], float(c.min())), max(hi[a], float(c.max()))
            if not math.isfinite(4 * (h - l)):
                raise Error("extent: the grid and the data span %g to %g on axis %d, whose distances overflow; "
                            "expected a span below %g" % (l, h, a + 1, _DBL_MAX / 4))
        n = shape[::-1]
        try:  # the CLI's cell centres, x fastest: lo + (i + 0.5)(hi - lo)/n
            axes = [lo[a] + (np.arange(n[a]) + 0.5) * (hi[a] - lo[a]) / n[a] for a in range(self.dim)]
            g = np.meshgrid(*axes[::-1], indexing="ij")
            x = np.ascontiguousarray(np.column_stack([g[self.dim - 1 - a].ravel() for a in range(self.dim)]))
        except (MemoryError, ValueError) as e:
            raise Error("shape: %s: %s" % (shape, e)) from None
        where = lambda t: "cell %d" % t
        if self._thr is not None:
            if variance is not None:
                refuse("variance", "no variance with indicator kriging (it gives probabilities)", variance)
            cdf, nc = self._indicator(x, where)
            return np.ascontiguousarray(cdf.T).reshape((self._thr.size,) + shape), nc
        variance = as_bool("variance", True if variance is None else variance)
        est, var = self._eval(x, variance, where)
        return (est.reshape(shape), var.reshape(shape)) if variance else est.reshape(shape)

    def cross_validate(self, folds=None, seed=0):
        """Leave-one-out cross-validation: see Krige.cross_validate; the
        trans-Gaussian in the data's units (nl_krige_tg_cv), the indicator's
        probabilities with each threshold's Brier score (as the CLI's
        --json); block refused."""
        if not self._flavour:
            return super().cross_validate(folds, seed)
        if folds is not None:
            raise Error("folds: expected leave-one-out with block, transform or indicator kriging (as the CLI), got "
                        "folds=%r" % (folds,))
        if self._b is not None:
            raise Error("block: expected no block with cross_validate (leave-one-out predicts the data points, not "
                        "blocks), got block=%r" % (self.block,))
        n = self.n
        if self._thr is not None:
            cdf, nc = self._indicator(None, None)
            ind = (self._v[:, None] <= self._thr[None, :]).astype(np.float64)
            brier = ((ind - cdf) ** 2 / n).sum(axis=0)
            return dict(observed=self._v.copy(), probabilities=cdf, thresholds=self._thr.copy(), brier=brier,
                        corrected=nc, points=n, kind="indicator")
        pred, var = np.full(n, np.nan), np.full(n, np.nan)
        s = ffi.new("nl_krige_cv_summary *")
        check(self._call(lib.nl_krige_tg_cv, self._local, self._lam, _dptr(self._v), _dptr(pred), _dptr(var), s))
        err = self._v - pred
        return dict(observed=self._v.copy(), predicted=pred, variance=var, error=err, zscore=err / np.sqrt(var),
                    points=n, kind=self.kind, mean_error=s.mean_error, var_error=s.var_error, mean_zscore=s.mean_z,
                    var_zscore=s.var_z, rmse=s.rmse)

    def simulator(self, *args, **kw):
        if self._flavour:
            raise Error("krige: conditional simulation is of point kriging; expected a Krige without block, "
                        "transform or indicator, got a %s kriging" % self.kind)
        return super().simulator(*args, **kw)


# -- fitting a given variogram ---------------------------------------------

def _table(variogram):
    """(distance, gamma, pairs) arrays of a table path (nl_variogram_read)
    or of three sequences, and a keep-alive."""
    if isinstance(variogram, (str, bytes, os.PathLike)):
        _, b = as_path("variogram", variogram)
        out = ffi.new("nl_variogram **")
        check(lib.nl_variogram_read(b, out))
        vg = ffi.gc(out[0], lib.nl_variogram_free)
        return vg.distance, vg.gamma, vg.pairs, vg.nbins, vg
    want = "a table path, or (distance, gamma, pairs): three sequences of one length of finite numbers"
    try:
        d, g, p = (np.array(c, dtype=np.float64, ndmin=1) for c in variogram)
    except (TypeError, ValueError):
        refuse("variogram", want, variogram)
    if d.ndim != 1 or d.shape != g.shape or d.shape != p.shape or d.size == 0:
        refuse("variogram", want, variogram)
    for name, c, ok in (("distance", d, d > 0), ("gamma", g, g >= 0), ("pairs", p, (p >= 0) & (p == np.floor(p)))):
        bad = np.flatnonzero(~(np.isfinite(c) & ok))
        if bad.size:
            raise Error("variogram: %s of bin %d is %r; expected %s" % (name, bad[0] + 1, c[bad[0]], {
                "distance": "a finite distance > 0", "gamma": "a finite semivariance >= 0",
                "pairs": "a whole number of pairs >= 0"}[name]))
    return _dptr(d), _dptr(g), _dptr(p), d.size, (d, g, p)


def fit(*args, variogram=None, **kw):
    """With variogram=, the WLS fit of a given variogram, as ``noiselab fit
    --variogram VARIO.tsv``: a table path (columns distance, gamma, pairs of
    noiselab variogram -o, or gstat's np, dist, gamma) or (distance, gamma,
    pairs) (variogram()'s result; bins with 0 pairs are skipped), with
    model=, nugget=, fix= and weights= alone (the bins are fitted as they
    are: no data, width, cutoff or bins; method wls).  The model is checked
    in 2D, as the CLI's.  Returns the dict of a wls fit."""
    if variogram is None:
        return _analysis.fit(*args, **kw)
    extra = sorted(set(kw) - {"model", "nugget", "fix", "weights", "method"})
    if args or extra:
        raise Error("variogram: expected only model, nugget, fix and weights with a variogram to fit (its bins as "
                    "they are), got %s" % ", ".join(["%d positional" % len(args)] * bool(args) + extra))
    method = kw.get("method", "wls")
    if method != "wls":
        refuse("method", '"wls" with variogram (a likelihood needs the data)', method)
    weights = kw.get("weights")
    o, keep = _analysis._fit_options(kw.get("model", "markov"), kw.get("nugget", False), kw.get("fix"),
                                     "distance" if weights is None else weights)
    d, g, p, nb, keep_vg = _table(variogram)
    r = ffi.new("nl_fit_result *")
    check(lib.nl_fit_check_options(o, 2))
    try:
        with planner:
            check(lib.nl_fit_variogram(d, g, p, nb, 2, o, r))
        return _analysis._fit_result(r, "wls")
    finally:
        lib.nl_fit_result_free(r)


fit.__doc__ = _analysis.fit.__doc__ + "\n\n    " + fit.__doc__
