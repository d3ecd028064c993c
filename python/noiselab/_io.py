"""Field files and the model catalogue (core/io.h, core/model.h)."""
import numpy as np

from ._args import as_bool, as_choice, as_int, as_path, as_str
from ._ffi import Error, FieldView, check, ffi, h5lib, lib, owned_field

# nl_meta's keys (core/provenance.h), in the order files record them.
META_KEYS = tuple(ffi.string(lib.nl_meta_key(i)).decode() for i in range(lib.NL_META_NKEYS))
_FLT_MAX = float(np.finfo(np.float32).max)


def read(path, meta=False):
    """Read a field with the library's reader (nl_field_read): EXR or PNG by
    content, else a 1D TSV table -- every format the library reads, so the
    formats it gains later are read here unchanged.

    Returns a float64 array over the library's memory (no copy) of shape
    (n0,), (ny, nx) or (nz, ny, nx) (EXR row j is array row j; a 3D EXR
    holds its slices one under another, noiselab.size says how).  EXR
    samples are float32 widened exactly.  With meta=True returns (array,
    dict): the provenance (model, method, seed, spacing, size, version,
    flags, origin: the strings recorded; the spacing "hx[,hy[,hz]]" lists x
    first) plus "spacing_array": the spacing in the array's axis order.
    """
    p, b = as_path("read: path", path)
    meta = as_bool("read: meta", meta)
    out = ffi.new("nl_field **")
    m = ffi.new("nl_meta *")
    if p.lower().endswith(".h5"):
        check(h5lib().nl_mpi_h5_read(b, out, m))
    else:
        check(lib.nl_field_read(b, out, m))
    f = out[0]
    spacing = tuple(float(f.h[a]) for a in reversed(range(f.dim)))
    arr = owned_field(f)
    if not meta:
        return arr
    d = {k: ffi.string(getattr(m, k)).decode("utf-8", "replace") for k in META_KEYS}
    d["spacing_array"] = spacing
    return arr, d


def _auto_provenance(f):
    """What the library records of field f itself: size, spacing and this
    library's version, as nl_provenance_format writes them."""
    p = ffi.new("nl_provenance *")
    kv = ffi.new("nl_meta *")
    lib.nl_provenance_init(p)
    p.version = ffi.string(lib.nl_version())
    p.dim = p.nspacing = f.dim
    for a in range(f.dim):
        p.n[a], p.h[a] = f.n[a], f.h[a]
    check(lib.nl_provenance_format(p, kv))
    return {k: ffi.string(getattr(kv, k)).decode() for k in ("size", "spacing", "version")}


def write(path, array, spacing=1.0, precision="single", **provenance):
    """Write a field: EXR (path ending in .exr: 32-bit float samples, rounded
    to nearest, any dimension), HDF5 (.h5: dataset /field, float32 or with
    precision="double" float64, as ``noiselab synth -o OUT.h5``; through
    libnoiselab_mpi) or TSV (1D only), as ``noiselab synth -o`` chooses the
    writer by the extension.

    array       1 to 3 axes, float64 (others converted), finite; in EXR each
                sample must fit in float32.
    spacing     one value or one per axis (the array's order).
    provenance  strings stored as noiselab.* attributes (TSV: "# key: value"
                lines): model, method, seed (or an integer), flags, origin, version (default:
                this library's); size and spacing are recorded from the
                array and `spacing`.  E.g. ``write(p, plan(seed),
                **plan.provenance(seed))`` writes the file noiselab synth
                writes.
    """
    keys = ("model", "method", "seed", "flags", "origin", "version")
    bad = set(provenance) - set(keys)
    if bad:
        raise Error("write: unknown provenance key %s (expected %s; size and spacing come from the array and "
                    "spacing=)" % (", ".join(sorted(bad)), ", ".join(keys)))
    p, b = as_path("write: path", path)
    precision = as_choice("write: precision", precision, ("single", "double"))
    v = FieldView(array, spacing, "write: array")
    f = v.f
    m = ffi.new("nl_meta *")
    auto = _auto_provenance(f)
    for k in META_KEYS:
        s = provenance.get(k) if k in keys else None
        if k == "seed" and s is not None and not isinstance(s, str):
            s = str(as_int("write: seed", s, 0, (1 << 64) - 1))  # the seed a Plan was called with
        s = as_str("write: " + k, auto.get(k, "") if s is None else s, empty=True)
        if len(s) >= ffi.sizeof(getattr(m, k)):
            raise Error("write: %s: expected at most %d bytes, got %d" % (k, ffi.sizeof(getattr(m, k)) - 1, len(s)))
        setattr(m, k, s)
    if p.lower().endswith(".h5"):
        dbl = precision == "double"
        if not dbl and lib.nl_field_check_finite(f, _FLT_MAX, ffi.NULL):
            raise Error("write: %s of float32; %s not written"
                        % (ffi.string(lib.nl_errmsg()).decode("utf-8", "replace"), p))
        check(h5lib().nl_mpi_h5_write_field(b, f, m, int(dbl)))
        return
    if precision != "single":
        raise Error('write: precision="double" needs an .h5 path (EXR stores float32), got "%s"' % p)
    exr = p.lower().endswith(".exr")
    if not exr and f.dim != 1:
        raise Error('write: TSV holds 1D fields; use .exr for a %dD field, got "%s"' % (f.dim, p))
    if exr:
        if lib.nl_field_check_finite(f, _FLT_MAX, ffi.NULL):
            raise Error("write: %s of float32 EXR; %s not written"
                        % (ffi.string(lib.nl_errmsg()).decode("utf-8", "replace"), p))
        check(lib.nl_exr_write(b, f, m))
    else:
        check(lib.nl_tsv_write_field(b, f, m, ffi.NULL, ffi.NULL))


_ROLES = {0: "shape", 1: "variance", 2: "scale", 3: "nugget", 4: "band"}


def _param(p):
    """One parameter of a family's descriptor as a dict."""
    lo = {0: None, 1: 0.0, 2: 0.0, 3: 0.0}[p.range]
    return dict(name=ffi.string(p.name).decode(), role=_ROLES[p.role],
                default=None if p.placeholder != ffi.NULL else getattr(p, "def"),
                lower=lo, lower_open=p.range in (1, 3), upper=p.hi if p.range == 3 else None)


def models():
    """The model catalogue (``noiselab models``), from the library's family
    registry (core/family.h): a list of dicts, one per family, with its name
    (as written in a spec; argument families as "expr:EXPR"), params (the
    parameters with defaults, required ones first, as the catalogue prints
    them), formula (R or S), aliases (other names a spec may use),
    peers (the peers' names with their own keys: a list of dicts with name,
    peer (gstat, GSTools, RandomFields), formula and parameters),
    parameters (a list of dicts: name, role (variance, scale, nugget, shape
    or band), default (None when required), lower, lower_open, upper: the
    valid range, None where unbounded), spectral (defined by S), intrinsic (a
    variogram without covariance: powvar), fit (fit
    accepts it), max_dim (not positive definite beyond this dimension; None:
    no such limit) and validity (what is known of its validity by
    dimension)."""
    n = ffi.new("size_t *")
    cat = lib.nl_model_catalogue(n)
    out = []
    for i in range(n[0]):
        f = lib.nl_family_get(i)
        out.append(dict(name=ffi.string(cat[i].name).decode(), params=ffi.string(cat[i].params).decode(),
                        formula=ffi.string(cat[i].formula).decode(),
                        aliases=ffi.string(f.aliases).decode().split(),
                        peers=[dict(name=ffi.string(a.name).decode(), peer=ffi.string(a.peer).decode(),
                                    formula=ffi.string(a.formula).decode(),
                                    parameters=[_param(a.params[k]) for k in range(a.nparams)])
                               for a in (f.peers[j] for j in range(f.npeers))],
                        parameters=[_param(f.params[k]) for k in range(f.nparams)],
                        spectral=bool(f.flags & lib.NL_FAMILY_SPECTRAL), fit=bool(f.flags & lib.NL_FAMILY_FIT),
                        intrinsic=bool(f.flags & lib.NL_FAMILY_INTRINSIC),
                        max_dim=f.max_dim or None, validity=ffi.string(f.validity).decode()))
    return out


def version():
    """The running library's version (nl_version)."""
    return ffi.string(lib.nl_version()).decode()
