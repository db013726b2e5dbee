#!/usr/bin/env python3
"""The mesh writers (spec/mesh3d.md) against outside readers: meshio reads
every .vtu, .msh and .mesh that d3_mesh_write produces, and gmsh loads and
checks the .msh and .mesh files. A missing meshio or gmsh is a failure.

Usage: mesh_readers_test.py PATH/TO/d3_mesh_write
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail, need_meshio, six_volume, tetrahedra  # noqa: E402


def six_volumes(points, tets):
    """Six times each tetrahedron's volume, on the lattice's integer points."""
    return [six_volume([[int(round(float(c))) for c in points[i]] for i in t]) for t in tets]


def main():
    if len(sys.argv) != 2:
        fail("usage: mesh_readers_test.py d3_mesh_write")
    meshio = need_meshio()
    gmsh = shutil.which("gmsh")
    if gmsh is None:
        fail("gmsh is not installed (scripts/setup.sh installs it)")
    # 6 * volume of the box, W*H*D*S^3 (spec/mesh3d.md M10); the split state's
    # counts are spec/mesh3d.md M18.
    expected = {
        "split": {"six_volume": 6 * 2 * 8**3, "points": 65, "tets": 168, "hull": 25},
        "graded": {"six_volume": 6 * 4 * 8**3},
    }
    with tempfile.TemporaryDirectory() as d:
        subprocess.run([sys.argv[1], d], check=True)
        for stem, want in expected.items():
            shapes = set()
            for ext in ("vtu", "msh", "mesh"):
                path = os.path.join(d, stem + "." + ext)
                m = meshio.read(path)
                tets = tetrahedra(m, path).tolist()
                vols = six_volumes(m.points.tolist(), tets)
                if min(vols) <= 0:
                    fail("%s: a tetrahedron is not positively oriented" % path)
                if sum(vols) != want["six_volume"]:
                    fail("%s: 6 * volume sums to %d, not %d" % (path, sum(vols), want["six_volume"]))
                if "points" in want and (len(m.points) != want["points"] or len(tets) != want["tets"]):
                    fail("%s: %d points, %d tetrahedra" % (path, len(m.points), len(tets)))
                if ext == "vtu":
                    kind = m.point_data["kind"].tolist()
                    if "hull" in want and kind.count(2) != want["hull"]:
                        fail("%s: %d hull vertices" % (path, kind.count(2)))
                shapes.add((len(m.points), len(tets)))
                if ext in ("msh", "mesh"):
                    r = subprocess.run([gmsh, "-check", path], capture_output=True, text=True)
                    log = r.stdout + r.stderr
                    if r.returncode != 0 or "Error" in log:
                        fail("gmsh -check %s:\n%s" % (path, log))
                    elements = len(tets) + sum(len(c.data) for c in m.cells if c.type == "triangle")
                    if "%d elements" % elements not in log and ext == "msh":
                        fail("gmsh -check %s does not report %d elements:\n%s" % (path, elements, log))
            if len(shapes) != 1:
                fail("%s: the formats disagree: %s" % (stem, shapes))
            print("%s: %s points and tetrahedra in all three formats" % (stem, shapes.pop()))
    print("ok")


if __name__ == "__main__":
    main()
