#!/usr/bin/env python3
"""Checks a 3D picture of `bccmis render` (spec/cli.md, render).

  d3/check_svg.py BCCMIS COUNTS RENDER_ARGS...

runs `BCCMIS render RENDER_ARGS... -o -`, parses its standard output as XML
(xml.etree: the SVG must be well-formed, with an <svg> root in the SVG
namespace) and compares the number of elements of each class with COUNTS,
a comma-separated list CLASS=N (tri, green, slice-trace, leaf, center, node,
junction, legend). Exit 0 when every count matches, 1 otherwise.
"""
import collections
import subprocess
import sys
import xml.etree.ElementTree as ET


def main():
    if len(sys.argv) < 4:
        print(__doc__, file=sys.stderr)
        return 2
    bccmis, counts, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    want = {k: int(v) for k, v in (item.split("=") for item in counts.split(","))}
    run = subprocess.run([bccmis, "render", *args, "-o", "-"], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"bccmis render exited {run.returncode}: {run.stderr}")
        return 1
    try:
        root = ET.fromstring(run.stdout)
    except ET.ParseError as e:
        print(f"the SVG is not well-formed XML: {e}")
        return 1
    if root.tag != "{http://www.w3.org/2000/svg}svg":
        print(f"the root element is {root.tag}, not an SVG <svg>")
        return 1
    got = collections.Counter(e.get("class") for e in root.iter() if e.get("class"))
    wrong = [f"{k}: {got.get(k, 0)} (want {n})" for k, n in sorted(want.items()) if got.get(k, 0) != n]
    if wrong:
        print("element counts differ: " + "; ".join(wrong))
        return 1
    print("ok: " + ", ".join(f"{k} {n}" for k, n in sorted(want.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
