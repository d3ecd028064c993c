"""Synthesis: noiselab.synth and noiselab.Plan (as `noiselab synth`)."""
import json
import threading

import numpy as np

from ._args import as_bool, as_float, as_int, as_size, as_spacing, as_str
from ._ffi import Error, Model, alloc_field, check, ffi, free_data, grid_args, lib, owned_field, planner


def _registry():
    """The library's methods, in its order: name -> descriptor."""
    return {ffi.string(t.name).decode(): t for t in (lib.nl_method_at(i) for i in range(lib.nl_method_count()))}


_METHODS = _registry()
METHODS = tuple(_METHODS)
_TYPES = {lib.NL_METHOD_INT: "int", lib.NL_METHOD_DOUBLE: "float", lib.NL_METHOD_CHOICE: "choice",
          lib.NL_METHOD_FLAG: "flag", lib.NL_METHOD_STRING: "str"}
_CAPS = (("model", lib.NL_METHOD_MODEL), ("no_model", lib.NL_METHOD_NO_MODEL), ("periodic", lib.NL_METHOD_PERIODIC),
         ("window", lib.NL_METHOD_WINDOW), ("distributed", lib.NL_METHOD_DISTRIBUTED),
         ("conditionable", lib.NL_METHOD_CONDITIONABLE), ("exact", lib.NL_METHOD_EXACT),
         ("clamp", lib.NL_METHOD_CLAMP), ("intrinsic", lib.NL_METHOD_INTRINSIC))


def _str(p):
    return ffi.string(p).decode() if p != ffi.NULL else None


def _rows(t):
    """The option table of descriptor t: keyword (with '_' for '-') -> row."""
    return {_str(t.options[k].name).replace("-", "_"): t.options[k] for k in range(t.noptions)}


def methods():
    """The synthesis methods, from the library's registry (synth/method.h):
    a list of dicts with name, summary, dims (the grid dimensions it
    synthesises), capabilities (model, no_model, periodic, window,
    distributed, conditionable, exact, clamp) and options (keyword ->
    dict of type, range or choices, default and help; a window method also
    takes origin)."""
    out = []
    for name, t in _METHODS.items():
        opts = {}
        for key, r in _rows(t).items():
            o = dict(type=_TYPES[r.type], default=_str(getattr(r, "def")), help=_str(r.help))
            if r.type in (lib.NL_METHOD_INT, lib.NL_METHOD_DOUBLE):
                o["range"] = (r.min, r.max)
            if r.type == lib.NL_METHOD_CHOICE:
                o["choices"] = tuple(_str(r.words).split("|"))
            opts[key] = o
        out.append(dict(name=name, summary=_str(t.summary), dims=tuple(d for d in (1, 2, 3) if t.dims >> (d - 1) & 1),
                        capabilities=tuple(c for c, bit in _CAPS if t.caps & bit), options=opts))
    return out


_CLAMP = 1  # NL_SYNTH_FFT_CLAMP == NL_SYNTH_LATTICE_CLAMP


def _model(method, acf, spectrum, t, replacing):
    """The model as the CLI parses --acf / --spectrum (cli/cmd_synth.c);
    replacing: the options given that stand in for a model."""
    if acf is not None and spectrum is not None:
        raise Error("synth: expected exactly one of acf or spectrum")
    alts = [k for k, r in _rows(t).items() if r.flags & lib.NL_METHOD_REPLACES_MODEL]
    if acf is None and spectrum is None:
        if t.caps & lib.NL_METHOD_MODEL and not replacing:
            raise Error("synth %s: expected exactly one of acf or spectrum%s"
                        % (method, "".join(" or " + k for k in alts)))
        return None
    if t.caps & lib.NL_METHOD_NO_MODEL:
        raise Error("synth %s: takes no model; got acf/spectrum" % method)
    if replacing:
        raise Error("synth %s: give either %s or a model, not both" % (method, " or ".join(replacing)))
    if spectrum is not None:
        s = as_str("spectrum", spectrum).decode()
        if not (s.startswith("power") or s.startswith("spectrum:")):
            s = "spectrum:" + s
        m = Model(s, "spectrum")
        if not m.spectral:
            raise Error('spectrum: "%s" is an autocorrelation model; pass it with acf' % spectrum)
        return m
    m = Model(acf, "acf")
    if m.spectral:
        raise Error('acf: "%s" is a spectrum model; pass it with spectrum' % acf)
    return m


def _origin(v):
    if v is None:
        return (0, 0)
    try:
        o = (v,) if np.ndim(v) == 0 else tuple(v)
    except TypeError:
        o = ()
    if not 1 <= len(o) <= 2:
        raise Error("origin: expected X or (X, Y), got %r" % (v,))
    o = tuple(as_int("origin", x, -(1 << 30), 1 << 30) for x in o)
    return o + (0,) * (2 - len(o))


class Plan:
    """Plan once, synthesise many: ``Plan(method, acf=..., size=...)(seed)``.

    Arguments are those of :func:`synth` (without ``seed``).  Making the plan
    does the expensive work once (FFTW plans, spectrum or covariance
    factorisation, subdivision coefficients); each call ``plan(seed)``
    returns a new float64 array of shape ``size`` over memory the library
    allocated (no copy), bit-identical to ``noiselab synth METHOD ...
    --seed SEED`` for the same arguments.

    Threads: the plan may be called from several Python threads at once.
    cffi releases the GIL around each C call, so the calls run in parallel
    (the library's executes only read the plan), except cholesky's, whose
    plan keeps its workspace (its calls take a lock of the plan's), and
    sparse's with a kernel expression (muParser: the package's lock).
    Making a plan takes the package's lock (FFTW's planner and muParser
    are not thread-safe).

    Attributes: ``method`` (the method string the CLI records, e.g.
    "circulant:embedding=128x128x1"), ``model`` (the spec), ``flags`` (e.g.
    "clamped"), ``info`` (a dict of the plan's report, the
    ``--json`` report of ``noiselab synth``: variance, eigenvalue range, ...), ``shape``, ``spacing``.
    """

    def __init__(self, method, acf=None, spectrum=None, size=None, spacing=1.0, clamp=False, **options):
        t = _METHODS.get(method) if isinstance(method, str) else None
        if t is None:
            raise Error('synth: unknown method "%s" (expected %s)' % (method, ", ".join(METHODS)))
        rows = _rows(t)
        allowed = set(rows) | ({"origin"} if t.caps & lib.NL_METHOD_WINDOW else set())
        bad = set(options) - allowed
        if bad:
            raise Error("synth %s: unknown option %s (this method takes: %s)"
                        % (method, ", ".join(sorted(bad)), ", ".join(sorted(allowed)) or "none"))
        self.shape = as_size("size", size)
        self.spacing = as_spacing("spacing", spacing, len(self.shape))
        self.method_name = method
        self.clamp = as_bool("clamp", clamp)
        self.options = dict(options)
        self.flags = ""
        self.info = {}
        self._lock = None  # serialises the calls of plans that are not thread-safe
        given = {k: v for k, v in options.items() if v is not None and v is not False}
        replacing = [k for k in given if k in rows and rows[k].flags & lib.NL_METHOD_REPLACES_MODEL]
        self._m = _model(method, acf, spectrum, t, replacing)
        self.model = self._m.spec if self._m else ""
        self._dim, self._n, self._h = grid_args(self.shape, self.spacing)
        if not t.dims >> (self._dim - 1) & 1:
            raise Error("synth %s: expected a %s size, got %dD"
                        % (method, " or ".join("%dD" % d for d in (1, 2, 3) if t.dims >> (d - 1) & 1), self._dim))
        self._origin = ffi.new("long[2]", _origin(options.get("origin")))
        self._window(t, rows, given)
        o = self._options(t, rows, given)
        g = ffi.new("nl_method_grid *", dict(dim=self._dim, n=list(self._n), h=list(self._h),
                                              origin=list(self._origin)))
        out = ffi.new("nl_method_plan **")
        with planner:
            check(lib.nl_method_plan_alloc(t, self._m.ptr if self._m else ffi.NULL, g, o, out))
        self._p = ffi.gc(out[0], lib.nl_method_plan_free)
        buf = ffi.new("char[4096]")
        check(lib.nl_method_describe(self._p, buf, 4096))
        self.method = ffi.string(buf).decode()
        if t.caps & lib.NL_METHOD_SERIAL:
            self._lock = threading.Lock()  # the plan holds its workspace
        if any(rows[k].flags & lib.NL_METHOD_EXPRESSION for k in given if k in rows):
            self._lock = planner  # an expression evaluated per call (muParser)
        r = ffi.new("nl_method_report *")
        check(lib.nl_method_report_of(self._p, self._m.ptr if self._m else ffi.NULL, 0, ffi.NULL, r))
        self.flags = ffi.string(r.flags).decode()
        self.info = json.loads(ffi.string(r.json).decode()) if r.json[0] != b"\0" else {}

    def _window(self, t, rows, given):
        """origin against the options that make or unmake a window."""
        if "origin" not in given:
            return
        for k, r in rows.items():
            if r.flags & lib.NL_METHOD_MAKES_WINDOW and k not in given:
                raise Error("synth %s: origin needs %s=True (a periodic field has no origin)" % (self.method_name, k))
            if r.flags & lib.NL_METHOD_NO_WINDOW and k in given:
                raise Error("synth %s: origin and %s exclude each other (a periodic tile has no origin)"
                            % (self.method_name, k))

    def _options(self, t, rows, given):
        """The library's options object from the keywords, checked by the method's table."""
        o = ffi.new("nl_method_options *")
        lib.nl_method_options_default(t, o)
        o.flags = lib.NL_METHOD_OPT_CLAMP if self.clamp else 0
        self._keep = []  # the option texts the plan refers to
        for k, v in given.items():
            if k not in rows:
                continue
            r = rows[k]
            if r.type == lib.NL_METHOD_FLAG:
                as_bool(k, v)
                text = None
            elif r.type == lib.NL_METHOD_INT and not isinstance(v, str):
                # the library checks the table's range, with the CLI's message
                want = "an integer from %d to %d" % (r.min, r.max)
                text = str(as_int(k, v, -(1 << 63), (1 << 63) - 1, want))
            elif r.type == lib.NL_METHOD_DOUBLE and not isinstance(v, str):
                text = repr(as_float(k, v))
            else:
                text = v
            c = as_str(k, text) if text is not None else ffi.NULL
            self._keep.append(c)
            check(lib.nl_method_options_set(o, r.name, c, as_str(k, k)))
        self._opts = o
        return o

    # -- execution --------------------------------------------------------

    def __call__(self, seed=0, out=None):
        """The field for `seed` (an integer 0 .. 2^64 - 1): a new float64
        array of shape ``self.shape`` (numpy order: x, the fastest axis in
        memory, last), over memory the library allocated for it.  With
        ``out=A`` the field is written into A instead and A is returned: A a
        writable C-ordered float64 array of the plan's shape whose data is
        64-byte aligned (an array returned by a plan is), e.g. to refill one
        array in a loop without allocating."""
        seed = as_int("seed", seed, 0, (1 << 64) - 1)
        if out is not None:
            return self._into(seed, out)
        # every method writes every sample: no zeroing needed (core/mem.h's nl_alloc)
        f = alloc_field(self.shape, self.spacing, zero=False)
        try:
            self._run(seed, f)
        except BaseException:
            free_data(f)
            raise
        return owned_field(f, free_data)

    def _run(self, seed, f):
        if self._lock is None:
            st = lib.nl_method_execute(self._p, seed, f)
        else:
            with self._lock:
                st = lib.nl_method_execute(self._p, seed, f)
        check(st)

    def _into(self, seed, out):
        if not (isinstance(out, np.ndarray) and out.dtype == np.float64 and out.shape == self.shape
                and out.flags.c_contiguous and out.flags.writeable and out.ctypes.data % 64 == 0):
            raise Error("out: expected a writable C-ordered float64 array of shape %s with 64-byte aligned data "
                        "(e.g. one the plan returned)" % (self.shape,))
        f = ffi.new("nl_field *")
        dim = len(self.shape)
        f.dim, f.count = dim, out.size
        for a in range(3):
            f.n[a], f.h[a] = self._n[a], self._h[a]
        f.data = ffi.cast("double *", ffi.from_buffer(out, require_writable=True))
        self._run(seed, f)
        return out

    def provenance(self, seed):
        """What `noiselab synth` records with the field of `seed`, as
        keywords for :func:`noiselab.write` (model, method, seed, flags,
        origin, and spacing in the array's axis order):
        ``noiselab.write(path, plan(seed), **plan.provenance(seed))``."""
        origin = ""
        rows = _rows(_METHODS[self.method_name])
        makes = [k for k, r in rows.items() if r.flags & lib.NL_METHOD_MAKES_WINDOW]
        unmakes = [k for k, r in rows.items() if r.flags & lib.NL_METHOD_NO_WINDOW]
        if _METHODS[self.method_name].caps & lib.NL_METHOD_WINDOW and (
                any(self.options.get(k) for k in makes) if makes
                else not any(self.options.get(k) for k in unmakes) and any(self._origin)):
            o = tuple(self._origin)
            origin = "%d" % o[0] if len(self.shape) == 1 else "%d,%d" % o
        seed = as_int("seed", seed, 0, (1 << 64) - 1)
        return dict(model=self.model, method=self.method, flags=self.flags, seed=str(seed),
                    origin=origin, spacing=self.spacing)

    def __repr__(self):
        return "noiselab.Plan(%r, model=%r, size=%r)" % (self.method, self.model, self.shape)


def synth(method, acf=None, spectrum=None, size=None, seed=0, spacing=1.0, **options):
    """Synthesise one field, as ``noiselab synth METHOD``.

    method    a method's name (``noiselab.methods()`` lists them, with what
              each can do and takes; ``noiselab synth --help`` says more).
    acf       an autocorrelation model spec (``noiselab.models()``), e.g.
              "markov:scale=8" (lags in length units: scale 8 at spacing 1 is
              8 samples), or
    spectrum  a spectrum model: "power:d=...", "spectrum:EXPR" or a bare EXPR
              in f/fx/fy/k (frequencies in cycles per unit length).
    size      the array's shape: N (1D), (ny, nx) (2D) or (nz, ny, nx) (3D),
              each >= 2.  Note the order: numpy's, x last; the CLI's
              ``--size NXxNY`` lists x first (size=(ny, nx) is --size nx x ny).
    seed      integer 0 .. 2^64 - 1 (the CLI's default is 1).
    spacing   grid spacing: one value, or one per axis in the order of size.
    options   clamp=True (synthesise a model that is not positive definite by
              zeroing its negative spectrum or variances, as --clamp), and the
              method's own, as its command-line options with '_' for '-'
              (``noiselab.methods()`` gives each method's table: type, range or
              choices, default), e.g. subdiv neighborhood=3 or "auto",
              tol=1e-3 or "variance:1e-3"; origin for a window method.

    Returns a float64 array of shape `size` (C order; row j of a 2D field is
    the EXR's row j), over memory the library allocated (no copy): the same
    numbers as ``noiselab synth METHOD --acf SPEC --size ... --seed SEED``
    before its 32-bit EXR rounding.  Raises noiselab.Error with the library's
    message on a bad argument or model.  For many seeds make a Plan once.
    """
    return Plan(method, acf=acf, spectrum=spectrum, size=size, spacing=spacing, **options)(seed)
