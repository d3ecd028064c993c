#!/bin/sh
# Inputs the catalogue's commands read, made in the current folder by the
# program under test ($1): fields, tables, points, a scene.
set -e
nl=$1
"$nl" synth fft --acf markov:scale=8 --size 64x64 --seed 1 -o f2.exr
"$nl" synth fft --acf markov:scale=8 --size 256 --seed 1 -o s1.tsv
"$nl" synth fft --acf gauss:scale=2 --size 16x16x16 --seed 1 -o f3.exr
"$nl" render f2.exr -o f2.png
awk 'BEGIN { srand(3); print "x\ty\tvalue"; for (i = 0; i < 40; i++) printf "%.6f\t%.6f\t%.6f\n", rand(), rand(), rand() }' >pts.tsv
printf 't\tvalue\n0\t1\n1\t2\n3\t0.5\n4\t1\n' >irregular.tsv
printf 'x\ty\n0\t1\n1\t2\n' >novalue.tsv
cat >scene.json <<'JSON'
{
  "size": [32, 24],
  "box": [[-3, -1.2, -2], [3, 2.5, 2]],
  "points": [[0, 0.3, 0, 1.0], [-1.1, 0.0, 0.3, 0.8], [1.2, 0.1, -0.2, 0.85], [0, 2.0, 0, 0.0]],
  "acf": "gauss:scale=0.9",
  "noise": {"acf": "markov:scale=0.12", "amplitude": 0.6, "period": 1.6, "grid": 16, "seed": 3},
  "threshold": 0.3,
  "extinction": 9,
  "grid": 16,
  "camera": {"position": [0, 0.6, -7], "look_at": [0, 0.5, 0], "fov": 42},
  "sun": [0.6, 0.7, -0.4]
}
JSON
# HDF5 fields: a good one, and bad ones made with h5py
"$nl" synth fft --acf markov:scale=4 --size 64x48 --seed 1 -o f2.h5
printf 'not an HDF5 file\n' >fake.h5
/usr/bin/python3 - <<'PY'
import h5py, numpy as np
with h5py.File("nan.h5", "w") as f:
    d = np.zeros((4, 5)); d[2, 3] = np.nan; f["field"] = d
with h5py.File("rank4.h5", "w") as f:
    f["field"] = np.zeros((2, 2, 2, 2))
with h5py.File("nofield.h5", "w") as f:
    f["other"] = np.zeros((4, 4))
with h5py.File("badspacing.h5", "w") as f:
    f["field"] = np.zeros((4, 4)); f["field"].attrs["spacing"] = np.bytes_("abc")
with h5py.File("huge.h5", "w") as f:
    f.create_dataset("field", shape=(1 << 30, 1 << 30), dtype="f4", chunks=(16, 16))
with h5py.File("ints.h5", "w") as f:
    f["field"] = np.arange(20, dtype=np.int32).reshape(4, 5)
PY
# More fixtures, one file per surface (sourced here, in this folder, with $nl)
for f in "$(dirname "$0")"/fixtures.d/*.sh; do
    if [ -e "$f" ]; then . "$f"; fi
done
