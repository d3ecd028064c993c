"""Analysis verbs: acf, psd, hist, check, coeffs, nonlin, shape, krige,
variogram, fit (as the CLI's; cli/cmd_*.c)."""
import math

import numpy as np

from ._args import (as_array, as_bool, as_choice, as_coords, as_float, as_int, as_positive, as_spacing, as_str,
                    as_values, refuse)
from ._ffi import Dist, Error, FieldView, Model, alloc_field, check, ffi, lib, owned_field, planner
from ._krige import Krige
from ._model import Model as PublicModel, model_of

_AXES = {"x": 0, "y": 1, "z": 2}


def _dptr(a):
    """double * over a C-ordered float64 numpy array (no copy)."""
    return ffi.cast("double *", ffi.from_buffer(a))


def _mean(mean):
    """The known mean, or NaN (none: the sample mean)."""
    return float("nan") if mean is None else as_float("mean", mean)


def _owned(out_pp):
    return owned_field(out_pp[0])


def _lags(x, axis, radial, max_lag, grid=None):
    """acf's axis index and number of lags for field x (acf's checks)."""
    ax = _AXES[as_choice("axis", axis, tuple(_AXES))]
    if ax >= x.dim:
        raise Error('axis: the field is %dD, got axis "%s"' % (x.dim, axis))
    if as_bool("radial", radial) and x.dim == 1:
        raise Error("radial: expected a 2D or 3D field, got 1D")
    _grid(grid)
    n_ax, h_ax = int(x.n[ax]), float(x.h[ax])
    if not math.isfinite(n_ax * h_ax):
        raise Error("spacing: the lags of %d samples at spacing %g overflow; expected a spacing below %.3g"
                    % (n_ax, h_ax, np.finfo(np.float64).max / n_ax))
    if max_lag is None:
        nl = n_ax // 4
    else:
        ml = as_float("max_lag", max_lag, 0.0)
        if not ml / h_ax < n_ax or math.floor(ml / h_ax + 1e-9) >= n_ax:
            raise Error("max_lag: expected at most %g for %d samples, got %g" % ((n_ax - 1) * h_ax, n_ax, ml))
        nl = int(math.floor(ml / h_ax + 1e-9))
    return ax, nl + 1


def _grid(grid):
    if grid is not None:
        as_choice("grid", grid, ("wrapped", "centred"))
    return grid


def acf(field, spacing=1.0, max_lag=None, axis="x", radial=False, unbiased=False, mean=None, target=None,
        grid=None, bands=False, realizations=1):
    """Autocorrelation (autocovariance) estimate of a field, as ``noiselab acf``.

    field     1D, 2D (ny, nx) or 3D array of finite samples.
    spacing   grid spacing (one value or one per axis): lags are in its
              length units.
    max_lag   largest lag in length units (default a quarter of the axis).
    axis      "x" (the last numpy axis), "y" or "z": the lag direction.
    radial    2D/3D: average over directions in bins one sample spacing wide.
    unbiased  divide by the number of overlapping pairs instead of N.
    mean      the known mean to remove (default: the sample mean).
    target    a model spec or noiselab.Model: also return the model's R at
              each lag.
    grid      None, "wrapped" or "centred": instead of a profile, the whole
              estimate (2 n per axis; wrapped: lag i at index i, negative lags
              from the end; centred: lag 0 at the centre, as -o OUT.exr),
              as an array over the library's memory.
    bands     True: also the 95% band of the (biased, along an axis)
              estimate, returned in a dict (below).  With target, the
              MODEL band: where the estimate of a field of this size falls
              when the model is true (Model.acf_band: its expectation and
              Bartlett's variance from the model's R).  Without, the
              PLUG-IN band of 1D fields (nl_acf_bartlett_band): Bartlett's
              variance with the estimate in place of R, around the estimate.
    realizations  with bands and target: the band of the mean of this many
              independent estimates (its half-width over sqrt(realizations)),
              e.g. for noiselab.ensemble_acf's mean.

    Returns (lag, acf) or, with target, (lag, acf, target) as float64 arrays
    of max_lag/h + 1 entries (radial: NaN for an empty bin), the estimate in
    the field's squared units (biased: sum of products / N).  With
    bands=True a dict: lag, acf, band ("model" or "plug-in") and, for the
    model band, target (R), expected (the estimate's expectation),
    model_lo, model_hi; for the plug-in band plugin_lo, plugin_hi.
    """
    v = FieldView(field, spacing, "acf: field")
    x = v.f
    ax, nl = _lags(x, axis, radial, max_lag, grid)
    radial, unbiased, mu = as_bool("radial", radial), as_bool("unbiased", unbiased), _mean(mean)
    m = None if target is None else model_of(target, "target")
    if as_bool("bands", bands):
        _bands_check(x, radial, unbiased, grid, m, realizations)
    full = ffi.new("nl_field **")
    with planner:
        check(lib.nl_acf_full(x, mu, 1 if unbiased else 0, full))
    F = full[0]
    if grid == "wrapped":
        return owned_field(F)
    try:
        if grid == "centred":
            C = ffi.new("nl_field **")
            check(lib.nl_acf_centred_alloc(F, C))
            return owned_field(C[0])
        lag, val = np.empty(nl), np.empty(nl)
        if radial:
            cnt = ffi.new("size_t[]", nl)
            check(lib.nl_acf_radial(F, nl, _dptr(lag), _dptr(val), cnt))
        else:
            check(lib.nl_acf_axis(F, ax, nl - 1, _dptr(lag), _dptr(val)))
        if bands and m is None:
            lo, hi = np.empty(nl), np.empty(nl)
            check(lib.nl_acf_bartlett_band(F, x.count, nl - 1, _dptr(val), _dptr(lo), _dptr(hi)))
            return dict(lag=lag, acf=val, band="plug-in", plugin_lo=lo, plugin_hi=hi)
    finally:
        if grid != "wrapped":
            lib.nl_field_free(F)
    if bands:
        shape = tuple(int(x.n[a]) for a in reversed(range(x.dim)))
        spacing = tuple(float(x.h[a]) for a in reversed(range(x.dim)))
        b = PublicModel(target).acf_band(shape, spacing, lag[-1], axis, realizations, known_mean=mean is not None)
        return dict(lag=lag, acf=val, band="model", target=b["target"], expected=b["expected"],
                    model_lo=b["lo"], model_hi=b["hi"])
    if m is None:
        return lag, val
    tgt = np.empty(nl)
    with planner:
        check(lib.nl_acf_model_values(m.ptr, x.dim, x.n, x.h, 0 if radial else ax, _dptr(lag), nl, _dptr(tgt)))
    return lag, val, tgt


def _bands_check(x, radial, unbiased, grid, m, realizations):
    """What acf(bands=True) takes: a profile of the biased estimate along an
    axis; without a model, a 1D field."""
    if radial or unbiased or grid is not None:
        raise Error("bands: Bartlett's band is for the biased estimate along an axis; expected radial=False, "
                    "unbiased=False and grid=None")
    if m is None and x.dim != 1:
        raise Error("bands: the plug-in band (no target) is for 1D fields, got %dD; give target= for the "
                    "model's band" % x.dim)
    if m is None and realizations != 1:
        raise Error("realizations: the plug-in band is for one field; give target= for the band of a mean")


def _welch(welch):
    """Welch's segment length in samples (0: none)."""
    return 0 if welch is None else as_int("welch", welch, 4, (1 << 63) - 1)


def psd(field, spacing=1.0, welch=None, mean=None, grid=None, target=None, counts=False):
    """Power spectral density estimate, as ``noiselab psd``.

    The periodogram P(f) = (h1...hd / N) |DFT(x - mean)|^2, or with
    welch=S Welch's average of Hann-windowed segments of S samples per axis
    overlapping by half (1D and 2D): a TWO-SIDED density, in the field's
    squared units per (cycles per unit length)^dim, so that the sum of P over
    the grid frequencies times the frequency cell is the mean square.

    Returns (freq, psd): 1D f = 0 .. Nyquist (i / (n h)); 2D/3D the radial
    average in bins one frequency step wide (NaN for an empty bin); freq in
    cycles per unit length.  grid="wrapped" returns the whole spectrum
    (wrapped order, numpy.fft.fftfreq's) and grid="centred" with zero
    frequency at the centre, as arrays over the library's memory.

    target (a model spec or noiselab.Model) adds the model's spectrum on the
    estimate's grid (the field's; with welch=S, S samples per axis), in the
    same layout: returns (freq, psd, target), the column of ``noiselab psd
    --target`` (Model.periodogram_target, Model.welch_target): the sampled
    process's spectrum, aliasing included.

    counts=True appends the number of grid ordinates averaged into each
    value (float64; 1 in 1D, 0 for an empty radial bin): a radial bin of c
    periodogram ordinates holds about c/2 independent ones (P(f) = P(-f)
    for a real field), so its average has about c degrees of freedom.
    """
    v = FieldView(field, spacing, "psd: field")
    _grid(grid)
    welch, mu = _welch(welch), _mean(mean)
    counts = as_bool("counts", counts)
    m = None if target is None else model_of(target, "target")
    if m is not None and grid is not None:
        raise Error("target: a column beside the profile; expected grid=None with target, got grid=%r" % grid)
    P = ffi.new("nl_field **")
    with planner:
        if welch:
            check(lib.nl_psd_welch(v.f, welch, mu, P, ffi.NULL))
        else:
            check(lib.nl_psd_periodogram(v.f, mu, P))
    if grid == "wrapped":
        return owned_field(P[0])
    try:
        if grid == "centred":
            C = ffi.new("nl_field **")
            check(lib.nl_fftshift_alloc(P[0], C))
            return owned_field(C[0])
        k = lib.nl_psd_profile_size(P[0])
        freq, val, cnt, nf = np.empty(k), np.empty(k), ffi.new("size_t[]", max(k, 1)), ffi.new("size_t *")
        check(lib.nl_psd_profile(P[0], _dptr(freq), _dptr(val), cnt, nf))
        ords = np.array([cnt[i] if P[0].dim > 1 else 1 for i in range(nf[0])], dtype=np.float64)
        if m is not None:
            tgt, nt = np.empty(k), ffi.new("size_t *")
            with planner:
                check(lib.nl_psd_model_profile(m.ptr, P[0].dim, P[0].n, P[0].h, _dptr(tgt), nt))
    finally:
        if grid != "wrapped":
            lib.nl_field_free(P[0])
    out = (freq[:nf[0]], val[:nf[0]]) + ((tgt[:nf[0]],) if m is not None else ())
    return out + (ords,) if counts else out


def moments(field):
    """Mean, unbiased variance, skewness, excess kurtosis, min, max and the
    sample count of a field (nl_moments_compute), as a dict."""
    v = FieldView(field, 1.0, "moments: field")
    m = ffi.new("nl_moments *")
    check(lib.nl_moments_compute(v.f, m))
    return dict(n=int(m.n), mean=m.mean, variance=m.variance, skewness=m.skewness, kurtosis=m.kurtosis,
                min=m.min, max=m.max)


def _bins(bins):
    """As the CLI's --bins: 1 to 10^7."""
    return as_int("bins", bins, 1, 10000000)


def hist(field, bins=50, against=None, draws=199, draw_seed=1):
    """Histogram of the samples in `bins` equal bins over [min, max] (the
    maximum in the last bin), as ``noiselab hist``.  Returns (edges, counts,
    moments): edges bins + 1 values, counts `bins` values (float64), and
    the dict of :func:`moments`.  With ``against=DIST`` (a law as in
    :func:`shape`) a fourth item, the test of ``noiselab hist --against``
    (analysis/gof_boot.h: `draws` null fields with the field's own
    correlation, seed `draw_seed`; chi-square on min(bins, n/5) bins): a
    dict with p (the Bonferroni verdict), p_from, tests (per statistic:
    statistic, expected, null_mean, null_sd, p, p_rank), draws,
    ks_effective_n, chi2_scale, chi2_dof, detectable (variance_ratio as
    (lo, hi), ks_distance, ks_q95) and window_radius."""
    bins = _bins(bins)
    v = FieldView(field, 1.0, "hist: field")
    edges, counts = np.empty(bins + 1), np.empty(bins)
    check(lib.nl_hist(v.f, bins, _dptr(edges), _dptr(counts)))
    if against is None:
        return edges, counts, moments(v.array)
    return edges, counts, moments(v.array), _gof_boot(v, bins, against, draws, draw_seed)


def _gof_boot(v, bins, against, draws, draw_seed):
    """The bootstrap goodness-of-fit test of one field (hist's against=)."""
    d = Dist(against, "against")
    draws = as_int("draws", draws, 2, 100000)
    draw_seed = as_int("draw_seed", draw_seed, 0, (1 << 64) - 1)
    n = v.f.count
    cb = max(2, min(bins, n // 5))
    b = ffi.new("nl_gof_boot *")
    fields = ffi.new("const nl_field *[1]", [v.f])
    with planner:
        check(lib.nl_gof_boot_test(fields, 1, d.ptr, draws, draw_seed, cb, b))

    def num(x):
        return None if math.isnan(x) else x
    tests = {}
    for i in range(6):
        t = b.stat[i]
        if t.tested:
            tests[ffi.string(lib.nl_gof_boot_name(i)).decode()] = {
                "statistic": t.value, "expected": num(t.expected), "null_mean": t.null_mean,
                "null_sd": t.null_sd, "p": t.p, "p_rank": t.p_rank}
    return {"p": b.p, "p_from": ffi.string(lib.nl_gof_boot_name(b.p_from)).decode(), "tests": tests,
            "draws": b.draws, "ks_effective_n": b.ks_n_eff, "chi2_scale": b.chi2_scale, "chi2_dof": b.chi2_dof,
            "detectable": {"variance_ratio": (num(b.var_ratio_lo), num(b.var_ratio_hi)),
                           "ks_distance": b.ks_detectable, "ks_q95": b.ks_q95},
            "window_radius": b.radius_max}


_WHY = ("valid", "negative-integral", "negative-spectrum", "isotropic-bound", "negative-eigenvalue",
        "line-spectrum-rises", "edge-asymptotics", "negative-tapered-spectrum", "known-not-positive-definite")


def _model_arg(acf, spectrum):
    if (acf is None) == (spectrum is None):
        raise Error("expected exactly one of acf or spectrum")
    if spectrum is not None:
        s = as_str("spectrum", spectrum).decode()
        return Model(s if s.startswith(("power", "spectrum:")) else "spectrum:" + s, "spectrum")
    return Model(acf, "acf")


def check_model(acf=None, spectrum=None, dim=1):
    """Is the model positive definite in `dim` dimensions, and how smooth is
    it?  As ``noiselab check``: returns a dict with the fields of nl_check
    (analysis/check.h): positive_definite, why (None when valid, else e.g.
    "negative-spectrum"), variance, min_spectrum, min_eigenvalue,
    differentiable_order (None: infinitely), r2, spectral_decay, ...,
    and neighbours (valid models near an invalid one, as a string)."""
    dim = as_int("dim", dim, 1, 3)
    m = _model_arg(acf, spectrum)
    c = ffi.new("nl_check *")
    with planner:
        check(lib.nl_check_model(m.ptr, dim, c))
        buf = ffi.new("char[]", 4096)
        nb = ""
        if not c.positive_definite and lib.nl_check_neighbours(m.ptr, c, buf, 4096) == 0:
            nb = ffi.string(buf).decode()
    d = {k: getattr(c, k) for k, _ in ffi.typeof(c[0]).fields}
    d["positive_definite"] = bool(c.positive_definite)
    d["why"] = None if c.why == 0 else _WHY[c.why]
    d["differentiable_order"] = None if c.differentiable_order < 0 else c.differentiable_order
    d["model"] = m.spec
    d["neighbours"] = nb
    return d


def _tol(tol):
    """(stop rule, tolerance) of a tol argument: a positive number, or
    "variance:T" / "improvement:T" (as --tol)."""
    if isinstance(tol, str):
        for prefix, rule in (("variance:", 1), ("improvement:", 0)):
            if tol.startswith(prefix):
                try:
                    t = float(tol[len(prefix):])
                except ValueError:
                    refuse("tol", "a positive number, variance:T or improvement:T", tol)
                return rule, as_positive("tol", t)
        refuse("tol", "a positive number, variance:T or improvement:T", tol)
    return 0, as_positive("tol", tol)


def coeffs(acf, dim=1, neighborhood=2, tol=1e-4, levels=10, spacing0=1.0, displacements="independent", taps=None):
    """Generalized stochastic subdivision's coefficients (Lewis 1987, eqs. 4,
    10, 12) per level, as ``noiselab coeffs``.  Returns a list (one per
    level, coarsest first) of dicts: level, spacing (observation spacing, lag
    units), N, classes (a list of dicts: class, coefficients (float64 array
    in neighbourhood order), variance (eq. 7), condition, min_eigenvalue,
    flags), and with displacements="correlated" the filter taps and
    filter_error."""
    dim = as_int("dim", dim, 1, 2)
    top = 64 if dim == 1 else 8  # as the CLI's --neighborhood
    N = 0 if isinstance(neighborhood, str) and neighborhood == "auto" else \
        as_int("neighborhood", neighborhood, 1, top, 'an integer from 1 to %d or "auto"' % top)
    stop, tol = _tol(tol)
    levels = as_int("levels", levels, 1, 40)
    s0 = as_positive("spacing0", spacing0)
    displacements = as_choice("displacements", displacements, ("independent", "correlated"))
    if taps is not None:
        taps = as_int("taps", taps, 1, 16)  # NL_SUBDIV_MAX_TAPS
        if displacements != "correlated":
            raise Error("taps: expected displacements=\"correlated\" (independent displacements have no filter), "
                        "got taps=%d" % taps)
    m = Model(acf, "acf")
    out = ffi.new("nl_subdiv_coeffs **")
    with planner:
        check(lib.nl_subdiv_coeffs_alloc_rule(m.ptr, dim, levels, s0, N, stop, tol, 16 if dim == 1 else 6, out))
        co = ffi.gc(out[0], lib.nl_subdiv_coeffs_free)
        if displacements == "correlated":
            check(lib.nl_subdiv_coeffs_correlate(co, m.ptr, taps or (4 if dim == 1 else 2), 1))
    res = []
    for k in range(co.levels):
        lv = co.level[k]
        classes = []
        for j in range(lv.nclass):
            c = lv.cls[j]
            classes.append(dict(
                cls=ffi.string(lib.nl_subdiv_class_name(c.cls)).decode(),
                coefficients=np.frombuffer(ffi.buffer(c.a, c.n * 8), dtype=np.float64).copy(),
                variance=c.variance, raw_variance=c.raw_variance, condition=c.condition,
                min_eigenvalue=c.min_eigenvalue,
                flags=",".join(ffi.string(lib.nl_subdiv_flag_name(b)).decode() for b in range(6) if c.flags & (1 << b))))
        d = dict(level=lv.level, spacing=lv.spacing, N=lv.N, classes=classes)
        if lv.filt != ffi.NULL:
            cnt = lv.nclass * lv.nclass * (2 * lv.taps + 1) ** dim
            d["taps"] = lv.taps
            d["filter"] = np.frombuffer(ffi.buffer(lv.filt, cnt * 8), dtype=np.float64).copy()
            d["filter_error"] = lv.filt_error
        res.append(d)
    return res


def nonlin(acf, g, size=4096, spacing=1.0, terms=24):
    """What the memoryless map g does to a Gaussian input with
    autocorrelation `acf` (Beckmann's Hermite series), as ``noiselab
    nonlin``: g a distribution spec (as shape's `to`) or expr:G.  On a
    periodic 1D grid of `size` samples at `spacing`, returns a dict: lag,
    input_acf, output_acf (size/2 + 1 lags), freq, input_psd, output_psd
    (two-sided, cycles per unit), hermite_coefficients, output_mean,
    output_variance, truncation."""
    n = as_int("size", size, 2, 16777216)  # as the CLI's --size
    h, = as_spacing("spacing", spacing, 1)
    terms = as_int("terms", terms, 2, 64)  # NL_HERMITE_MAX
    m = Model(acf, "acf")
    d = Dist(g, "g")
    he = ffi.new("nl_hermite *")
    with planner:
        check(lib.nl_hermite_expand(d.ptr, terms, he))
        R, Ry, S, Sy = (alloc_field((n,), (h,)) for _ in range(4))
        try:
            check(lib.nl_wk_sample_acf(m.ptr, R))
            if not R.data[0] > 0:
                raise Error("acf: %s has R(0) = %g; expected a positive variance" % (m.spec, R.data[0]))
            lib.nl_nonlin_output_acf(he, R.data, n, R.data[0], Ry.data)
            check(lib.nl_wk_acf_to_spectrum(R, S))
            check(lib.nl_wk_acf_to_spectrum(Ry, Sy))
        except BaseException:
            for f in (R, Ry, S, Sy):
                lib.nl_field_free(f)
            raise
    nl = n // 2 + 1
    h = float(R.h[0])
    R, Ry, S, Sy = (owned_field(f)[:nl] for f in (R, Ry, S, Sy))
    out = dict(lag=np.arange(nl) * h, input_acf=R, output_acf=Ry, freq=np.arange(nl) / (n * h), input_psd=S,
               output_psd=Sy, hermite_coefficients=np.array([he.c[k] for k in range(he.terms)]),
               output_mean=he.c[0], output_variance=he.variance, truncation=he.truncation)
    for k, x in out.items():
        if not np.isfinite(x).all():
            raise Error("nonlin: %s overflows with %s on %d samples at spacing %g; expected a smaller variance "
                        "or spacing" % (k, m.spec, n, h))
    return out


def shape(field, to, empirical=False):
    """The memoryless map y = F_to^-1(F_x(x)) (Lewis GI '86, section 4), as
    ``noiselab shape --to DIST``: F_x the Gaussian CDF with the field's
    mean and sd (or, empirical=True, the field's ranks).  `to`: gauss,
    uniform, laplace, hyperbolic, lognormal, chi2-1, power:p=P, table:FILE
    or expr:G (see ``noiselab shape --help``).  Returns a new array (the
    input is not changed)."""
    a = as_array("shape: field", field)
    empirical = as_bool("empirical", empirical)
    d = Dist(to, "to")
    if not empirical and a.size >= 2:
        # the library's moments refuse a variance that overflows, where
        # nl_synth_shape's sd would be inf and map every sample to the median
        m = ffi.new("nl_moments *")
        st = lib.nl_moments_compute(FieldView(a, 1.0, "shape: field").f, m)
        if st:
            raise Error("shape: " + ffi.string(lib.nl_errmsg()).decode("utf-8", "replace"), int(st))
    f = alloc_field(a.shape, (1.0,) * a.ndim)
    out = owned_field(f)
    out[...] = a
    with planner:
        check(lib.nl_synth_shape(f, d.ptr, 1 if empirical else 0))
    return out


def _points(points, values, what):
    p = as_coords(what + ": points", points)
    return p, as_values(what + ": values", values, p.shape[0])


def krige(points, values, acf, at, mean=None, strict=False, variance=False):
    """Kriging (Stam and Fiume 1991, eqs. 19-22), as ``noiselab krige``:
    ordinary (unknown mean) or, with mean=M, simple.

    points  (n, d) coordinates (d = 1, 2, 3; x first) of the data, lag
            units of the model; values their n values.
    at      (m, d) coordinates where to estimate.
    strict  refuse a singular system instead of solving by the pseudo-inverse.
    Returns the m estimates, or (estimates, kriging variances) with
    variance=True.  One-shot :class:`noiselab.Krige` (make one to predict
    many times, or for nmax, radius, drift, cross-validation)."""
    p, v = _points(points, values, "krige")
    x = as_coords("krige: at", at, p.shape[1], least=0)
    _mean(mean), as_bool("strict", strict), as_bool("variance", variance)
    k = Krige(p, v, acf, mean=mean, strict=strict)
    return k.predict(x, variance=variance)


def _check_spread(what, v):
    """Refuse values whose squared differences would overflow the
    variogram's sums: a bin sums at most n (n - 1) / 2 squared differences,
    each at most (max - min)^2 (Cressie's estimator, the fourth power of a
    mean square root, stays below 1.1 times that); with a factor 4 for
    rounding and Cressie's, all stay finite for max - min below
    sqrt(DBL_MAX / 4 / pairs).  Data near 1e200 would give gamma = inf."""
    n = float(v.size)
    pairs = max(n * (n - 1) / 2, 1.0)
    lo, hi = float(v.min()), float(v.max())
    bound = math.sqrt(np.finfo(np.float64).max / 4 / pairs)
    if not hi - lo <= bound:
        raise Error("%s: the values run from %g to %g: the sums of squared differences of the variogram overflow; "
                    "expected a range below %.3g (sqrt(DBL_MAX / 4 / %.0f pairs))" % (what, lo, hi, bound, pairs))


def _vopts(width, cutoff, estimator, direction, tolerance, bins="gstat", drift="constant"):
    o = ffi.new("nl_variogram_options *")
    lib.nl_variogram_options_default(o)
    o.bins = ("gstat", "floor").index(as_choice("bins", bins, ("gstat", "floor")))
    o.drift = ("constant", "linear", "quadratic").index(as_choice("drift", drift, ("constant", "linear", "quadratic")))
    for name, val in (("width", width), ("cutoff", cutoff)):
        if val is not None:
            setattr(o, name, as_positive(name, val))
    o.estimator = 1 if as_choice("estimator", estimator, ("matheron", "cressie")) == "cressie" else 0
    if (direction is None) != (tolerance is None):
        raise Error("direction: expected direction and tolerance together")
    if direction is not None:
        o.directional, o.direction = 1, as_float("direction", direction)
        o.tolerance = as_float("tolerance", tolerance, 0.0, 90.0)
    return o


def _field_points(field, spacing):
    """A field's samples as points at index * spacing (as the CLI's fit)."""
    a = as_array("fit: field", field)
    v = FieldView(a, spacing, "fit: field")
    idx = np.indices(a.shape).reshape(a.ndim, -1)[::-1].T  # x first
    h = np.array([v.f.h[k] for k in range(a.ndim)])
    return np.ascontiguousarray(idx * h), a.ravel()


def variogram(points=None, values=None, field=None, spacing=1.0, width=None, cutoff=None, estimator="matheron",
              direction=None, tolerance=None, bins="gstat", drift="constant", covariates=None):
    """Empirical semivariogram binned as gstat's variogram(), as ``noiselab
    variogram``: of scattered data (points (n, d), values) or of a field's
    samples at index * spacing.  width: bin width (default cutoff / 15);
    cutoff: largest distance (default a third of the bounding-box
    diagonal); direction (degrees clockwise from +y) with tolerance
    (degrees); bins "gstat" ((lo, hi], h <= cutoff, the default) or "floor"
    ([lo, hi), h < cutoff); drift "linear" or "quadratic" (points): the
    variogram of the least-squares drift's residuals, gstat's variogram(z ~ x
    + y); covariates (n, q) (points) add external covariates to that drift
    (gstat's z ~ sqrt(dist); ``variogram --drift COLUMN``).  Returns
    (distance, gamma, pairs) over the non-empty bins."""
    o = _vopts(width, cutoff, estimator, direction, tolerance, bins, drift)
    out = ffi.new("nl_variogram **")
    if field is not None:
        if points is not None:
            raise Error("variogram: expected points and values, or field, not both")
        if covariates is not None:
            raise Error("covariates: expected points and values with covariates, got a field")
        fv = FieldView(field, spacing, "variogram: field")
        _check_spread("variogram: field", fv.array)
        check(lib.nl_variogram_field(fv.f, o, out))
    else:
        p, v = _points(points, values, "variogram")
        _check_spread("variogram: values", v)
        P = ffi.new("nl_points *")
        P.dim, P.n, P.pts, P.val = p.shape[1], p.shape[0], _dptr(p), _dptr(v)
        if covariates is None:
            check(lib.nl_variogram_points(P, o, out))
        else:
            c = np.ascontiguousarray(np.asarray(covariates, dtype=np.float64))
            c = c.reshape(-1, 1) if c.ndim == 1 else c
            if c.ndim != 2 or c.shape[0] != p.shape[0] or c.shape[1] == 0:
                raise Error("covariates: expected an array of %d rows (one per point) and at least one column, got "
                            "shape %s" % (p.shape[0], c.shape))
            check(lib.nl_variogram_points_design(P, _dptr(c), c.shape[1], o, out))
    vg = ffi.gc(out[0], lib.nl_variogram_free)
    k = vg.nbins
    get = lambda q: np.frombuffer(ffi.buffer(q, k * 8), dtype=np.float64).copy()
    return get(vg.distance), get(vg.gamma), get(vg.pairs)


_WEIGHTS = ("cressie", "pairs", "reweighted", "distance", "ols")  # nl_fit_weights by index
_DRIFTS = ("constant", "linear", "quadratic")  # NL_DRIFT_* by index
# gstat's fit.method numbers
_GSTAT_WEIGHTS = {1: "pairs", 2: "reweighted", 6: "ols", 7: "distance"}


def _fit_status(q):
    """A fitted parameter's status word (as the CLI's JSON)."""
    if q.fixed:
        return "fixed"
    if q.flags & 2:
        return "at bound"
    return "not identifiable (singular information)" if q.flags & 1 else "ok"


def fit(points=None, values=None, field=None, spacing=1.0, model="markov", nugget=False, fix=None, method="wls",
        weights=None, width=None, cutoff=None, bins="gstat", drift="constant", covariates=None):
    """Fit a model family to data, as ``noiselab fit``: weighted least
    squares on the empirical variogram (method="wls", weights distance, the
    default, gstat's fit.method 7; pairs, 1; reweighted, 2; ols, 6; or cressie;
    gstat's numbers 7, 1, 2, 6 are accepted too; bins as variogram()), or
    the Gaussian likelihood ("ml", "reml", started from the wls fit,
    Cressie-weighted unless weights is given, with 95% profile-likelihood
    intervals).
    model: a family whose entry in models() has fit=True, or a spec of
    them with starting values or nested ("spherical:var=0.5,scale=12 +
    markov:scale=40": every structure's parameters, named var.1, scale.2,
    ...); fix: {"nu": 1.5, ...} parameters held.  drift (ml, reml; as
    ``noiselab fit --drift``): "constant", "linear" or "quadratic" in the
    coordinates (centred on and scaled by the data's bounding box), and
    covariates: an (n, p) array of external covariates in the drift after
    those terms (gstat's z ~ x + y + c); the result's "drift" lists the GLS
    coefficients in that order and "drift_se" their standard errors.  The
    likelihood is searched over a box; "starts", "restarts" and "gradient"
    report the search (analysis/fit.h).  Returns a dict: spec
    (ready for acf=), parameters, standard_errors, intervals (ml/reml:
    {name: (lower, upper)}), objective, aic, mean (ml/reml), n, converged,
    iterations, status ({name: "ok", "fixed", "at bound" or "not
    identifiable (singular information)"}, as the CLI's JSON: the last two
    have a NaN standard error) and rcond (the information matrix's
    reciprocal condition number)."""
    if field is not None:
        if points is not None:
            raise Error("fit: expected points and values, or field, not both")
        p, v = _field_points(field, spacing)
    else:
        p, v = _points(points, values, "fit")
    _check_spread("fit: values", v)
    method = as_choice("method", method, ("wls", "ml", "reml"))
    if weights is None:  # as the CLI: gstat's default; ml, reml start from Cressie's fit
        weights = "distance" if method == "wls" else "cressie"
    o, keep = _fit_options(model, nugget, fix, weights)
    o.likelihood = 1 if method == "reml" else 0
    o.drift = _DRIFTS.index(as_choice("drift", drift, _DRIFTS))
    cov = None
    if covariates is not None:
        cov = np.ascontiguousarray(np.asarray(covariates, dtype=float))
        if cov.ndim == 1:
            cov = cov.reshape(-1, 1)
        if cov.ndim != 2 or cov.shape[0] != p.shape[0] or cov.shape[1] == 0:
            raise Error("covariates: expected an array of %d rows (one per datum) and at least one column, got "
                        "shape %s" % (p.shape[0], cov.shape))
    # wls with a drift fits the variogram of the drift's least-squares residuals
    # (gstat's variogram(z ~ x + y + c)); ml and reml start from the plain one's fit
    wls_drift = method == "wls" and (o.drift != 0 or cov is not None)
    vo = _vopts(width, cutoff, "matheron", None, None, bins, _DRIFTS[o.drift] if wls_drift else "constant")
    r = ffi.new("nl_fit_result *")
    dim = p.shape[1]
    check(lib.nl_fit_check_options(o, dim))
    P = ffi.new("nl_points *")
    P.dim, P.n, P.pts, P.val = dim, p.shape[0], _dptr(p), _dptr(v)
    out = ffi.new("nl_variogram **")
    if wls_drift and cov is not None:
        check(lib.nl_variogram_points_design(P, _dptr(cov), cov.shape[1], vo, out))
    else:
        check(lib.nl_variogram_points(P, vo, out))
    vg = ffi.gc(out[0], lib.nl_variogram_free)
    try:
        with planner:
            check(lib.nl_fit_variogram(vg.distance, vg.gamma, vg.pairs, vg.nbins, dim, o, r))
            if method != "wls":
                start = ffi.new("double[]", [r.param[k].value for k in range(r.np)])
                lib.nl_fit_result_free(r)
                o.start = start
                o.intervals = 1
                if cov is None:
                    check(lib.nl_fit_ml(_dptr(p), _dptr(v), p.shape[0], dim, o, r))
                else:
                    check(lib.nl_fit_ml_design(_dptr(p), _dptr(v), p.shape[0], dim, _dptr(cov), cov.shape[1], o, r))
        return _fit_result(r, method)
    finally:
        lib.nl_fit_result_free(r)


def _fit_options(model, nugget, fix, weights):
    """nl_fit_options of fit's arguments, and the strings it points to."""
    if isinstance(weights, int) and not isinstance(weights, bool) and weights in _GSTAT_WEIGHTS:
        weights = _GSTAT_WEIGHTS[weights]
    weights = as_choice("weights", weights, _WEIGHTS)
    if fix is None:
        fix = {}
    if not isinstance(fix, dict):
        refuse("fix", "a dict of parameter names and values", fix)
    if len(fix) > 8:
        raise Error("fix: expected at most 8 parameters, got %d" % len(fix))
    o = ffi.new("nl_fit_options *")
    keep = [ffi.new("char[]", as_str("model", model))]
    o.family = keep[0]
    o.nugget = 1 if as_bool("nugget", nugget) else 0
    for i, (k, val) in enumerate(fix.items()):
        keep.append(ffi.new("char[]", as_str("fix", k)))
        o.fix_name[i] = keep[-1]
        o.fix_value[i] = as_float("fix: " + k, val)
    o.nfix = len(fix)
    o.weights = _WEIGHTS.index(weights)
    return o, keep


def _fit_result(r, method):
    """fit's dict of an nl_fit_result."""
    q = [r.param[k] for k in range(r.np)]
    names = [ffi.string(x.name).decode() for x in q]
    res = dict(spec=ffi.string(r.spec).decode(), method=method, n=int(r.nobs), converged=bool(r.converged),
               iterations=r.iterations, objective=r.objective, aic=r.aic,
               parameters={nm: x.value for nm, x in zip(names, q)},
               standard_errors={nm: x.se for nm, x in zip(names, q)},
               fixed={nm: bool(x.fixed) for nm, x in zip(names, q)},
               status={nm: _fit_status(x) for nm, x in zip(names, q)}, rcond=r.rcond)
    if method != "wls":
        res["mean"] = r.mean
        res["drift"] = [r.drift[k] for k in range(r.ndrift)]
        res["drift_se"] = [r.drift_se[k] for k in range(r.ndrift)]
        res.update(starts=r.starts, restarts=r.restarts, gradient=r.gradient)
        res["intervals"] = {nm: (x.lower, x.upper) for nm, x in zip(names, q)
                            if not (math.isnan(x.lower) or math.isnan(x.upper))}
    return res
