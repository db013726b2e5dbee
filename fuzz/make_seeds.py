#!/usr/bin/env python3
"""Writes the hand-made seeds of fuzz/corpus/fuzz_refine_coarsen/ and
fuzz/corpus/fuzz_refine_coarsen_3d/.

The input formats are described at the top of refine_coarsen_fuzzer.cpp
(three bytes W-1, H-1, L, then (selector, operand...) groups) and
refine_coarsen_3d_fuzzer.cpp (four bytes W-1, H-1, D-1, L; a raw position
has three coordinate bytes). Run from anywhere:
    python3 fuzz/make_seeds.py
"""
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "corpus", "fuzz_refine_coarsen")
OUT3 = os.path.join(HERE, "corpus", "fuzz_refine_coarsen_3d")
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


def lattice3(w, h, d, l):
    return bytes([w - 1, h - 1, d - 1, l])


def seeds3():
    rng = random.Random(20090102)
    s = {}
    # The root cube refined to the bottom, always at the first live center.
    s["corner_cascade_1x1x1_L4"] = lattice3(1, 1, 1, 4) + bytes([REFINE, 0] * 10)
    # spec/lattice3d.md §7: two cubes sharing a face; refine the left one,
    # try the child at the shared face (coarser-neighbor), coarsen back.
    s["face_2x1x1_L2"] = lattice3(2, 1, 1, 2) + bytes(
        [REFINE, 0, RAW_REFINE, 7, 3, 3, COARSEN_REFINED, 0, REFINE, 1, REFINE, 3, COARSEN_REFINED, 1])
    # Refinements spread by index over a 3x3x3 lattice.
    s["spread_3x3x3_L2"] = lattice3(3, 3, 3, 2) + bytes(b for k in range(24) for b in (REFINE, (k * 37) % 256))
    # Refine and coarsen interleaved.
    s["mixed_2x2x2_L3"] = lattice3(2, 2, 2, 3) + bytes(
        b for k in range(45) for b in ((REFINE, (k * 11) % 256) if k % 3 else (COARSEN_REFINED, k)))
    # Every applied operation is inverted at once.
    s["inverted_2x1x2_L3"] = lattice3(2, 1, 2, 3) + bytes(
        b for k in range(24) for b in (REFINE | (INVERT if k % 2 else 0), (k * 5) % 256))
    s["inverted_coarsen_1x2x1_L3"] = lattice3(1, 2, 1, 3) + bytes([REFINE, 4] * 8) + bytes(
        [COARSEN_REFINED | INVERT, 0, COARSEN_REFINED | INVERT, 1, COARSEN_REFINED | INVERT, 2])
    # Raw positions: centers, nodes, points outside, INT64_MAX/INT64_MIN.
    s["raw_positions_2x2x1_L2"] = lattice3(2, 2, 1, 2) + bytes(
        [RAW_REFINE, 5, 5, 5, RAW_REFINE, 0xff, 0xfe, 0xff, RAW_COARSEN, 9, 9, 5, RAW_COARSEN, 1, 1, 1,
         RAW_REFINE, 1, 5, 0xfe, RAW_COARSEN, 5, 5, 5, RAW_REFINE, 3, 3, 3, RAW_COARSEN, 0xfe, 0xff, 0xfe,
         COARSEN_ANY, 3, COARSEN_ANY, 7])
    # Long random programs on the largest lattices.
    s["random_3x3x3_L4"] = lattice3(3, 3, 3, 4) + bytes(rng.randrange(256) for _ in range(200))
    s["random_2x3x1_L3"] = lattice3(2, 3, 1, 3) + bytes(rng.randrange(256) for _ in range(200))
    # Level 0 only: every refine is refused (max-level).
    s["max_level_0_3x1x2"] = lattice3(3, 1, 2, 0) + bytes(
        [REFINE, 0, REFINE, 1, COARSEN_ANY, 2, RAW_REFINE, 4, 4, 4])
    return s


def write(out, corpus):
    os.makedirs(out, exist_ok=True)
    for name, data in corpus.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)


def main():
    write(OUT, seeds())
    write(OUT3, seeds3())


if __name__ == "__main__":
    main()
