#!/usr/bin/python3
"""Execute the course notebooks top to bottom, as a student would, and say which fail.

usage: tests/course/run.py [--budget S] [--jobs N] [--out DIR] [NOTEBOOK.ipynb ...]

With no notebook, every docs/course/*.ipynb of the tree.  Each runs in a fresh
kernel "python3" whose working folder is the notebook's own (docs/course for
the course), with the tree's package first on PYTHONPATH; NOISELAB_LIB and
NOISELAB pass through to the kernel as they are.  N notebooks run at once
(default 2, the machine's cores), each in a process of its own, within a
budget of S seconds (default 60) counted from the first cell's start to the
last cell's end (the kernel's start is not the notebook's and is not
counted).  One line per notebook: its name, seconds, cells run, ok or
FAILED/OVERRUN, then for a failure the failing cell's first lines and the
exception's last line.  Then every slider is moved: for each function the
notebook hands to widgets.interact, each of its sliders is set to its
minimum and maximum (a dropdown to its first and last option) and back, in
the notebook's kernel, as a student dragging it would; each move must redraw
(one figure at least) without an error.  --out DIR writes each executed
notebook, outputs and all (the moves left out), to DIR/NAME.ipynb (make
course renders those).  Exit status: 0 when
every notebook ran in its budget, 1 otherwise, 2 for bad usage.
"""
import argparse
import glob
import json
import math
import os
import re
import signal
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# the kernel's start and shutdown, beyond the cells' budget, before the
# runner gives up on a notebook's process altogether
GRACE_S = 60
# tries to start a notebook's kernel (see run_one's execute)
KERNEL_STARTS = 3


def kernel_env():
    """The environment the kernel inherits: the tree's package first."""
    env = dict(os.environ)
    py = os.path.join(TOP, "python")
    env["PYTHONPATH"] = py + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"  # ipykernel's debugger warns about frozen modules otherwise
    return env


# one move of one slider: the child J of the interact widget of F set to
# its minimum (0), maximum (1) or first value (2); a dropdown by its index.
# A cell per move: ipywidgets clears the output it drew before each redraw.
PROBE = """\
_nl_ch = [c for c in %(f)s.widget.children if hasattr(c, "value")]
if %(j)d < len(_nl_ch):
    _nl_c = _nl_ch[%(j)d]
    if not hasattr(_nl_c, "_nl_v0"):
        _nl_c._nl_v0 = _nl_c.index if hasattr(_nl_c, "index") and getattr(_nl_c, "options", None) else _nl_c.value
    if hasattr(_nl_c, "min") and hasattr(_nl_c, "max"):
        _nl_key, _nl_v = "value", [_nl_c.min, _nl_c.max, _nl_c._nl_v0][%(k)d]
    elif getattr(_nl_c, "options", None) and hasattr(_nl_c, "index"):
        _nl_key, _nl_v = "index", [0, len(_nl_c.options) - 1, _nl_c._nl_v0][%(k)d]
    else:
        _nl_key = None
    if _nl_key and getattr(_nl_c, _nl_key) != _nl_v:
        setattr(_nl_c, _nl_key, _nl_v)  # the redraw clears the cell's output first: print after
        print("slider move: %%s = %%r" %% (_nl_c.description or _nl_key, _nl_c.value))
"""
INTERACT = re.compile(r"widgets\.interact\(\s*([A-Za-z_]\w*)\s*,")
MAX_SLIDERS = 4  # of one interact call


def add_probes(nb):
    """Append the cells moving the sliders of each function given to
    widgets.interact; return (number of cells, number of functions)."""
    import nbformat
    names = []
    for c in nb.cells:
        if c.cell_type == "code":
            names += [n for n in INTERACT.findall(c.source) if n not in names]
    cells = [nbformat.v4.new_code_cell(PROBE % {"f": n, "j": j, "k": k}, metadata={"slider_probe": n})
             for n in names for j in range(MAX_SLIDERS) for k in range(3)]
    nb.cells += cells
    return len(cells), len(names)


def probe_result(cell):
    """Why a move failed ("" when it redrew or there was nothing to move)."""
    outs = cell.get("outputs", [])
    text = "".join(o.get("text", "") for o in outs if o.get("output_type") == "stream")
    m = re.search(r"slider move: (.*)", text)
    errs = [o for o in outs if o.get("output_type") == "error"]
    what = "%s() with %s" % (cell.metadata["slider_probe"], m.group(1).strip() if m else "its sliders")
    if errs:
        return "%s: %s: %s" % (what, errs[0].get("ename"), (errs[0].get("evalue") or "").splitlines()[0][:200]
                               if errs[0].get("evalue") else "")
    if m and not any("image/png" in o.get("data", {}) for o in outs):
        return "%s drew no figure" % what
    return ""


def run_one(path, budget, out):
    """Execute one notebook in this process; return the result as a dict."""
    import nbformat
    from nbclient import NotebookClient
    from nbclient.exceptions import CellExecutionError, CellTimeoutError, DeadKernelError

    class Client(NotebookClient):
        """nbclient 0.7.2 expects every comm_open of a widget to carry its
        state; ipywidgets 6's carry none, and those are ignored here."""

        def on_comm_open_jupyter_widget(self, msg):
            if "state" not in msg["content"].get("data", {}):
                return None
            return super().on_comm_open_jupyter_widget(msg)

        async def async_execute_cell(self, cell, cell_index, *args, **kwargs):
            if self.t0 is None:
                self.t0 = time.monotonic()
            self.current_index = cell_index
            return await super().async_execute_cell(cell, cell_index, *args, **kwargs)

    nb = nbformat.read(path, as_version=4)
    nprobe, nfunc = add_probes(nb)

    def remaining(cell):
        # each cell may use what the notebook's budget has left
        return max(1, math.ceil(budget - (time.monotonic() - client.t0)))

    def execute():
        """client.execute(), with a new kernel when one dies before the first
        cell: kernels started at once may draw the same free port (the kernel
        binds the ports its manager picked), which is the machine's, not the
        notebook's, failure."""
        nonlocal client
        for attempt in range(KERNEL_STARTS):
            client = Client(nb, kernel_name="python3", timeout_func=remaining,
                            resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}})
            client.current_index, client.t0 = None, None
            try:
                return client.execute()
            except RuntimeError as e:
                if client.t0 is not None or "before replying to kernel_info" not in str(e) \
                        or attempt == KERNEL_STARTS - 1:
                    raise

    client = None
    res = {"status": "ok", "cells": 0, "why": "", "source": ""}
    try:
        execute()
    except CellTimeoutError:
        res["status"] = "OVERRUN"
        res["why"] = "the notebook's budget of %g s ran out in this cell" % budget
    except CellExecutionError as e:
        res["status"] = "FAILED"
        last = [ln for ln in ("%s: %s" % (e.ename, e.evalue)).splitlines() if ln.strip()]
        res["why"] = last[-1] if last else e.ename
    except DeadKernelError as e:
        res["status"] = "FAILED"
        res["why"] = "the kernel died: %s" % e
    except Exception as e:  # a notebook that does not parse, a kernel that does not start
        res["status"] = "FAILED"
        res["why"] = "%s: %s" % (type(e).__name__, str(e).strip().splitlines()[-1] if str(e).strip() else "")
    res["seconds"] = time.monotonic() - client.t0 if client.t0 is not None else 0.0
    probes = nb.cells[len(nb.cells) - nprobe:]
    del nb.cells[len(nb.cells) - nprobe:]
    if res["status"] == "ok":
        why = [w for w in map(probe_result, probes) if w]
        if why:
            res["status"], res["why"] = "FAILED", "; ".join(why)
    res["sliders"] = nfunc
    res["moves"] = sum(1 for c in probes if "slider move:" in "".join(
        o.get("text", "") for o in c.get("outputs", []) if o.get("output_type") == "stream"))
    code = [i for i, c in enumerate(nb.cells) if c.cell_type == "code"]
    res["total"] = len(code)
    res["cells"] = sum(1 for i in code if nb.cells[i].get("execution_count") is not None)
    if res["status"] != "ok" and client.current_index is not None and client.current_index < len(nb.cells):
        res["cell"] = client.current_index
        res["source"] = "\n".join(nb.cells[client.current_index].source.splitlines()[:3])
    if res["status"] == "ok" and res["seconds"] > budget:
        res["status"] = "OVERRUN"
        res["why"] = "took more than the budget of %g s" % budget
    if out:
        nbformat.write(nb, os.path.join(out, os.path.basename(path)))
    return res


def line(name, res):
    """The report of one notebook: one line, and the failure's detail under it."""
    s = "%-7s %-36s %6.1f s  %d/%d cells, %d slider moves (%d interact)" % (
        res["status"], name, res["seconds"], res["cells"], res["total"], res.get("moves", 0), res.get("sliders", 0))
    if res["status"] != "ok":
        if "cell" in res:
            s += "\n        in cell %d:" % res["cell"]
            s += "".join("\n        | " + ln for ln in res["source"].splitlines())
        s += "\n        " + res["why"]
    return s


def start(path, args):
    cmd = [sys.executable, os.path.abspath(__file__), "--child", "--budget", str(args.budget)]
    if args.out:
        cmd += ["--out", args.out]
    # a session of its own: the notebook's kernel goes with it if it must be killed
    return subprocess.Popen(cmd + [path], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=kernel_env(), start_new_session=True, text=True)


def finish(proc, t0, budget):
    """The result of a notebook's process, killing it (and its kernel) past the budget."""
    try:
        out, err = proc.communicate(timeout=max(1, budget + GRACE_S - (time.monotonic() - t0)))
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return {"status": "OVERRUN", "seconds": time.monotonic() - t0, "cells": 0, "total": 0,
                "why": "still running %d s past the budget of %g s: killed" % (GRACE_S, budget)}
    for ln in reversed(out.splitlines()):
        if ln.startswith("{"):
            return json.loads(ln)
    tail = (err.strip().splitlines() or ["no output"])[-1]
    return {"status": "FAILED", "seconds": time.monotonic() - t0, "cells": 0, "total": 0,
            "why": "the runner's process exited %d: %s" % (proc.returncode, tail)}


def main():
    ap = argparse.ArgumentParser(description="Execute notebooks top to bottom; report one line each.")
    ap.add_argument("--budget", type=float, default=60.0, help="seconds each notebook may take (default 60)")
    ap.add_argument("--jobs", type=int, default=2, help="notebooks run at once (default 2)")
    ap.add_argument("--out", help="write the executed notebooks into this folder")
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("notebooks", nargs="*")
    args = ap.parse_args()
    if not args.budget > 0 or args.jobs < 1:
        ap.error("--budget: expected seconds > 0 and --jobs: expected N >= 1")
    if args.child:
        print(json.dumps(run_one(args.notebooks[0], args.budget, args.out)))
        return 0
    paths = args.notebooks or sorted(glob.glob(os.path.join(TOP, "docs", "course", "*.ipynb")))
    if not paths:
        print("course: no notebooks to run")
        return 0
    for p in paths:
        if not os.path.isfile(p):
            ap.error("%s: no such notebook" % p)
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        args.out = os.path.abspath(args.out)
    def interrupted(signum, frame):
        raise KeyboardInterrupt
    signal.signal(signal.SIGTERM, interrupted)  # make's timeouts and kill: as Ctrl-C
    todo, running, bad = list(paths), [], 0
    t_all = time.monotonic()
    try:
        while todo or running:
            while todo and len(running) < args.jobs:
                p = todo.pop(0)
                running.append((p, start(p, args), time.monotonic()))
            # wait for the oldest: they were started in order and share one budget
            p, proc, t0 = running[0]
            res = finish(proc, t0, args.budget)
            running.pop(0)
            bad += res["status"] != "ok"
            print(line(os.path.basename(p), res), flush=True)
    except KeyboardInterrupt:
        # the notebooks' processes are in sessions of their own: Ctrl-C does not reach their kernels
        for _, proc, _ in running:
            os.killpg(proc.pid, signal.SIGKILL)
        raise
    print("course: %d notebooks, %d failed, %.1f s" % (len(paths), bad, time.monotonic() - t_all))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
