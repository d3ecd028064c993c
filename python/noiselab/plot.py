"""noiselab.plot: the figures of a course in random fields, drawn with
matplotlib (imported by this module, not by ``import noiselab``).

    import noiselab.plot as nlp
    nlp.acf(noiselab.synth("circulant", acf="markov:scale=8", size=1024), model="markov:scale=8")

Every function draws on `ax` (a matplotlib Axes; `axes`, a sequence, for
the multi-panel ones) or, when None, on a figure of its own (about 6 x 4
inches a panel, constrained layout), and returns the Axes (a list for the
multi-panel ones).  Every axis is labelled with its unit in parentheses:
`unit` names the length unit (default "samples" at spacing 1, else "length
units"), `value_unit` the field's values (default: none, "value^2" for a
variance); frequencies are in cycles per length unit; colour bars are
labelled.  Legends go where they cover the fewest plotted
points (outside the axes, on the right, when no place inside is clear).

Every number drawn comes from noiselab's own functions (acf with bands,
Model.acf_band, psd, Model.periodogram_target / welch_target, band_chisq,
welch_edf, hist with against=, Dist, nonlin, variogram, fit, Krige): this
module arranges what they return and computes nothing statistical itself.
Bad arguments raise noiselab.Error naming the argument.
"""
import numpy as np

from . import _analysis, _ensemble
from ._args import Error, as_array, as_choice, as_int, as_spacing, refuse
from ._dist import Dist, band_chisq, welch_edf
from ._krige import _extent
from ._model import Model
from ._plot_util import (axes, colorbar, finish, legend, length_unit, map_figsize, overlay_points, per, per_dim,
                         short_spec, squared, text, value_axis)
from ._plot_geo import conditional, kriging, variogram

__all__ = ["field", "acf", "spectrum", "periodogram_welch", "histogram", "nonlinearity", "variogram", "kriging",
           "conditional"]


def _vunit(value_unit):
    vu = text("value_unit", value_unit, none=True)
    return " (%s)" % vu if vu else ""


def _fields(fields, what="fields"):
    """A list of arrays: one array (one field) or a sequence of them."""
    if isinstance(fields, np.ndarray):
        return [as_array(what, fields)]
    if isinstance(fields, (list, tuple)) and fields and all(isinstance(f, np.ndarray) for f in fields):
        return [as_array("%s: field %d" % (what, k), f) for k, f in enumerate(fields)]
    refuse(what, "a numpy array (one field) or a non-empty list of arrays (an ensemble)", fields)


def _model(model):
    if model is None or isinstance(model, Model):
        return model
    if not isinstance(model, str):
        refuse("model", "a model spec string, a noiselab.Model or None", model)
    return Model(model)


# -- 1. a field ---------------------------------------------------------------

def field(f, spacing=1.0, origin=None, ax=None, unit=None, label="value", title=None, cmap="viridis", points=None,
          value_unit=None, extent=None):
    """A field: 1D a line against position; 2D an image (origin lower left,
    sample (i, j) a cell centred at origin + (j hx, i hy)) with a labelled
    colour bar; 3D its middle z slice, said in the title.  origin: the
    first sample's coordinates, x first (a number or one per axis, length
    units; default 0); extent: instead, (lo, hi) per axis, x first, cells
    of width (hi - lo)/n (the grids of Krige.grid and CondSim).  points
    (m, 2): data locations overlaid as small markers."""
    a = as_array("f", f)
    dim = a.ndim
    label, title, cmap = text("label", label), text("title", title, none=True), text("cmap", cmap)
    h = as_spacing("spacing", spacing, dim)[::-1]  # x first
    u = length_unit(unit, spacing if extent is None else 0.0)
    vu = _vunit(value_unit)
    if extent is not None:
        if origin is not None:
            raise Error("extent: expected extent or origin, not both")
        lo, hi = _extent(extent, dim)
        h = [(hi[d] - lo[d]) / a.shape[dim - 1 - d] for d in range(dim)]
        o = [lo[d] + 0.5 * h[d] for d in range(dim)]
    else:
        o = [0.0] * dim if origin is None else list(np.atleast_1d(np.asarray(origin, dtype=float)))
        if len(o) == 1 and dim > 1:
            o = o * dim
        if len(o) != dim or not np.isfinite(o).all():
            refuse("origin", "a number or %d finite numbers, x first" % dim, origin)
    if dim == 1:
        fs = (6, 2.8)
    else:
        fs = map_figsize(a.shape[-2] * h[1] / (a.shape[-1] * h[0]))
    ax, = axes(ax, figsize=fs)
    if dim == 3:
        k = a.shape[0] // 2
        a = a[k]
        title = ("%s: " % title if title else "") + "slice z = %g %s (index %d)" % (o[2] + k * h[2], u, k)
    if dim == 1:
        x = o[0] + np.arange(a.size) * h[0]
        ax.plot(x, a, lw=0.8, color="C0")
        finish(ax, "position (%s)" % u, value_axis(label, value_unit), title)
        if points is not None:
            raise Error("points: expected a 2D or 3D field for points, got 1D")
        return ax
    ny, nx = a.shape
    ext = (o[0] - h[0] / 2, o[0] + (nx - 0.5) * h[0], o[1] - h[1] / 2, o[1] + (ny - 0.5) * h[1])
    im = ax.imshow(a, origin="lower", extent=ext, cmap=cmap, interpolation="nearest")
    colorbar(ax, im, label + vu)
    overlay_points(ax, points)
    finish(ax, "x (%s)" % u, "y (%s)" % u, title)
    return ax


# -- 2. the autocovariance -------------------------------------------------------

def acf(fields, model=None, spacing=1.0, max_lag=None, axis="x", ax=None, unit=None, title=None, value_unit=None):
    """The biased sample autocovariance (noiselab.acf) along `axis` of one
    field, or the mean of the estimates of a list of K fields
    (noiselab.ensemble_acf).  With a model: its R, the estimate's
    expectation and the 95% band of the estimate (of the mean of K) when the
    model is true (acf(bands=True, target=), Model.acf_band(realizations=K)).
    Without: one 1D field, Bartlett's plug-in band (acf(bands=True)); K
    fields, the mean -+ 1.96 standard errors of the K estimates."""
    fl = _fields(fields)
    m = _model(model)
    title = text("title", title, none=True)
    u = length_unit(unit, spacing)
    ax_, = axes(ax)
    K = len(fl)
    band = None
    if K == 1:
        x = fl[0]
        if m is not None:
            d = _analysis.acf(x, spacing, max_lag, axis, bands=True, target=m)
            lag, est = d["lag"], d["acf"]
            band = (d["model_lo"], d["model_hi"], "95% band of the estimate under the model")
            expected, target = d["expected"], d["target"]
        elif x.ndim == 1:
            d = _analysis.acf(x, spacing, max_lag, axis, bands=True)
            lag, est = d["lag"], d["acf"]
            band = (d["plugin_lo"], d["plugin_hi"], "95% band, Bartlett's variance from the estimate")
        else:
            lag, est = _analysis.acf(x, spacing, max_lag, axis)
        what = "estimate (biased, sample mean removed)"
    else:
        lag, est, se = _ensemble.ensemble_acf(fl, spacing, max_lag, axis)
        what = "mean of %d estimates" % K
        if m is not None:
            b = m.acf_band(fl[0].shape, spacing, lag[-1], axis, realizations=K)
            band = (b["lo"], b["hi"], "95%% band of the mean of %d estimates under the model" % K)
            expected, target = b["expected"], b["target"]
        else:
            band = (est - 1.959964 * se, est + 1.959964 * se, "mean -+ 1.96 standard errors of the %d" % K)
    if band is not None:
        ax_.fill_between(lag, band[0], band[1], color="C0", alpha=0.22, lw=0, label=band[2])
    ax_.plot(lag, est, color="C0", lw=1.4, label=what)
    if m is not None:
        ax_.plot(lag, target, "k-", lw=1.0, label="model R: " + short_spec(m.spec))
        ax_.plot(lag, expected, "k--", lw=1.0, label="expectation of the estimate")
    ax_.axhline(0.0, color="0.6", lw=0.5, zorder=0)
    finish(ax_, "lag along %s (%s)" % (axis, u), "autocovariance R(lag) (%s)" % squared(value_unit), title)
    legend(ax_)
    return ax_


# -- 3, 4. spectra -------------------------------------------------------------

def _chisq_band(nu, tgt):
    lo, hi = band_chisq(nu)
    return tgt * lo, tgt * hi


def _psd_of(fl, spacing, welch):
    """(freq, estimate) of one field, or the mean over a list."""
    if len(fl) == 1:
        return _analysis.psd(fl[0], spacing, welch)
    f, p, _ = _ensemble.ensemble_psd(fl, spacing, welch)
    return f, p


def _spectrum_axes(ax, dim, u, value_unit, title, loglog):
    if loglog:
        ax.set_xscale("log")
        ax.set_yscale("log")
    finish(ax, "frequency (cycles per %s)" % per(u),
           "spectral density (%s %s)" % (squared(value_unit), per_dim(u, dim)), title)


def _positive(f, *ys):
    """Frequencies above 0 where every curve is finite (log axes)."""
    keep = f > 0
    for y in ys:
        keep &= np.isfinite(y)
    return keep


def spectrum(fields, model=None, spacing=1.0, welch=None, ax=None, unit=None, title=None, loglog=True,
             value_unit=None):
    """The periodogram (noiselab.psd; 2D/3D its radial profile), or Welch's
    estimate with welch=S (segments of S samples), of one field or the mean
    over a list of K.  With a model: the estimate's target
    (Model.periodogram_target / welch_target) and, for 1D fields, its 95%
    band: chi-square with nu = 2 per periodogram ordinate, nu =
    noiselab.welch_edf for Welch, times K for a mean (noiselab.band_chisq).
    The band is drawn about the target (the expectation is the target
    smoothed by the Fejer or Hann kernel: approximate where the spectrum is
    steep over 1/(n h)).  A radial profile (2D, 3D) of the periodogram
    gets the band of each ring's average: nu = the ring's ordinate count
    (psd(counts=True)) times K, half of them independent (P(f) = P(-f)),
    and the spectrum taken constant around the ring (approximate for an
    anisotropic model); Welch's radial profile gets none (its neighbouring
    ordinates are correlated by the window)."""
    fl = _fields(fields)
    m = _model(model)
    title = text("title", title, none=True)
    loglog = bool(loglog) if isinstance(loglog, (bool, np.bool_)) else refuse("loglog", "True or False", loglog)
    u = length_unit(unit, spacing)
    ax_, = axes(ax)
    K, dim, shape = len(fl), fl[0].ndim, fl[0].shape
    f, p = _psd_of(fl, spacing, welch)
    kind = "periodogram" if welch is None else "Welch, segments of %d" % welch
    what = kind if K == 1 else "mean of %d (%s)" % (K, kind)
    if m is not None:
        ft, tgt = m.periodogram_target(shape, spacing) if welch is None else m.welch_target(shape, spacing, welch)
        keep = _positive(ft, tgt) if loglog else np.isfinite(tgt)
        if dim == 1:
            nu = (2.0 if welch is None else welch_edf(shape, welch)) * K
            lo, hi = _chisq_band(nu, tgt)
            ax_.fill_between(ft[keep], lo[keep], hi[keep], color="C1", alpha=0.25, lw=0,
                             label="95%% band under the model (chi-square, nu = %.3g; approx.)" % nu)
        elif welch is None:  # a ring of c ordinates: about c/2 independent ones, nu = c per field
            c = _analysis.psd(fl[0], spacing, counts=True)[-1]
            keep &= c > 0
            lo, hi = np.full(tgt.shape, np.nan), np.full(tgt.shape, np.nan)
            for i in np.flatnonzero(keep):
                lo[i], hi[i] = _chisq_band(c[i] * K, tgt[i])
            ax_.fill_between(ft[keep], lo[keep], hi[keep], color="C1", alpha=0.25, lw=0,
                             label="95% band under the model (chi-square per ring; approx.)")
    keep = _positive(f, p) if loglog else np.isfinite(p)
    ax_.plot(f[keep], p[keep], color="C0", lw=0.7 if welch is None and K == 1 else 1.2, label=what)
    if m is not None:
        keep = _positive(ft, tgt) if loglog else np.isfinite(tgt)
        ax_.plot(ft[keep], tgt[keep], "k-", lw=1.2, label="target: " + short_spec(m.spec))
    _spectrum_axes(ax_, dim, u, value_unit, title, loglog)
    legend(ax_)
    return ax_


def periodogram_welch(field, model=None, segment=None, spacing=1.0, ax=None, unit=None, title=None, value_unit=None):
    """The periodogram and Welch's estimate (Hann segments of `segment`
    samples per axis overlapping by half; default the largest power of 2 up
    to an eighth of the shortest axis) of one 1D or 2D field on one log-log
    axes, with the model's targets (Model.periodogram_target, welch_target);
    the legend gives the segment length and the number of segments."""
    x = as_array("field", field)
    if x.ndim > 2:
        raise Error("field: Welch's estimate is 1D or 2D, got %dD" % x.ndim)
    if segment is None:
        segment = max(4, 1 << int(np.log2(max(min(x.shape) // 8, 4))))
    segment = as_int("segment", segment, 4, min(x.shape), "an integer from 4 to the smallest axis, %d" % min(x.shape))
    m = _model(model)
    title = text("title", title, none=True)
    u = length_unit(unit, spacing)
    ax_, = axes(ax)
    nu, nseg = welch_edf(x.shape, segment, segments=True)
    f, p = _analysis.psd(x, spacing)
    fw, w = _analysis.psd(x, spacing, welch=segment)
    k, kw = _positive(f, p), _positive(fw, w)
    ax_.plot(f[k], p[k], color="0.55", lw=0.6, label="periodogram")
    ax_.plot(fw[kw], w[kw], color="C0", lw=1.6, label="Welch: %d segments of %d samples" % (nseg, segment))
    if m is not None:
        ft, tgt = m.periodogram_target(x.shape, spacing)
        fwt, wt = m.welch_target(x.shape, spacing, segment)
        k, kw = _positive(ft, tgt), _positive(fwt, wt)
        ax_.plot(ft[k], tgt[k], "k-", lw=1.0, label="periodogram's target: " + short_spec(m.spec))
        ax_.plot(fwt[kw], wt[kw], "--", color="C3", lw=1.2, label="Welch's target (on the segment's grid)")
    _spectrum_axes(ax_, x.ndim, u, value_unit, title, True)
    legend(ax_)
    return ax_


# -- 5. the histogram ------------------------------------------------------------

def histogram(fields, against=None, bins=50, ax=None, unit=None, label="value", title=None, draws=199,
              value_unit=None):
    """The density histogram (noiselab.hist; the mean over a list of
    fields, noiselab.ensemble_hist) of the values.  With `against` (a law:
    "gauss", "laplace:a=1", ...): the law's density (noiselab.Dist(against)
    .pdf) and the verdict of noiselab.hist(..., against=, draws=) (of the
    first field of a list) as the legend's last entry, clear of the data: the overall
    p-value and the test it comes from (the smallest).  `unit` is unused
    (the axis is in the values' unit, value_unit)."""
    fl = _fields(fields)
    label, title = text("label", label), text("title", title, none=True)
    length_unit(unit, 1.0)
    vu = text("value_unit", value_unit, none=True)
    ax_, = axes(ax)
    if against is not None:
        law = Dist(against)
    if len(fl) == 1:
        r = _analysis.hist(fl[0], bins, against, draws) if against is not None else _analysis.hist(fl[0], bins)
        edges, counts, mom = r[0], r[1], r[2]
        n = mom["n"]
    else:
        edges, counts, _, mom, _ = _ensemble.ensemble_hist(fl, bins)
        n = mom["n"] / len(fl)  # counts are the mean count per field
        if against is not None:
            r = _analysis.hist(fl[0], bins, against, draws)
    dens = counts / (n * np.diff(edges))
    ax_.bar(edges[:-1], dens, width=np.diff(edges), align="edge", color="C0", alpha=0.55, edgecolor="C0", lw=0.3,
            label="histogram of %d values" % mom["n"])
    if against is not None:
        pad = 0.05 * (edges[-1] - edges[0])
        y = np.linspace(edges[0] - pad, edges[-1] + pad, 400)
        pdf = law.pdf(y)
        ax_.plot(y, pdf, "k-", lw=1.3, label="density of " + law.spec)
        # headroom above the bars and the curve: the legend and the verdict
        # go in the upper corners, clear of the data
        top = max(float(dens.max()), float(np.nanmax(pdf)) if np.isfinite(pdf).any() else 0.0)
        ax_.set_ylim(0.0, 1.6 * top)
        t = r[3]
        verdict = "test against %s%s:\np = %.3g (%s, %d null draws)" % (
            law.spec, "" if len(fl) == 1 else " (field 1)", t["p"], t["p_from"], t["draws"])
        # the verdict is the legend's last entry (no handle): one box, clear
        # of the bars in the headroom above them
        ax_.plot([], [], " ", label=verdict)
        legend(ax_)
    else:
        legend(ax_)
    finish(ax_, value_axis(label, vu), "probability density (per %s)" % (vu or "unit of %s" % label), title)
    return ax_


# -- 6. a nonlinearity ---------------------------------------------------------

def nonlinearity(acf, g, field=None, size=4096, spacing=1.0, ax=None, unit=None, title=None, show="spectrum",
                 terms=24, welch="auto", value_unit=None, max_lag=None):
    """What g does to a Gaussian field of autocorrelation `acf`: the
    spectrum (show="spectrum", the default) or autocovariance (show="acf")
    of g(X) predicted by noiselab.nonlin's Hermite series (both are what it
    returns) against the one measured on `field` (1D, already transformed);
    without a field, one synthesised by fft at `size` with seed 1 and
    mapped by noiselab.Dist(g).transform (g a law or expr:G, applied to X /
    sd as nonlin does).  The measured spectrum is Welch's (welch="auto":
    segments of size/16, at least 64; an integer: that segment; None: the
    periodogram).  show="acf": lags up to max_lag (length units; default
    four times the lag where the predicted autocovariance first falls
    below 5% of its variance, at most a quarter of the field)."""
    show = as_choice("show", show, ("spectrum", "acf"))
    title = text("title", title, none=True)
    u = length_unit(unit, spacing)
    pred = _analysis.nonlin(acf, g, size, spacing, terms)
    if field is None:
        x = _synth_one(acf, size, spacing)
        y = Dist(g, function=True).transform(x / np.sqrt(pred["input_acf"][0]))
    else:
        y = as_array("field", field)
        if y.ndim != 1:
            raise Error("field: expected a 1D field (nonlin's prediction is 1D), got %dD" % y.ndim)
    ax_, = axes(ax)
    nterm = len(pred["hermite_coefficients"])
    plab = "predicted (Hermite, %d terms)" % nterm
    if show == "acf":
        if max_lag is None:
            low = np.flatnonzero(np.abs(pred["output_acf"]) < 0.05 * pred["output_acf"][0])
            max_lag = min(4 * pred["lag"][low[0]] if low.size else np.inf, (y.size // 4) * pred["lag"][1])
        lag, est = _analysis.acf(y, spacing, max_lag=max_lag)
        k = min(len(lag), len(pred["lag"]))
        ax_.plot(lag, est, color="C0", lw=1.4, label="measured")
        ax_.plot(pred["lag"][:k], pred["output_acf"][:k], "k--", lw=1.2, label=plab)
        finish(ax_, "lag (%s)" % u, "autocovariance of g(X) (%s)" % squared(value_unit), title)
    else:
        if welch == "auto":
            welch = max(64, y.size // 16) if y.size >= 256 else None
        fw, w = _analysis.psd(y, spacing, welch=welch)
        kw = _positive(fw, w)
        ax_.plot(fw[kw], w[kw], color="C0", lw=1.2,
                 label="measured" + (" (Welch, segments of %d)" % welch if welch else " (periodogram)"))
        f, s = pred["freq"], pred["output_psd"]
        k = _positive(f, s) & (s > 1e-9 * np.nanmax(s))
        ax_.plot(f[k], s[k], "k--", lw=1.2, label=plab)
        ax_.set_ylim(bottom=max(ax_.get_ylim()[0], 1e-9 * np.nanmax(s)))
        _spectrum_axes(ax_, 1, u, value_unit, title, True)
    legend(ax_)
    return ax_


def _synth_one(acf, size, spacing):
    from ._synth import synth
    return synth("fft", acf=acf, size=as_int("size", size, 2, 16777216), seed=1, spacing=spacing)
