"""noiselab.plot's geostatistics figures: the empirical variogram with a
model, a kriging map with its standard deviation, conditional
realizations beside the kriging mean."""
import numpy as np

from . import _analysis
from ._args import Error, as_array, as_int, refuse
from ._krige import _extent
from ._model import Model
from ._plot_util import axes, colorbar, finish, legend, length_unit, map_figsize, mpl, overlay_points, short_spec, text


def _vlabel(label, value_unit):
    label = text("label", label)
    vu = text("value_unit", value_unit, none=True)
    return label, vu


def variogram(points=None, values=None, field=None, fit=None, model=None, width=None, cutoff=None, ax=None,
              unit=None, label="value", title=None, spacing=1.0, value_unit=None, counts=True):
    """The empirical semivariogram (noiselab.variogram, gstat's bins) of
    scattered data (points (n, d), values) or of a field's samples, as
    points whose area grows with the bin's pair count, the counts written
    beside them (counts=False: not); with the fitted model (fit: a dict of
    noiselab.fit, its "spec"; or model=, a spec) as a curve,
    Model.variogram (nugget included) along x in the data's dimension."""
    label, vu = _vlabel(label, value_unit)
    title = text("title", title, none=True)
    if fit is not None and model is not None:
        raise Error("fit: expected fit (a dict of noiselab.fit) or model (a spec), not both")
    if fit is not None:
        if not isinstance(fit, dict) or not isinstance(fit.get("spec"), str):
            refuse("fit", "a dict returned by noiselab.fit (with its \"spec\")", fit)
        m, how = Model(fit["spec"]), "%s fit: " % fit.get("method", "wls").upper()
    elif model is not None:
        m, how = (model if isinstance(model, Model) else Model(model)), "model: "
        if not isinstance(model, (str, Model)):
            refuse("model", "a model spec string or a noiselab.Model", model)
    else:
        m = None
    if field is not None:
        fa = as_array("field", field)
        dim = fa.ndim
        d, g, n = _analysis.variogram(field=fa, spacing=spacing, width=width, cutoff=cutoff)
    else:
        d, g, n = _analysis.variogram(points, values, width=width, cutoff=cutoff)
        dim = np.asarray(points).shape[1]
    u = length_unit(unit, spacing if field is not None else 0.0)
    ax_, = axes(ax)
    size = 12 + 60 * n / n.max()
    ax_.scatter(d, g, s=size, color="C0", edgecolors="k", linewidths=0.4, zorder=3,
                label="empirical (area ~ pairs per bin)")
    if counts:
        for x, y, k in zip(d, g, n):
            ax_.annotate("%d" % k, (x, y), xytext=(4, -9), textcoords="offset points", fontsize=7, color="0.3")
    if m is not None:
        h = np.linspace(0, d.max() * 1.05, 240)
        ax_.plot(h, m.variogram(h, dim=dim), "k-", lw=1.3, label=how + short_spec(m.spec))
    ax_.set_xlim(0, d.max() * 1.08)
    ax_.set_ylim(0, max(g.max(), ax_.get_ylim()[1]) * 1.3)  # headroom for the legend
    sq = "%s^2" % vu if vu else "%s^2" % label
    finish(ax_, "distance (%s)" % u, "semivariance (%s)" % sq, title)
    legend(ax_)
    return ax_


def _map_extent(extent):
    lo, hi = _extent(extent, 2)
    return (lo[0], hi[0], lo[1], hi[1])


def _map(a, what):
    a = as_array(what, a)
    if a.ndim != 2:
        raise Error("%s: expected a 2D map (ny, nx), got %dD" % (what, a.ndim))
    return a


def kriging(estimate, variance, extent, points=None, values=None, axes=None, unit=None, label="value", title=None,
            value_unit=None, cmap="viridis"):
    """Two panels: the kriged map (Krige.grid's estimate) and its kriging
    standard deviation (the square root of its variance), each with a
    labelled colour bar; extent: the grid's (lo, hi) per axis, x first (as
    Krige.grid took it).  points (m, 2): the data, overlaid (coloured by
    `values` on the estimate's scale when given)."""
    label, vu = _vlabel(label, value_unit)
    title = text("title", title, none=True)
    est, var = _map(estimate, "estimate"), _map(variance, "variance")
    if var.shape != est.shape:
        raise Error("variance: expected the estimate's shape %s, got %s" % (est.shape, var.shape))
    if (var < 0).any():
        raise Error("variance: expected variances >= 0, got %g" % var.min())
    ext = _map_extent(extent)
    u = length_unit(unit, 0.0)
    ratio = (ext[3] - ext[2]) / (ext[1] - ext[0])
    a, b = _axes2(axes, 2, map_figsize(ratio, 2, 2))
    im = a.imshow(est, origin="lower", extent=ext, cmap=cmap, interpolation="nearest")
    colorbar(a, im, "estimate of %s%s" % (label, " (%s)" % vu if vu else ""))
    overlay_points(a, points, values, im.norm, im.cmap)
    sd = b.imshow(np.sqrt(var), origin="lower", extent=ext, cmap="magma", interpolation="nearest")
    colorbar(b, sd, "kriging standard deviation%s" % (" (%s)" % vu if vu else ""))
    overlay_points(b, points)
    for k, axk in enumerate((a, b)):
        finish(axk, "x (%s)" % u, "y (%s)" % u, None)
    a.set_title(title or "kriged %s" % label, fontsize="medium")
    b.set_title("its standard deviation", fontsize="medium")
    return [a, b]


def _axes2(ax, n, figsize):
    return axes(ax, n, figsize, name="axes")


def conditional(realizations, mean, extent, points=None, axes=None, unit=None, label="value", title=None, n=3,
                value_unit=None, cmap="viridis"):
    """The kriging mean beside the first n conditional realizations (an
    array (K, ny, nx) or a list of (ny, nx) maps, as CondSim gives them), on
    one colour scale with one labelled colour bar; extent: the grid's (lo,
    hi) per axis, x first; points (m, 2): the data, overlaid."""
    label, vu = _vlabel(label, value_unit)
    title = text("title", title, none=True)
    n = as_int("n", n, 1, 16)
    mu = _map(mean, "mean")
    if isinstance(realizations, np.ndarray) and realizations.ndim == 2:
        realizations = realizations[None]
    try:
        reals = [_map(r, "realizations: realization %d" % k) for k, r in enumerate(list(realizations)[:n])]
    except TypeError:
        refuse("realizations", "an array (K, ny, nx) or a list of (ny, nx) maps", realizations)
    if not reals:
        refuse("realizations", "at least one realization", realizations)
    if any(r.shape != mu.shape for r in reals):
        raise Error("realizations: expected maps of the mean's shape %s" % (mu.shape,))
    ext = _map_extent(extent)
    u = length_unit(unit, 0.0)
    k = len(reals)
    ratio = (ext[3] - ext[2]) / (ext[1] - ext[0])
    axs = _axes2(axes, k + 1, map_figsize(ratio, k + 1, 1, min(9.0, 2.4 * (k + 1) + 0.9)))
    lo = min(float(mu.min()), min(float(r.min()) for r in reals))
    hi = max(float(mu.max()), max(float(r.max()) for r in reals))
    plt = mpl()
    norm = plt.Normalize(lo, hi)
    for j, (axj, a) in enumerate(zip(axs, [mu] + reals)):
        im = axj.imshow(a, origin="lower", extent=ext, cmap=cmap, norm=norm, interpolation="nearest")
        overlay_points(axj, points)
        axj.set_title("kriging mean" if j == 0 else "realization %d" % j, fontsize="medium")
        finish(axj, "x (%s)" % u, "y (%s)" % u, None)
    colorbar(axs[-1], im, label + (" (%s)" % vu if vu else ""))
    if title:
        axs[0].figure.suptitle(title)
    return axs
