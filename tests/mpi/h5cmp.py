"""Compare HDF5 fields: h5cmp.py TOL REF OTHER... exits 1 when an OTHER's
/field differs from REF's by more than TOL times REF's largest magnitude
(TOL 0: bit for bit), or differs in shape or provenance (every attribute
but "processes")."""
import sys

import h5py
import numpy as np

tol = float(sys.argv[1])
with h5py.File(sys.argv[2], "r") as f:
    ref = f["field"][...]
    attrs = {k: v for k, v in f["field"].attrs.items() if k != "processes"}
bad = 0
for path in sys.argv[3:]:
    with h5py.File(path, "r") as f:
        x = f["field"][...]
        a = {k: v for k, v in f["field"].attrs.items() if k != "processes"}
    if x.shape != ref.shape or x.dtype != ref.dtype:
        print(f"{path}: shape {x.shape} {x.dtype}, expected {ref.shape} {ref.dtype}")
        bad = 1
        continue
    if a != attrs:
        print(f"{path}: provenance {a}, expected {attrs}")
        bad = 1
    d = np.max(np.abs(x.astype(float) - ref.astype(float))) / max(np.max(np.abs(ref)), 1e-300)
    if (tol == 0 and not np.array_equal(x, ref)) or d > tol:
        print(f"{path}: largest difference {d:.3g} of the largest magnitude, above {tol:g}")
        bad = 1
sys.exit(bad)
