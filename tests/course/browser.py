#!/usr/bin/python3
"""Open rendered pages in headless Chromium and fail on what a reader would see broken.

usage: tests/course/browser.py [--shots DIR] [--no-figure-ok NAME.html ...] PAGE.html ...

Each page is loaded from its file (no network is needed or used: the pages
must carry or link what they load).  A page fails on any console error
(console.error, an uncaught exception, a resource that did not load: the
browser logs each as an error), on an <img> that did not load (naturalWidth
0), on a link to a local file that does not exist, or when it shows no
figure at all (no loaded <img>; pages named with --no-figure-ok, such as an
index, are spared that rule).  --shots DIR saves a
screenshot of each page (the first 6000 pixels of it, 1000 wide) to
DIR/NAME.png.  One line per page; exit status 0 when every page passed, 1
otherwise, 2 for bad usage.

Chromium is driven through the DevTools protocol over a pipe
(--remote-debugging-pipe: JSON messages ending in a NUL byte on file
descriptors 3 and 4), which needs nothing beyond the standard library.
"""
import argparse
import base64
import fcntl
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.parse

CHROMIUM = os.environ.get("CHROMIUM", "chromium")
WIDTH, MAX_HEIGHT = 1000, 6000
# after the load event, a page is settled when no request has been pending for
# this long (MathJax fetches its pieces after the load), or at the cap
QUIET_S, SETTLE_CAP_S, LOAD_CAP_S = 0.5, 20.0, 30.0


class Browser:
    """One headless Chromium and a DevTools session on one tab."""

    def __init__(self):
        self.profile = tempfile.mkdtemp(prefix="course-chromium-")
        to_r, to_w = os.pipe()
        from_r, from_w = os.pipe()
        # moved above 10 so that putting them on 3 and 4 in the child clobbers nothing
        hi_r, hi_w = fcntl.fcntl(to_r, fcntl.F_DUPFD, 10), fcntl.fcntl(from_w, fcntl.F_DUPFD, 10)

        def fds():
            os.dup2(hi_r, 3)
            os.dup2(hi_w, 4)

        args = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
                "--no-first-run", "--no-default-browser-check", "--disable-extensions",
                "--user-data-dir=" + self.profile, "--window-size=%d,800" % WIDTH, "about:blank"]
        self.proc = subprocess.Popen(args, preexec_fn=fds, pass_fds=(3, 4), stdin=subprocess.DEVNULL,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for fd in (to_r, from_w, hi_r, hi_w):
            os.close(fd)
        self.w, self.r = os.fdopen(to_w, "wb", buffering=0), os.fdopen(from_r, "rb", buffering=0)
        os.set_blocking(from_r, False)
        self.buf, self.next_id, self.events = b"", 0, []
        tabs = self.call("Target.getTargets")["targetInfos"]
        target = next(t["targetId"] for t in tabs if t["type"] == "page")
        self.session = self.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.call(domain + ".enable", session=True)
        self.call("Emulation.setDeviceMetricsOverride", session=True, width=WIDTH, height=800,
                  deviceScaleFactor=1, mobile=False)

    def _read(self, timeout):
        """The messages that arrive within timeout seconds (at least one poll)."""
        end = time.monotonic() + timeout
        while True:
            try:
                chunk = self.r.read(1 << 20)
            except BlockingIOError:
                chunk = None
            if chunk == b"":
                raise RuntimeError("chromium closed its DevTools pipe (exit %s)" % self.proc.poll())
            if chunk:
                self.buf += chunk
            while b"\0" in self.buf:
                msg, self.buf = self.buf.split(b"\0", 1)
                yield json.loads(msg)
            if time.monotonic() >= end:
                return
            if not chunk:
                time.sleep(0.02)

    def call(self, method, session=False, timeout=30.0, **params):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params}
        if session:
            msg["sessionId"] = self.session
        self.w.write(json.dumps(msg).encode() + b"\0")
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for m in self._read(0.05):
                if m.get("id") == self.next_id:
                    if "error" in m:
                        raise RuntimeError("%s: %s" % (method, m["error"].get("message")))
                    return m.get("result", {})
                if "method" in m:
                    self.events.append(m)
        raise RuntimeError("%s: no answer in %g s" % (method, timeout))

    def pump(self, seconds):
        for m in self._read(seconds):
            if "method" in m:
                self.events.append(m)

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except (RuntimeError, OSError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        shutil.rmtree(self.profile, ignore_errors=True)


def errors_of(events):
    """The console errors and failed loads among the DevTools events, one line each."""
    out = []
    for e in events:
        m, p = e["method"], e.get("params", {})
        if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            out.append("console.%s: %s" % (p["type"], " ".join(
                str(a.get("value", a.get("description", ""))) for a in p.get("args", []))))
        elif m == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            out.append("uncaught: %s" % d.get("exception", {}).get("description", d.get("text", "")))
        elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            en = p["entry"]
            out.append("%s: %s %s" % (en.get("source", "log"), en.get("text", ""), en.get("url", "")[:120]))
        elif m == "Network.loadingFailed" and not p.get("canceled"):
            out.append("failed load: %s (%s)" % (p.get("requestId"), p.get("errorText")))
    return out


IMAGES_JS = """JSON.stringify(Array.from(document.images).map(function (i) {
    return [i.src.slice(0, 60), i.complete, i.naturalWidth]; }))"""


LINKS_JS = """JSON.stringify(Array.from(document.links).map(function (a) { return a.href; }))"""


def dead_links(b):
    """The page's links to local files that do not exist."""
    res = b.call("Runtime.evaluate", session=True, expression=LINKS_JS, returnByValue=True)
    out = []
    for href in json.loads(res["result"]["value"]):
        if href.startswith("file://"):
            path = urllib.parse.unquote(urllib.parse.urlsplit(href).path)
            if not os.path.exists(path):
                out.append("dead link: %s" % path)
    return out


def visit(b, path, shots):
    """Load one page, let it settle; return its problems and its loaded figures."""
    b.events = []
    b.call("Page.navigate", session=True, url="file://" + os.path.abspath(path))
    t0, loaded = time.monotonic(), False
    while not loaded and time.monotonic() - t0 < LOAD_CAP_S:
        b.pump(0.1)
        loaded = any(e["method"] == "Page.loadEventFired" for e in b.events)
    pending, quiet_since, seen = set(), time.monotonic(), 0
    while time.monotonic() - t0 < LOAD_CAP_S + SETTLE_CAP_S:
        for e in b.events[seen:]:
            rid = e.get("params", {}).get("requestId")
            if e["method"] == "Network.requestWillBeSent":
                pending.add(rid)
                quiet_since = time.monotonic()
            elif e["method"] in ("Network.loadingFinished", "Network.loadingFailed"):
                pending.discard(rid)
                quiet_since = time.monotonic()
        seen = len(b.events)
        if not pending and time.monotonic() - quiet_since >= QUIET_S:
            break
        b.pump(0.1)
    problems = [] if loaded else ["the page did not finish loading in %g s" % LOAD_CAP_S]
    # a failed load is reported twice (the network event and the log line): keep the log's, which names the URL
    problems += [p for p in errors_of(b.events) if not p.startswith("failed load") or
                 not any(e["method"] == "Log.entryAdded" for e in b.events)]
    res = b.call("Runtime.evaluate", session=True, expression=IMAGES_JS, returnByValue=True)
    images = json.loads(res["result"]["value"])
    problems += ["<img> not loaded: %s" % src for src, complete, w in images if w == 0]
    problems += dead_links(b)
    if shots:
        size = b.call("Page.getLayoutMetrics", session=True)["cssContentSize"]
        h = min(MAX_HEIGHT, max(1, int(size["height"])))
        shot = b.call("Page.captureScreenshot", session=True, format="png", captureBeyondViewport=True,
                      clip={"x": 0, "y": 0, "width": WIDTH, "height": h, "scale": 1})
        name = os.path.splitext(os.path.basename(path))[0] + ".png"
        with open(os.path.join(shots, name), "wb") as f:
            f.write(base64.b64decode(shot["data"]))
    return problems, sum(1 for _, _, w in images if w > 0)


def main():
    ap = argparse.ArgumentParser(description="Open pages in headless Chromium; fail on console errors, "
                                             "broken images, pages without a figure.")
    ap.add_argument("--shots", help="save a screenshot of each page into this folder")
    ap.add_argument("--no-figure-ok", action="append", default=[], metavar="NAME",
                    help="a page (file name) that need not show a figure")
    ap.add_argument("pages", nargs="+")
    args = ap.parse_args()
    for p in args.pages:
        if not os.path.isfile(p):
            ap.error("%s: no such page" % p)
    if shutil.which(CHROMIUM) is None:
        print("browser: %s not found (Debian's chromium)" % CHROMIUM, file=sys.stderr)
        return 2
    if args.shots:
        os.makedirs(args.shots, exist_ok=True)
    bad, t_all = 0, time.monotonic()
    b = Browser()
    try:
        for p in args.pages:
            t0 = time.monotonic()
            problems, figures = visit(b, p, args.shots)
            if figures == 0 and os.path.basename(p) not in args.no_figure_ok:
                problems.append("no figure on the page")
            bad += bool(problems)
            print("%-7s %-36s %5.1f s  %d figures" % ("FAILED" if problems else "ok", os.path.basename(p),
                                                      time.monotonic() - t0, figures))
            for q in problems[:10]:
                print("        " + q[:300])
    finally:
        b.close()
    print("browser: %d pages, %d failed, %.1f s" % (len(args.pages), bad, time.monotonic() - t_all))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
