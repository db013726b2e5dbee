#!/usr/bin/env python3
"""Writes the uniform refinement trace of a W x H lattice of depth L, or of a
W x H x D lattice (3D) when four numbers are given.

The trace is `lattice W H L` (`lattice W H D L`), then every cell refined,
level by level, each level in canonical order (sorted by position,
spec/formats.md): W H (4^L - 1) / 3 refines and W H 4^L cells at the end in
2D, W H D (8^L - 1) / 7 refines and W H D 8^L cells in 3D.
bench/replay_e2e.sh replays it.

    bench/make_uniform_trace.py 16 16 5 -o uniform16_5.trace
    bench/make_uniform_trace.py 4 4 4 4 -o uniform3d_4.trace
"""
import argparse
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sizes", type=int, nargs="+", metavar="N", help="W H L (2D) or W H D L (3D)")
    ap.add_argument("-o", "--output", default="-", help="output file, - for stdout (default)")
    a = ap.parse_args()
    if len(a.sizes) not in (3, 4):
        ap.error("give W H L (2D) or W H D L (3D)")
    *extents, L = a.sizes
    if min(extents) < 1 or L < 0:
        ap.error("W, H (and D) >= 1 and L >= 0")
    out = sys.stdout if a.output == "-" else open(a.output, "w", encoding="ascii")
    lines = [f"lattice {' '.join(map(str, a.sizes))}\n"]
    for level in range(L):
        side = 1 << (L + 1 - level)  # a level-l cell's side, 2^(L+1-l)
        half = side // 2
        centers = [[i * side + half for i in range(n << level)] for n in extents]
        if len(extents) == 2:
            lines.extend(f"refine {x} {y}\n" for x in centers[0] for y in centers[1])
        else:
            lines.extend(f"refine {x} {y} {z}\n" for x in centers[0] for y in centers[1] for z in centers[2])
    out.write("".join(lines))
    if out is not sys.stdout:
        out.close()


if __name__ == "__main__":
    main()
