#!/usr/bin/env python3
"""Non-browser checks of a `bccmis view` page (tests/viewer/viewer.cmake).

usage: check_model.py BCCMIS TRACE WORKDIR [--budget BYTES] [--check MODE]

Writes the page for TRACE, then checks the model it embeds (spec/viewer.md):
one step per trace command, labelled with it; the decisions equal the
decision log of `bccmis replay`; the counts of every step equal those of
the state rebuilt from the deltas; at sampled steps (every step of a short
trace) the rebuilt state is byte-identical to `bccmis replay` of the trace
prefix and the counts equal `bccmis stats`; the page loads nothing from
elsewhere (no src, href, link, import, url(), fetch). With --budget, the
page must not be larger than BYTES.
"""
import argparse
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import viewlib  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bccmis")
    ap.add_argument("trace")
    ap.add_argument("workdir")
    ap.add_argument("--budget", type=int)
    ap.add_argument("--check", default="every")
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    page = os.path.join(a.workdir, "view.html")
    t0 = time.monotonic()
    p = viewlib.run([a.bccmis, "view", a.trace, "-o", page, "--check=" + a.check])
    seconds = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit("bccmis view exited with %d: %s" % (p.returncode, p.stderr))
    html = open(page, encoding="utf-8").read()
    model = viewlib.extract_model(html)
    cli = viewlib.Cli(a.bccmis, a.trace, a.workdir)
    steps = model["steps"]
    errors = []
    if model["format"] != "bccmis-view 1":
        errors.append("format is %r" % model["format"])
    if len(steps) != len(cli.commands) + 1:
        errors.append("%d steps for %d commands" % (len(steps), len(cli.commands)))
    for k, cmd in enumerate(cli.commands, 1):
        if k < len(steps) and steps[k]["label"] != cmd:
            errors.append("step %d is labelled %r, the command is %r" % (k, steps[k]["label"], cmd))
    decisions = [s["label"] + " " + s["decision"] for s in steps if "decision" in s]
    if decisions != cli.decisions():
        errors.append("the decisions differ from the decision log of bccmis replay")
    # Every step: the counts the model states equal those of the rebuilt state.
    state = {(r[0], r[1]): r for r in model["init"]}
    samples = set(viewlib.sample_steps(len(steps) - 1))
    rebuilt = {}
    for k in range(len(steps)):
        if k:
            viewlib.rebuild(model, k, state, start=k - 1)
        cells = sum(1 for r in state.values() if r[2] >= 0)
        if steps[k]["n"] != [cells, len(state) - cells]:
            errors.append("step %d: the model says %s cells, nodes; its deltas give %s" % (k, steps[k]["n"], [cells, len(state) - cells]))
        if k in samples:
            rebuilt[k] = viewlib.canonical(model, state)
    # Sampled steps: the CLI's state and stats of the trace prefix.
    for k in sorted(samples):
        want = cli.state(k)
        if rebuilt[k] != want:
            errors.append("step %d: the state rebuilt from the deltas differs from bccmis replay of the prefix" % k)
        st = cli.stats(k)
        if steps[k]["n"] != [st["cells"], st["nodes"]]:
            errors.append("step %d: model counts %s, bccmis stats %s" % (k, steps[k]["n"], [st["cells"], st["nodes"]]))
    # Self-contained: nothing is loaded from elsewhere.
    for pattern in (r"<script[^>]*\bsrc=", r"<link\b", r"@import", r"url\(", r"\bhref=", r"\bfetch\(", r"XMLHttpRequest",
                    r"<img\b", r"<iframe\b"):
        if re.search(pattern, html):
            errors.append("the page is not self-contained: it matches %r" % pattern)
    size = len(html.encode("utf-8"))
    print("%s: %d steps, final %d cells and %d nodes, page %d bytes (%.0f bytes per step), written in %.2f s; "
          "%d steps compared with bccmis replay and stats" %
          (a.trace, len(steps) - 1, steps[-1]["n"][0], steps[-1]["n"][1], size, size / max(1, len(steps) - 1),
           seconds, len(samples)))
    if a.budget is not None and size > a.budget:
        errors.append("the page has %d bytes, above the budget of %d" % (size, a.budget))
    if errors:
        print("FAIL:\n  " + "\n  ".join(errors[:20]))
        sys.exit(1)


if __name__ == "__main__":
    main()
