"""The declarations the package uses in ABI mode (noiselab/_ffi.py CDEF,
copied from the headers) match the headers: the same declarations compiled
in cffi's API mode against the tree's headers make the compiler check every
prototype (-Werror) and cffi check every struct's size and field offsets
when the module loads.  Also: the soname the package looks for is
core/version.h's major version, and pyproject.toml's version the library's."""
import os
import re
import shutil
import sys

import pytest

from conftest import TOP
import noiselab
from noiselab import _ffi

HEADERS = ["core/version.h", "core/nl_error.h", "core/field.h", "core/mem.h", "core/io.h", "core/format.h", "core/provenance.h", "core/model.h",
           "core/dist.h", "core/wk.h", "synth/fft.h", "synth/circulant.h", "synth/cholesky.h", "synth/subdiv.h",
           "synth/midpoint.h", "synth/faulting.h", "synth/sparse.h", "synth/lattice.h", "synth/method.h", "synth/shape.h",
           "analysis/acf.h", "analysis/psd.h", "analysis/welch.h", "analysis/radial.h", "analysis/spectral.h",
           "analysis/fftshift.h", "analysis/bands.h", "analysis/hist.h", "analysis/gof_boot.h", "analysis/ensemble.h", "analysis/check.h", "analysis/nonlin.h", "analysis/krige.h",
           "analysis/krige_local.h", "analysis/krige_flavours.h", "analysis/condsim.h", "core/field_sample.h", "core/io_points.h", "analysis/variogram.h", "analysis/fit.h"]


def test_declarations_match_headers(tmp_path):
    if not shutil.which(os.environ.get("CC", "cc")):
        pytest.skip("no C compiler")
    from cffi import FFI
    api = FFI()
    api.cdef(_ffi.CDEF)
    src = "".join('#include "%s"\n' % h for h in HEADERS)
    api.set_source("_nl_layout", src, include_dirs=[TOP], extra_compile_args=["-Werror", "-Wno-unused"],
                   libraries=["noiselab"], library_dirs=[os.path.dirname(os.path.realpath(_ffi.LIBRARY_PATH))]
                   if os.path.isabs(_ffi.LIBRARY_PATH) else [])
    so = api.compile(tmpdir=str(tmp_path), verbose=False)
    sys.path.insert(0, str(tmp_path))
    try:
        import importlib
        mod = importlib.import_module("_nl_layout")  # cffi checks struct layouts here
    finally:
        sys.path.pop(0)
    for name in re.findall(r"}\s*(nl_\w+);", _ffi.CDEF):
        assert mod.ffi.sizeof(name) == _ffi.ffi.sizeof(name), name
        if _ffi.ffi.typeof(name).kind != "struct":
            continue  # an enum: its size is all there is
        for field, _ in _ffi.ffi.typeof(name).fields:
            assert mod.ffi.offsetof(name, field) == _ffi.ffi.offsetof(name, field), (name, field)
    assert so


def test_declarations_exported():
    """Every function the package declares is one the library exports (it
    exports exactly what its installed headers declare)."""
    if not shutil.which("nm") or not os.path.isabs(_ffi.LIBRARY_PATH):
        pytest.skip("no nm, or the library found by its soname")
    import subprocess
    out = subprocess.run(["nm", "-D", "--defined-only", _ffi.LIBRARY_PATH], capture_output=True, text=True,
                         check=True).stdout
    exported = {line.split()[-1] for line in out.splitlines() if len(line.split()) >= 3}
    declared = set(re.findall(r"\b(nl_\w+)\s*\(", _ffi.CDEF))
    assert declared and not declared - exported, sorted(declared - exported)


def test_versions_agree():
    h = open(os.path.join(TOP, "core", "version.h")).read()
    v = [re.search(r"#define NL_VERSION_%s (\d+)" % k, h).group(1) for k in ("MAJOR", "MINOR", "PATCH")]
    assert _ffi.SOVERSION == int(v[0])
    assert noiselab.version() == ".".join(v)
    toml = open(os.path.join(TOP, "python", "pyproject.toml")).read()
    assert 'version = "%s"' % ".".join(v) in toml
