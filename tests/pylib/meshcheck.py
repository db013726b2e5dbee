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
