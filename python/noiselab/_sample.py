"""noiselab.sample: a field's values at points, as the CLI's ``sample``
(core/field_sample.h): the same library calls."""
import numpy as np

from ._args import Error, as_choice, as_coords, as_float, as_int, refuse
from ._ffi import FieldView, check, ffi, lib
from ._krige import _dptr, _extent, _grid_spacing


_INTERP = ("nearest", "bilinear")  # NL_INTERP_* by index, as --interpolation


def sample(field, points=None, *, spacing=1.0, origin=None, extent=None, interpolation="bilinear", random=None,
           seed=1):
    """A field's values at points, as ``noiselab sample``: the nearest
    sample's value, or multilinear between the 2^dim samples around a point
    (interpolation="bilinear", the default).

    field    1D, 2D (ny, nx) or 3D array.
    points   (n, d) coordinates, x first, within the samples' span (the
             first outside is refused), or
    random   N points drawn uniformly within the span from `seed` (default 1,
             as the CLI's; the CLI prints them to 10 digits, these are not
             rounded).
    Coordinates: sample i of an axis at (origin + i) h (spacing h, one value
    or one per axis in numpy order; origin in samples, x first, as
    noiselab.origin), or, with extent ((lo, hi) per axis, x first, or
    "a:b,c:d"; a field of :meth:`Krige.grid` or :class:`CondSim`), at the
    cell centres lo + (i + 0.5)(hi - lo)/n.
    Returns the n values or, with random, (points, values)."""
    interp = _INTERP.index(as_choice("interpolation", interpolation, _INTERP))
    a = np.asarray(field) if isinstance(field, np.ndarray) else field
    fv0 = FieldView(a, 1.0, "field")
    dim = fv0.array.ndim
    if extent is not None and origin is not None:
        raise Error("extent: expected extent or origin, not both")
    if extent is not None:
        lo, hi = _extent(extent, dim)
        hx = _grid_spacing(lo, hi, fv0.array.shape)
        x0 = [lo[d] + 0.5 * hx[d] for d in range(dim)]
        spacing = hx[::-1]
    fv = FieldView(fv0.array, spacing, "field")
    if extent is None:
        o = [0] * dim if origin is None else origin
        o = [o] if np.ndim(o) == 0 else list(o)
        if len(o) != dim:
            refuse("origin", "%d numbers (x first)" % dim, origin)
        x0 = [as_float("origin", o[d]) * fv.f.h[d] for d in range(dim)]
    x0c = ffi.new("double[3]", x0 + [0.0] * (3 - dim))
    if (points is None) == (random is None):
        raise Error("sample: expected exactly one of points or random")
    if random is not None:
        n = as_int("random", random, 1, (1 << 40))
        pts = np.empty((n, dim))
        lib.nl_field_random_points(fv.f, x0c, as_int("seed", seed, 0, (1 << 64) - 1), n, _dptr(pts))
    else:
        pts = as_coords("points", points, dim, least=0)
    vals = np.empty(pts.shape[0])
    if pts.shape[0]:
        check(lib.nl_field_sample(fv.f, x0c, interp, pts.shape[0], _dptr(pts), _dptr(vals)))
    return (pts, vals) if random is not None else vals
