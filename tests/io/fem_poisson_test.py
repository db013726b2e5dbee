#!/usr/bin/env python3
"""A use of the .msh as an FEM code uses it (spec/mesh3d.md M21): P1 finite
elements for -laplace(u) = f on the stuffed unit sphere, with the exact
solution u = 1 + x + 2 y - 3 z (f = 0, reproduced exactly) and
u = 1 - |x|^2 + x y + z / 2 (f = 6) as Dirichlet data on the physical
surface "boundary", assembled in numpy from what meshio reads (ASCII and
binary files), solved by conjugate gradients and compared with u at the
nodes.

What would break it: node or element tags off by one (the assembled
operator is garbage: the error is of order 1), tetrahedra not positively
oriented (the stiffness uses the signed volume: it would not be positive
definite), a boundary group that misses nodes (a Neumann condition there:
the error grows) or holds interior nodes (checked directly: the group's
nodes are exactly those on the unit sphere), triangles facing inward (the
divergence theorem over the group gives -3 V instead of 3 V).

Usage: fem_poisson_test.py BCCMIS
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "pylib"))
from meshcheck import fail, need_meshio  # noqa: E402

import numpy as np  # noqa: E402

# P1 elements reproduce a linear u: what is left is the solver's and the
# coordinates' rounding (measured 5e-13 at -L 3 --cells 2).
MAX_LINEAR_ERROR = 1e-9
# The quadratic u's nodal error at -L 3 --cells 2 is 8.9e-3 (the coarse
# interior dominates: it is graded coarser than the surface band); the bound
# leaves a third of it as margin. A wrong numbering or group gives errors of
# order 0.1-1.
MAX_QUADRATIC_ERROR = 1.2e-2


def quadratic(p):
    """-laplace = 6."""
    return 1 - (p ** 2).sum(axis=1) + p[:, 0] * p[:, 1] + 0.5 * p[:, 2]


def linear(p):
    """-laplace = 0; P1 elements reproduce it exactly."""
    return 1 + p[:, 0] + 2 * p[:, 1] - 3 * p[:, 2]


def groups(m, path):
    """The tetrahedra (every volume group) and the boundary group's triangles."""
    names = {name: (int(tag), int(dim)) for name, (tag, dim) in m.field_data.items()}
    components = sorted(n for n in names if n.startswith("component_"))
    if "boundary" not in names or names["boundary"][1] != 2 or not components:
        fail("%s: physical groups %s" % (path, names))
    tets, tris = [], []
    for block, physical in zip(m.cells, m.cell_data["gmsh:physical"]):
        tags = set(int(t) for t in physical)
        if block.type == "tetra" and tags <= {names[c][0] for c in components}:
            tets.append(block.data)
        elif block.type == "triangle" and tags == {names["boundary"][0]}:
            tris.append(block.data)
        else:
            fail("%s: a block of %s in the physical groups %s" % (path, block.type, tags))
    return np.concatenate(tets), np.concatenate(tris)


def solve(path, exact, f, max_error):
    import meshio
    m = meshio.read(path)
    p = m.points
    tets, tris = groups(m, path)

    # The boundary group: outward (divergence theorem: the flux of x is 3 V)
    # and exactly the nodes on the unit sphere.
    a, b, c = p[tris[:, 0]], p[tris[:, 1]], p[tris[:, 2]]
    flux = (((a + b + c) / 3) * np.cross(b - a, c - a) / 2).sum()
    e = p[tets]
    d = np.stack([e[:, 1] - e[:, 0], e[:, 2] - e[:, 0], e[:, 3] - e[:, 0]], axis=1)  # rows: edges from v0
    det = np.linalg.det(d)
    volume = det.sum() / 6
    if det.min() <= 0:
        fail("%s: a tetrahedron is not positively oriented (det %g)" % (path, det.min()))
    if abs(flux - 3 * volume) > 1e-9 * volume:
        fail("%s: the boundary's flux of x is %.12g, 3 V = %.12g (inward or incomplete)" % (path, flux, 3 * volume))
    on_boundary = np.zeros(len(p), dtype=bool)
    on_boundary[tris.ravel()] = True
    radius = np.linalg.norm(p, axis=1)
    if abs(radius[on_boundary] - 1).max() > 1e-9:
        fail("%s: a node of the boundary group is off the sphere (|x| - 1 = %g)" %
             (path, abs(radius[on_boundary] - 1).max()))
    if radius[~on_boundary].max() > 1 - 1e-9:
        fail("%s: a node on the sphere is not in the boundary group" % path)

    # P1 stiffness: the gradients of the barycentric functions are the rows
    # of [-1 -1 -1; I] inv(D)^T... written as G = [-(sum); inv(D)] per tet.
    inv = np.linalg.inv(d)  # inv(D): columns are the gradients of lambda_1..3
    grads = np.concatenate([-inv.sum(axis=2, keepdims=True), inv], axis=2)  # (m, 3, 4)
    local = np.einsum("tki,tkj->tij", grads, grads) * (det / 6)[:, None, None]
    rows = np.repeat(tets, 4, axis=1).ravel()
    cols = np.tile(tets, (1, 4)).ravel()
    vals = local.ravel()
    load = np.zeros(len(p))
    np.add.at(load, tets.ravel(), np.repeat(f * det / 24, 4))

    u = np.where(on_boundary, exact(p), 0.0)
    free = ~on_boundary

    def apply(x):
        y = np.zeros(len(p))
        np.add.at(y, rows, vals * x[cols])
        return y

    rhs = (load - apply(u))[free]

    def apply_free(x):
        full = np.zeros(len(p))
        full[free] = x
        return apply(full)[free]

    x = np.zeros(free.sum())
    r = rhs - apply_free(x)
    s = r.copy()
    rr = r @ r
    for _ in range(5000):
        q = apply_free(s)
        alpha = rr / (s @ q)
        x += alpha * s
        r -= alpha * q
        rr_new = r @ r
        if np.sqrt(rr_new) < 1e-12 * np.linalg.norm(rhs):
            break
        s = r + (rr_new / rr) * s
        rr = rr_new
    else:
        fail("%s: conjugate gradients did not converge" % path)
    u[free] = x
    error = abs(u - exact(p)).max()
    print("%s, %s: %d nodes, %d tetrahedra, %d boundary triangles, nodal error %.3g" %
          (os.path.basename(path), exact.__name__, len(p), len(tets), len(tris), error))
    if not error < max_error:
        fail("%s: nodal error %.3g above %.3g" % (path, error, max_error))


def main():
    if len(sys.argv) != 2:
        fail("usage: fem_poisson_test.py BCCMIS")
    need_meshio()
    with tempfile.TemporaryDirectory() as d:
        ascii_msh, binary_msh = os.path.join(d, "ascii.msh"), os.path.join(d, "binary.msh")
        base = [sys.argv[1], "stuff", "--shape", "sphere", "-L", "3", "--cells", "2", "--quiet"]
        subprocess.run(base + ["-o", ascii_msh], check=True)
        subprocess.run(base + ["--binary", "-o", binary_msh], check=True)
        for path in (ascii_msh, binary_msh):
            solve(path, linear, 0, MAX_LINEAR_ERROR)
            solve(path, quadratic, 6, MAX_QUADRATIC_ERROR)
    print("ok")


if __name__ == "__main__":
    main()
