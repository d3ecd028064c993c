"""Kriging a 200 x 200 grid of Meuse from Python and from the CLI: the
median wall-clock seconds of the plan plus the grid (estimates and
variances), beside the CLI's own "seconds" (--json: the same work, without
reading and writing files), for global kriging and for nmax = 20.
usage: krige_time.py MEUSE.tsv NOISELAB RUNS  (MEUSE.tsv: x, y, value)
prints one line per case: case, then wall-clock and CPU seconds (all threads)
of Krige.grid, of Krige.predict at the cell centres, of the CLI's whole run
(process start and files included), and the CLI's "seconds"."""
import json
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import noiselab

SPEC = "nugget:var=0.05 + spherical:var=0.59,scale=897"
EXT = ((178440.0, 181560.0), (329600.0, 333760.0))
tsv, cli, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
t = np.loadtxt(tsv, skiprows=1)
p, v = np.ascontiguousarray(t[:, :2]), np.ascontiguousarray(t[:, 2])
n = 200
hx, hy = [(b - a) / n for a, b in EXT]
X, Y = np.meshgrid(EXT[0][0] + (np.arange(n) + 0.5) * hx, EXT[1][0] + (np.arange(n) + 0.5) * hy)
x = np.column_stack([X.ravel(), Y.ravel()])
for case, kw, extra in (("global", {}, []), ("nmax=20", dict(nmax=20), ["--nmax", "20"])):
    g, gc, pt, ptc, w, wc, c = [], [], [], [], [], [], []
    for r in range(runs):
        t0, c0 = time.perf_counter(), time.process_time()
        noiselab.Krige(p, v, SPEC, **kw).grid(EXT, (n, n))
        g.append(time.perf_counter() - t0), gc.append(time.process_time() - c0)
        t0, c0 = time.perf_counter(), time.process_time()
        noiselab.Krige(p, v, SPEC, **kw).predict(x)
        pt.append(time.perf_counter() - t0), ptc.append(time.process_time() - c0)
        with tempfile.TemporaryDirectory() as d:
            u = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            o = subprocess.run([cli, "krige", "--data", tsv, "--acf", SPEC, "--grid", "%dx%d" % (n, n), "--extent",
                                "%r:%r,%r:%r" % (EXT[0] + EXT[1]), "-o", d + "/e.exr", "--variance", d + "/v.exr",
                                "--json"] + extra, capture_output=True, text=True, check=True)
            w.append(time.perf_counter() - t0)
            u2 = resource.getrusage(resource.RUSAGE_CHILDREN)
            wc.append(u2.ru_utime + u2.ru_stime - u.ru_utime - u.ru_stime)
            c.append(json.loads(o.stdout)["seconds"])
    med = statistics.median
    print("%s\tgrid %.3f s (cpu %.3f)\tpredict %.3f s (cpu %.3f)\tcli %.3f s (cpu %.3f; its seconds %.3f)"
          % (case, med(g), med(gc), med(pt), med(ptc), med(w), med(wc), med(c)))
