"""What noiselab.plot's functions share: matplotlib imported on first use,
the checks of the arguments every figure takes (ax, unit, label, title),
axis and colour-bar labels with units, and legends and text boxes placed
where they cover the fewest plotted points."""
import numpy as np

from ._args import Error, refuse

PANEL = (6.0, 4.0)  # inches per panel, as the API's "about (6, 4)"
CLEAR = 0.02  # a box may cover at most this fraction of the plotted points before it moves out of the axes
_LOCS = ("upper right", "upper left", "lower left", "lower right", "center right", "center left", "upper center",
         "lower center")


def mpl():
    """matplotlib.pyplot, imported here so that `import noiselab` needs no
    matplotlib."""
    try:
        import matplotlib.pyplot as plt
    except ImportError as e:  # pragma: no cover - depends on the system
        raise ImportError("noiselab.plot needs matplotlib (Debian: python3-matplotlib): %s" % e)
    return plt


def text(name, value, none=False):
    """A label, unit or title: a str (None where `none`)."""
    if value is None and none:
        return None
    if not isinstance(value, str):
        refuse(name, "a string" + (" or None" if none else ""), value)
    return value


def length_unit(unit, spacing):
    """The name of the length unit: unit, else "samples" at unit spacing,
    else "length units"."""
    unit = text("unit", unit, none=True)
    if unit is not None:
        if not unit.strip():
            refuse("unit", "a non-empty string or None", unit)
        return unit
    h = np.atleast_1d(np.asarray(spacing, dtype=float)) if not isinstance(spacing, str) else None
    return "samples" if h is not None and np.all(h == 1.0) else "length units"


def per(unit):
    """The length unit after "per": "sample" for "samples"."""
    return "sample" if unit == "samples" else unit


def value_axis(label, value_unit):
    """A value axis' label: "<label> (<value unit>)", "arbitrary units"
    without one."""
    vu = text("value_unit", value_unit, none=True)
    return "%s (%s)" % (label, vu or "arbitrary units")


def short_spec(spec):
    """A spec with its numbers to 4 significant digits, for a legend."""
    import re
    return re.sub(r"(?<=[=])[-+0-9.eE]+", lambda m: "%.4g" % float(m.group(0)) if _num(m.group(0)) else m.group(0),
                  spec)


def _num(s):
    try:
        float(s)
        return True
    except ValueError:
        return False


def squared(value_unit):
    """The unit of a variance: "<value unit>^2", or "value^2" without one."""
    value_unit = text("value_unit", value_unit, none=True)
    return "value^2" if not value_unit else "%s^2" % value_unit


def per_dim(unit, dim):
    return unit if dim == 1 else "%s^%d" % (unit, dim)


def axes(ax, n=1, figsize=None, name="ax"):
    """The Axes to draw on: ax (one Axes, or for n > 1 a sequence of n), or
    new ones in a figure of their own (constrained layout).  Returns a list."""
    plt = mpl()
    from matplotlib.axes import Axes
    if ax is None:
        fig, a = plt.subplots(1, n, figsize=figsize or (PANEL[0] * n, PANEL[1]), constrained_layout=True)
        return list(np.atleast_1d(a))
    if n == 1:
        if not isinstance(ax, Axes):
            refuse(name, "a matplotlib Axes or None", ax)
        return [ax]
    try:
        items = list(ax)
    except TypeError:
        refuse(name, "a sequence of %d matplotlib Axes or None" % n, ax)
    if len(items) != n or not all(isinstance(a, Axes) for a in items):
        refuse(name, "a sequence of %d matplotlib Axes or None" % n, ax)
    return items


def map_figsize(ratio, panels=1, colorbars=1, width=None):
    """A figure size for `panels` maps of height/width `ratio` side by side
    (with `colorbars` colour bars) in which the maps fill their panels, so
    that the figure has little blank: about 0.75 inch of y label per panel,
    0.85 per colour bar and 0.75 of title and x label."""
    width = width or min(9.0, PANEL[0] * panels)
    w = (width - 0.75 * panels - 0.85 * colorbars) / panels
    return width, float(np.clip(w * ratio + 0.75, 2.0, 6.5))


def finish(ax, xlabel, ylabel, title):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title)


# -- boxes clear of the data -------------------------------------------------

def data_points(ax):
    """The plotted points of ax in display coordinates: the vertices of its
    lines, of its filled bands and scatters, and points spread over its bars
    (a box over a bar hides it)."""
    pts = []
    for ln in ax.lines:
        xy = np.column_stack([np.asarray(ln.get_xdata(), float), np.asarray(ln.get_ydata(), float)])
        if len(xy):
            pts.append(ln.get_transform().transform(xy))
    for c in ax.collections:
        offs = c.get_offsets()
        if len(offs) and c.get_paths() and len(c.get_paths()) == 1 and len(offs) > 1:  # a scatter
            pts.append(c.get_offset_transform().transform(np.asarray(offs, float)))
            continue
        for p in c.get_paths():
            v = p.vertices
            if len(v):
                pts.append(c.get_transform().transform(v))
    for t in ax.texts:  # annotations written beside the data (variogram's pair counts)
        xy = getattr(t, "xy", None)
        if xy is not None:
            pts.append(ax.transData.transform(np.array([xy], float)))
    for r in ax.patches:
        try:
            x0, y0, w, h = r.get_x(), r.get_y(), r.get_width(), r.get_height()
        except AttributeError:
            continue
        xs = x0 + w * np.array([0.2, 0.5, 0.8])
        ys = y0 + h * np.linspace(0, 1, 6)
        grid = np.array([(x, y) for x in xs for y in ys])
        pts.append(r.get_transform().transform(grid))
    if not pts:
        return np.empty((0, 2))
    p = np.concatenate(pts)
    return p[np.isfinite(p).all(axis=1)]


def covered(bbox, pts):
    """The fraction of pts inside bbox (display coordinates)."""
    if not len(pts):
        return 0.0
    inside = (pts[:, 0] >= bbox.x0) & (pts[:, 0] <= bbox.x1) & (pts[:, 1] >= bbox.y0) & (pts[:, 1] <= bbox.y1)
    return float(inside.mean())


def _renderer(fig):
    """The figure's renderer, without drawing: a full draw (constrained
    layout, log axes' tick labels) costs seconds, and the axes keep their
    place within a few per cent after the layout (place() pads the boxes
    for it)."""
    get = getattr(fig.canvas, "get_renderer", None)
    return get() if get is not None else None


def place(ax, make, avoid=()):
    """Add the box make(loc) (a legend or an AnchoredText) at the location
    inside ax covering the fewest plotted points and none of the boxes in
    `avoid`; outside ax, right of it, when every inside location covers more
    than CLEAR of them.  Returns the box."""
    r = _renderer(ax.figure)
    if r is None:
        return make("best")
    pts = data_points(ax)
    best, best_loc = None, None
    for loc in _LOCS:
        box = make(loc)
        bb = box.get_window_extent(r).expanded(1.15, 1.15)  # the axes shrink a little in the layout
        score = covered(bb, pts) + sum(1.0 for a in avoid if bb.overlaps(a.get_window_extent(r)))
        box.remove()
        if best is None or score < best:
            best, best_loc = score, loc
        if score == 0:
            break
    if best <= CLEAR:
        return make(best_loc)
    box = make(("upper left", (1.02, 1.0)))
    axbb = ax.get_window_extent(r)
    bb = box.get_window_extent(r)
    if bb.width > 0.45 * axbb.width:  # too wide for the side: above the axes, the title above it
        box.remove()
        box = make(("lower left", (0.0, 1.02)))
        title = ax.get_title()
        if title:
            ax.set_title(title, y=1.04 + box.get_window_extent(r).height / axbb.height)
    return box


def legend(ax, avoid=()):
    """The legend of ax's labelled artists, where it covers no data."""
    def make(loc):
        if isinstance(loc, tuple):
            return ax.legend(loc=loc[0], bbox_to_anchor=loc[1], borderaxespad=0.0, fontsize="small")
        return ax.legend(loc=loc, framealpha=0.85, fontsize="small")
    return place(ax, make, avoid)


def colorbar(ax, mappable, label):
    """A labelled colour bar right of ax, as tall as its (aspect-kept) map:
    an inset of the axes, so that it follows the map's box."""
    cax = ax.inset_axes([1.04, 0.0, 0.05, 1.0])
    cb = ax.figure.colorbar(mappable, cax=cax)
    cb.set_label(label)
    return cb


def overlay_points(ax, points, values=None, norm=None, cmap=None, label="data"):
    """Data locations (m, 2), x first, as small markers; with values,
    coloured on the map's scale."""
    p = np.asarray(points, dtype=float) if points is not None else None
    if p is None:
        return None
    if p.ndim != 2 or p.shape[1] != 2 or not np.isfinite(p).all():
        raise Error("points: expected an (m, 2) array of finite coordinates, x first, got shape %s"
                    % (p.shape,))
    if values is not None:
        v = np.asarray(values, dtype=float).reshape(-1)
        if v.size != p.shape[0]:
            raise Error("values: expected %d values (one per point), got %d" % (p.shape[0], v.size))
        return ax.scatter(p[:, 0], p[:, 1], c=v, s=14, norm=norm, cmap=cmap, edgecolors="k", linewidths=0.5,
                          label=label)
    return ax.scatter(p[:, 0], p[:, 1], s=8, facecolors="w", edgecolors="k", linewidths=0.6, label=label)
