"""Synthesis: noiselab.synth and noiselab.Plan (as `noiselab synth`)."""
import math
import threading

import numpy as np

from ._ffi import (Error, Model, alloc_field, check, cstr, ffi, free_data, grid_args, lib, owned_field, planner,
                   size_tuple, spacing_tuple)

METHODS = ("fft", "subdiv", "midpoint", "circulant", "cholesky", "faulting", "sparse", "lattice")

# The options each method takes (keyword names: the CLI's with '_' for '-').
_OPTIONS = {
    "fft": set(),
    "circulant": set(),
    "cholesky": set(),
    "subdiv": {"levels", "neighborhood", "tol", "nonperiodic", "origin", "random_neighborhoods",
               "displacements", "taps"},
    "midpoint": {"H", "levels", "variance_scale", "interpolant"},
    "faulting": {"density"},
    "sparse": {"density", "cell", "radius", "wrap", "origin", "kernel"},
    "lattice": {"cell", "octaves", "interpolant"},
}

_CLAMP = 1  # NL_SYNTH_FFT_CLAMP == NL_SYNTH_LATTICE_CLAMP
_FFT_CLAMP_TOL = 1e-6  # NL_SYNTH_FFT_CLAMP_TOL
_CIRC_LOSS_TOL = 1e-3  # NL_SYNTH_CIRCULANT_LOSS_TOL


def _int(name, v, lo, hi):
    if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or not lo <= v <= hi:
        raise Error("%s: expected an integer from %d to %d, got %r" % (name, lo, hi, v))
    return int(v)


def _positive(name, v):
    try:
        x = float(v)
    except (TypeError, ValueError):
        x = float("nan")
    if not (math.isfinite(x) and x > 0):
        raise Error("%s: expected a positive number, got %r" % (name, v))
    return x


def _model(method, acf, spectrum, needed):
    """The model as the CLI parses --acf / --spectrum (cli/cmd_synth.c)."""
    if acf is not None and spectrum is not None:
        raise Error("synth: expected exactly one of acf or spectrum")
    if acf is None and spectrum is None:
        if needed:
            if method == "sparse":
                raise Error("synth sparse: expected exactly one kernel: acf/spectrum or kernel")
            raise Error("synth: expected exactly one of acf or spectrum")
        return None
    if not needed:
        if method == "faulting":
            raise Error("synth faulting: takes no model (its spectrum is f^-2); got acf/spectrum")
        raise Error("synth %s: give either H or a power-law model, not both" % method
                    if method == "midpoint" else "synth %s: give either a model or a kernel, not both" % method)
    if spectrum is not None:
        s = cstr(spectrum, "spectrum").decode()
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
    o = (v,) if np.ndim(v) == 0 else tuple(v)
    if not 1 <= len(o) <= 2:
        raise Error("origin: expected X or (X, Y), got %r" % (v,))
    o = tuple(_int("origin", x, -(1 << 30), 1 << 30) for x in o)
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
    sparse's with a kernel expression (libmatheval: the package's lock).
    Making a plan takes the package's lock (FFTW's planner and libmatheval
    are not thread-safe).

    Attributes: ``method`` (the method string the CLI records, e.g.
    "circulant:embedding=128x128x1"), ``model`` (the spec), ``flags`` (e.g.
    "clamped"), ``info`` (a dict of the plan's report: variance, eigenvalue
    range, ...), ``shape``, ``spacing``.
    """

    def __init__(self, method, acf=None, spectrum=None, size=None, spacing=1.0, clamp=False, **options):
        if method not in METHODS:
            raise Error('synth: unknown method "%s" (expected %s)' % (method, ", ".join(METHODS)))
        bad = set(options) - _OPTIONS[method]
        if bad:
            raise Error("synth %s: unknown option %s (this method takes: %s)"
                        % (method, ", ".join(sorted(bad)), ", ".join(sorted(_OPTIONS[method])) or "none"))
        self.shape = size_tuple(size)
        self.spacing = spacing_tuple(spacing, len(self.shape))
        self.method_name = method
        self.clamp = bool(clamp)
        self.options = dict(options)
        self.flags = ""
        self.info = {}
        self._lock = None  # serialises the calls of plans that are not thread-safe
        needs = not (method == "faulting" or (method == "midpoint" and options.get("H") is not None)
                     or (method == "sparse" and options.get("kernel") is not None))
        self._m = _model(method, acf, spectrum, needs)
        self.model = self._m.spec if self._m else ""
        self._dim, self._n, self._h = grid_args(self.shape, self.spacing)
        if method in ("subdiv", "midpoint", "faulting", "sparse", "lattice") and self._dim > 2:
            raise Error("synth %s: expected a 1D or 2D size, got %dD" % (method, self._dim))
        with planner:
            getattr(self, "_plan_" + method)()

    # -- planning, one per method (cli/synth_methods.c) --------------------

    def _plan_fft(self):
        out = ffi.new("nl_synth_fft_plan **")
        check(lib.nl_synth_fft_plan_alloc(self._m.ptr, self._dim, self._n, self._h, _CLAMP if self.clamp else 0,
                                          out))
        self._p = ffi.gc(out[0], lib.nl_synth_fft_plan_free)
        info = ffi.new("nl_synth_fft_info *")
        lib.nl_synth_fft_plan_info(self._p, info)
        self.method = "fft"
        self.flags = "clamped" if info.clamp_error > _FFT_CLAMP_TOL else ""
        self.info = dict(variance=info.variance, min_spectrum=info.min_lambda, max_spectrum=info.max_lambda,
                         clamped=int(info.negatives), clamp_error=info.clamp_error)
        self._exec = lambda seed, f: lib.nl_synth_fft_execute(self._p, seed, f)

    def _plan_circulant(self):
        out = ffi.new("nl_synth_circulant_plan **")
        check(lib.nl_synth_circulant_plan_alloc(self._m.ptr, self._dim, self._n, self._h,
                                                _CLAMP if self.clamp else 0, 16, out))
        self._p = ffi.gc(out[0], lib.nl_synth_circulant_plan_free)
        info = ffi.new("nl_synth_circulant_info *")
        lib.nl_synth_circulant_plan_info(self._p, info)
        self.method = "circulant:embedding=%dx%dx%d" % tuple(info.m)
        clamped, lost = info.clamp_error > _FFT_CLAMP_TOL, abs(info.variance_loss) > _CIRC_LOSS_TOL
        self.flags = ",".join(x for x, c in (("clamped", clamped), ("variance-changed", lost)) if c)
        self.info = dict(embedding=tuple(info.m), min_eigenvalue=info.min_eigenvalue,
                         max_eigenvalue=info.max_eigenvalue, clamp_error=info.clamp_error,
                         doublings=info.doublings, variance_loss=info.variance_loss)
        self._exec = lambda seed, f: lib.nl_synth_circulant_execute(self._p, seed, f)

    def _plan_cholesky(self):
        out = ffi.new("nl_synth_cholesky_plan **")
        check(lib.nl_synth_cholesky_plan_alloc(self._m.ptr, self._dim, self._n, self._h, out))
        self._p = ffi.gc(out[0], lib.nl_synth_cholesky_plan_free)
        self.method = "cholesky"
        self._lock = threading.Lock()  # the plan holds the workspace z (synth/cholesky.h)
        self._exec = lambda seed, f: lib.nl_synth_cholesky_execute(self._p, seed, f)

    def _plan_subdiv(self):
        o = ffi.new("nl_subdiv_options *")
        lib.nl_subdiv_options_default(o)
        opt = self.options
        o.levels = _int("levels", opt["levels"], 1, 30) if opt.get("levels") is not None else 0
        nb = opt.get("neighborhood", 2)
        o.N = 0 if nb == "auto" else _int("neighborhood", nb, 1, 2 ** 31 - 1)
        tol = opt.get("tol", 1e-4)
        o.stop = 0
        if isinstance(tol, str):
            for prefix, rule in (("variance:", 1), ("improvement:", 0)):
                if tol.startswith(prefix):
                    o.stop, tol = rule, tol[len(prefix):]
                    break
        o.tol = _positive("tol", tol)
        o.nonperiodic = bool(opt.get("nonperiodic", False))
        o.allow_not_pd = self.clamp
        o.random_nb = _int("random_neighborhoods", opt["random_neighborhoods"], 1, 256) \
            if opt.get("random_neighborhoods") else 0
        disp = opt.get("displacements", "independent")
        if disp not in ("independent", "correlated"):
            raise Error('displacements: expected independent or correlated, got "%s"' % disp)
        o.displacements = 1 if disp == "correlated" else 0
        o.taps = _int("taps", opt["taps"], 1, 16) if opt.get("taps") else 0
        if o.taps and not o.displacements:
            raise Error("taps %d: expected displacements='correlated' (independent displacements have no filter)"
                        % o.taps)
        if o.random_nb and o.displacements:
            raise Error("displacements correlated: expected the standard neighbourhoods, got "
                        "random_neighborhoods %d" % o.random_nb)
        if opt.get("origin") is not None and not o.nonperiodic:
            raise Error("synth subdiv: origin needs nonperiodic=True (a periodic field has no origin)")
        self._origin = ffi.new("long[2]", _origin(opt.get("origin")))
        if len(set(self.spacing)) > 1:
            raise Error("spacing: subdivision needs the same spacing on every axis, got %g and %g"
                        % (self.spacing[-1], self.spacing[0]))
        out = ffi.new("nl_subdiv_plan **")
        check(lib.nl_subdiv_plan_alloc(self._m.ptr, self._dim, self._n, self._h[0], o, out))
        self._p = ffi.gc(out[0], lib.nl_subdiv_plan_free)
        info = ffi.new("nl_subdiv_info *")
        lib.nl_subdiv_plan_info(self._p, info)
        c = lib.nl_subdiv_plan_coeffs(self._p)
        self.method = "subdiv:levels=%d,neighborhood=%s,tol=%s%g,%s" % (
            info.levels, o.N or "auto", "variance:" if o.stop == 1 else "", o.tol,
            "nonperiodic" if o.nonperiodic else "periodic")
        if o.random_nb:
            self.method += ",random-neighborhoods=%d" % o.random_nb
        if c.level[0].filt != ffi.NULL:
            self.method += ",displacements=correlated,taps=%d" % c.level[0].taps
        if o.nonperiodic:
            self.method += ",origin=%d:%d" % tuple(self._origin)
        self.flags = ",".join(ffi.string(lib.nl_subdiv_flag_name(b)).decode()
                              for b in range(6) if c.flags & (1 << b))
        self.info = dict(levels=info.levels, spacing0=info.spacing0, variance=c.r0)
        if o.nonperiodic:
            self.info["coarse_correlation"] = info.coarse_correlation
            self._exec = lambda seed, f: lib.nl_subdiv_plan_execute_window(self._p, seed, self._origin, f)
        else:
            self._exec = lambda seed, f: lib.nl_subdiv_plan_execute(self._p, seed, f)

    def _plan_midpoint(self):
        opt = self.options
        H = opt.get("H")
        if H is not None:
            H = float(H)
            if not 0 < H < 1:
                raise Error("H: expected a Hurst exponent between 0 and 1, got %r" % opt.get("H"))
        else:
            hp = ffi.new("double *")
            check(lib.nl_subdiv_midpoint_hurst(self._m.ptr, self._dim, hp))
            H = hp[0]
        vs = _positive("variance_scale", opt.get("variance_scale", 1.0))
        levels = _int("levels", opt["levels"], 1, 30) if opt.get("levels") is not None else 0
        interp = opt.get("interpolant", "fournier")
        if interp == "miller":
            L = levels or lib.nl_midpoint_miller_default_levels(self._dim, self._n)
            self.method = "midpoint:H=%.17g,levels=%d,variance-scale=%.17g,interpolant=miller" % (H, L, vs)
            self.info = dict(H=H, levels=L, variance_scale=vs, interpolant="miller")
            self._exec = lambda seed, f: lib.nl_midpoint_miller(L, H, 1.0, vs, seed, f)
            return
        if interp != "fournier":
            raise Error('interpolant: expected fournier or miller for midpoint, got "%s"' % interp)
        out = ffi.new("nl_subdiv_plan **")
        check(lib.nl_subdiv_plan_alloc_midpoint(self._dim, self._n, self._h[0], levels, H, 1.0, vs, out))
        self._p = ffi.gc(out[0], lib.nl_subdiv_plan_free)
        info = ffi.new("nl_subdiv_info *")
        lib.nl_subdiv_plan_info(self._p, info)
        self.method = "midpoint:H=%.17g,levels=%d,variance-scale=%.17g" % (H, info.levels, vs)
        self.info = dict(H=H, levels=info.levels, variance_scale=vs, variance=info.variance)
        self._exec = lambda seed, f: lib.nl_subdiv_plan_execute(self._p, seed, f)

    def _plan_faulting(self):
        d = _positive("density", self.options.get("density", 1.0))
        self.method = "faulting:density=%.17g" % d
        self.info = dict(density=d)
        self._exec = lambda seed, f: lib.nl_synth_faulting(seed, d, f, ffi.new("size_t *"))

    def _plan_sparse(self):
        opt = self.options
        density = _positive("density", opt.get("density", 1.0))
        cell = _int("cell", opt["cell"], 1, 2 ** 31 - 1) if opt.get("cell") else 0
        radius = _int("radius", opt["radius"], 1, 4096) if opt.get("radius") else 0
        wrap = bool(opt.get("wrap", False))
        kernel = opt.get("kernel")
        if opt.get("origin") is not None and wrap:
            raise Error("synth sparse: origin and wrap exclude each other (a periodic tile has no origin)")
        self._origin = ffi.new("long[2]", _origin(opt.get("origin")))
        if radius or kernel is not None:
            check(lib.nl_synth_sparse_check_work(self._dim, self._n, radius or 16, cell, density, 0))
        out = ffi.new("nl_synth_sparse_plan **")
        if kernel is not None:
            check(lib.nl_synth_sparse_plan_expr(cstr(kernel, "kernel"), self._dim, radius or 16, cell, density,
                                                out))
            self._lock = planner  # the kernel's expression is evaluated per call (libmatheval)
        else:
            check(lib.nl_synth_sparse_plan_model_flags(self._m.ptr, self._dim, self._h, radius, cell, density,
                                                       _CLAMP if self.clamp else 0, out))
        self._p = ffi.gc(out[0], lib.nl_synth_sparse_plan_free)
        info = ffi.new("nl_synth_sparse_info *")
        lib.nl_synth_sparse_plan_info(self._p, info)
        org = ""
        if not wrap and any(self._origin):
            org = ",origin=%d:%d" % tuple(self._origin)
        self.method = "sparse:radius=%d,cell=%d,density=%.17g%s%s" % (
            info.radius, info.cell, info.density, ",wrap" if wrap else org,
            "|kernel=" + kernel if kernel is not None else "")
        fl = []
        if info.clamp_error > _FFT_CLAMP_TOL:
            fl.append("clamped")
        if info.truncated > 1e-3:
            fl.append("truncated=%.2g" % info.truncated)
        self.flags = ",".join(fl)
        self.info = dict(radius=info.radius, cell=info.cell, density=info.density, variance=info.variance,
                         mean=info.mean, excess_kurtosis=info.kurtosis, truncated_energy=info.truncated)
        origin = ffi.NULL if wrap else self._origin
        self._exec = lambda seed, f: lib.nl_synth_sparse_execute(self._p, seed, int(wrap), origin, f)

    def _plan_lattice(self):
        opt = self.options
        interp = opt.get("interpolant", "perlin")
        if interp not in ("perlin", "wiener"):
            raise Error('interpolant: expected perlin or wiener for lattice, got "%s"' % interp)
        cell = _int("cell", opt["cell"], 1, 2 ** 31 - 1) if opt.get("cell") else 0
        if interp == "wiener":
            return self._plan_lattice_wiener(cell or 4)
        c0 = float(cell) if cell else lib.nl_synth_lattice_default_cell(self._n)
        O = _int("octaves", opt["octaves"], 1, 16) if opt.get("octaves") else \
            lib.nl_synth_lattice_default_octaves(c0)
        err = ffi.new("double *")
        check(lib.nl_synth_lattice_check_grid(self._m.ptr, self._dim, self._n, int(self.clamp), err))
        self._p = ffi.new("nl_synth_lattice_plan *")
        check(lib.nl_synth_lattice_plan_init_flags(self._m.ptr, self._dim, c0, O, _CLAMP if self.clamp else 0,
                                                   self._p))
        self.flags = "clamped" if err[0] > 0 or self._p.negatives else ""
        self.method = "lattice:cell=%.17g,octaves=%d" % (c0, O)
        self.info = dict(octaves=[dict(cell=self._p.cell[o], weight=self._p.weight[o], peak=self._p.peak[o],
                                       leakage=self._p.leakage[o]) for o in range(self._p.octaves)])
        self._exec = lambda seed, f: lib.nl_synth_lattice_execute(self._p, seed, f)

    def _plan_lattice_wiener(self, cell):
        """interpolant="wiener": one lattice of the target's covariance, each
        sample its simple-kriging estimate from the nearest nodes."""
        if self.options.get("octaves"):
            raise Error("octaves: the Wiener lattice has one lattice (no octaves), got octaves=%r"
                        % self.options["octaves"])
        out = ffi.new("nl_synth_lattice_wiener_plan **")
        check(lib.nl_synth_lattice_wiener_plan_alloc(self._m.ptr, self._dim, self._n, cell,
                                                     _CLAMP if self.clamp else 0, out))
        self._p = ffi.gc(out[0], lib.nl_synth_lattice_wiener_plan_free)
        info = ffi.new("nl_synth_lattice_wiener_info *")
        lib.nl_synth_lattice_wiener_plan_info(self._p, info)
        self.method = "lattice:cell=%d,interpolant=wiener" % cell
        self.flags = "clamped" if info.negatives else ""
        self.info = dict(cell=cell, nodes=tuple(info.nodes), variance=info.variance,
                         mean_error_variance=info.mean_error, max_error_variance=info.max_error, rank=info.rank)
        self._exec = lambda seed, f: lib.nl_synth_lattice_wiener_execute(self._p, seed, f, ffi.NULL)

    # -- execution --------------------------------------------------------

    def __call__(self, seed=0, out=None):
        """The field for `seed` (an integer 0 .. 2^64 - 1): a new float64
        array of shape ``self.shape`` (numpy order: x, the fastest axis in
        memory, last), over memory the library allocated for it.  With
        ``out=A`` the field is written into A instead and A is returned: A a
        writable C-ordered float64 array of the plan's shape whose data is
        64-byte aligned (an array returned by a plan is), e.g. to refill one
        array in a loop without allocating."""
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed < 2 ** 64:
            raise Error("seed: expected an integer from 0 to 2^64 - 1, got %r" % (seed,))
        if out is not None:
            return self._into(int(seed), out)
        # every method writes every sample: no zeroing needed (core/mem.h's nl_alloc)
        f = alloc_field(self.shape, self.spacing, zero=False)
        try:
            self._run(int(seed), f)
        except BaseException:
            free_data(f)
            raise
        return owned_field(f, free_data)

    def _run(self, seed, f):
        if self._lock is None:
            st = self._exec(seed, f)
        else:
            with self._lock:
                st = self._exec(seed, f)
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
        if self.options.get("nonperiodic") or (self.method_name == "sparse" and not self.options.get("wrap")
                                               and any(self._origin)):
            o = tuple(self._origin)
            origin = "%d" % o[0] if len(self.shape) == 1 else "%d,%d" % o
        return dict(model=self.model, method=self.method, flags=self.flags, seed=str(int(seed)),
                    origin=origin, spacing=self.spacing)

    def __repr__(self):
        return "noiselab.Plan(%r, model=%r, size=%r)" % (self.method, self.model, self.shape)


def synth(method, acf=None, spectrum=None, size=None, seed=0, spacing=1.0, **options):
    """Synthesise one field, as ``noiselab synth METHOD``.

    method    fft, circulant, cholesky, subdiv, midpoint, faulting, sparse or
              lattice (see ``noiselab synth --help`` for what each does).
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
              method's: subdiv levels, neighborhood (int or "auto"), tol (float
              or "variance:E"), nonperiodic, origin, random_neighborhoods,
              displacements, taps; midpoint H, levels, variance_scale,
              interpolant ("fournier" or "miller"); faulting density; sparse
              density, cell, radius, wrap, origin, kernel (an expression in
              x, y); lattice cell, octaves, interpolant ("perlin" or
              "wiener").

    Returns a float64 array of shape `size` (C order; row j of a 2D field is
    the EXR's row j), over memory the library allocated (no copy): the same
    numbers as ``noiselab synth METHOD --acf SPEC --size ... --seed SEED``
    before its 32-bit EXR rounding.  Raises noiselab.Error with the library's
    message on a bad argument or model.  For many seeds make a Plan once.
    """
    return Plan(method, acf=acf, spectrum=spectrum, size=size, spacing=spacing, **options)(seed)
