#!/usr/bin/env python3
"""bccmis mesh's files against outside readers: meshio reads the .vtu, .msh
and .mesh that `bccmis mesh STATE -o ...` writes for
spec/examples/d3/face_refined.state and finds the hand counts of
spec/mesh3d.md M18 (65 vertices, 168 tetrahedra, 25 hull vertices), the
vertex kinds and cell levels of M20/M22, positive volumes summing to
6 * W*H*D*S^3 = 6 * 2 * 8^3 (M10); gmsh loads the .msh. A missing meshio or
gmsh is a failure.

Usage: mesh_cli_readers.py BCCMIS face_refined.state
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail, need_meshio, six_volume, tetrahedra  # noqa: E402


def main():
    if len(sys.argv) != 3:
        fail("usage: mesh_cli_readers.py BCCMIS STATE")
    meshio = need_meshio()
    if shutil.which("gmsh") is None:
        fail("gmsh is not installed (scripts/setup.sh installs it)")
    with tempfile.TemporaryDirectory() as d:
        outs = [os.path.join(d, "face." + ext) for ext in ("vtu", "msh", "mesh")]
        args = [sys.argv[1], "mesh", sys.argv[2], "--quiet"]
        for o in outs:
            args += ["-o", o]
        subprocess.run(args, check=True)
        for path in outs:
            m = meshio.read(path)
            tets = tetrahedra(m, path).tolist()
            points = [[int(round(float(x))) for x in p] for p in m.points.tolist()]
            if len(points) != 65 or len(tets) != 168:
                fail("%s: %d points, %d tetrahedra (expected 65, 168)" % (path, len(points), len(tets)))
            vols = [six_volume([points[i] for i in t]) for t in tets]
            if min(vols) <= 0 or sum(vols) != 6 * 2 * 8 ** 3:
                fail("%s: six-volumes min %d sum %d (expected > 0, %d)" % (path, min(vols), sum(vols), 6 * 2 * 8 ** 3))
            if path.endswith(".vtu"):
                kinds = [int(k) for k in m.point_data["kind"]]
                levels = sorted(set(int(l) for l in m.cell_data["level"][0]))
                if kinds.count(2) != 25 or kinds.count(1) != 9 or kinds.count(0) != 31:
                    fail("%s: kinds %s (expected 31 nodes, 9 centers, 25 hull vertices)" % (path, kinds))
                if levels != [0, 1]:
                    fail("%s: levels %s (expected 0 and 1)" % (path, levels))
            if path.endswith(".mesh"):
                refs = sorted(set(int(l) for l in m.cell_data["medit:ref"][0]))
                if refs != [0, 1]:
                    fail("%s: tetrahedron references %s (expected the levels 0 and 1)" % (path, refs))
        r = subprocess.run(["gmsh", "-check", outs[1]], capture_output=True, text=True)
        # 168 tetrahedra and 104 boundary triangles (mesh3d.md M18, M21)
        if r.returncode != 0 or "272 elements" not in r.stdout + r.stderr:
            fail("gmsh -check %s: exit %d\n%s%s" % (outs[1], r.returncode, r.stdout, r.stderr))
    print("ok: meshio read .vtu, .msh and .mesh; gmsh checked the .msh")


main()
