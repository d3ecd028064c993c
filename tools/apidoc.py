#!/usr/bin/python3
"""docs/api.md from the installed headers: one line per function the shared
libraries export (tools/exports.sh lists them, as the compiler reads the
headers), its name, header and the first sentence of the comment that
documents it, grouped by header under that header's first comment line.

usage: tools/apidoc.py HEADER... > docs/api.md
  (the Makefile's PUB_HDR, then MPI_HDR; CPPFLAGS with MPI's include flags
  in the environment, as tools/exports.sh takes them)

A function's comment is the one after it on the declaration's last line, or
else the one that ends above it or above the run of declarations, #defines
and typedefs it belongs to (one comment may document a group), or else the
first sentence of the header's comments that names it (a function the
header's opening notes document).  A sentence ends at a full stop followed
by two spaces or by the end of a line (the headers' convention), or at the
comment's end.  A function with no comment gets its name alone."""
import os
import re
import subprocess
import sys

ABBREV = ("e.g.", "i.e.", "eq.", "Eq.", "cf.", "vs.", "et al.", "resp.", "approx.")


def exports(headers):
    """{header: [(line, name)]} from tools/exports.sh."""
    tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "exports.sh")
    out = subprocess.run(["sh", tool] + headers, check=True, capture_output=True, text=True).stdout
    by = {}
    for row in out.splitlines():
        name, header, line = row.split()
        by.setdefault(header, []).append((int(line), name))
    return by


def comment_text(lines):
    """The text of a /* ... */ block given as its source lines."""
    text = []
    for ln in lines:
        ln = ln.strip()
        ln = re.sub(r"^/\*+\s?", "", ln)
        ln = re.sub(r"\s*\*+/$", "", ln)
        ln = re.sub(r"^\*(\s|$)", "", ln)
        text.append(ln.rstrip())
    return text


def sentences(text):
    """The sentences of a comment's lines: a sentence ends at a full stop
    followed by two spaces, or at the end of a line when the next line does
    not go on in lower case (an abbreviation such as e.g. never ends one),
    or at a blank line."""
    joined = ""
    for i, ln in enumerate(text):
        nxt = text[i + 1] if i + 1 < len(text) else ""
        end = not ln or (re.search(r"[.?!]\)?$", ln) and not ln.endswith(ABBREV) and not nxt[:1].islower())
        joined += ln + ("\n" if end else " ")
    out = []
    for part in joined.split("\n"):
        out += [re.sub(r"\s+", " ", x).strip() for x in re.split(r"(?<=[.?!])\s{2,}|(?<=[.?!]\))\s{2,}", part)]
    return [x for x in out if x]


def first_sentence(text):
    """The first sentence of a comment's lines."""
    s = sentences(text)
    return s[0] if s else ""


def comment_above(src, at):
    """The comment documenting the declaration whose name is on line `at`
    (0-based), or None."""
    i = at
    # the declaration's first line: back over its continuation lines
    while i > 0 and src[i - 1].strip() and not src[i - 1].rstrip().endswith((";", "*/", "{", "}")) \
            and not src[i - 1].lstrip().startswith("#"):
        i -= 1
    # a comment on the declaration's own last line
    k = at
    while k < len(src) and ";" not in src[k]:
        k += 1
    if k < len(src):
        tail = src[k].split(";", 1)[1]
        if "/*" in tail:
            return comment_text([tail[tail.index("/*"):]])
    j = i - 1
    # over the run of declarations, #defines and typedefs just above (a
    # group under one comment; a typedef may stand a blank line apart)
    while j >= 0:
        ln = src[j].strip()
        if not ln and j > 0 and re.match(r"(typedef\b|\}).*;", src[j - 1].strip()):
            j -= 1
            continue
        if not ln or (ln.startswith("#") and not ln.startswith("#define")) or \
                (ln.endswith("*/") and ln.startswith(("/*", "*"))):
            break
        j -= 1
    if j >= 0 and src[j].rstrip().endswith("*/"):
        end = j
        while j >= 0 and "/*" not in src[j]:
            j -= 1
        block = src[j:end + 1]
        if block and block[0].lstrip().startswith("/*"):
            return comment_text(block)
    return None


def mention(src, name):
    """The first sentence of the header's comments that names the function
    (a function documented with others in a header's opening notes)."""
    block, inside = [], False
    for ln in src:
        if ln.lstrip().startswith("/*"):
            inside, block = True, []
        if inside:
            block.append(ln)
            if ln.rstrip().endswith("*/"):
                inside = False
                text = comment_text(block)
                if any(re.search(r"\b%s\b" % name, t) for t in text):
                    for s in sentences(text):
                        if re.search(r"\b%s\b" % name, s):
                            return s
    return ""


def heading(src):
    for ln in src:
        if ln.lstrip().startswith("/*"):
            return comment_text([ln])[0]
    return ""


def main(headers):
    by = exports(headers)
    print("# The noiselab API")
    print()
    print("Every function the shared libraries export (libnoiselab, then libnoiselab_mpi), one line")
    print("each: its name, its header and the first sentence of its comment there; the header says")
    print("the rest (sizes, layout, units, ownership, NL_E* codes, thread safety).  Generated by")
    print("tools/apidoc.py from the installed headers (`make apidoc`); `make test` checks it is")
    print("current.")
    # libnoiselab's headers by path, then libnoiselab_mpi's
    for h in sorted(headers, key=lambda h: (h.startswith("mpi/"), h)):
        if h not in by:
            continue
        src = open(h).read().split("\n")
        print()
        print("## %s: %s" % (h, heading(src)))
        print()
        for line, name in sorted(by[h]):
            text = comment_above(src, line - 1)
            what = first_sentence(text) if text else mention(src, name)
            print("- `%s` (%s)%s" % (name, h, ": " + what if what else ""))


if __name__ == "__main__":
    main(sys.argv[1:])
