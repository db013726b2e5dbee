#!/usr/bin/env python3
"""The viewer in a real browser (ctest label `browser`, tests/viewer/viewer.cmake).

usage: browser_test.py BCCMIS SOURCE_DIR WORKDIR [--chromium PATH]

Opens `bccmis view` pages in headless Chromium and checks the DOM after the
page's scripts ran (the page writes its counts into <body data-...>):
  1. at several steps (#step=K) the drawn cells, nodes and junctions and the
     graph and hull edge counts equal `bccmis stats` of the trace prefix;
  2. #selftest drives the controls (next/prev buttons, arrow keys, slider,
     last/Home) and every state it reaches matches `bccmis stats`;
  3. a state sequence with an invalid state opens at that step with the
     offending vertices marked and the message shown;
  4. a conformance page, and a --from-log page, show both states at the
     first disagreement;
  5. a 1,000-step page on a 2,600-cell lattice steps and jumps in time;
and saves a screenshot. Exits 77 (ctest SKIP_RETURN_CODE) without Chromium.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viewlib  # noqa: E402

SKIP = 77


class Browser:
    def __init__(self, exe, workdir):
        self.exe = exe
        self.profile = tempfile.mkdtemp(prefix="chromium-profile-", dir=workdir)

    def args(self):
        a = [self.exe, "--headless", "--disable-gpu", "--no-first-run", "--disable-extensions",
             "--user-data-dir=" + self.profile, "--virtual-time-budget=3000"]
        if os.geteuid() == 0:
            a.append("--no-sandbox")
        return a

    def dump(self, page, fragment=""):
        url = "file://" + os.path.abspath(page) + fragment
        # Chromium's stderr is noise (D-Bus, GPU); only the DOM on stdout matters.
        p = subprocess.run(self.args() + ["--dump-dom", url], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                           text=True, timeout=120, env=dict(os.environ, HOME=self.profile))
        if p.returncode != 0 or "<body" not in p.stdout:
            raise AssertionError("chromium --dump-dom %s failed (exit %d)" % (url, p.returncode))
        return p.stdout

    def screenshot(self, page, fragment, out, size="1200,800"):
        url = "file://" + os.path.abspath(page) + fragment
        subprocess.run(self.args() + ["--window-size=" + size, "--screenshot=" + out, "--hide-scrollbars", url],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120,
                       env=dict(os.environ, HOME=self.profile))
        with open(out, "rb") as f:
            data = f.read()
        if not data.startswith(b"\x89PNG") or len(data) < 10000:
            raise AssertionError("the screenshot %s is not a plausible PNG (%d bytes)" % (out, len(data)))
        return len(data)


def body(dom):
    m = re.search(r"<body([^>]*)>", dom)
    attrs = dict(re.findall(r'data-([a-z-]+)="([^"]*)"', m.group(1)))
    if attrs.get("ready") != "1":
        raise AssertionError("the page did not finish its script (no data-ready); body: %s" % m.group(1))
    return attrs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bccmis")
    ap.add_argument("source_dir")
    ap.add_argument("workdir")
    ap.add_argument("--chromium")
    a = ap.parse_args()
    exe = a.chromium or os.environ.get("BCCMIS_CHROMIUM") or next(
        (shutil.which(n) for n in ("chromium", "chromium-browser", "google-chrome") if shutil.which(n)), None)
    if not exe:
        print("SKIP: no Chromium found (install Debian's 'chromium', or set BCCMIS_CHROMIUM); the viewer's browser "
              "test did not run")
        return SKIP
    shutil.rmtree(a.workdir, ignore_errors=True)
    os.makedirs(a.workdir)
    browser = Browser(exe, a.workdir)
    here = os.path.dirname(os.path.abspath(__file__))
    failures = []

    def expect(what, got, want):
        ok = got == want
        print("  %-58s %s%s" % (what, "ok" if ok else "FAIL", "" if ok else ": got %r, want %r" % (got, want)))
        if not ok:
            failures.append(what)

    def make_trace(name, *args):
        path = os.path.join(a.workdir, name)
        with open(path, "w") as f:
            f.write(viewlib.run([sys.executable, os.path.join(here, "make_trace.py")] + [str(x) for x in args]).stdout)
        return path

    def view(args, expect_exit=0):
        p = viewlib.run([a.bccmis, "view"] + args)
        if p.returncode != expect_exit:
            raise AssertionError("bccmis view %s exited with %d: %s" % (args, p.returncode, p.stderr))

    def compare(prefix, attrs, st):
        for attr, key in (("cells", "cells"), ("nodes", "nodes"), ("junctions", "junctions"),
                          ("graph-edges", "graph_edges"), ("hull-edges", "hull_edges")):
            expect("%s: %s" % (prefix, attr), int(attrs[attr]), st[key])

    # 1. Steps opened by URL, against bccmis stats of the trace prefix.
    trace = make_trace("random.trace", 10, 10, 3, 150, 3)
    page = os.path.join(a.workdir, "random.html")
    view([trace, "-o", page])
    cli = viewlib.Cli(a.bccmis, trace, a.workdir)
    last = len(cli.commands)
    print("1. %s: steps opened with #step=K" % trace)
    for k in (0, 1, 7, last // 2, last):
        attrs = body(browser.dump(page, "#step=%d" % k))
        expect("#step=%d: data-step" % k, int(attrs["step"]), k)
        compare("#step=%d" % k, attrs, cli.stats(k))
    # 2. The controls, driven by the page's self-test.
    print("2. the controls (#step=3&selftest=4)")
    dom = browser.dump(page, "#step=3&selftest=4")
    log = json.loads(re.search(r'<pre id="selftest-result">(.*?)</pre>', dom, re.S).group(1))
    want = [("start", 3)] + [("next", 3 + i) for i in range(1, 5)] + [
        ("prev", 6), ("ArrowRight", 7), ("ArrowLeft", 6), ("slider", last // 2), ("last", last), ("Home", 0)]
    expect("the controls reach the steps", [(r["action"], r["step"]) for r in log], want)
    stats = {}
    for r in log:
        st = stats.setdefault(r["step"], cli.stats(r["step"]))
        expect("after %s (step %d): cells, nodes, junctions" % (r["action"], r["step"]),
               [r["cells"], r["nodes"], r["junctions"]], [st["cells"], st["nodes"], st["junctions"]])
    # 3. A state sequence with an invalid state opens at it, the vertices marked.
    print("3. --states with an invalid state")
    spage = os.path.join(a.workdir, "states.html")
    view(["--states", os.path.join(here, "states"), "-o", spage], expect_exit=1)
    model = viewlib.extract_model(open(spage, encoding="utf-8").read())
    dom = browser.dump(spage)
    attrs = body(dom)
    expect("opens at the invalid state", int(attrs["step"]), 2)
    expect("violation code", attrs["violation"], "symmetry")
    expect("offending vertices marked", int(attrs["marks"]), len(model["steps"][2]["v"]["where"]) // 2)
    expect("the message is shown", "invariant violated at step 2: symmetry: node (2, 4) lists center (1, 3)" in dom, True)
    attrs = body(browser.dump(spage, "#step=3"))
    expect("a valid step has no marks", (attrs["violation"], attrs["marks"]), ("", "0"))
    # 4. A conformance page: both states side by side at the first disagreement.
    print("4. conformance --view")
    cpage = os.path.join(a.workdir, "conformance.html")
    impl = "sh %s %s" % (os.path.join(a.source_dir, "tests", "conformance", "missing_boundary_junction.sh"), a.bccmis)
    p = viewlib.run([a.bccmis, "conformance", "--impl", impl, "--random", "50", "--seed", "1", "--dim", "2", "--view",
                     cpage])
    expect("conformance exit code", p.returncode, 1)
    model = viewlib.extract_model(open(cpage, encoding="utf-8").read())
    dom = browser.dump(cpage)
    attrs = body(dom)
    expect("opens at the first disagreement", int(attrs["step"]), model["side"]["step"])
    expect("the differing positions are marked", int(attrs["diffmarks"]) > 0, True)
    side_cells = len(re.findall(r'<rect [^>]*class="cell l', dom.split('id="side"', 1)[1]))
    expect("the implementation's panel draws its cells", side_cells, sum(1 for r in model["side"]["state"] if r[2] >= 0))
    expect("the difference is shown", "only in A: node" in dom, True)
    # 4b. --from-log: another implementation's output whose final state is wrong.
    print("4b. view --from-log with a wrong final state")
    lpage = os.path.join(a.workdir, "from_log.html")
    view([os.path.join(a.source_dir, "spec", "examples", "fig2.trace"), "--from-log",
          os.path.join(here, "fig2_wrong_state.out"), "-o", lpage], expect_exit=1)
    model = viewlib.extract_model(open(lpage, encoding="utf-8").read())
    dom = browser.dump(lpage)
    attrs = body(dom)
    expect("opens at the last step", int(attrs["step"]), 4)
    expect("the differing positions are marked", int(attrs["diffmarks"]), len(model["side"]["marks"]) // 2)
    side_dom = dom.split('id="side"', 1)[1]
    expect("the log's state is drawn (cells)", len(re.findall(r'class="cell l', side_dom)), 9)
    expect("its violation is marked", len(re.findall(r'class="violation"', side_dom)), len(model["side"]["v"]["where"]) // 2)
    # 5. A 1,000-step page on a few-thousand-cell lattice.
    print("5. 1,000 steps on a 40 x 40 lattice")
    big = make_trace("big.trace", 40, 40, 3, 1000, 1)
    bpage = os.path.join(a.workdir, "big.html")
    view([big, "-o", bpage, "--check=end"])
    dom = browser.dump(bpage, "#selftest=5")
    log = json.loads(re.search(r'<pre id="selftest-result">(.*?)</pre>', dom, re.S).group(1))
    bcli = viewlib.Cli(a.bccmis, big, a.workdir)
    st = bcli.stats(1000)
    at_last = [r for r in log if r["action"] == "last"][0]
    expect("the last step: cells, nodes", [at_last["cells"], at_last["nodes"]], [st["cells"], st["nodes"]])
    steps_ms = [r["ms"] for r in log if r["action"] in ("next", "prev", "ArrowLeft", "ArrowRight")]
    print("  one step: %.1f-%.1f ms (median %.1f); jump to step 500: %.0f ms, to 1000: %.0f ms, to 0: %.0f ms" % (
        min(steps_ms), max(steps_ms), sorted(steps_ms)[len(steps_ms) // 2],
        [r for r in log if r["action"] == "slider"][0]["ms"], at_last["ms"],
        [r for r in log if r["action"] == "Home"][0]["ms"]))
    expect("a single step takes under 200 ms (median)", sorted(steps_ms)[len(steps_ms) // 2] < 200, True)
    # The screenshot.
    shot = os.path.join(a.workdir, "screenshot.png")
    n = browser.screenshot(page, "#step=7", shot)
    print("screenshot: %s (%d bytes)" % (shot, n))
    if failures:
        print("FAILED: %d checks" % len(failures))
        return 1
    print("all browser checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
