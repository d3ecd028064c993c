#!/usr/bin/env python3
"""Compares two runs of tools/compat/run.sh: BASE and NEW folders, each with
run/ (the files the lines wrote) and out/ (N.cmd, N.out, N.err, N.rc, N.files
per line N of the command list).

    compare.py BASE NEW BASE_VERSION NEW_VERSION

What may differ, and nothing else:
  - the version string: BASE_VERSION in the base's outputs and NEW_VERSION in
    the new one's read as VERSION (text: every occurrence as a whole
    X.Y.Z; EXR: the bytes, or, when the two strings differ in length, the
    header attributes with the version normalised, the offset table relative
    to the end of the table and the chunks byte for byte; other binary files:
    the bytes when the lengths agree);
  - HDF5 files are compared as `h5dump -m %.17g` text (every attribute and
    every sample, exactly): the library stamps each object with the time it
    was written, so two runs of one build never agree byte for byte;
  - the timings that vary from run to run of one build (TIMINGS below): the
    seconds in krige --json, in validate's JSON and index.md, and in
    noiselab-mpi's synth --json with its peak resident memory.

Prints one line per difference and "N passed, M failed" (N lines whose stdout,
stderr, exit status and files all agree); exit status 1 when any differ.
"""
import os
import re
import shutil
import struct
import subprocess
import sys

# Outputs found to vary between two runs of one build (tools/compat/run.sh
# with the same build twice), each as (where, pattern, replacement): where
# is a regular expression on the output's name (stdout/stderr: "N.out",
# "N.err"; files: their path under run/).
TIMINGS = [
    # krige --json and validate --json, verdict.json: "seconds": 0.0026 (the
    # time kriging or each method took)
    (r".*", rb'"seconds": ?-?[0-9][0-9.]*([eE][+-]?[0-9]+)?', b'"seconds":SECONDS'),
    # synth -o OUT.h5 --json under mpirun (noiselab-mpi): the slowest process's
    # seconds and the largest peak resident memory (getrusage)
    (r".*", rb'"seconds":\{"synthesis":[^,}]*,"write":[^,}]*\}', b'"seconds":SECONDS'),
    (r".*", rb'"peak_rss_mib":[0-9][0-9.]*([eE][+-]?[0-9]+)?', b'"peak_rss_mib":MIB'),
    # validate -o DIR: DIR/index.md, the time column of the methods' table
    (r"(^|/)index\.md$", rb"\| [0-9]+\.[0-9]+ s \|\n", b"| SECONDS s |\n"),
]


def version_re(v):
    return re.compile(rb"(?<![0-9.])" + re.escape(v.encode()) + rb"(?![0-9]|\.[0-9])")


class Side:
    def __init__(self, root, version):
        self.root = root
        self.version = version
        self.vre = version_re(version) if version else None

    def norm_text(self, name, data):
        if self.vre:
            data = self.vre.sub(b"VERSION", data)
        for where, pat, rep in ([] if os.environ.get("COMPAT_RAW") == "1" else TIMINGS):
            if re.search(where, name):
                data = re.sub(pat, rep, data)
        return data


def first_diff(a, b):
    n = min(len(a), len(b))
    i = 0
    while i < n and a[i] == b[i]:
        i += 1
    return i


def show(a, b):
    """Where two byte strings first differ, and a little of each from there."""
    i = first_diff(a, b)
    lo = max(0, i - 16)
    where = "byte %d" % i
    if b"\0" not in a[:i]:
        where += " (line %d)" % (a[:i].count(b"\n") + 1)
    if i >= len(a) or i >= len(b):
        where += ", base %d bytes, new %d bytes" % (len(a), len(b))
    return "%s: base %r new %r" % (where, a[lo:i + 48], b[lo:i + 48])


def is_text(data):
    return b"\0" not in data[:65536]


def h5dump(path, side):
    if not shutil.which("h5dump"):
        return None
    r = subprocess.run(["h5dump", "-m", "%.17g", os.path.basename(path)], cwd=os.path.dirname(path),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    return side.norm_text(path, r.stdout) + b"\nexit %d\n" % r.returncode


def exr_parts(data):
    """EXR (single part, not deep): header attributes, the offset table
    relative to its end, and the chunks; None when it does not parse."""
    try:
        if data[:4] != b"\x76\x2f\x31\x01":
            return None
        flags = struct.unpack_from("<I", data, 4)[0]
        if flags & 0x1800:  # multi-part or deep
            return None
        p, attrs = 8, []
        while data[p] != 0:
            e = data.index(b"\0", p)
            name = data[p:e]
            t = data.index(b"\0", e + 1)
            typ = data[e + 1:t]
            size = struct.unpack_from("<i", data, t + 1)[0]
            attrs.append((name, typ, data[t + 5:t + 5 + size]))
            p = t + 5 + size
        p += 1
        offsets, q, first = [], p, None
        while first is None or q < first:
            o = struct.unpack_from("<Q", data, q)[0]
            first = o if first is None else min(first, o)
            offsets.append(o)
            q += 8
        if q != first:
            return None
        return attrs, [o - q for o in offsets], data[q:]
    except (IndexError, struct.error, ValueError):
        return None


def compare_exr(a, b, sa, sb):
    """None when equal, else a description."""
    if len(sa.version) == len(sb.version):
        x = a.replace(sa.version.encode(), b"#" * len(sa.version)) if sa.version else a
        y = b.replace(sb.version.encode(), b"#" * len(sb.version)) if sb.version else b
        return None if x == y else show(x, y)
    pa, pb = exr_parts(a), exr_parts(b)
    if pa is None or pb is None:
        x, y = sa.norm_text("", a), sb.norm_text("", b)
        return None if x == y else "(not a plain EXR) " + show(x, y)
    ha = [(n, t, sa.norm_text("", v)) for n, t, v in pa[0]]
    hb = [(n, t, sb.norm_text("", v)) for n, t, v in pb[0]]
    if ha != hb:
        if sorted(ha) == sorted(hb):
            return "header: the attributes in another order: base %r new %r" % ([x[0] for x in ha], [x[0] for x in hb])
        return "header: base %r new %r" % (sorted(set(ha) - set(hb)), sorted(set(hb) - set(ha)))
    if pa[1] != pb[1]:
        return "offset table: base %r new %r" % (pa[1][:8], pb[1][:8])
    return None if pa[2] == pb[2] else "pixel data " + show(pa[2], pb[2])


def compare_file(rel, sa, sb):
    fa, fb = os.path.join(sa.root, "run", rel), os.path.join(sb.root, "run", rel)
    a, b = open(fa, "rb").read(), open(fb, "rb").read()
    if a.startswith(b"\x89HDF\r\n\x1a\n") and b.startswith(b"\x89HDF\r\n\x1a\n"):
        da, db = h5dump(fa, sa), h5dump(fb, sb)
        if da is not None:
            return None if da == db else "h5dump " + show(da, db)
    if a.startswith(b"\x76\x2f\x31\x01") or b.startswith(b"\x76\x2f\x31\x01"):
        return compare_exr(a, b, sa, sb)
    if is_text(a) and is_text(b):
        x, y = sa.norm_text(rel, a), sb.norm_text(rel, b)
        return None if x == y else show(x, y)
    if len(sa.version) == len(sb.version) and sa.version:
        a = a.replace(sa.version.encode(), b"#" * len(sa.version))
        b = b.replace(sb.version.encode(), b"#" * len(sb.version))
    return None if a == b else show(a, b)


def read(path):
    try:
        return open(path, "rb").read()
    except OSError:
        return None


def main():
    if len(sys.argv) != 5:
        sys.stderr.write("usage: compare.py BASE NEW BASE_VERSION NEW_VERSION\n")
        return 2
    sa, sb = Side(sys.argv[1], sys.argv[3]), Side(sys.argv[2], sys.argv[4])
    lines = sorted(int(f[:-4]) for f in os.listdir(os.path.join(sa.root, "out")) if f.endswith(".cmd"))
    cmd, failed = {}, {}

    def fail(n, what):
        failed.setdefault(n, []).append(what)

    owner = {}  # file -> the last line that changed it (in either run)
    for n in lines:
        cmd[n] = read(os.path.join(sa.root, "out", "%d.cmd" % n)).decode(errors="replace").rstrip("\n")
        rc = [read(os.path.join(s.root, "out", "%d.rc" % n)) for s in (sa, sb)]
        if rc[0] != rc[1]:
            fail(n, "exit status: base %s, new %s" % tuple((r or b"none").decode().strip() for r in rc))
        for ext, what in (("out", "stdout"), ("err", "stderr")):
            x = read(os.path.join(sa.root, "out", "%d.%s" % (n, ext)))
            y = read(os.path.join(sb.root, "out", "%d.%s" % (n, ext)))
            if x is None or y is None:
                fail(n, "%s: missing in %s" % (what, "base" if x is None else "new"))
                continue
            x, y = sa.norm_text("%d.%s" % (n, ext), x), sb.norm_text("%d.%s" % (n, ext), y)
            if x != y:
                fail(n, "%s differs at %s" % (what, show(x, y)))
        for s in (sa, sb):
            for f in (read(os.path.join(s.root, "out", "%d.files" % n)) or b"").decode().split("\n"):
                if f:
                    owner[f[2:] if f.startswith("./") else f] = n

    def files(s):
        out = set()
        top = os.path.join(s.root, "run")
        for d, _, fs in os.walk(top):
            for f in fs:
                out.add(os.path.relpath(os.path.join(d, f), top))
        return out

    fa, fb = files(sa), files(sb)
    orphans = 0
    for rel in sorted(fa | fb):
        n = owner.get(rel)
        if rel not in fb:
            what = "file %s: only in base" % rel
        elif rel not in fa:
            what = "file %s: only in new" % rel
        else:
            d = compare_file(rel, sa, sb)
            what = None if d is None else "file %s differs at %s" % (rel, d)
        if what is None:
            continue
        if n is None:
            orphans += 1
            print("line ?: %s" % what)
        else:
            fail(n, what)

    for n in sorted(failed):
        for what in failed[n]:
            print("line %d: %s: %s" % (n, cmd[n], what))
    nfail = len(failed) + orphans
    print("%d passed, %d failed" % (len(lines) - len(failed), nfail))
    return 1 if nfail else 0


if __name__ == "__main__":
    sys.exit(main())
