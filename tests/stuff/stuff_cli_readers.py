#!/usr/bin/env python3
"""bccmis stuff's files against outside readers and independent geometry
(spec/stuffing.md S11, S13).

For each case, `bccmis stuff ... --hausdorff --json --check` writes .vtu, .msh,
.mesh, .off and .obj; then:
- meshio reads every tetrahedral file and finds the JSON's vertex and
  tetrahedron counts, one block of tetras, every tetrahedron positively
  oriented, their volumes summing to the JSON's volume, and the same volume
  in all three formats;
- gmsh loads the .msh (gmsh -check);
- the .off and .obj (read by meshio) hold the same triangles; the boundary's
  Euler characteristic V - E + F is the shape's (2 for a sphere or a
  two-sphere union that overlaps, 0 for a torus, -2 for a double torus),
  every edge is used once in each direction (closed and consistently
  oriented), and the volume it encloses (divergence theorem) equals the
  tetrahedra's;
- the JSON's angles lie in Labelle and Shewchuk's interval
  [10.7792, 164.8092] (S10) and the volume is within the stated tolerance of
  the shape's closed-form volume; for the sphere, every boundary vertex is
  on the unit sphere.
A missing meshio or gmsh is a failure.

Usage: stuff_cli_readers.py BCCMIS [CGAL_MESHES_DIR]
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail, need_meshio, six_volume, tetrahedra  # noqa: E402


def check_case(bccmis, d, name, args, euler, exact_volume, tolerance, on_unit_sphere=False):
    import meshio
    stem = os.path.join(d, name)
    outs = {ext: stem + "." + ext for ext in ("vtu", "msh", "mesh", "off", "obj")}
    cmd = [bccmis, "stuff"] + args + ["--hausdorff", "--json", "--check", "--quiet"]
    for path in outs.values():
        cmd += ["-o", path]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        fail("%s: exit %d: %s" % (name, run.returncode, run.stderr))
    stats = json.loads(run.stdout)
    volumes = []
    for ext in ("vtu", "msh", "mesh"):
        m = meshio.read(outs[ext])
        tets = tetrahedra(m, outs[ext])
        if len(tets) != stats["tetrahedra"] or len(m.points) != stats["vertices"]:
            fail("%s.%s: %d points, %d tets; JSON says %d, %d" % (name, ext, len(m.points), len(tets),
                                                                 stats["vertices"], stats["tetrahedra"]))
        total = 0.0
        for t in tets:
            v = six_volume([m.points[i] for i in t])
            if not v > 0:
                fail("%s.%s: tetrahedron %s has volume %g" % (name, ext, list(t), v / 6))
            total += v / 6
        volumes.append(total)
    if max(volumes) - min(volumes) > 1e-9 * abs(volumes[0]):
        fail("%s: the formats disagree on the volume: %s" % (name, volumes))
    if abs(volumes[0] - stats["volume"]) > 1e-9 * abs(volumes[0]):
        fail("%s: meshio's volume %.12g, JSON %.12g" % (name, volumes[0], stats["volume"]))
    gmsh = subprocess.run(["gmsh", "-check", outs["msh"]], capture_output=True, text=True)
    if gmsh.returncode != 0:
        fail("%s: gmsh -check: %s" % (name, gmsh.stdout[-2000:] + gmsh.stderr[-2000:]))
    off = meshio.read(outs["off"])
    obj = meshio.read(outs["obj"])
    tri_off = [list(map(int, t)) for c in off.cells for t in c.data]
    tri_obj = [list(map(int, t)) for c in obj.cells for t in c.data]
    if tri_off != tri_obj or len(tri_off) != stats["boundary_triangles"]:
        fail("%s: .off has %d triangles, .obj %d, JSON %d" % (name, len(tri_off), len(tri_obj),
                                                             stats["boundary_triangles"]))
    edges = {}
    for t in tri_off:
        for i in range(3):
            e = (t[i], t[(i + 1) % 3])
            edges[e] = edges.get(e, 0) + 1
    for (a, b), n in edges.items():
        if n != 1 or edges.get((b, a)) != 1:
            fail("%s: boundary edge %d-%d used %d times, reverse %s" % (name, a, b, n, edges.get((b, a))))
    V, E, F = len(off.points), len(edges) // 2, len(tri_off)
    if V - E + F != euler:
        fail("%s: Euler characteristic %d - %d + %d = %d, expected %d" % (name, V, E, F, V - E + F, euler))
    enclosed = 0.0
    for t in tri_off:
        a, b, c = (off.points[i] for i in t)
        enclosed += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                     + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    if abs(enclosed - volumes[0]) > 1e-9 * abs(volumes[0]):
        fail("%s: the boundary encloses %.12g, the tetrahedra sum to %.12g" % (name, enclosed, volumes[0]))
    if not (10.7792 <= stats["min_dihedral"] and stats["max_dihedral"] <= 164.8092):
        fail("%s: dihedral angles [%g, %g] outside [10.7792, 164.8092]" % (name, stats["min_dihedral"],
                                                                          stats["max_dihedral"]))
    if exact_volume is None:
        exact_volume = stats["shape_volume"]
    if abs(volumes[0] - exact_volume) > tolerance * exact_volume:
        fail("%s: volume %.6g, the shape's %.6g" % (name, volumes[0], exact_volume))
    if on_unit_sphere:
        for p in off.points:
            if abs(math.sqrt(p[0] ** 2 + p[1] ** 2 + p[2] ** 2) - 1) > 1e-9:
                fail("%s: boundary vertex %s is off the unit sphere" % (name, list(p)))
        # S13's Hausdorff distance from the boundary: the largest |1 - |p||
        # over the vertices, edge midpoints and centroid of every boundary
        # triangle, computed here from the .off; the distance from the
        # surface is positive and below the largest boundary edge.
        worst, longest = 0.0, 0.0
        for t in tri_off:
            a, b, c = (list(map(float, off.points[i])) for i in t)
            samples = [a, b, c, [(a[k] + b[k]) / 2 for k in range(3)], [(b[k] + c[k]) / 2 for k in range(3)],
                       [(a[k] + c[k]) / 2 for k in range(3)], [(a[k] + b[k] + c[k]) / 3 for k in range(3)]]
            for q in samples:
                worst = max(worst, abs(1 - math.sqrt(sum(x * x for x in q))))
            for u, v in ((a, b), (b, c), (c, a)):
                longest = max(longest, math.dist(u, v))
        h = stats["hausdorff"]
        if abs(h["from_boundary"] - worst) > 1e-8 * max(worst, 1e-12):  # the JSON has 9 digits
            fail("%s: hausdorff from_boundary %.12g, computed %.12g" % (name, h["from_boundary"], worst))
        if not (0 < h["from_surface"] < longest):
            fail("%s: hausdorff from_surface %g not in (0, %g)" % (name, h["from_surface"], longest))
    print("%s: %d vertices, %d tetrahedra, dihedral [%.3f, %.3f], volume error %.4f, Euler %d" % (
        name, stats["vertices"], stats["tetrahedra"], stats["min_dihedral"], stats["max_dihedral"],
        stats["volume_rel_error"], euler))


def check_animation(bccmis, d):
    """--animate 2 --check: the .pvd indexes frames 0..2, each a .vtu meshio
    reads as tetrahedra; --check has compared every frame's lattice with the
    one built from scratch (spec/stuffing.md S15)."""
    import meshio
    import xml.etree.ElementTree as ET
    pvd = os.path.join(d, "anim", "ball.pvd")
    os.makedirs(os.path.dirname(pvd))
    run = subprocess.run([bccmis, "stuff", "--shape", "sphere:r=0.4", "-L", "2", "--cells", "6", "--animate", "2",
                          "--path", "0.8,0,0", "-o", pvd, "--stats", "--json", "--check", "--quiet"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        fail("animate: exit %d: %s" % (run.returncode, run.stderr))
    stats = json.loads(run.stdout)
    files = [e.get("file") for e in ET.parse(pvd).getroot().iter("DataSet")]
    if files != ["ball_0000.vtu", "ball_0001.vtu", "ball_0002.vtu"]:
        fail("animate: the .pvd lists %s" % files)
    for k, f in enumerate(files):
        m = meshio.read(os.path.join(d, "anim", f))
        if [c.type for c in m.cells] != ["tetra"] or len(m.cells[0].data) != stats["frames"][k]["tetrahedra"]:
            fail("animate: %s has %s cells, the JSON says %d tetrahedra" % (f, [len(c.data) for c in m.cells],
                                                                          stats["frames"][k]["tetrahedra"]))
    if stats["operations"] != sum(f["refines"] + f["coarsens"] for f in stats["frames"]) or stats["operations"] == 0:
        fail("animate: operations %d" % stats["operations"])
    print("animate: %d frames, %d lattice operations" % (len(files), stats["operations"]))


def main():
    if len(sys.argv) not in (2, 3):
        fail("usage: stuff_cli_readers.py BCCMIS [CGAL_MESHES_DIR]")
    need_meshio()
    if shutil.which("gmsh") is None:
        fail("gmsh is not installed (scripts/setup.sh installs it)")
    bccmis = sys.argv[1]
    with tempfile.TemporaryDirectory() as d:
        check_case(bccmis, d, "sphere", ["--shape", "sphere", "-L", "2"], 2, 4 / 3 * math.pi, 0.08, True)
        check_case(bccmis, d, "torus", ["--shape", "torus:R=1,r=0.45", "-L", "2", "--cells", "5"], 0,
                   2 * math.pi ** 2 * 0.45 ** 2, 0.1)
        if len(sys.argv) == 3:
            # CGAL's double torus (genus 2), against the volume the JSON reports of the input.
            path = os.path.join(sys.argv[2], "double-torus-example.off")
            check_case(bccmis, d, "double_torus", [path, "-L", "3"], -2, None, 0.1)
        check_animation(bccmis, d)
        # --impl reference and --impl fast write the same bytes (stuffing.md S11's outputs),
        # on a built-in shape and on a triangle mesh (whose fast path asks for the side only, S5).
        inputs = [("torus", ["--shape", "torus", "-L", "2", "--cells", "6"])]
        if len(sys.argv) == 3:
            inputs.append(("double_torus", [os.path.join(sys.argv[2], "double-torus-example.off"), "-L", "2"]))
        for name, args in inputs:
            outs = {}
            for impl in ("fast", "reference"):
                path = os.path.join(d, "impl_%s_%s.vtu" % (name, impl))
                subprocess.run([bccmis, "stuff"] + args + ["--impl", impl, "-o", path, "--quiet"], check=True)
                with open(path, "rb") as f:
                    outs[impl] = f.read()
            if outs["fast"] != outs["reference"] or len(outs["fast"]) < 1000:
                fail("%s: --impl fast and --impl reference wrote different meshes" % name)
    print("ok")


main()
