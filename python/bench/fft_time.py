"""The Python side of tools/bench-python.sh: the median time of
noiselab.Plan("fft", ...)(seed), a new array per call over the library's
memory, and of plan(seed, out=a), refilling one array; the plan made once
outside the timing.
usage: fft_time.py N RUNS SPEC  -> prints "new_s<TAB>out_s"."""
import statistics
import sys
import time

import noiselab

n, runs, spec = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
plan = noiselab.Plan("fft", acf=spec, size=(n, n))
a = plan(0)  # warm-up, as the C side
new, out = [], []
for r in range(runs):
    t0 = time.perf_counter()
    f = plan(r + 1)
    new.append(time.perf_counter() - t0)
    del f
for r in range(runs):
    t0 = time.perf_counter()
    plan(r + 1, out=a)
    out.append(time.perf_counter() - t0)
print("%.6f\t%.6f" % (statistics.median(new), statistics.median(out)))
