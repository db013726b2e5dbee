#!/usr/bin/env python3
"""spec/stuffing.md S28: the mesh is the same bit for bit on any number of
threads.

`bccmis stuff --shape torus -L 3` (13,208 leaves: four blocks of 4,096, so
rounds of two and three blocks run at once) and `--shape sphere -L 3` (20,336
leaves; blocks whose first leaves lie inside the shape, so that a block's
first vertex misnumbered (S28b) changes the mesh) write a binary .vtu and
.msh with --threads 1, 2 and 3; every file must equal the --threads 1 one
byte for byte. (The reference stuffer's mesh is held equal to the flat one's by
tests/stuff/stuffing_fast_test.cpp and bench-smoke.stuff; at this size its
Debug run takes 20 s.)

Usage: stuff_threads.py BCCMIS
"""
import filecmp
import json
import os
import subprocess
import sys
import tempfile


def main():
    bccmis = sys.argv[1]
    for shape in (["--shape", "torus", "-L", "3"], ["--shape", "sphere", "-L", "3"]):
        check(bccmis, shape)


def check(bccmis, shape):
    with tempfile.TemporaryDirectory() as d:
        runs = {"threads1": ["--threads", "1"], "threads2": ["--threads", "2"], "threads3": ["--threads", "3"]}
        for name, extra in runs.items():
            cmd = [bccmis, "stuff"] + shape + extra + ["--binary", "--json", "-q",
                                                      "-o", os.path.join(d, name + ".vtu"),
                                                      "-o", os.path.join(d, name + ".msh")]
            run = subprocess.run(cmd, capture_output=True, text=True)
            if run.returncode != 0:
                sys.exit("%s: exit %d: %s" % (" ".join(cmd), run.returncode, run.stderr))
            leaves = json.loads(run.stdout)["leaves"]
            if leaves <= 3 * 4096:
                sys.exit("%s: %d leaves, too few for three blocks of 4,096" % (name, leaves))
        for name in runs:
            for ext in ("vtu", "msh"):
                a, b = os.path.join(d, "threads1." + ext), os.path.join(d, name + "." + ext)
                if not filecmp.cmp(a, b, shallow=False):
                    sys.exit("%s %s.%s differs from threads1.%s" % (" ".join(shape), name, ext, ext))
    print("%s: the same .vtu and .msh on 1, 2 and 3 threads" % " ".join(shape))

if __name__ == "__main__":
    main()
