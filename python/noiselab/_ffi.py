"""The C side: libnoiselab loaded through cffi in ABI mode with the
declarations of _cdef.py, the library's location, errors, the lock around
what is not thread-safe, and fields shared between numpy and C."""
import ctypes.util
import os
import threading

import numpy as np
from cffi import FFI

from ._args import Error, as_array, as_spacing, as_str
from ._cdef import CDEF


ffi = FFI()
ffi.cdef(CDEF)

#: The soname's major version (core/version.h NL_VERSION_MAJOR).
SOVERSION = 1

_here = os.path.dirname(os.path.abspath(__file__))


def _candidates():
    """Where the library is looked for, in order: $NOISELAB_LIB, the build/
    folder of the source tree next to python/, the installed soname."""
    env = os.environ.get("NOISELAB_LIB")
    if env:
        yield env
        return
    tree = os.path.join(os.path.dirname(os.path.dirname(_here)), "build", "libnoiselab.so")
    if os.path.exists(tree):
        yield tree
    yield "libnoiselab.so.%d" % SOVERSION
    found = ctypes.util.find_library("noiselab")
    if found:
        yield found


_keep = []


def _load():
    errors = []
    for path in _candidates():
        try:
            lib = ffi.dlopen(path)
            # Never unload: cffi dlcloses the library when `lib` is collected
            # at interpreter exit, while OpenMP's idle worker threads (FFTW's,
            # libgomp) may still run its code: a crash at exit.  A ctypes
            # handle, never closed, keeps it and its dependencies mapped.
            _keep.append(ctypes.CDLL(path))
            return lib, path
        except OSError as e:
            errors.append("%s (%s)" % (path, e))
    raise ImportError("noiselab: cannot load libnoiselab: tried " + "; ".join(errors) +
                      "; set NOISELAB_LIB to the library's path")


lib, LIBRARY_PATH = _load()

_h5 = []


def h5lib():
    """libnoiselab_mpi (HDF5 fields, mpi/h5.h), loaded on first use from
    beside libnoiselab: it brings Open MPI and parallel HDF5 (about 40
    libraries), which only .h5 files need."""
    if not _h5:
        ffi.cdef("""
            int nl_mpi_h5_read(const char *path, nl_field **out, nl_meta *meta);
            int nl_mpi_h5_write_field(const char *path, const nl_field *f, const nl_meta *meta, int dbl);
        """)
        d = os.path.dirname(LIBRARY_PATH)
        names = [os.path.join(d, "libnoiselab_mpi.so")] if d else []
        names.append("libnoiselab_mpi.so.%d" % SOVERSION)
        errors = []
        for path in names:
            try:
                _h5.append(ffi.dlopen(path))
                _keep.append(ctypes.CDLL(path))
                break
            except OSError as e:
                errors.append("%s (%s)" % (path, e))
        if not _h5:
            raise Error("HDF5: cannot load libnoiselab_mpi: tried " + "; ".join(errors))
    return _h5[0]

# FFTW's planner, muParser's parser and evaluator, and GSL's error
# handler set-up are not thread-safe (core/fftw_plan.h, core/model.h): every
# call that may plan or evaluate a model holds this lock.  cffi releases the
# GIL around every C call, so other Python threads run meanwhile; executing
# a finished synthesis plan (Plan.__call__) does not take it.
planner = threading.RLock()


def check(status):
    """Raise Error with the library's message for a non-zero status.  The
    message is per thread in the library (core/nl_error.h) and is read in
    the thread that made the call."""
    if status:
        raise Error(ffi.string(lib.nl_errmsg()).decode("utf-8", "replace"), int(status))


# -- fields ----------------------------------------------------------------

def owned_field(f, free=None):
    """A numpy array over the samples of the library-owned field f (from
    nl_field_alloc or a reader; free: how to release it, nl_field_free by
    default): no copy; the field is freed when the last view of it goes.
    Shape (n0,), (n1, n0) or (n2, n1, n0): numpy's axis order, x (n0, fastest
    in memory) last."""
    shape = tuple(int(f.n[a]) for a in reversed(range(f.dim)))
    nbytes = int(f.count) * 8
    free = free or lib.nl_field_free
    # the gc'd pointer owns the field; the buffer keeps the pointer alive
    data = ffi.gc(f.data, lambda _p, f=f: free(f), size=nbytes)
    return np.frombuffer(ffi.buffer(data, nbytes), dtype=np.float64).reshape(shape)


def _free_data(f):
    lib.nl_free(f.data)


def alloc_field(shape, spacing, zero=True):
    """A new library field for a numpy shape and spacing (numpy axis order):
    nl_field_alloc's (zeroed; release with nl_field_free), or with
    zero=False a field struct of Python's over nl_alloc'ed samples left
    unset, for outputs the library overwrites (release with
    owned_field(f, free_data) or _free_data).  Returns the nl_field *."""
    dim = len(shape)
    n = ffi.new("size_t[3]", [int(s) for s in reversed(shape)] + [1] * (3 - dim))
    h = ffi.new("double[3]", [float(s) for s in reversed(spacing)] + [1.0] * (3 - dim))
    st = ffi.new("int *")
    if zero:
        f = lib.nl_field_alloc(dim, n, h, st)
        if f == ffi.NULL:
            check(st[0])
        return f
    count = ffi.new("size_t *")
    check(lib.nl_size_check(dim, n, 8, 1, count))
    f = ffi.new("nl_field *")
    f.dim, f.count = dim, count[0]
    for a in range(3):
        f.n[a], f.h[a] = n[a], h[a]
    f.data = ffi.cast("double *", lib.nl_alloc(count[0] * 8))
    if f.data == ffi.NULL:
        raise Error("out of memory for %d samples" % count[0], 6)
    return f


free_data = _free_data


class FieldView:
    """An nl_field describing a numpy array's memory (C order, float64), for
    inputs the library only reads (or, for shape, rewrites in place).  Keeps
    the array alive while the view lives."""

    def __init__(self, array, spacing=1.0, what="field", finite=True, writable=False):
        a = as_array(what, array, finite=finite)
        if writable and not (a is array and a.flags.writeable):
            raise Error("%s: expected a writable C-ordered float64 array to change in place" % what)
        self.array = a
        dim = a.ndim
        hs = as_spacing(what + ": spacing", spacing, dim)
        self.f = ffi.new("nl_field *")
        self.f.dim = dim
        for ax in range(3):
            self.f.n[ax] = a.shape[dim - 1 - ax] if ax < dim else 1
            self.f.h[ax] = hs[dim - 1 - ax] if ax < dim else 1.0
        self.f.count = a.size
        self.f.data = ffi.cast("double *", ffi.from_buffer(a, require_writable=writable))
        self._keep = a


def grid_args(shape, spacing):
    """(dim, n[3], h[3]) in the library's axis order (x first) for a numpy
    shape and spacing."""
    dim = len(shape)
    n = ffi.new("size_t[3]", [int(s) for s in reversed(shape)] + [1] * (3 - dim))
    h = ffi.new("double[3]", [float(s) for s in reversed(spacing)] + [1.0] * (3 - dim))
    return dim, n, h


class Model:
    """A parsed model spec (nl_model), freed with the object."""

    def __init__(self, spec, what="acf"):
        out = ffi.new("nl_model **")
        b = as_str(what, spec)
        with planner:  # muParser's C interface is not thread-safe
            check(lib.nl_model_parse(b, out))
        self.ptr = ffi.gc(out[0], lib.nl_model_free)
        self.spec = ffi.string(lib.nl_model_spec(self.ptr)).decode()
        self.spectral = bool(lib.nl_model_is_spectral(self.ptr))


class Dist:
    """A parsed distribution spec (nl_dist), freed with the object."""

    def __init__(self, spec, what="to"):
        out = ffi.new("nl_dist **")
        b = as_str(what, spec)
        with planner:
            check(lib.nl_dist_parse(b, out))
        self.ptr = ffi.gc(out[0], lib.nl_dist_free)
