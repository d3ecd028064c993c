"""Ensembles: the mean of several fields' estimates and its standard error
(analysis/ensemble.h), as ``noiselab acf|psd|hist F1 F2 ...`` print them."""
import numpy as np

from ._analysis import _bins, _dptr, _lags, _mean, _welch
from ._args import as_bool, as_fields
from ._ffi import Error, FieldView, ffi, lib, owned_field, planner


class _Source:
    """The fields as the library's callback source: field k is viewed
    (converted when it is not float64) when the driver asks for it and let go
    when the driver hands it back, so that K converted copies never coexist."""

    def __init__(self, fields, spacing, what):
        fields = as_fields(what + ": fields", fields)
        self.fields, self.spacing, self.what = fields, spacing, what
        self.views, self.error = {}, None
        self._get = ffi.callback("int(void *, size_t, const nl_field **)", self.get, error=1, onerror=self.onerror)
        self._put = ffi.callback("void(void *, size_t, const nl_field *)", self.put)
        self.src = ffi.new("nl_ensemble_source *")
        self.src.K = len(fields)
        self.src.get, self.src.put = self._get, self._put

    def get(self, ctx, k, out):
        v = FieldView(self.fields[k], self.spacing, "%s: field %d" % (self.what, k))
        self.views[k] = v
        out[0] = v.f
        return 0

    def put(self, ctx, k, f):
        self.views.pop(k, None)

    def onerror(self, exc_type, exc_value, tb):
        self.error = exc_value

    def first(self):
        """Field 0's view, for the checks made on the first field."""
        return FieldView(self.fields[0], self.spacing, "%s: field 0" % self.what).f

    def check(self, status, bad):
        """Raise what the driver met: the callback's own error, or the
        library's message with the field it concerns."""
        if self.error is not None:
            raise self.error
        if status:
            msg = ffi.string(lib.nl_errmsg()).decode("utf-8", "replace")
            where = "field %d: " % bad[0] if bad[0] < self.src.K else ""
            raise Error("%s: %s%s" % (self.what, where, msg), int(status))


def ensemble_acf(fields, spacing=1.0, max_lag=None, axis="x", radial=False, unbiased=False, mean=None):
    """The autocorrelation of K >= 2 fields of one shape and spacing (e.g.
    realizations with different seeds), each estimated as :func:`acf` does,
    then their mean and its standard error (their sample sd over sqrt K), as
    ``noiselab acf F1 F2 ...``.  Returns (lag, acf, se), float64 arrays of
    max_lag/h + 1 entries."""
    s = _Source(fields, spacing, "ensemble_acf")
    ax, nl = _lags(s.first(), axis, radial, max_lag)
    o = ffi.new("nl_ensemble_acf_opts *", dict(mean=_mean(mean), unbiased=1 if as_bool("unbiased", unbiased) else 0,
                                                axis=ax, radial=1 if radial else 0, nlag=nl))
    lag, val, se, bad = np.empty(nl), np.empty(nl), np.empty(nl), ffi.new("size_t *")
    with planner:
        st = lib.nl_ensemble_acf(s.src, o, _dptr(lag), _dptr(val), _dptr(se), bad)
    s.check(st, bad)
    return lag, val, se


def ensemble_psd(fields, spacing=1.0, welch=None, mean=None, grid=False):
    """The spectrum of K >= 2 fields of one shape and spacing, each estimated
    as :func:`psd` does (periodogram, or Welch's with welch=S), then the mean
    profile and its standard error, as ``noiselab psd F1 F2 ...``.  Returns
    (freq, psd, se); with grid=True also the mean spectrum on the grid
    (wrapped order) as a fourth array over the library's memory."""
    s = _Source(fields, spacing, "ensemble_psd")
    x = s.first()
    grid = as_bool("grid", grid)
    o = ffi.new("nl_ensemble_psd_opts *", dict(mean=_mean(mean), welch=_welch(welch)))
    k = int(x.n[0] + x.n[1] + x.n[2])
    freq, val, se = np.empty(k), np.empty(k), np.empty(k)
    P, nf, bad = ffi.new("nl_field **"), ffi.new("size_t *"), ffi.new("size_t *")
    with planner:
        st = lib.nl_ensemble_psd(s.src, o, P, _dptr(freq), _dptr(val), _dptr(se), nf, ffi.NULL, bad)
    s.check(st, bad)
    spectrum = owned_field(P[0])
    n = nf[0]
    return (freq[:n], val[:n], se[:n], spectrum) if grid else (freq[:n], val[:n], se[:n])


def _moments_dict(m):
    return dict(n=int(m.n), mean=m.mean, variance=m.variance, skewness=m.skewness, kurtosis=m.kurtosis,
                min=m.min, max=m.max)


def ensemble_hist(fields, bins=50):
    """Moments and histogram of K >= 2 fields (of any sizes), as ``noiselab
    hist F1 F2 ...``: each field's moments, their means and standard errors;
    the histogram on `bins` equal bins over the overall range, as the mean
    count per field and its standard error.  Returns (edges, counts, se,
    moments, moments_se): moments as :func:`moments` gives them (n the samples
    of all fields, min and max the overall range), moments_se the standard
    errors of mean, variance, skewness and kurtosis."""
    bins = _bins(bins)
    s = _Source(fields, 1.0, "ensemble_hist")
    if s.src.K < 2:
        raise Error("ensemble_hist: expected at least 2 fields, got %d" % s.src.K)
    m, mse, bad = ffi.new("nl_moments *"), ffi.new("nl_moments *"), ffi.new("size_t *")
    s.check(lib.nl_ensemble_moments(s.src, m, mse, bad), bad)
    edges, counts, se = np.empty(bins + 1), np.empty(bins), np.empty(bins)
    s.check(lib.nl_ensemble_hist(s.src, bins, m.min, m.max, _dptr(edges), _dptr(counts), _dptr(se), bad), bad)
    mse_d = {k: v for k, v in _moments_dict(mse).items() if k in ("mean", "variance", "skewness", "kurtosis")}
    return edges, counts, se, _moments_dict(m), mse_d

