"""What the Python mesh tests share: failing with a message, six times a
tetrahedron's signed volume, and meshio (a missing meshio is a failure)."""
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def six_volume(p):
    """det[p1 - p0, p2 - p0, p3 - p0] of four points (sequences of 3)."""
    a = [p[1][k] - p[0][k] for k in range(3)]
    b = [p[2][k] - p[0][k] for k in range(3)]
    c = [p[3][k] - p[0][k] for k in range(3)]
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]))


def need_meshio():
    try:
        import meshio
    except ImportError as e:
        fail("meshio is not installed (scripts/setup.sh installs python3-meshio): %s" % e)
    return meshio


def tetrahedra(mesh, path):
    """The tetrahedra of a meshio mesh, its blocks of tetra joined (a .msh
    has one block per component, spec/mesh3d.md M21); any block other than
    tetra or triangle (the boundary of a .msh or .mesh) is a failure."""
    import numpy
    types = [c.type for c in mesh.cells]
    if "tetra" not in types or set(types) - {"tetra", "triangle"}:
        fail("%s: cell blocks %s" % (path, types))
    return numpy.concatenate([c.data for c in mesh.cells if c.type == "tetra"])
