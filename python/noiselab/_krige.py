"""Kriging as an object, conditional simulation and sampling: noiselab.Krige,
noiselab.CondSim, noiselab.condsim and noiselab.sample, as the CLI's
``krige``, ``synth --condition`` and ``sample`` (analysis/krige.h,
analysis/krige_local.h, analysis/condsim.h, core/field_sample.h): every
number comes from the same library calls."""
import math
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from ._args import Error, as_bool, as_choice, as_coords, as_float, as_int, as_positive, as_values, refuse
from ._ffi import FieldView, Model, alloc_field, check, ffi, free_data, lib, owned_field, planner
from ._synth import _METHODS, Plan

_DRIFTS = ("constant", "linear", "quadratic")  # NL_DRIFT_* by index, as --drift
_BLOCK = 256        # NL_KRIGE_BLOCK: the global plan's blocks, whose bits do not depend on the split
_PARALLEL = 4096    # samples above which nl_krige_eval_grid runs its blocks in parallel
_EMPTY = "data in the neighbourhood of"  # nl_kl_point's message for too few data around a location
_DBL_MAX = float(np.finfo(np.float64).max)


def _dptr(a):
    return ffi.cast("double *", ffi.from_buffer(a))


def _workers():
    """Threads for the global plan's blocks at points: OpenMP's count
    (OMP_NUM_THREADS, else the CPUs this process may use), as the C
    functions' parallel loops."""
    try:
        k = int(os.environ.get("OMP_NUM_THREADS", "").split(",")[0])
    except ValueError:
        k = 0
    return k if k > 0 else len(os.sched_getaffinity(0))


def _extent(extent, dim):
    """(lo, hi) per axis, x first, from "a:b[,c:d[,e:f]]" (as --extent) or
    ((a, b), (c, d), ...); each a < b, finite, with a width that does not
    overflow (the CLI's checks)."""
    want = "%d ranges (lo, hi) with lo < hi, x first, or \"a:b%s\"" % (dim, ",c:d" * (dim - 1))
    if isinstance(extent, str):
        try:
            pairs = [tuple(float(v) for v in r.split(":")) for r in extent.split(",")]
        except ValueError:
            refuse("extent", want, extent)
    else:
        try:
            items = list(extent)
            if dim == 1 and len(items) == 2 and not any(isinstance(r, (str, bytes)) or hasattr(r, "__len__")
                                                        for r in items):
                items = [items]  # (lo, hi) of a 1D grid
            pairs = [tuple(r) for r in items]
        except TypeError:
            refuse("extent", want, extent)
    if len(pairs) != dim or any(len(r) != 2 for r in pairs):
        refuse("extent", want, extent)
    lo, hi = [], []
    for a, b in pairs:
        a, b = as_float("extent", a), as_float("extent", b)
        if not (b > a and math.isfinite(4 * (b - a))):
            refuse("extent", want + " whose widths do not overflow", extent)
        lo.append(a), hi.append(b)
    return lo, hi


def _shape(shape, dim):
    """A grid's numpy shape ((ny, nx): x last) of dim axes, each >= 1."""
    want = "%d integers >= 1 (numpy order: x last)" % dim
    items = (shape,) if np.ndim(shape) == 0 and not isinstance(shape, (str, bytes)) else shape
    try:
        items = tuple(items)
    except TypeError:
        refuse("shape", want, shape)
    if isinstance(shape, (str, bytes)) or len(items) != dim:
        refuse("shape", want, shape)
    return tuple(as_int("shape", s, 1, (1 << 63) - 1, want) for s in items)


def _covariates(name, cov, n, p=None):
    """An (n, p) float64 array of finite covariates (a vector: p = 1)."""
    try:
        c = np.asarray(cov, dtype=np.float64)
    except (TypeError, ValueError):
        refuse(name, "an array of numbers", cov)
    if c.ndim == 1:
        c = c.reshape(-1, 1)
    want = "an array of %d rows and %s columns" % (n, p if p else "at least 1")
    if c.ndim != 2 or c.shape[0] != n or c.shape[1] == 0 or (p and c.shape[1] != p):
        raise Error("%s: expected %s, got shape %s" % (name, want, c.shape))
    if not np.all(np.isfinite(c)):
        raise Error("%s: expected finite numbers, got %r" % (name, c[~np.isfinite(c)][0]))
    return np.ascontiguousarray(c)


def _grid_spacing(lo, hi, shape):
    """Spacing per axis, x first: (hi - lo) / n, as the CLI's."""
    n = shape[::-1]
    return [(hi[a] - lo[a]) / n[a] for a in range(len(n))]


class Krige:
    """Kriging planned once, as ``noiselab krige``: ordinary (unknown mean),
    simple (mean=M), universal (drift=), in local neighbourhoods (nmax=,
    radius=), with leave-one-out cross-validation and conditional
    simulation.

    points  (n, d) coordinates of the data (d = 1, 2, 3; x first), in the
            model's lag units; values their n values.
    acf     a covariance model spec, sums included
            ("nugget:var=0.05 + spherical:var=0.59,scale=897").
    mean    the known mean: simple kriging (--mean).
    nmax    each location from its nmax nearest data (gstat's nmax; --nmax).
    radius  only the data within this distance (gstat's maxdist; --radius).
    drift   "constant", "linear" or "quadratic": universal kriging with a
            polynomial drift in the coordinates (--drift; not with mean).
    covariates  (n, p) external drift: p covariates of each datum after the
            drift's terms (--drift NAME,...: gstat's z ~ c1 + ...); then
            predict and grid take the locations' covariates too.
    strict  refuse a singular system instead of solving it by the
            pseudo-inverse (global kriging only: no nmax, radius or drift).

    Without nmax, radius and drift the plan is analysis/krige.h's (the
    covariance matrix factorised once; rcond and pseudo_inverse say how it
    went); with any of them it is analysis/krige_local.h's (neighbourhoods
    through a k-d tree), as the CLI chooses.  Locations whose
    neighbourhood holds no datum (radius), or fewer than the drift's
    terms, get NaN estimates and variances (where the CLI stops with an
    error, and gstat gives NA).  Estimates and variances use every core
    (the library's OpenMP loops; at points with the global plan, blocks of
    256 on as many threads): the same bits whatever the thread count.

    Attributes: n, dim, model (the spec), kind ("ordinary", "simple",
    "universal-linear", ...), terms (drift terms: 1 ordinary, 0 simple),
    rcond, pseudo_inverse and mean (the plan's: the generalised-least-
    squares mean of ordinary kriging, or the known one; NaN, NaN, False and
    the known mean or NaN with a local plan).
    """

    def __init__(self, points, values, acf, *, mean=None, nmax=None, radius=None, drift=None, strict=False,
                 covariates=None):
        p = as_coords("points", points)
        v = as_values("values", values, p.shape[0])
        self._p, self._v = p, v
        self.n, self.dim = p.shape
        self._cov = None if covariates is None else _covariates("covariates", covariates, self.n)
        self.ncov = 0 if self._cov is None else self._cov.shape[1]
        if self.ncov and mean is not None:
            raise Error("covariates: expected no known mean with an external drift (universal kriging), got mean=%r"
                        % (mean,))
        self._mean = None if mean is None else as_float("mean", mean)
        self.nmax = None if nmax is None else as_int("nmax", nmax, 1, (1 << 63) - 1)
        self.radius = None if radius is None else as_positive("radius", radius)
        self.drift = None if drift is None else as_choice("drift", drift, _DRIFTS)
        self.strict = as_bool("strict", strict)
        if self.drift not in (None, "constant") and self._mean is not None:
            raise Error("mean: expected no drift with a known mean, got mean=%r and drift=%r" % (mean, drift))
        self.local = nmax is not None or radius is not None or drift is not None or self.ncov > 0
        if self.local and self.strict:
            raise Error("strict: applies to global kriging (no nmax, radius or drift), got strict=True")
        self._acf = acf
        self._m = Model(acf, "acf")
        self.model = self._m.spec
        self._reentrant = bool(lib.nl_model_is_reentrant(self._m.ptr))
        self._plan = self._local = self._cv = self._missing = None
        if self.local:
            self._local = self._local_plan(self.nmax or 0, self.radius or 0.0)
        else:
            self._global_plan()

    # -- plans --------------------------------------------------------------

    def _global_plan(self):
        out = ffi.new("nl_krige_plan **")
        simple = self._mean is not None
        with planner:
            check(lib.nl_krige_plan_alloc(self._m.ptr, self.dim, self.n, _dptr(self._p), _dptr(self._v),
                                          1 if simple else 0, self._mean if simple else 0.0,
                                          1 if self.strict else 0, out))
        self._plan = ffi.gc(out[0], lib.nl_krige_plan_free)
        info = ffi.new("nl_krige_info *")
        lib.nl_krige_plan_info(self._plan, info)
        self._info = (info.rcond, bool(info.pseudo_inverse), info.mean)

    def _local_plan(self, nmax, radius, pts=None, val=None, cov=None, missing=0):
        o = ffi.new("nl_krige_local_options *")
        o.nmax, o.radius, o.missing = nmax, radius, missing
        o.drift = _DRIFTS.index(self.drift or "constant")
        if self._mean is not None:
            o.drift, o.mean = lib.NL_DRIFT_NONE, self._mean
        cov = self._cov if cov is None and pts is None else cov
        if self.ncov:
            o.ncov, o.cov = self.ncov, _dptr(cov)
        pts = self._p if pts is None else pts
        val = self._v if val is None else val
        out = ffi.new("nl_krige_local **")
        with planner:
            check(lib.nl_krige_local_alloc(self._m.ptr, self.dim, pts.shape[0], _dptr(pts), _dptr(val), o, out))
        return ffi.gc(out[0], lib.nl_krige_local_free)

    @property
    def kind(self):
        if self._mean is not None:
            return "simple"
        return {"linear": "universal-linear", "quadratic": "universal-quadratic"}.get(self.drift, "ordinary")

    @property
    def terms(self):
        if self._local is not None:
            return int(lib.nl_krige_local_terms(self._local))
        return 0 if self._mean is not None else 1

    @property
    def rcond(self):
        """Reciprocal condition number of the data's covariance matrix
        (1-norm estimate; global plan; NaN for a local one)."""
        return self._info[0] if self._plan is not None else float("nan")

    @property
    def pseudo_inverse(self):
        """The global system was singular and solved by the pseudo-inverse."""
        return self._info[1] if self._plan is not None else False

    @property
    def mean(self):
        """The global plan's mean (generalised least squares, or the known
        one); a local plan: the known mean, or NaN."""
        if self._plan is not None:
            return self._info[2]
        return float("nan") if self._mean is None else self._mean

    # -- estimates ----------------------------------------------------------

    def _call(self, fn, *args):
        """A C call on the plan: under the package's lock for models that
        are not reentrant (expr:, muParser)."""
        if self._reentrant:
            return fn(*args)
        with planner:
            return fn(*args)

    def _blocks(self, x, est, var):
        """The global plan at points: blocks of 256 on threads (cffi
        releases the GIL), cut at multiples of 256 so each block is the one
        a single call would make."""
        m = x.shape[0]
        vp = lambda a, b: _dptr(var[a:b]) if var is not None else ffi.NULL
        one = lambda a, b: check(self._call(lib.nl_krige_eval_block, self._plan, b - a, _dptr(x[a:b]),
                                            _dptr(est[a:b]), vp(a, b)))
        k = _workers() if self._reentrant and m > _PARALLEL else 1
        if k <= 1:
            one(0, m)
            return
        nblk = (m + _BLOCK - 1) // _BLOCK
        step = (nblk + k - 1) // k * _BLOCK
        with ThreadPoolExecutor(max_workers=k) as ex:
            for r in ex.map(lambda a: one(a, min(a + step, m)), range(0, m, step)):
                pass

    def _holes(self, st, est, var, where, retry):
        """After a local run that failed with status st: the locations left
        NaN whose neighbourhood is too small stay NaN (retry(t) re-runs
        location t alone and returns its status and estimate, variance);
        any other failure raises the library's error."""
        msg = ffi.string(lib.nl_errmsg()).decode("utf-8", "replace")
        if st != 1 or _EMPTY not in msg:
            raise Error(msg, int(st))
        for t in np.flatnonzero(np.isnan(est)):
            s, e, v = retry(int(t))
            if s == 0:
                est[t] = e
                if var is not None:
                    var[t] = v
            elif s != 1 or _EMPTY not in ffi.string(lib.nl_errmsg()).decode("utf-8", "replace"):
                raise Error(ffi.string(lib.nl_errmsg()).decode("utf-8", "replace") + " (%s)" % where(t), int(s))

    def _at(self, x):
        """Location x (dim coordinates) alone on the local plan."""
        e, v = ffi.new("double *"), ffi.new("double *")
        xs = np.ascontiguousarray(x, dtype=np.float64)
        s = self._call(lib.nl_krige_local_eval, self._local, 1, _dptr(xs), e, v)
        return s, e[0], v[0]

    def _with_cov(self, x, cov, variance):
        """The external drift's estimates at x with the locations' covariates
        (nl_krige_local_eval_at; NaN where the neighbourhood is too small)."""
        est = np.full(x.shape[0], np.nan)
        var = np.full(x.shape[0], np.nan) if variance else None
        if x.shape[0]:
            k = self._missing if self._missing is not None else self._local_plan(self.nmax or 0, self.radius or 0.0,
                                                                                  missing=1)
            self._missing = k
            st = self._call(lib.nl_krige_local_eval_at, k, x.shape[0], _dptr(x), _dptr(cov), _dptr(est),
                            _dptr(var) if variance else ffi.NULL)
            if st and not (st == 1 and _EMPTY in ffi.string(lib.nl_errmsg()).decode("utf-8", "replace")):
                check(st)
        return (est, var) if variance else est

    def predict(self, points, variance=True, covariates=None):
        """Estimates at points ((m, d) coordinates, x first): (estimate,
        variance) as float64 arrays of m values, or the estimates alone with
        variance=False; NaN where the neighbourhood holds too few data.
        covariates: (m, p), the points' covariates (a Krige with an external
        drift needs them; as krige --at with --drift NAME)."""
        x = as_coords("points", points, self.dim, least=0)
        variance = as_bool("variance", variance)
        m = x.shape[0]
        if self.ncov or covariates is not None:
            return self._with_cov(x, self._loc_cov(covariates, m), variance)
        est = np.full(m, np.nan)
        var = np.full(m, np.nan) if variance else None
        if m and self._plan is not None:
            self._blocks(x, est, var)
        elif m:
            st = self._call(lib.nl_krige_local_eval, self._local, m, _dptr(x), _dptr(est),
                            _dptr(var) if variance else ffi.NULL)
            if st:
                self._holes(st, est, var, lambda t: "point %d" % (t + 1), lambda t: self._at(x[t]))
        return (est, var) if variance else est

    def grid(self, extent, shape, variance=True, covariates=None):
        """Estimates on the cell centres of a grid, as ``noiselab krige
        --grid --extent``: sample i of axis a at lo + (i + 0.5)(hi - lo)/n.
        extent: (lo, hi) per axis, x first ((xlo, xhi), (ylo, yhi)), or the
        CLI's "a:b,c:d"; shape: numpy order, (ny, nx) (x last; --grid
        nx x ny).  Returns (estimate, variance) arrays of that shape, or the
        estimates alone with variance=False; NaN where the neighbourhood
        holds too few data.  covariates: (p,) + shape, the cells'
        covariates (a Krige with an external drift needs them; as krige
        --covariate NAME=FIELD)."""
        lo, hi = _extent(extent, self.dim)
        shape = _shape(shape, self.dim)
        variance = as_bool("variance", variance)
        if self.ncov or covariates is not None:
            n = shape[::-1]
            if covariates is not None:  # (p,) + shape, or shape for one covariate: cells x fastest
                c = np.asarray(covariates, dtype=np.float64)
                if c.shape == shape:
                    c = c[None]
                if c.shape != (self.ncov,) + shape:
                    raise Error("covariates: expected an array of shape %s, the Krige's %d covariates on the grid, "
                                "got %s" % ((self.ncov,) + shape, self.ncov, c.shape))
                covariates = c.reshape(self.ncov, -1).T
            c = self._loc_cov(covariates, int(np.prod(shape)))
            axes = [lo[a] + (np.arange(n[a]) + 0.5) * ((hi[a] - lo[a]) / n[a]) for a in range(self.dim)]
            g = np.meshgrid(*axes[::-1], indexing="ij")
            x = np.ascontiguousarray(np.column_stack([g[self.dim - 1 - a].ravel() for a in range(self.dim)]))
            r = self._with_cov(x, c, variance)
            return (r[0].reshape(shape), r[1].reshape(shape)) if variance else r.reshape(shape)
        for a in range(self.dim):  # the grid and the data span finite distances (the CLI's check)
            c = self._p[:, a]
            l, h = min(lo[a], float(c.min())), max(hi[a], float(c.max()))
            if not math.isfinite(4 * (h - l)):
                raise Error("extent: the grid and the data span %g to %g on axis %d, whose distances overflow; "
                            "expected a span below %g" % (l, h, a + 1, _DBL_MAX / 4))
        hx = _grid_spacing(lo, hi, shape)
        fields, arrays = [], []
        for _ in range(2 if variance else 1):
            try:
                fields.append(alloc_field(shape, hx[::-1], zero=False))
            except Error as e:
                raise Error("shape: %s: %s" % (shape, e), e.code) from None
            arrays.append(owned_field(fields[-1], free_data))
        for a in arrays:
            a[...] = np.nan
        E, V = fields[0], fields[1] if variance else ffi.NULL
        lo_c = ffi.new("double[3]", lo + [0.0] * (3 - self.dim))
        if self._plan is not None:
            check(self._call(lib.nl_krige_eval_grid, self._plan, lo_c, E, V))
        else:
            st = self._call(lib.nl_krige_local_grid, self._local, lo_c, E, V)
            if st:
                n = list(shape[::-1]) + [1] * (3 - self.dim)

                def cell(t):  # as the library's cell centres
                    idx = (t % n[0], t // n[0] % n[1], t // (n[0] * n[1]))
                    return [lo[a] + (idx[a] + 0.5) * hx[a] for a in range(self.dim)]
                self._holes(st, arrays[0].reshape(-1), arrays[1].reshape(-1) if variance else None,
                            lambda t: "cell %d" % t, lambda t: self._at(cell(t)))
        return (arrays[0], arrays[1]) if variance else arrays[0]

    def cross_validate(self, folds=None, seed=0):
        """Leave-one-out cross-validation, as ``noiselab krige
        --cross-validate`` (gstat's krige.cv): each datum predicted from its
        neighbourhood without it.  Returns a dict of arrays (n each):
        observed, predicted, variance, error (observed - predicted), zscore
        (error / sqrt(variance)), and of numbers: mean_error, var_error,
        mean_zscore, var_zscore (divisor n - 1), rmse, points, kind (the
        CLI's --json).  A global plan cross-validates with every datum (at
        most 2000).  Data whose neighbourhood without them holds too few data
        get NaN, and the summary is over the others.
        folds: K (an integer, 2 <= K < n: K-fold, the folds drawn from seed
        as ``--cross-validate K --seed S``) or n fold ids (any integers, as
        ``--folds COLUMN``: gstat's krige.cv(nfold = K) with its folds):
        each fold predicted from the other data alone."""
        if folds is not None or self.ncov:
            return self._folds(folds, seed)
        k = self._local
        if k is None:
            if self._cv is None:
                self._cv = self._local_plan(0, 0.0)
            k = self._cv
        n = self.n
        pred, var = np.full(n, np.nan), np.full(n, np.nan)
        s = ffi.new("nl_krige_cv_summary *")
        st = self._call(lib.nl_krige_local_cv, k, _dptr(pred), _dptr(var), s)
        err = self._v - pred
        out = dict(observed=self._v.copy(), predicted=pred, variance=var, error=err, zscore=err / np.sqrt(var),
                   points=n, kind=self.kind)
        if st == 0:
            out.update(mean_error=s.mean_error, var_error=s.var_error, mean_zscore=s.mean_z, var_zscore=s.var_z,
                       rmse=s.rmse)
            return out
        self._holes(st, pred, var, lambda t: "datum %d" % (t + 1), self._left_out)
        ok = ~np.isnan(pred)
        if (var[ok] <= 0).any():
            t = int(np.flatnonzero(ok & (var <= 0))[0])
            raise Error("kriging: cross-validation: the kriging variance at datum %d is %g; expected a positive "
                        "variance (duplicate points?)" % (t + 1, var[t]))
        out["error"] = err = self._v - pred
        out["zscore"] = z = err / np.sqrt(var)
        e, z, m = err[ok], z[ok], max(int(ok.sum()), 1)
        out.update(mean_error=e.sum() / m, mean_zscore=z.sum() / m, rmse=math.sqrt((e * e).sum() / m),
                   var_error=((e * e).sum() - e.sum() ** 2 / m) / (m - 1) if m > 1 else float("nan"),
                   var_zscore=((z * z).sum() - z.sum() ** 2 / m) / (m - 1) if m > 1 else float("nan"))
        return out

    def _folds(self, folds, seed):
        """k-fold (or, with covariates and no folds, leave-one-out)
        cross-validation through nl_krige_local_cv_folds."""
        n = self.n
        if folds is None:
            f = np.arange(1, n + 1, dtype=np.int64)
        elif np.ndim(folds) == 0:
            K = as_int("folds", folds, 2, n, "an integer K, 2 <= K <= %d (the data), or %d fold ids" % (n, n))
            seed = as_int("seed", seed, 0, (1 << 64) - 1)
            f = np.empty(n, dtype=np.int64) if K < n else np.arange(1, n + 1, dtype=np.int64)
            if K < n:
                lib.nl_krige_draw_folds(seed, n, K, ffi.cast("long *", ffi.from_buffer(f)))
        else:
            f = np.asarray(folds)
            if f.shape != (n,) or not np.all(np.isfinite(f.astype(float))) or np.any(f != np.round(f)):
                refuse("folds", "an integer K or %d integer fold ids" % n, folds)
            f = np.ascontiguousarray(f, dtype=np.int64)
        k = self._local_plan(self.nmax or 0, self.radius or 0.0, missing=1)
        pred, var = np.full(n, np.nan), np.full(n, np.nan)
        s = ffi.new("nl_krige_cv_summary *")
        check(self._call(lib.nl_krige_local_cv_folds, k, ffi.cast("long *", ffi.from_buffer(f)), _dptr(pred),
                         _dptr(var), s))
        err = self._v - pred
        return dict(observed=self._v.copy(), predicted=pred, variance=var, error=err, zscore=err / np.sqrt(var),
                    fold=f, points=n, kind=self.kind, mean_error=s.mean_error, var_error=s.var_error,
                    mean_zscore=s.mean_z, var_zscore=s.var_z, rmse=s.rmse)

    def _loc_cov(self, cov, m):
        """The locations' covariates: (m, p) as the data's."""
        if not self.ncov:
            raise Error("covariates: expected none (this Krige has no external drift), got an array")
        if cov is None:
            raise Error("covariates: expected the locations' %d covariates (the Krige's external drift), got none"
                        % self.ncov)
        return _covariates("covariates", cov, m, self.ncov)

    def _left_out(self, t):
        """Datum t predicted by a plan of the other data (its
        cross-validation neighbourhood: the same nearest, by index)."""
        keep = np.r_[0:t, t + 1:self.n]
        try:
            k = self._local_plan(self.nmax or 0, self.radius or 0.0, np.ascontiguousarray(self._p[keep]),
                                 np.ascontiguousarray(self._v[keep]))
        except Error as e:
            return e.code, float("nan"), float("nan")
        e, v = ffi.new("double *"), ffi.new("double *")
        s = self._call(lib.nl_krige_local_eval, k, 1, _dptr(self._p[t]), e, v)
        return s, e[0], v[0]

    # -- conditional simulation ----------------------------------------------

    def simulator(self, method, shape, extent, at=None, hood=None, rekrige=False, **options):
        """A :class:`CondSim` of this kriging's data, model, mean and nmax."""
        return CondSim(self, method, shape, extent, at=at, hood=hood, rekrige=rekrige, **options)

    def simulate(self, method, shape, extent, seed=0, realizations=1, at=None, hood=None, rekrige=False,
                 **options):
        """Conditional realizations on a grid, as ``noiselab synth METHOD
        --condition DATA --extent ... --seed SEED --realizations K`` (with
        this plan's mean and nmax): realization k from seed + k, bit for bit
        the CLI's.  See :class:`CondSim` for the arguments.  Returns an array
        of shape (realizations,) + shape or, with at, (fields, values) with
        values (realizations, len(at)): each realization at the points."""
        sim = self.simulator(method, shape, extent, at=at, hood=hood, rekrige=rekrige, **options)
        seed = as_int("seed", seed, 0, (1 << 64) - 1)
        k = as_int("realizations", realizations, 1, 9999)
        if seed + k - 1 >= 1 << 64:
            raise Error("realizations: seed + realizations - 1 must be below 2^64, got seed %d and %d" % (seed, k))
        runs = [sim(seed + j) for j in range(k)]
        if at is None:
            return np.stack(runs)
        return np.stack([r[0] for r in runs]), np.stack([r[1] for r in runs])

    def __repr__(self):
        return "noiselab.Krige(%s, n=%d, dim=%d, model=%r)" % (self.kind, self.n, self.dim, self.model)


class CondSim:
    """Conditional simulation planned once (analysis/condsim.h): Z = U +
    K[d - U(t)], U an unconditional realization of the kriging's model by
    `method` (fft, circulant, subdiv: an exact, conditionable one) on a grid
    of cell centres, K kriging (ordinary, or simple with the Krige's mean;
    from the nmax nearest data with its nmax; not with radius or drift).
    ``sim(seed)`` returns the field (numpy shape, x last) or, with at,
    (field, values at the points), the same bits as ``noiselab synth METHOD
    --acf SPEC --size ... --condition DATA --extent ... --seed SEED``.

    krige    a :class:`Krige` (its data, model, mean, nmax).
    shape    the grid's numpy shape ((ny, nx); --size nx x ny).
    extent   (lo, hi) per axis, x first, or "a:b,c:d" (--extent): sample i of
             axis a at lo + (i + 0.5)(hi - lo)/n.
    at       (np, d) points within the extent where the realizations are
             also returned, drawn jointly with the grid.
    hood     samples per axis around a datum between samples (1..16;
             default 4); rekrige: krige each residual anew instead of
             keeping the weights.
    options  the method's own (as :func:`noiselab.synth`).

    Attributes: info (the plan's figures: n, on_samples, sites, hood,
    groups, largest, unlinked, screening, worst, max_move, reuse,
    weight_bytes), plan (the unconditional :class:`noiselab.Plan`),
    shape, extent.  Calls may run from several threads at once.
    """

    def __init__(self, krige, method, shape, extent, at=None, hood=None, rekrige=False, **options):
        if not isinstance(krige, Krige):
            refuse("krige", "a noiselab.Krige", krige)
        if krige.radius is not None or krige.drift is not None:
            raise Error("krige: conditional simulation kriges with nmax and mean only; expected no radius or drift, "
                        "got radius=%r, drift=%r" % (krige.radius, krige.drift))
        t = _METHODS.get(method) if isinstance(method, str) else None
        if t is not None and not t.caps & lib.NL_METHOD_CONDITIONABLE:
            names = [k for k, d in _METHODS.items() if d.caps & lib.NL_METHOD_CONDITIONABLE]
            raise Error("method: conditional simulation takes %s, got %r" % (", ".join(names), method))
        dim = krige.dim
        self.shape = _shape(shape, dim)
        lo, hi = _extent(extent, dim)
        self.extent = tuple(zip(lo, hi))
        hx = _grid_spacing(lo, hi, self.shape)
        self.plan = Plan(method, acf=krige._acf, size=self.shape, spacing=hx[::-1], **options)
        self._spacing = hx[::-1]
        ats = np.zeros((0, dim)) if at is None else as_coords("at", at, dim, least=0)
        self._np, self._at = ats.shape[0], at is not None
        o = ffi.new("nl_condsim_options *")
        o.simple = 1 if krige._mean is not None else 0
        o.mean = krige._mean or 0.0
        o.nmax = krige.nmax or 0
        o.hood = 0 if hood is None else as_int("hood", hood, 1, 16)
        o.rekrige = 1 if as_bool("rekrige", rekrige) else 0
        g = ffi.new("nl_field *")
        g.dim = dim
        for a in range(3):
            g.n[a] = self.shape[::-1][a] if a < dim else 1
            g.h[a] = hx[a] if a < dim else 1.0
        g.count = int(np.prod(self.shape))
        lo_c = ffi.new("double[3]", lo + [0.0] * (3 - dim))
        out = ffi.new("nl_condsim_plan **")
        with planner:
            check(lib.nl_condsim_plan_alloc(krige._m.ptr, krige.n, _dptr(krige._p), _dptr(krige._v), lo_c, g, o,
                                            ats.shape[0], _dptr(ats) if ats.shape[0] else ffi.NULL, out))
        self._p = ffi.gc(out[0], lib.nl_condsim_plan_free)
        self._krige = krige  # the plan borrows its model
        i = ffi.new("nl_condsim_info *")
        lib.nl_condsim_plan_info(self._p, i)
        self.info = {k: getattr(i, k) for k, _ in ffi.typeof(i[0]).fields}
        self.info["reuse"] = bool(i.reuse)

    def __call__(self, seed=0):
        """Realization `seed` (0 .. 2^64 - 1: the unconditional field's and
        the draws'): the field or, with at, (field, values at the points)."""
        seed = as_int("seed", seed, 0, (1 << 64) - 1)
        f = self.plan(seed)
        v = FieldView(f, self._spacing, "field", writable=True)
        z = np.empty(self._np)
        zp = _dptr(z) if self._np else ffi.NULL
        check(self._krige._call(lib.nl_condsim_execute, self._p, v.f, seed, zp))
        return (f, z) if self._at else f

    def __repr__(self):
        return "noiselab.CondSim(%r, shape=%r, extent=%r)" % (self.plan.method, self.shape, self.extent)


def condsim(points, values, acf, method, shape, extent, *, mean=None, nmax=None, seed=0, realizations=1, at=None,
            hood=None, rekrige=False, **options):
    """Conditional realizations, as ``noiselab synth METHOD --acf SPEC
    --condition DATA --extent ... --seed SEED --realizations K [--mean M]
    [--nmax K]``: ``Krige(points, values, acf, mean=, nmax=).simulate(...)``
    (see :class:`Krige` and :class:`CondSim`).  Returns an array of shape
    (realizations,) + shape, or (fields, values at the points) with at."""
    k = Krige(points, values, acf, mean=mean, nmax=nmax)
    return k.simulate(method, shape, extent, seed=seed, realizations=realizations, at=at, hood=hood,
                      rekrige=rekrige, **options)
