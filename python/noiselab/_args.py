"""The arguments of the public functions, checked before C sees them: one
converter per kind of argument, each returning the value C takes or
raising Error with a message that names the argument, says what was
expected and what came, as the CLI's do ("size: expected an integer from
2 to 2^63 - 1, got 2.7").  Nothing is truncated or coerced silently: 2.7
is not an integer, "no" is not a bool, a complex array is not real."""
import math
import numbers
import operator
import os

import numpy as np


class Error(ValueError):
    """A failure reported by libnoiselab: the message is nl_errmsg()'s line
    (or the binding's own check of an argument, in the same style); `code`
    is the NL_E* status (1 EINVAL, 2 EINPUT, 3 ETOOBIG, 4 ENOTPD, 5 EIO,
    6 ENOMEM, 7 EFAIL; 1 for the binding's checks)."""

    def __init__(self, message, code=1):
        super().__init__(message)
        self.code = code


Error.__module__ = "noiselab"  # its public name (pickles, tracebacks)


def _show(value):
    """A value for a message: short, and never failing."""
    try:
        s = repr(value)
    except Exception:  # a hostile __repr__ must not hide the message
        s = "<%s>" % type(value).__name__
    return s if len(s) <= 80 else s[:77] + "..."


def _bound(n):
    """An integer bound as people read it: 2^64 - 1 rather than its digits."""
    a = abs(n)
    for k in range(20, 128):
        if a == 1 << k:
            return ("-" if n < 0 else "") + "2^%d" % k
        if a == (1 << k) - 1:
            return ("-" if n < 0 else "") + "2^%d - 1" % k
    return "%d" % n


def refuse(name, expected, value):
    """The binding's error for argument `name`."""
    raise Error("%s: expected %s, got %s" % (name, expected, _show(value)))


def _is_bool(v):
    return isinstance(v, (bool, np.bool_))


def as_int(name, value, lo, hi, want=None):
    """An integer lo..hi: a Python or numpy integer (anything with
    __index__), not a bool, not a float (2.0 included: no rounding).
    want: what the message says was expected, when not the range."""
    want = want or "an integer from %s to %s" % (_bound(lo), _bound(hi))
    if _is_bool(value):
        refuse(name, want, value)
    try:
        v = operator.index(value)
    except TypeError:
        refuse(name, want, value)
    if not lo <= v <= hi:
        refuse(name, want, value)
    return v


def as_float(name, value, lo=-math.inf, hi=math.inf, lo_open=False):
    """A finite real number in [lo, hi] ((lo, hi] with lo_open): a Python or
    numpy real, not a bool or a string."""
    if hi == math.inf and lo > -math.inf:
        want = "a finite number %s %g" % ("above" if lo_open else ">=", lo)
    elif lo > -math.inf or hi < math.inf:
        want = "a finite number in %s%g, %g]" % ("(" if lo_open else "[", lo, hi)
    else:
        want = "a finite number"
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
        value = value[()]
    if _is_bool(value) or not isinstance(value, numbers.Real):
        refuse(name, want, value)
    try:
        v = float(value)
    except (OverflowError, TypeError, ValueError):
        refuse(name, want, value)
    if not math.isfinite(v) or v < lo or v > hi or (lo_open and v == lo):
        refuse(name, want, value)
    return v


def as_positive(name, value):
    """A finite number above 0 (a spacing, a width, a tolerance)."""
    return as_float(name, value, 0.0, math.inf, lo_open=True)


def as_bool(name, value):
    """True or False (numpy's too, and the integers 0 and 1): not a string,
    whose truth would be its length."""
    if _is_bool(value):
        return bool(value)
    if isinstance(value, (int, np.integer)) and value in (0, 1):
        return bool(value)
    refuse(name, "True or False", value)


def as_str(name, value, empty=False):
    """A str without NUL characters that UTF-8 encodes (no lone surrogates):
    the bytes C takes.  empty: whether "" is allowed."""
    if not isinstance(value, str):
        refuse(name, "a string", value)
    if not value and not empty:
        refuse(name, "a non-empty string", value)
    if "\0" in value:
        refuse(name, "a string without NUL characters", value)
    try:
        return value.encode("utf-8")
    except UnicodeEncodeError:
        refuse(name, "a string that UTF-8 encodes (no lone surrogates)", value)


def as_choice(name, value, choices):
    """One of the strings `choices`."""
    if not isinstance(value, str) or value not in choices:
        refuse(name, "one of " + ", ".join('"%s"' % c for c in choices), value)
    return value


def as_path(name, value):
    """A file name: str, bytes or os.PathLike, not empty, without NUL, that
    the file system encoding encodes (str names made of undecodable bytes
    by Python, surrogateescape, round-trip).  Returns (str for messages and
    suffix tests, bytes for C)."""
    want = "a file name (str, bytes or os.PathLike)"
    if not isinstance(value, (str, bytes, os.PathLike)):
        refuse(name, want, value)
    try:
        p = os.fspath(value)
    except TypeError:
        refuse(name, want, value)
    if not isinstance(p, (str, bytes)):
        refuse(name, want, value)
    if not p:
        refuse(name, "a non-empty file name", value)
    if (b"\0" if isinstance(p, bytes) else "\0") in p:
        refuse(name, "a file name without NUL characters", value)
    try:
        b = os.fsencode(p)
    except UnicodeEncodeError:
        refuse(name, "a file name that the file system encoding encodes (no lone surrogates)", value)
    return os.fsdecode(b), b


def as_size(name, value):
    """A numpy shape of 1 to 3 axes, each an integer >= 2 (as the CLI's --size)."""
    if value is None or isinstance(value, (str, bytes)):
        refuse(name, "N, (ny, nx) or (nz, ny, nx)", value)
    items = (value,) if np.ndim(value) == 0 else value
    try:
        items = tuple(items)
    except TypeError:
        refuse(name, "N, (ny, nx) or (nz, ny, nx)", value)
    if not 1 <= len(items) <= 3:
        raise Error("%s: expected 1 to 3 axes, got %d" % (name, len(items)))
    return tuple(as_int(name, s, 2, (1 << 63) - 1, "integers of at least 2 samples per axis (at most 2^63 - 1)")
                 for s in items)


_DBL_MIN = float(np.finfo(np.float64).tiny)


def _spacing(name, value):
    h = as_positive(name, value)
    if h < _DBL_MIN:  # as the library's synthesis plans refuse it
        raise Error("%s: %g is below the smallest normal double %r (its frequencies 1/spacing overflow); "
                    "expected spacings nearer 1" % (name, h, _DBL_MIN))
    return h


def as_spacing(name, value, dim):
    """One spacing per numpy axis, each finite, positive and at least the
    smallest normal double (a scalar: the same on every axis)."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, (numbers.Real, np.generic)) or value is None or isinstance(value, (str, bytes)):
        return (_spacing(name, value),) * dim
    try:
        items = tuple(value)
    except TypeError:
        refuse(name, "a positive number or one per axis", value)
    if len(items) != dim:
        raise Error("%s: expected one value or %d (one per axis), got %d" % (name, dim, len(items)))
    return tuple(_spacing(name, v) for v in items)


def _real(name, value):
    """value as a numpy array of real numbers (bool, complex, strings,
    objects refused: converting them would invent or drop information)."""
    if value is None or isinstance(value, (str, bytes)):
        refuse(name, "an array of real numbers", value)
    try:
        a = np.asarray(value)
    except (TypeError, ValueError, OverflowError):
        refuse(name, "an array of real numbers", value)
    if a.dtype.kind not in "iuf":
        raise Error("%s: expected an array of real numbers, got dtype %s" % (name, a.dtype))
    return a


def as_array(name, value, finite=True):
    """A field: float64, C-ordered, 1 to 3 axes, each >= 1 sample, finite.
    Converts (copies) only when the input is not that."""
    a = _real(name, value)
    if a.ndim < 1 or a.ndim > 3:
        raise Error("%s: expected an array of 1 to 3 axes, got %d" % (name, a.ndim))
    if a.size == 0:
        raise Error("%s: expected at least one sample per axis, got shape %s" % (name, a.shape))
    a = np.ascontiguousarray(a, dtype=np.float64)
    if finite and not np.isfinite(a).all():
        bad = int(np.flatnonzero(~np.isfinite(a.ravel()))[0])
        raise Error("%s: sample %d is %r; expected finite samples" % (name, bad, a.ravel()[bad]))
    return a


def as_coords(name, value, d=None, least=1):
    """(n, d) finite coordinates with d = 1, 2 or 3 (or the given d) and
    n >= least, float64 C order; a 1D array is n points of one coordinate."""
    a = _real(name, value)
    if a.ndim == 1:
        a = a.reshape(-1, 1)
    want = "an (n, d) array with d = 1, 2 or 3" if d is None else "an (n, %d) array" % d
    want += " and n >= %d" % least if least else ""
    if a.ndim != 2 or a.shape[0] < least or not (1 <= a.shape[1] <= 3 if d is None else a.shape[1] == d):
        raise Error("%s: expected %s, got shape %s" % (name, want, np.shape(value)))
    a = np.ascontiguousarray(a, dtype=np.float64)
    if not np.isfinite(a).all():
        raise Error("%s: expected finite coordinates" % name)
    return a


def as_values(name, value, n):
    """n finite values, float64."""
    a = _real(name, value).ravel()
    if a.shape[0] != n:
        raise Error("%s: expected %d values (one per point), got %d" % (name, n, a.shape[0]))
    a = np.ascontiguousarray(a, dtype=np.float64)
    if not np.isfinite(a).all():
        raise Error("%s: expected finite numbers" % name)
    return a


def as_fields(name, value):
    """A sequence of at least one field (arrays are checked as the
    library asks for them)."""
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__len__") or not hasattr(value, "__getitem__"):
        refuse(name, "a sequence of fields (arrays of one shape)", value)
    if len(value) < 1:
        refuse(name, "a sequence of at least one field", value)
    return value
