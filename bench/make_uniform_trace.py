#!/usr/bin/env python3
"""Writes the uniform refinement trace of a W x H lattice of depth L.

The trace is `lattice W H L`, then every cell refined, level by level, each
level in canonical order (sorted by (x, y), spec/formats.md): W H (4^L - 1) / 3
refines, W H 4^L cells at the end. bench/replay_e2e.sh replays it.

    bench/make_uniform_trace.py 16 16 5 -o uniform16_5.trace
"""
import argparse
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("W", type=int)
    ap.add_argument("H", type=int)
    ap.add_argument("L", type=int)
    ap.add_argument("-o", "--output", default="-", help="output file, - for stdout (default)")
    a = ap.parse_args()
    if a.W < 1 or a.H < 1 or a.L < 0:
        ap.error("W, H >= 1 and L >= 0")
    out = sys.stdout if a.output == "-" else open(a.output, "w", encoding="ascii")
    lines = [f"lattice {a.W} {a.H} {a.L}\n"]
    for level in range(a.L):
        side = 1 << (a.L + 1 - level)  # a level-l cell's side, 2^(L+1-l)
        half = side // 2
        for i in range(a.W << level):
            x = i * side + half
            lines.extend(f"refine {x} {j * side + half}\n" for j in range(a.H << level))
    out.write("".join(lines))
    if out is not sys.stdout:
        out.close()


if __name__ == "__main__":
    main()
