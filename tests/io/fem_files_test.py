#!/usr/bin/env python3
"""The FEM files of `bccmis stuff` and `bccmis mesh` (spec/mesh3d.md M20-M23,
spec/cli.md) read by outside readers, on two separate spheres (two
components):
- gmsh reads the .msh, ASCII and binary, and writes it again (gmsh -0):
  its own file lists the physical groups component_1, component_2 (volumes)
  and boundary (surface);
- meshio reads the .msh (ASCII and binary: the same points and cells), the
  .vtu (ASCII and binary: the same points, cells, kind and level), the .mesh
  and the .off/.obj written with --surface-vertices all;
- each component is one sphere: the tetrahedra of component_1 lie at x < 0,
  those of component_2 at x > 0 (the spheres are centred at x = -0.75 and
  0.75, radius 0.5), and so do the boundary triangles by their .mesh
  reference; the boundary has the JSON's boundary_triangles;
- the .off and .obj in the volume numbering hold the .msh's points in its
  order and the .msh's boundary triangles.
A missing meshio or gmsh is a failure.

Usage: fem_files_test.py BCCMIS STATE3D
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail, need_meshio  # noqa: E402

import numpy as np  # noqa: E402


def gmsh_physical_groups(path, d):
    """The $PhysicalNames of the file gmsh writes after reading `path`."""
    again = os.path.join(d, "gmsh-" + os.path.basename(path))
    r = subprocess.run(["gmsh", "-0", path, "-o", again, "-format", "msh4"], capture_output=True, text=True)
    if r.returncode != 0 or "Error" in r.stdout + r.stderr:
        fail("gmsh -0 %s: exit %d\n%s%s" % (path, r.returncode, r.stdout[-2000:], r.stderr[-2000:]))
    text = open(again, encoding="latin-1").read()
    block = re.search(r"\$PhysicalNames\n(\d+)\n(.*?)\$EndPhysicalNames", text, re.S)
    if not block:
        fail("gmsh's %s has no $PhysicalNames" % again)
    return sorted(tuple(line.split()) for line in block.group(2).strip().split("\n"))


def blocks(m, kind):
    return np.concatenate([c.data for c in m.cells if c.type == kind])


def physical(m, kind):
    return np.concatenate([p for c, p in zip(m.cells, m.cell_data["gmsh:physical"]) if c.type == kind])


def check_stuff(meshio, bccmis, d):
    stem = os.path.join(d, "two")
    shape = ["--shape", "spheres:r=0.5,d=1.5", "-L", "3", "--cells", "2", "--quiet"]
    run = subprocess.run([bccmis, "stuff"] + shape + ["--stats", "--json", "-o", stem + ".msh", "-o", stem + ".vtu",
                          "-o", stem + ".mesh", "-o", stem + ".off", "-o", stem + ".obj", "--surface-vertices", "all"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        fail("bccmis stuff: exit %d: %s" % (run.returncode, run.stderr))
    stats = json.loads(run.stdout)
    subprocess.run([bccmis, "stuff"] + shape + ["--binary", "-o", stem + "-b.msh", "-o", stem + "-b.vtu"], check=True)
    subprocess.run([bccmis, "stuff"] + shape + ["--compress", "-o", stem + "-z.vtu", "-o", stem + "-z.msh"], check=True)

    want = [("2", "3", '"boundary"'), ("3", "1", '"component_1"'), ("3", "2", '"component_2"')]
    for path in (stem + ".msh", stem + "-b.msh"):
        got = gmsh_physical_groups(path, d)
        if got != want:
            fail("gmsh lists the physical groups of %s as %s, not %s" % (path, got, want))
    print("gmsh: physical groups %s in the ASCII and the binary .msh" % [w[2] for w in want])

    a, b = meshio.read(stem + ".msh"), meshio.read(stem + "-b.msh")
    for kind in ("tetra", "triangle"):
        if not (np.array_equal(blocks(a, kind), blocks(b, kind)) and np.array_equal(physical(a, kind),
                                                                                   physical(b, kind))):
            fail("the ASCII and binary .msh differ in their %s" % kind)
    if not np.array_equal(a.points, b.points):
        fail("the ASCII and binary .msh differ in their points")
    tets, tet_group = blocks(a, "tetra"), physical(a, "tetra")
    tris, tri_group = blocks(a, "triangle"), physical(a, "triangle")
    if len(tets) != stats["tetrahedra"] or len(tris) != stats["boundary_triangles"]:
        fail(".msh: %d tetrahedra, %d triangles; JSON %d, %d" % (len(tets), len(tris), stats["tetrahedra"],
                                                                  stats["boundary_triangles"]))
    x = a.points[tets].mean(axis=1)[:, 0]
    if set(tet_group[x < 0]) != {1} or set(tet_group[x > 0]) != {2}:
        fail(".msh: the components are not the two spheres")
    if set(tri_group) != {3}:
        fail(".msh: boundary triangles in the physical groups %s" % set(tri_group))

    va = meshio.read(stem + ".vtu")
    for suffix in ("-b", "-z"):
        vb = meshio.read(stem + suffix + ".vtu")
        if not (np.array_equal(va.points, vb.points) and np.array_equal(blocks(va, "tetra"), blocks(vb, "tetra"))
                and np.array_equal(va.point_data["kind"], vb.point_data["kind"])
                and np.array_equal(va.cell_data["level"][0], vb.cell_data["level"][0])):
            fail("the ASCII and %s .vtu differ" % suffix)
        if "format=\"binary\"" not in open(stem + suffix + ".vtu").read() or len(vb.points) != stats["vertices"]:
            fail("the %s .vtu is not binary or has %d points" % (suffix, len(vb.points)))
    # --compress: VTK's zlib compressor, and smaller than the uncompressed binary file.
    z = open(stem + "-z.vtu").read()
    if 'compressor="vtkZLibDataCompressor"' not in z or len(z) * 2 > os.path.getsize(stem + "-b.vtu"):
        fail("the --compress .vtu is not zlib-compressed to under half the binary file")
    if open(stem + "-z.msh", "rb").read() != open(stem + "-b.msh", "rb").read():
        fail("--compress: the .msh is not the binary .msh")
    print(".vtu: ASCII, binary and zlib-compressed read the same (%d points, %d tetrahedra)" % (len(vb.points), len(tets)))

    medit = meshio.read(stem + ".mesh")
    mtris = blocks(medit, "triangle")
    refs = np.concatenate([r for c, r in zip(medit.cells, medit.cell_data["medit:ref"]) if c.type == "triangle"])
    mx = medit.points[mtris].mean(axis=1)[:, 0]
    if len(mtris) != len(tris) or set(refs[mx < 0]) != {1} or set(refs[mx > 0]) != {2}:
        fail(".mesh: %d triangles, references %s" % (len(mtris), sorted(set(refs))))

    key = lambda t: tuple(sorted(map(int, t)))  # noqa: E731
    for ext in ("off", "obj"):
        s = meshio.read(stem + "." + ext)
        if not np.array_equal(s.points, a.points):
            fail(".%s with --surface-vertices all: not the .msh's points in its order" % ext)
        if sorted(map(key, blocks(s, "triangle"))) != sorted(map(key, tris)):
            fail(".%s with --surface-vertices all: not the .msh's boundary triangles" % ext)
    print(".off, .obj: the .msh's numbering; .mesh: triangles referenced by component")


def check_mesh(meshio, bccmis, state, d):
    ascii_msh, binary_msh = os.path.join(d, "face.msh"), os.path.join(d, "face-b.msh")
    subprocess.run([bccmis, "mesh", state, "--quiet", "-o", ascii_msh], check=True)
    subprocess.run([bccmis, "mesh", state, "--quiet", "--binary", "-o", binary_msh], check=True)
    ascii_vtu, zlib_vtu = os.path.join(d, "face.vtu"), os.path.join(d, "face-z.vtu")
    subprocess.run([bccmis, "mesh", state, "--quiet", "-o", ascii_vtu], check=True)
    subprocess.run([bccmis, "mesh", state, "--quiet", "--compress", "-o", zlib_vtu], check=True)
    va, vz = meshio.read(ascii_vtu), meshio.read(zlib_vtu)
    if not (np.array_equal(va.points, vz.points) and np.array_equal(blocks(va, "tetra"), blocks(vz, "tetra"))
            and 'compressor="vtkZLibDataCompressor"' in open(zlib_vtu).read()):
        fail("bccmis mesh --compress: the .vtu differs from the ASCII one or is not compressed")
    a, b = meshio.read(ascii_msh), meshio.read(binary_msh)
    if not (np.array_equal(a.points, b.points) and np.array_equal(blocks(a, "tetra"), blocks(b, "tetra"))
            and np.array_equal(blocks(a, "triangle"), blocks(b, "triangle"))):
        fail("bccmis mesh: the ASCII and binary .msh differ")
    # 168 tetrahedra and 104 boundary triangles (mesh3d.md M18), one component.
    if (len(blocks(b, "tetra")), len(blocks(b, "triangle"))) != (168, 104):
        fail("bccmis mesh --binary: %d tetrahedra, %d triangles" % (len(blocks(b, "tetra")), len(blocks(b, "triangle"))))
    if gmsh_physical_groups(binary_msh, d) != [("2", "2", '"boundary"'), ("3", "1", '"component_1"')]:
        fail("bccmis mesh --binary: gmsh lists %s" % gmsh_physical_groups(binary_msh, d))
    print("bccmis mesh --binary: gmsh and meshio read it as the ASCII file")


def main():
    if len(sys.argv) != 3:
        fail("usage: fem_files_test.py BCCMIS STATE3D")
    meshio = need_meshio()
    with tempfile.TemporaryDirectory() as d:
        check_stuff(meshio, sys.argv[1], d)
        check_mesh(meshio, sys.argv[1], sys.argv[2], d)
    print("ok")


if __name__ == "__main__":
    main()
