#!/usr/bin/env python3
"""Writes the hand-made seeds of fuzz/corpus/fuzz_refine_coarsen/.

The input format is described at the top of refine_coarsen_fuzzer.cpp:
three bytes W-1, H-1, L, then (selector, operand...) groups. Run from fuzz/:
    python3 make_seeds.py
"""
import os
import random

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "fuzz_refine_coarsen")
REFINE, COARSEN_REFINED, COARSEN_ANY, RAW_REFINE, RAW_COARSEN, INVERT = 0, 3, 5, 6, 7, 0x80


def lattice(w, h, l):
    return bytes([w - 1, h - 1, l])


def seeds():
    rng = random.Random(20090101)
    s = {}
    # Always refine the first (lowest x, then y) live center: a deep cascade
    # into the corner of a 1x1 lattice, then undo it at the end.
    s["corner_cascade_1x1_L4"] = lattice(1, 1, 4) + bytes([REFINE, 0] * 12)
    # Uniform refinement of a 3x3 lattice, picking centers spread by index.
    s["spread_3x3_L3"] = lattice(3, 3, 3) + bytes(b for k in range(40) for b in (REFINE, (k * 37) % 256))
    # Refine then coarsen refined centers, interleaved.
    s["mixed_3x3_L2"] = lattice(3, 3, 2) + bytes(
        b for k in range(60) for b in ((REFINE, (k * 11) % 256) if k % 3 else (COARSEN_REFINED, k)))
    # Every applied operation is inverted at once.
    s["inverted_2x3_L3"] = lattice(2, 3, 3) + bytes(
        b for k in range(30) for b in (REFINE | (INVERT if k % 2 else 0), (k * 5) % 256))
    s["inverted_coarsen_3x2_L3"] = lattice(3, 2, 3) + bytes([REFINE, 4] * 10) + bytes(
        [COARSEN_REFINED | INVERT, 0, COARSEN_REFINED | INVERT, 1, COARSEN_REFINED | INVERT, 2])
    # Raw positions, including INT64_MAX/INT64_MIN (0xff/0xfe) and points
    # just outside the domain.
    s["raw_positions_2x2_L2"] = lattice(2, 2, 2) + bytes(
        [RAW_REFINE, 4, 4, RAW_REFINE, 0xff, 0xfe, RAW_COARSEN, 8, 8, RAW_COARSEN, 0, 0,
         RAW_REFINE, 0, 4, RAW_COARSEN, 4, 4, RAW_REFINE, 2, 2, RAW_COARSEN, 0xfe, 0xff,
         COARSEN_ANY, 3, COARSEN_ANY, 7])
    # A long random program on the largest lattice.
    s["random_3x3_L4"] = lattice(3, 3, 4) + bytes(rng.randrange(256) for _ in range(200))
    # Level 0 only: every refine is refused (max-level).
    s["max_level_0_3x1"] = lattice(3, 1, 0) + bytes([REFINE, 0, REFINE, 1, COARSEN_ANY, 2, RAW_REFINE, 4, 4])
    return s


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, data in seeds().items():
        with open(os.path.join(OUT, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
