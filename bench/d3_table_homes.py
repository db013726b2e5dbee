#!/usr/bin/env python3
"""The fast 3D lattice's position table homes (spec/lattice3d.md §9.4): how
crowded linear-probing runs get when a cell's 8 children take their homes in
one block of the table, against homes drawn from one hash of the parent.

Every center of a uniform W x H x D lattice at levels 0..L is a key (the
leaves at level L and the refined centers below), as after refining the
lattice uniformly to level L; the keys are placed with linear probing
(the displacements of a Robin Hood table are the same in total) in 2^bits
slots. Printed: the mean displacement (what a lookup walks) and the mean
distance from a key's home to the next empty slot (what an insert walks).

    /usr/bin/python3 bench/d3_table_homes.py [W H D L bits]   # default 4 4 2 4 18

Numbers: bench/RESULTS.md section 38.
"""
import random
import sys

M64 = (1 << 64) - 1


def rotl(x, r):
    return ((x << r) | (x >> (64 - r))) & M64


def mix(p):  # lattice.cpp's mix()
    x, y, z = p
    h = (x * 0x9E3779B97F4A7C15) & M64
    h = (h + rotl((y * 0xC2B2AE3D27D4EB4F) & M64, 21)) & M64
    h = (h + rotl((z * 0x165667B19E3779F9) & M64, 42)) & M64
    h ^= h >> 30
    h = (h * 0xBF58476D1CE4E5B9) & M64
    h ^= h >> 27
    h = (h * 0x94D049BB133111EB) & M64
    h ^= h >> 31
    return h


def main():
    W, H, D, L, bits = (int(a) for a in sys.argv[1:6]) if len(sys.argv) >= 6 else (4, 4, 2, 4, 18)
    n, shift = 1 << bits, 64 - bits
    mask = n - 1
    S = 1 << (L + 1)

    def keys(child_home):
        out = []
        for l in range(L + 1):
            t, side = L - l, S >> l
            for i in range(W << l):
                for j in range(H << l):
                    for k in range(D << l):
                        p = (i * side + side // 2, j * side + side // 2, k * side + side // 2)
                        if t >= L:
                            out.append(mix(p) >> shift)
                            continue
                        s = 1 << (t + 2)
                        parent = tuple((c & ~(s - 1)) | (s // 2) for c in p)
                        o = sum(1 << a for a in range(3) if p[a] & (s // 2))
                        out.append(child_home(mix(parent), o))
        return out

    def report(name, homes):
        occ = bytearray(n)
        disp = 0
        for h in homes:
            i = h
            while occ[i]:
                i = (i + 1) & mask
            occ[i] = 1
            disp += (i - h) & mask
        walk = 0
        for h in homes:
            i = h
            while occ[i]:
                i = (i + 1) & mask
            walk += (i - h) & mask
        print(f"{name:44s} mean displacement {disp / len(homes):5.2f}   home to empty {walk / len(homes):6.2f}")

    def block(size, stride):
        return lambda h, o: (((h >> shift) & ~(size - 1)) | (((h >> shift) + 1 + stride * o) & (size - 1))) & mask

    def family(h, o):  # position_table.h's family_slot
        return ((((h ^ (o * 0x9E3779B97F4A7C15)) & M64) * 0xD6E8FEB86659FD93) & M64) >> shift

    homes = keys(block(32, 4))
    print(f"{len(homes)} keys in {n} slots: load {len(homes) / n:.3f}")
    report("children in a 32-slot block, stride 4", homes)
    report("children in a 64-slot block, stride 8", keys(block(64, 8)))
    report("children from one hash of the parent (§9.4)", keys(family))
    random.seed(1)
    report("uniform random homes", [random.randrange(n) for _ in homes])


if __name__ == "__main__":
    main()
