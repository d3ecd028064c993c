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
exception's last line.  --out DIR writes each executed notebook, outputs and
all, to DIR/NAME.ipynb (make course renders those).  Exit status: 0 when
every notebook ran in its budget, 1 otherwise, 2 for bad usage.
"""
import argparse
import glob
import json
import math
import os
import signal
import subprocess
import sys
import time

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# the kernel's start and shutdown, beyond the cells' budget, before the
# runner gives up on a notebook's process altogether
GRACE_S = 60


def kernel_env():
    """The environment the kernel inherits: the tree's package first."""
    env = dict(os.environ)
    py = os.path.join(TOP, "python")
    env["PYTHONPATH"] = py + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"  # ipykernel's debugger warns about frozen modules otherwise
    return env


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

    def remaining(cell):
        # each cell may use what the notebook's budget has left
        return max(1, math.ceil(budget - (time.monotonic() - client.t0)))

    client = Client(nb, kernel_name="python3", timeout_func=remaining,
                    resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}})
    client.current_index, client.t0 = None, None
    res = {"status": "ok", "cells": 0, "why": "", "source": ""}
    try:
        client.execute()
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
    code = [i for i, c in enumerate(nb.cells) if c.cell_type == "code"]
    res["total"] = len(code)
    res["cells"] = sum(1 for i in code if nb.cells[i].get("execution_count") is not None)
    if res["status"] != "ok" and client.current_index is not None:
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
    s = "%-7s %-36s %6.1f s  %d/%d cells" % (res["status"], name, res["seconds"], res["cells"], res["total"])
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
