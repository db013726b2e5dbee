"""No reference leaks (spec/python.md P4): a loop of 1,000 calls keeps the
resident set flat."""
import numpy as np

import bccmis

# A trace whose lattice has 545 vertices, so that a leaked lattice per call
# would show at once.
TRACE = "lattice 8 8 2\n" + "".join(f"refine {x} {y}\n" for x in range(4, 64, 8) for y in range(4, 64, 8))


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096


def calls(mesh, bad):
    g, log = bccmis.replay(TRACE, impl="fast")
    g.cells(), g.nodes(), g.levels(), g.canonical_state(), g.neighbors((4, 4))
    mesh.points, mesh.tets, mesh.levels, mesh.boundary_faces, mesh.dihedral_angles()
    try:
        bccmis.stuff(bad, np.zeros((1, 3), dtype=np.int32))
    except ValueError:
        pass


def test_rss_stays_flat():
    mesh = bccmis.stuff(bccmis.shapes.torus(), max_level=2, cells=4)
    bad = np.full((3, 3), np.nan)
    for _ in range(100):  # the allocator's pools and numpy's caches fill first
        calls(mesh, bad)
    before = rss_bytes()
    for _ in range(1000):
        calls(mesh, bad)
    # A lattice (545 vertices, about 100 KB) or an angle array (17 KB) leaked
    # per call would add 17 to 100 MB.
    assert rss_bytes() - before < 8 * 2**20
