"""The Python side of tools/bench-python.sh: the median time of
noiselab.Plan("fft", ...)(seed) (a new array per call, over the library's
memory), the plan made once outside the timing.
usage: fft_time.py N RUNS SPEC  -> prints the median in seconds."""
import statistics
import sys
import time

import noiselab

n, runs, spec = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
plan = noiselab.Plan("fft", acf=spec, size=(n, n))
plan(0)  # warm-up, as the C side
t = []
for r in range(runs):
    t0 = time.perf_counter()
    f = plan(r + 1)
    t.append(time.perf_counter() - t0)
    del f
print("%.6f" % statistics.median(t))
