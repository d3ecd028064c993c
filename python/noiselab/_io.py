"""Field files and the model catalogue (core/io.h, core/model.h)."""
import os

import numpy as np

from ._args import as_bool, as_choice, as_int, as_path, as_size, as_str
from ._ffi import Error, FieldView, check, ffi, h5lib, lib, owned_field

# nl_meta's keys (core/provenance.h), in the order files record them.
META_KEYS = tuple(ffi.string(lib.nl_meta_key(i)).decode() for i in range(lib.NL_META_NKEYS))
_FLT_MAX = float(np.finfo(np.float32).max)


_DIMS = {1: "1D", 2: "2D", 3: "3D"}
_TYPES = ("float32", "float64", "uint16", "uint8")
_METAS = ("provenance", "spacing", "origin", "range", "crs", "nodata")


def formats():
    """The field file formats (``noiselab formats``), from the library's
    registry (core/format.h): a list of dicts with name (as format= takes
    it), extensions (those that select it), dims (the dimensions it holds),
    values (float32, float64, uint16), metadata (provenance, spacing,
    origin, range, crs, nodata: what it records; [] for none), external
    (True: read and written through libnoiselab_mpi, HDF5), off (True: not
    in this build, e.g. GeoTIFF and NetCDF without GDAL; the summary says
    why) and summary."""
    out = []
    for i in range(lib.nl_format_count()):
        f = lib.nl_format_get(i)
        out.append(dict(name=ffi.string(f.name).decode(), extensions=ffi.string(f.extensions).decode().split(),
                        dims=[d for d in (1, 2, 3) if f.dims & (1 << d)],
                        values=[t for k, t in enumerate(_TYPES) if f.types & (1 << k)],
                        metadata=[m for k, m in enumerate(_METAS) if f.meta & (1 << k)],
                        external=bool(f.flags & 1), off=bool(f.flags & 8), summary=ffi.string(f.summary).decode()))
    return out


def _format(what, path, b, format):
    """The registry's descriptor for format= (a name) or else path's
    extension; Error naming what is expected otherwise."""
    out = ffi.new("const nl_format **")
    name = ffi.NULL if format is None else as_str(what + ": format", format)
    check(lib.nl_format_resolve(b, name, out))
    return out[0]


def _range(what, value):
    """(lo, hi) with lo < hi, or (0, 0) for None."""
    if value is None:
        return 0.0, 0.0
    try:
        lo, hi = (float(v) for v in value)
    except (TypeError, ValueError):
        raise Error("%s: range: expected (lo, hi), got %r" % (what, value))
    if not (np.isfinite(lo) and np.isfinite(hi) and lo < hi):
        raise Error("%s: range: expected finite lo < hi, got %r" % (what, value))
    return lo, hi


def read(path, meta=False, format=None, size=None, range=None):
    """Read a field with the library's reader (nl_field_read, core/format.h):
    by content where the format has a signature (EXR, PNG, .npy, HDF5,
    TIFF, netCDF), else
    by extension (.r16/.raw, .f32), else a 1D TSV table -- every format of
    the registry (formats()), so the formats it gains later are read here
    unchanged.

    format  a registered name (formats()) to read the file as, whatever its name.
    size    headerless formats (r16, f32): the shape, numpy's order (the
            file holds no size; without it, a square is assumed, as Unity does).
    range   r16: (lo, hi), the values of codes 0 and 65535 (default 0, 1).
            A 16-bit PNG written by noiselab maps back by its own range.

    Returns a float64 array over the library's memory (no copy) of shape
    (n0,), (ny, nx) or (nz, ny, nx) (EXR and PNG row j is array row j; a 3D
    EXR holds its slices one under another, noiselab.size says how).  EXR
    samples are float32 widened exactly.  With meta=True returns (array,
    dict): the provenance (model, method, seed, spacing, size, version,
    flags, origin: the strings recorded; the spacing "hx[,hy[,hz]]" lists x
    first) plus "spacing_array": the spacing in the array's axis order, and
    "crs" and "extent" (GeoTIFF, NetCDF: "EPSG:N" or WKT, and the cells'
    outer edges "x0:x1,y0:y1"; array row 0 is the south; "" when none).
    """
    p, b = as_path("read: path", path)
    meta = as_bool("read: meta", meta)
    out = ffi.new("nl_field **")
    m = ffi.new("nl_meta *")
    o = ffi.new("nl_read_options *")
    keep = []
    if format is not None:
        keep.append(ffi.new("char[]", as_str("read: format", format)))
        o.format = keep[0]
    if size is not None:
        shape = as_size("read: size", size)
        o.dim = len(shape)
        for ax, n in enumerate(reversed(shape)):
            o.n[ax] = n
    o.lo, o.hi = _range("read", range)
    head = b""
    try:
        with open(b, "rb") as fp:
            head = fp.read(8)
    except OSError:
        pass  # the library names the file in its message
    if format == "h5" or (format is None and (head == b"\x89HDF\r\n\x1a\n" or p.lower().endswith(".h5"))):
        check(h5lib().nl_mpi_h5_read(b, out, m))
    else:
        check(lib.nl_field_read_opts(b, o, out, m))
    f = out[0]
    spacing = tuple(float(f.h[a]) for a in reversed(range_(f.dim)))
    arr = owned_field(f)
    if not meta:
        return arr
    d = {k: ffi.string(getattr(m, k)).decode("utf-8", "replace") for k in META_KEYS}
    d["spacing_array"] = spacing
    for k in _GEO_KEYS:  # georeferencing: GeoTIFF and NetCDF (core/formats/gdal_io.h)
        d[k] = ffi.string(getattr(m, k)).decode("utf-8", "replace")
    return arr, d


range_ = range  # read() and write() take a keyword named range
_GEO_KEYS = ("crs", "extent")


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


def write(path, array, spacing=1.0, precision=None, format=None, range=None, **provenance):
    """Write a field through the library's format registry (nl_field_write,
    core/format.h; formats() lists it), the writer chosen by format= or by
    the path's extension, as ``noiselab synth -o`` chooses it: EXR (.exr:
    float32, any dimension), NumPy (.npy: float64, or float32 with
    precision="single"; no metadata), 16-bit PNG heightmaps (.png, 2D),
    raw heightmaps (.r16/.raw uint16, .f32 float32; no header), HDF5 (.h5:
    dataset /field, float32 or with precision="double" float64, with an
    .xmf sidecar for ParaView; through libnoiselab_mpi) or TSV (.tsv, 1D
    only).  An unknown extension or format raises Error.

    array       1 to 3 axes, float64 (others converted), finite; in float32
                formats each sample must fit in float32.
    spacing     one value or one per axis (the array's order).
    precision   None (the format's own), "single" or "double".
    range       integer formats (png16, r16): (lo, hi) mapped onto 0..65535;
                default the array's min..max (recorded in the PNG).
    provenance  strings stored as noiselab.* attributes (TSV: "# key: value"
                lines; PNG: text chunks): model, method, seed (or an integer),
                flags, origin, version (default: this library's); size and
                spacing are recorded from the array and `spacing`.  E.g.
                ``write(p, plan(seed), **plan.provenance(seed))`` writes the
                file noiselab synth writes.  The georeferenced formats
                (geotiff, cog, netcdf) also take crs ("EPSG:N" or WKT) and
                extent ("x0:x1,y0:y1", the cells' outer edges; array row 0
                is the southernmost), and read() returns both.
    """
    keys = ("model", "method", "seed", "flags", "origin", "version") + _GEO_KEYS
    bad = set(provenance) - set(keys)
    if bad:
        raise Error("write: unknown provenance key %s (expected %s; size and spacing come from the array and "
                    "spacing=)" % (", ".join(sorted(bad)), ", ".join(keys)))
    p, b = as_path("write: path", path)
    if precision is not None:
        precision = as_choice("write: precision", precision, ("single", "double"))
    t = _format("write", p, b, format)
    lo, hi = _range("write", range)
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
    for k in _GEO_KEYS:
        s = as_str("write: " + k, provenance.get(k, ""), empty=True)
        if len(s) >= ffi.sizeof(getattr(m, k)):
            raise Error("write: %s: expected at most %d bytes, got %d" % (k, ffi.sizeof(getattr(m, k)) - 1, len(s)))
        if k == "crs" and s:
            check(lib.nl_format_crs_check(s))
        setattr(m, k, s)
    if t.flags & 1:  # NL_FORMAT_EXTERNAL: HDF5, through libnoiselab_mpi
        dbl = precision == "double"
        if not dbl and lib.nl_field_check_finite(f, _FLT_MAX, ffi.NULL):
            raise Error("write: %s of float32; %s not written"
                        % (ffi.string(lib.nl_errmsg()).decode("utf-8", "replace"), p))
        check(h5lib().nl_mpi_h5_write_field(b, f, m, int(dbl)))
        xmf = os.fsencode(p[:-3] if p.lower().endswith(".h5") else p) + b".xmf"
        origin = ffi.new("double[3]")
        check(lib.nl_xdmf_write(xmf, os.path.basename(b), f.dim, f.n, f.h, origin, int(dbl)))
        return
    o = ffi.new("nl_write_options *")
    name = ffi.new("char[]", ffi.string(t.name))
    o.format = name
    o.precision = {None: 0, "single": 32, "double": 64}[precision]
    o.lo, o.hi = lo, hi
    check(lib.nl_field_write(b, f, m, o))


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
