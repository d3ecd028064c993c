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
