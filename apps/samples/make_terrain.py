#!/usr/bin/env python3
"""Writes the procedural sample height fields of apps/samples (deterministic).

    make_terrain.py terrain --size 128 --bits 16 -o terrain128.pgm   (P5, 16-bit)
    make_terrain.py crater  --size 64  --bits 8 --plain -o crater64.pgm (P2, 8-bit)

terrain: five octaves of value noise (a hashed integer lattice, smoothstep
         interpolation) plus a diagonal ridge: hills, valleys and one sharp crest.
crater:  a rim around a flat floor, a central peak, on a gentle slope.
The values are normalized to [0, maxval]. No randomness beyond a fixed hash,
so the files are reproducible: `--check FILE` compares (tests/apps/apps.cmake runs it
for terrain128.pgm, which uses only + - * / and floor; crater uses exp and
hypot, whose last bit may differ between C libraries).
"""
import argparse
import math
import sys


def hash01(ix, iy, seed):
    """A value in [0, 1) from integer coordinates: a 32-bit integer hash."""
    h = (ix * 374761393 + iy * 668265263 + seed * 2246822519) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    h ^= h >> 16
    return h / 4294967296.0


def value_noise(x, y, seed):
    ix, iy = math.floor(x), math.floor(y)
    fx, fy = x - ix, y - iy
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    a, b = hash01(ix, iy, seed), hash01(ix + 1, iy, seed)
    c, d = hash01(ix, iy + 1, seed), hash01(ix + 1, iy + 1, seed)
    return (a + (b - a) * sx) * (1 - sy) + (c + (d - c) * sx) * sy


def terrain(u, v):
    z, amp, freq = 0.0, 1.0, 3.0
    for octave in range(5):
        z += amp * value_noise(u * freq, v * freq, 17 + octave)
        amp *= 0.5
        freq *= 2.0
    ridge = max(0.0, 1.0 - abs(u - 0.8 * v - 0.1) / 0.08)
    return z + 0.6 * ridge


def crater(u, v):
    r = math.hypot(u - 0.55, v - 0.45)
    rim = math.exp(-((r - 0.28) / 0.05) ** 2)
    bowl = -0.5 if r < 0.28 else -0.5 * math.exp(-((r - 0.28) / 0.03) ** 2)
    peak = 0.6 * math.exp(-(r / 0.05) ** 2)
    return 0.3 * u + 0.2 * v + rim + bowl + peak


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["terrain", "crater"])
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--bits", type=int, choices=[8, 16], default=16)
    ap.add_argument("--plain", action="store_true", help="P2 (ASCII) instead of P5")
    ap.add_argument("-o", "--output", help="output file, - for stdout")
    ap.add_argument("--check", metavar="FILE", help="compare with FILE instead of writing (exit 1 if different)")
    args = ap.parse_args()
    n = args.size
    f = terrain if args.kind == "terrain" else crater
    z = [[f(col / (n - 1), row / (n - 1)) for col in range(n)] for row in range(n)]
    lo = min(min(r) for r in z)
    hi = max(max(r) for r in z)
    maxval = 255 if args.bits == 8 else 65535
    q = [[round((x - lo) / (hi - lo) * maxval) for x in r] for r in z]
    header = f"{'P2' if args.plain else 'P5'}\n# bccmis sample: make_terrain.py {args.kind} --size {n} --bits {args.bits}\n{n} {n}\n{maxval}\n"
    data = bytearray(header.encode("ascii"))
    for r in q:
        if args.plain:
            data += (" ".join(str(x) for x in r) + "\n").encode("ascii")
        else:
            for x in r:
                data += bytes([x >> 8, x & 0xFF]) if maxval > 255 else bytes([x])
    if args.check:
        with open(args.check, "rb") as f:
            same = f.read() == bytes(data)
        print(f"{args.check}: {'reproduced' if same else 'DIFFERS from the generator output'}")
        sys.exit(0 if same else 1)
    if not args.output:
        ap.error("give -o FILE or --check FILE")
    if args.output == "-":
        sys.stdout.buffer.write(data)
    else:
        with open(args.output, "wb") as out:
            out.write(data)


if __name__ == "__main__":
    main()
