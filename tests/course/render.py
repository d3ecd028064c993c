#!/usr/bin/python3
"""Render executed notebooks to HTML pages that work offline, and an index of them.

usage: tests/course/render.py [--src DIR] OUTDIR NOTEBOOK.ipynb ...

Each executed notebook (tests/course/run.py --out) becomes OUTDIR/NAME.html
(nbconvert's lab template, figures embedded as data: PNGs), and OUTDIR/index.html
lists them, one line each: the notebook's title and what it teaches (the
table of docs/course/README.md, else the notebook's first sentence).
nbconvert's pages load require.js and MathJax from URLs: here they name copies
beside the pages (OUTDIR/require.min.js, OUTDIR/mathjax/ a link to Debian's
libjs-mathjax), so the folder opens in a browser with no network.  The widget
state nbclient records (empty with ipywidgets 6) is dropped, since the page
would otherwise fetch the widget manager from unpkg.com; each page says,
above the notebook, that its sliders move only in Jupyter and that its
figures are drawn at the sliders' defaults.  The notebooks' relative links,
written for their folder (--src, default docs/course/), are rewritten to
work from OUTDIR: a link to a course notebook goes to its page, any other
to the file in the tree.
"""
import html
import os
import re
import shutil
import sys

REQUIRE_JS = "/usr/share/javascript/requirejs/require.min.js"   # Debian's libjs-requirejs
MATHJAX_DIR = "/usr/share/javascript/mathjax"                    # Debian's libjs-mathjax
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SRC = os.path.join(TOP, "docs", "course")  # where the notebooks' relative links start

def note_cell(nbformat):
    text = ("*A rendered copy of the notebook: its sliders move only when the notebook runs in "
            "Jupyter (docs/course/README.md says how); each figure here is drawn at the slider's "
            "default value.*")
    return nbformat.v4.new_markdown_cell(text)


def readme_lines():
    """What each notebook teaches, from the table of docs/course/README.md: {name.ipynb: text}."""
    rows = {}
    try:
        with open(os.path.join(SRC, "README.md"), encoding="utf-8") as f:
            for ln in f:
                m = re.match(r"\|\s*\[([^\]]+\.ipynb)\]\([^)]*\)\s*\|(.*)\|\s*$", ln)
                if m:
                    rows[m.group(1)] = m.group(2).strip()
    except OSError:
        pass
    return rows


def title_and_line(nb, fallback):
    """The notebook's first heading and the first sentence of text after it."""
    for cell in nb.cells:
        if cell.cell_type != "markdown":
            continue
        lines = [ln.strip() for ln in cell.source.splitlines() if ln.strip()]
        heads = [i for i, ln in enumerate(lines) if ln.startswith("#")]
        if not heads:
            continue
        title = lines[heads[0]].lstrip("#").strip()
        rest = " ".join(ln for ln in lines[heads[0] + 1:] if not ln.startswith("#"))
        return title, re.split(r"(?<=\.)\s", rest, maxsplit=1)[0]
    return fallback, ""


def relink(nb, src, out):
    """Relative links of the markdown cells, written for the notebook's folder src,
    made to work from out: a notebook of the course becomes its page, anything
    else (../models.md) the path to the tree's file."""
    def fix(m):
        link, anchor = m.group(1), m.group(2) or ""
        if re.match(r"[a-z]+:", link):
            return m.group(0)
        if link.endswith(".ipynb") and os.path.dirname(link) == "":
            return "](%s.html%s)" % (link[:-len(".ipynb")], anchor)
        return "](%s%s)" % (os.path.relpath(os.path.join(src, link), out), anchor)
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            cell.source = re.sub(r"\]\(([^)#\s]+)(#[^)\s]*)?\)", fix, cell.source)


def plain(md):
    """A markdown line as plain text for the index: links, emphasis, code and math marks dropped."""
    md = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", md)
    return re.sub(r"[*_`$]|\\(?=[a-zA-Z])", "", md)


def main(argv):
    src = SRC
    if argv[:1] == ["--src"] and len(argv) > 1:
        src, argv = os.path.abspath(argv[1]), argv[2:]
    if len(argv) < 2 or argv[0].startswith("-"):
        print("usage: render.py [--src DIR] OUTDIR NOTEBOOK.ipynb ...", file=sys.stderr)
        return 2
    import nbformat
    from nbconvert import HTMLExporter

    out = argv[0]
    os.makedirs(out, exist_ok=True)
    shutil.copyfile(REQUIRE_JS, os.path.join(out, "require.min.js"))
    link = os.path.join(out, "mathjax")
    if not os.path.islink(link):
        os.symlink(MATHJAX_DIR, link)
    exporter = HTMLExporter(require_js_url="require.min.js",
                            mathjax_url="mathjax/MathJax.js?config=TeX-AMS_CHTML-full,Safe")
    rows, teaches = [], readme_lines()
    for path in argv[1:]:
        name = os.path.splitext(os.path.basename(path))[0]
        nb = nbformat.read(path, as_version=4)
        nb.metadata.pop("widgets", None)
        relink(nb, src, out)
        title, first = title_and_line(nb, name)
        first = teaches.get(name + ".ipynb", first)
        heading = next((i for i, c in enumerate(nb.cells) if c.cell_type == "markdown"), -1)
        nb.cells.insert(heading + 1, note_cell(nbformat))
        body, _ = exporter.from_notebook_node(nb, resources={"metadata": {"name": title}})
        with open(os.path.join(out, name + ".html"), "w", encoding="utf-8") as f:
            f.write(body)
        rows.append('<li><a href="%s.html">%s</a>: %s</li>' % (
            html.escape(name), html.escape(title), html.escape(plain(first))))
        print("rendered %s.html" % name)
    with open(os.path.join(out, "index.html"), "w", encoding="utf-8") as f:
        f.write("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                "<title>noiselab: a course in stationary random fields</title>\n"
                "<style>body { font-family: sans-serif; max-width: 60em; margin: 2em auto; line-height: 1.5 }"
                " li { margin-bottom: 0.6em }</style></head>\n<body>\n"
                "<h1>A course in stationary random fields</h1>\n"
                "<p>The course's notebooks, executed and rendered. Their sliders move only when a notebook "
                "runs in Jupyter (docs/course/README.md says how to start it); on these pages each figure "
                "is drawn at its slider's default value.</p>\n<ul>\n%s\n</ul>\n</body></html>\n"
                % "\n".join(rows))
    print("rendered index.html (%d notebooks)" % len(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
