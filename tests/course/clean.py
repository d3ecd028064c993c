#!/usr/bin/python3
"""Check committed course notebooks without running them: clean, and shaped as a lesson.

usage: tests/course/clean.py [NOTEBOOK.ipynb ...]   (default: every docs/course/*.ipynb)
       tests/course/clean.py --strip NOTEBOOK.ipynb ...

A notebook passes when it
  - is valid nbformat 4 and names the kernel "python3" (if it names one);
  - carries no outputs, no execution counts and no widget state (committed
    notebooks are stripped: outputs are made by the runner, not stored);
  - has a slider: a code cell calling widgets.interact with a FloatSlider,
    IntSlider or SelectionSlider;
  - has at least two exercise checks: code cells with an `assert` statement;
  - ends with references: a markdown heading "References";
  - links, from its markdown, only to files that exist (relative links).
With no notebook named, docs/course/README.md must also list each of them.
One line per notebook (ok, or FAILED and what is wrong); exit status 0 when
all pass, 1 otherwise, 2 for bad usage.  It takes well under a second.
--strip rewrites the notebooks given without their outputs, execution counts
and widget state (what to do before committing one), then checks them.
"""
import glob
import os
import re
import sys

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SLIDER = re.compile(r"widgets\.interact\s*\((?s:.*)\b(Float|Int|Selection)Slider\s*\(")
ASSERT = re.compile(r"^\s*assert\b", re.M)
REFERENCES = re.compile(r"^#+\s*References\b", re.M | re.I)
LINK = re.compile(r"\]\(([^)#:\s]+)(?:#[^)]*)?\)")


def problems(path):
    """What is wrong with one notebook, as short sentences (none: it passes)."""
    import nbformat
    try:
        nb = nbformat.read(path, as_version=nbformat.NO_CONVERT)
        nbformat.validate(nb)
    except Exception as e:  # not JSON, not a notebook, not valid
        return ["not a valid notebook: %s" % str(e).strip().splitlines()[0]]
    out = []
    if nb.nbformat != 4:
        out.append("nbformat %d, expected 4" % nb.nbformat)
    kernel = nb.metadata.get("kernelspec", {}).get("name")
    if kernel not in (None, "python3"):
        out.append('kernel "%s", expected "python3"' % kernel)
    code = [(i, c) for i, c in enumerate(nb.cells) if c.cell_type == "code"]
    with_out = [i for i, c in code if c.get("outputs")]
    counted = [i for i, c in code if c.get("execution_count") is not None]
    if with_out:
        out.append("outputs committed in cells %s (clear them)" % with_out[:8])
    if counted:
        out.append("execution counts committed in cells %s (clear them)" % counted[:8])
    if "widgets" in nb.metadata:
        out.append("widget state committed in the notebook's metadata (clear it)")
    if not any(SLIDER.search(c.source) for _, c in code):
        out.append("no slider: no code cell calls widgets.interact with a FloatSlider/IntSlider")
    checks = sum(1 for _, c in code if ASSERT.search(c.source))
    if checks < 2:
        out.append("%d exercise checks (code cells with assert), expected at least 2" % checks)
    md = [c.source for c in nb.cells if c.cell_type == "markdown"]
    if not any(REFERENCES.search(s) for s in md):
        out.append('no "References" heading')
    here = os.path.dirname(os.path.abspath(path))
    for s in md:
        for link in LINK.findall(s):
            if not os.path.exists(os.path.join(here, link)):
                out.append("links to %s, which does not exist" % link)
    return out


def index_problems(paths):
    """docs/course/README.md, the course's index, must link to every notebook of
    docs/course; a link to a notebook not (yet) there is only reported.  The
    number of failures (0 or 1)."""
    readme = os.path.join(TOP, "docs", "course", "README.md")
    with open(readme, encoding="utf-8") as f:
        links = set(LINK.findall(f.read()))
    missing = [os.path.basename(p) for p in paths if os.path.basename(p) not in links]
    for link in sorted(links):
        if link.endswith(".ipynb") and not os.path.exists(os.path.join(os.path.dirname(readme), link)):
            print("note    docs/course/README.md lists %s, which is not there" % link)
    if missing:
        print("FAILED  docs/course/README.md does not list %s" % ", ".join(missing))
    return 1 if missing else 0


def strip(path):
    """Rewrite a notebook without outputs, execution counts and widget state."""
    import nbformat
    nb = nbformat.read(path, as_version=nbformat.NO_CONVERT)
    for c in nb.cells:
        if c.cell_type == "code":
            c.outputs, c.execution_count = [], None
    nb.metadata.pop("widgets", None)
    nbformat.write(nb, path)


def main(argv):
    do_strip = argv[:1] == ["--strip"]
    argv = argv[1:] if do_strip else argv
    if any(a.startswith("-") for a in argv) or (do_strip and not argv):
        print("usage: clean.py [--strip] [NOTEBOOK.ipynb ...]", file=sys.stderr)
        return 2
    paths = argv or sorted(glob.glob(os.path.join(TOP, "docs", "course", "*.ipynb")))
    bad = 0
    for p in paths:
        if not os.path.isfile(p):
            print("clean.py: %s: no such notebook" % p, file=sys.stderr)
            return 2
        if do_strip:
            strip(p)
        why = problems(p)
        bad += bool(why)
        print("%-7s %s" % ("FAILED" if why else "ok", os.path.basename(p)))
        for w in why:
            print("        " + w)
    if not argv:
        bad += index_problems(paths)
    print("course notebooks' shape: %d notebooks, %d failed" % (len(paths), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
