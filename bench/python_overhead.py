#!/usr/bin/env python3
"""The Python module's overhead (spec/python.md): one built-in shape meshed
by `bccmis stuff` and by bccmis.stuff(), each timed on its own (best of 3):

- cli: the whole `bccmis stuff --shape SHAPE -L LEVEL -o OUT.off -q`
  process (the boundary written: the CLI needs an output);
- python: bccmis.stuff() from the call to the returned TetMesh (its arrays
  are views of the C++ mesh, nothing is copied);
- phases: the library's lattice and stuffing phases inside that Python
  call, from its progress lines ("N leaves (T s)", "M tetrahedra (T s)");
  the rest of mesh_shape (the boundary, S24's map back, S27's topology)
  reports no line.

Run from a Release build for the figures that count:

  PYTHONPATH=build/release/python python3 bench/python_overhead.py build/release/tools/bccmis/bccmis torus 6
"""
import json
import re
import subprocess
import sys
import tempfile
import time

import bccmis


def best(n, f):
    return min(f() for _ in range(n))


def main(cli, shape, level, repeat=3):
    spec = shape
    level = int(level)

    def cli_run():
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            subprocess.run([cli, "stuff", "--shape", spec, "-L", str(level), "-o", tmp + "/out.off", "-q"],
                           check=True)
            return time.perf_counter() - t0

    cli_wall = best(repeat, cli_run)
    shape_object = bccmis.shapes.builtin(spec)

    def python_run():
        lines = []
        t0 = time.perf_counter()
        mesh = bccmis.stuff(shape_object, max_level=level, progress=lines.append)
        wall = time.perf_counter() - t0
        inside = sum(float(m) for m in re.findall(r"\(([0-9.e+-]+) s\)", "\n".join(lines)))
        python_run.inside = inside
        python_run.tets = len(mesh)
        return wall

    python_wall = best(repeat, python_run)
    inside = python_run.inside
    print(json.dumps({
        "shape": spec, "level": level, "tetrahedra": python_run.tets,
        "cli_seconds": cli_wall, "python_seconds": python_wall, "python_phases_seconds": inside,
        "python_over_cli": python_wall / cli_wall - 1,
    }, indent=1))


if __name__ == "__main__":
    main(*sys.argv[1:])
