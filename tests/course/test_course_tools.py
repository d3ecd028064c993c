"""The course's tools fail when they should: tests/course/run.py, clean.py, render.py, browser.py.

Each tool meets tests/course/tiny.ipynb (a slider, two exercise checks, a
figure) and variants of it made here that are broken in one way each, and
browser.py meets the crafted pages of tests/course/pages/.  Run by `make test`
(pytest tests/course); about 15 s, most of it the kernels' starts.
"""
import os
import subprocess
import sys

import nbformat
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
TINY = os.path.join(HERE, "tiny.ipynb")
PY = sys.executable


def tool(name, *args, env=None):
    r = subprocess.run([PY, os.path.join(HERE, name)] + [str(a) for a in args],
                       capture_output=True, text=True, timeout=180, env=env)
    return r.returncode, r.stdout + r.stderr


def variant(tmp, name, edit):
    """tiny.ipynb changed by edit(nb), written as tmp/name; its path."""
    nb = nbformat.read(TINY, as_version=4)
    edit(nb)
    path = os.path.join(tmp, name)
    nbformat.write(nb, path)
    return path


def code_cell(nb, text):
    return next(c for c in nb.cells if c.cell_type == "code" and text in c.source)


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """One runner on tiny, a variant whose first check fails and two whose
    slider breaks, one on a variant that sleeps past a 4 s budget, side by
    side; their outputs."""
    tmp = tmp_path_factory.mktemp("runs")
    wrong = variant(tmp, "wrong-answer.ipynb",
                    lambda nb: setattr(code_cell(nb, "answer_1 ="), "source", "answer_1 = rho[7]"))
    # no imports: only the sleep can use the budget up, however loaded the machine
    slow = variant(tmp, "overrun.ipynb", lambda nb: setattr(nb, "cells", [
        nbformat.v4.new_code_cell("import time"), nbformat.v4.new_code_cell("time.sleep(120)")]))
    # sliders: one that raises at its maximum, one that draws nothing at its minimum
    def guard(cond, act):
        def edit(nb):
            c = code_cell(nb, "def draw(")
            c.source = c.source.replace('    mm = noiselab', '    if %s:\n        %s\n    mm = noiselab' % (cond, act), 1)
        return edit
    breaks = variant(tmp, "slider-breaks.ipynb", guard("scale > 39", 'raise ValueError("scale too large")'))
    blank = variant(tmp, "slider-blank.ipynb", guard("scale < 2", "return"))
    out = tmp / "executed"
    a = subprocess.Popen([PY, os.path.join(HERE, "run.py"), "--out", out, TINY, wrong, breaks, blank],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    b = subprocess.Popen([PY, os.path.join(HERE, "run.py"), "--budget", "4", slow],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return {"both": (a.wait(180), a.stdout.read()), "slow": (b.wait(180), b.stdout.read()), "out": out}


def report(text, name):
    """The runner's lines about one notebook."""
    lines = text.splitlines()
    i = next(k for k, ln in enumerate(lines) if name in ln.split())
    j = next((k for k in range(i + 1, len(lines)) if not lines[k].startswith(" ")), len(lines))
    return "\n".join(lines[i:j])


def test_runner_passes_tiny_and_fails_a_wrong_answer(runs):
    rc, text = runs["both"]
    assert rc == 1, text
    assert report(text, "tiny.ipynb").startswith("ok"), text
    bad = report(text, "wrong-answer.ipynb")
    assert bad.startswith("FAILED"), text
    # the failing cell's first line and the assertion's message
    assert "| # closed form exp(-8/8)" in bad and "AssertionError: rho(8) should be exp(-1)" in bad, bad


def test_runner_moves_every_slider(runs):
    """Each slider is set to its minimum and maximum and back: a redraw that
    raises or draws nothing fails the notebook, naming the slider's value."""
    rc, text = runs["both"]
    assert "3 slider moves (1 interact)" in report(text, "tiny.ipynb"), text
    bad = report(text, "slider-breaks.ipynb")
    assert bad.startswith("FAILED") and "draw() with scale = 40.0: ValueError: scale too large" in bad, text
    bad = report(text, "slider-blank.ipynb")
    assert bad.startswith("FAILED") and "draw() with scale = 1.0 drew no figure" in bad, text


def test_runner_stops_a_notebook_past_its_budget(runs):
    rc, text = runs["slow"]
    assert rc == 1, text
    line = report(text, "overrun.ipynb")
    assert line.startswith("OVERRUN") and "time.sleep(120)" in line, text
    seconds = float(line.split()[2])
    assert seconds < 30, "the runner let a 4 s budget run %g s" % seconds


def test_runner_writes_executed_notebooks(runs):
    nb = nbformat.read(str(runs["out"] / "tiny.ipynb"), as_version=4)
    pngs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs if "image/png" in o.get("data", {})]
    assert len(pngs) == 1, "tiny.ipynb draws one figure, the executed copy holds %d" % len(pngs)


def test_clean_check(runs, tmp_path):
    rc, text = tool("clean.py", TINY)
    assert rc == 0, text
    rc, text = tool("clean.py", runs["out"] / "tiny.ipynb")
    assert rc == 1 and "outputs committed" in text and "execution counts committed" in text, text
    no_slider = variant(tmp_path, "no-slider.ipynb", lambda nb: nb.cells.remove(code_cell(nb, "interact")))
    one_check = variant(tmp_path, "one-check.ipynb", lambda nb: nb.cells.remove(code_cell(nb, "assert abs(answer_2")))
    no_refs = variant(tmp_path, "no-refs.ipynb", lambda nb: nb.cells.pop())
    bad_link = variant(tmp_path, "bad-link.ipynb",
                       lambda nb: nb.cells.append(nbformat.v4.new_markdown_cell("[gone](no-such-page.md)")))
    rc, text = tool("clean.py", no_slider, one_check, no_refs, bad_link)
    assert rc == 1, text
    assert "no slider" in report(text, "no-slider.ipynb"), text
    assert "1 exercise checks" in report(text, "one-check.ipynb"), text
    assert 'no "References"' in report(text, "no-refs.ipynb"), text
    assert "links to no-such-page.md" in report(text, "bad-link.ipynb"), text
    # --strip leaves nothing of the run behind (the copy's relative links point nowhere from tmp_path)
    executed = tmp_path / "executed.ipynb"
    executed.write_bytes((runs["out"] / "tiny.ipynb").read_bytes())
    rc, text = tool("clean.py", "--strip", executed)
    assert "committed" not in text and "links to ../../docs/models.md" in text, text


def test_rendered_page_opens_clean_offline(runs, tmp_path):
    """tiny's executed copy rendered: the page loads require.js and MathJax from
    beside it (the network is not needed) and shows its figure."""
    html = tmp_path / "html"
    rc, text = tool("render.py", "--src", HERE, html, runs["out"] / "tiny.ipynb")
    assert rc == 0, text
    page = (html / "tiny.html").read_text()
    assert "https://" not in page.split("<style")[0] and 'src="require.min.js"' in page, "the page loads from the network"
    shots = tmp_path / "shots"
    rc, text = tool("browser.py", "--shots", shots, "--no-figure-ok", "index.html", html / "tiny.html",
                    html / "index.html")
    assert rc == 0, text
    assert "1 figures" in report(text, "tiny.html"), text
    assert (shots / "tiny.png").stat().st_size > 10000


def test_browser_check_fails_broken_pages():
    pages = os.path.join(HERE, "pages")
    names = ["good.html", "broken-img.html", "console-error.html", "uncaught.html", "missing-script.html",
             "no-figure.html", "dead-link.html"]
    rc, text = tool("browser.py", *[os.path.join(pages, n) for n in names])
    assert rc == 1, text
    assert report(text, "good.html").startswith("ok"), text
    want = {"broken-img.html": "<img> not loaded", "console-error.html": "a crafted console error",
            "uncaught.html": "uncaught: Error: a crafted exception",
            "missing-script.html": "no-such-script.js", "no-figure.html": "no figure on the page",
            "dead-link.html": "dead link: " + os.path.join(pages, "no-such-page.html")}
    for name, why in want.items():
        r = report(text, name)
        assert r.startswith("FAILED") and why in r, text
