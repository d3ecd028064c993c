"""Hostile HDF5 files: noiselab.read refuses an attribute or a dataset that
noiselab does not write with noiselab.Error naming it, and never crashes.
Each read runs in a child interpreter, so that a crash (an array attribute
read into one buffer killed the interpreter) fails one test, not pytest."""
import os
import subprocess
import sys

import numpy as np
import pytest

import noiselab

h5py = pytest.importorskip("h5py")

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VLEN = h5py.string_dtype("utf-8")


def _field(path, data=None, **attrs):
    if data is None:
        data = np.arange(64, dtype="f4").reshape(8, 8)
    with h5py.File(path, "w") as f:
        d = f.create_dataset("field", data=data)
        for k, v in attrs.items():
            d.attrs[k] = v


CASES = {
    "model_array": (dict(model=np.array([b"markov:scale=4", b"gauss"])), "attribute model: expected one string"),
    "model_vlen_array": (dict(model=np.array(["markov:scale=4", "gauss"], dtype=object).astype(VLEN)),
                         "attribute model: expected one string"),
    "flags_array": (dict(flags=np.array([b"a", b"b", b"c"])), "attribute flags: expected one string"),
    "spacing_2d": (dict(spacing=np.array([[b"1", b"2"], [b"3", b"4"]])), "attribute spacing: expected one string"),
    "model_int": (dict(model=np.int32(5)), "attribute model: expected one string"),
    "spacing_floats": (dict(spacing=np.array([0.5, 2.0])), "attribute spacing: expected one string"),
    "model_too_long": (dict(model="markov:scale=4;" + "x" * 2000), "expected at most 1023 bytes"),
    "seed_too_long_fixed": (dict(seed=np.bytes_(b"1" * 40)), "attribute seed: expected at most 31 bytes"),
    "flags_nul": (dict(flags=np.bytes_(b"clamped\x00injected")), "got a NUL at byte 7"),
    "flags_newline": (dict(flags="a\nb"), "without control characters"),
    "model_not_ascii": (dict(model=np.bytes_(b"markov\xff")), "expected ASCII text"),
    "processes_text": (dict(processes="two"), "attribute processes: expected one integer >= 1"),
    "compound_field": ({"data": np.zeros((4, 4), dtype=[("re", "f8"), ("im", "f8")])}, "compound samples"),
    "string_field": ({"data": np.array([b"1", b"2"])}, "string samples"),
    "enum_field": ({"data": np.ones((4, 4), dtype=bool)}, "enum samples"),
}

_CHILD = """
import sys
sys.path.insert(0, sys.argv[2])
import noiselab
try:
    noiselab.read(sys.argv[1], meta=True)
except noiselab.Error as e:
    print(e)
    sys.exit(3)
sys.exit(0)
"""


@pytest.mark.parametrize("name", sorted(CASES))
def test_read_refuses_what_noiselab_does_not_write(tmp_path, name):
    kw, needle = CASES[name]
    p = tmp_path / (name + ".h5")
    _field(p, **kw)
    r = subprocess.run([sys.executable, "-c", _CHILD, str(p), os.path.join(TOP, "python")], capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 3, "exit %d (3: noiselab.Error): %s %s" % (r.returncode, r.stdout, r.stderr)
    assert needle in r.stdout and p.name in r.stdout, r.stdout


def test_a_field_as_noiselab_writes_it_reads(tmp_path):
    p = tmp_path / "good.h5"
    _field(p, model="markov:scale=4", seed=np.bytes_(b"7"), spacing="0.5,2", processes=np.int32(1))
    a, m = noiselab.read(p, meta=True)
    assert a.shape == (8, 8) and m["model"] == "markov:scale=4" and m["seed"] == "7"
    assert m["spacing_array"] == (2.0, 0.5)
