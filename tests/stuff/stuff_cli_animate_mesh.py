#!/usr/bin/env python3
"""bccmis stuff MESH --animate: a triangle mesh moved rigidly through the
lattice (spec/stuffing.md S14, S15), checked from outside.

`bccmis stuff MESH --animate N --path DX,DY,DZ --check` writes a .pvd and
its frames; then:
- the .pvd lists the N + 1 frames STEM_0000.vtu .. in order, timesteps
  0 .. N, and every file exists beside it;
- meshio reads every frame as one block of tetrahedra, as many as the JSON
  reports for that frame, every one positively oriented, their volume within
  5% of the input's (a rigid motion keeps it);
- frame k is the input moved by (k / N) d: every point lies in the input's
  bounding box moved by (k / N) d, and on every side the points reach that
  box within h, the finest cell side (S2, fitted to the swept box, S14).
  A frame at another offset along an axis whose step |d_i| / N exceeds h
  fails one of the two.
--check has compared every frame's lattice with the one built from scratch.

Usage: stuff_cli_animate_mesh.py BCCMIS MESH
"""
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail, need_meshio, six_volume  # noqa: E402

FRAMES = 3
PATH = (1.5, -0.9, 0.9)
LEVEL = 3
CELLS = 3


def main():
    if len(sys.argv) != 3:
        fail("usage: stuff_cli_animate_mesh.py BCCMIS MESH")
    meshio = need_meshio()
    bccmis, mesh = sys.argv[1], sys.argv[2]

    surface = meshio.read(mesh)
    triangles = [t for c in surface.cells if c.type == "triangle" for t in c.data]
    lo = [min(p[i] for p in surface.points) for i in range(3)]
    hi = [max(p[i] for p in surface.points) for i in range(3)]
    volume = 0.0
    for t in triangles:
        a, b, c = (surface.points[i] for i in t)
        volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                   + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    volume = abs(volume)
    # S14: the lattice is fitted to the box swept from offset 0 to d; S2: its
    # longest side E gives h = E / (N 2^L - 10).
    swept = max(hi[i] - lo[i] + abs(PATH[i]) for i in range(3))
    h = swept / (CELLS * 2 ** LEVEL - 10)
    if not all(abs(PATH[i]) / FRAMES > h for i in range(3)):
        fail("the path's steps %s do not exceed h = %g: the offsets would not be told apart"
             % ([abs(x) / FRAMES for x in PATH], h))

    with tempfile.TemporaryDirectory() as d:
        pvd = os.path.join(d, "moving.pvd")
        run = subprocess.run([bccmis, "stuff", mesh, "-L", str(LEVEL), "--cells", str(CELLS),
                              "--animate", str(FRAMES), "--path", ",".join(map(str, PATH)), "-o", pvd,
                              "--stats", "--json", "--check", "--quiet"], capture_output=True, text=True)
        if run.returncode != 0:
            fail("exit %d: %s" % (run.returncode, run.stderr))
        stats = json.loads(run.stdout)
        if len(stats["frames"]) != FRAMES + 1:
            fail("the JSON has %d frames, expected %d" % (len(stats["frames"]), FRAMES + 1))
        datasets = list(ET.parse(pvd).getroot().iter("DataSet"))
        files = [e.get("file") for e in datasets]
        expected = ["moving_%04d.vtu" % k for k in range(FRAMES + 1)]
        if files != expected:
            fail("the .pvd lists %s, expected %s" % (files, expected))
        if [e.get("timestep") for e in datasets] != [str(k) for k in range(FRAMES + 1)]:
            fail("the .pvd's timesteps are %s" % [e.get("timestep") for e in datasets])
        for k, f in enumerate(files):
            path = os.path.join(d, f)
            if not os.path.isfile(path):
                fail("%s: listed in the .pvd, not written" % f)
            m = meshio.read(path)
            if [c.type for c in m.cells] != ["tetra"]:
                fail("%s: cell blocks %s" % (f, [c.type for c in m.cells]))
            tets = m.cells[0].data
            if len(tets) != stats["frames"][k]["tetrahedra"]:
                fail("%s: %d tetrahedra, the JSON says %d" % (f, len(tets), stats["frames"][k]["tetrahedra"]))
            total = 0.0
            for t in tets:
                v = six_volume([m.points[i] for i in t])
                if not v > 0:
                    fail("%s: tetrahedron %s has volume %g" % (f, list(t), v / 6))
                total += v / 6
            if abs(total - volume) > 0.05 * volume:
                fail("%s: volume %.6g, the input's %.6g" % (f, total, volume))
            offset = [k * PATH[i] / FRAMES for i in range(3)]
            for i in range(3):
                want_lo, want_hi = lo[i] + offset[i], hi[i] + offset[i]
                got_lo = min(p[i] for p in m.points)
                got_hi = max(p[i] for p in m.points)
                slack = 1e-9 * (1 + abs(want_lo) + abs(want_hi))
                if not (want_lo - slack <= got_lo <= want_lo + h and want_hi - h <= got_hi <= want_hi + slack):
                    fail("%s: axis %s spans [%.9g, %.9g], the input moved by %.9g spans [%.9g, %.9g] (h = %g)"
                         % (f, "xyz"[i], got_lo, got_hi, offset[i], want_lo, want_hi, h))
            print("%s: %d tetrahedra, volume %.6g, box [%s] .. [%s]" % (
                f, len(tets), total, ", ".join("%.4g" % min(p[i] for p in m.points) for i in range(3)),
                ", ".join("%.4g" % max(p[i] for p in m.points) for i in range(3))))
    print("ok: %d frames, h = %g, %d lattice operations" % (FRAMES + 1, h, stats["operations"]))


main()
