"""The mesher from Python against the CLI (spec/python.md P1-P5)."""
import json
import subprocess

import meshio
import numpy as np
import pytest

import bccmis


def tets_by_position(points, tets):
    """Each tetrahedron as its 4 vertex positions (exact doubles), sorted."""
    return sorted(tuple(sorted(tuple(points[v]) for v in t)) for t in tets)


def cli_mesh(cli, tmp_path, *args, stats=True):
    """The CLI's mesh of `args` (read back from its Medit file, whose numbers
    round-trip exactly) and its --json statistics."""
    out = tmp_path / "cli.mesh"
    run = subprocess.run([cli, "stuff", *args, "-o", str(out), "-q"] + (["--json"] if stats else []),
                         capture_output=True, text=True, check=True)
    m = meshio.read(out)
    return m.points, m.cells_dict["tetra"], json.loads(run.stdout) if stats else None


def without_seconds(stats):
    return {k: v for k, v in stats.items() if k != "seconds"}


def test_builtin_shape_equals_cli(cli, tmp_path):
    points, tets, stats = cli_mesh(cli, tmp_path, "--shape", "sphere:r=1", "-L", "2", "--cells", "3")
    mesh = bccmis.stuff(bccmis.shapes.sphere(r=1), max_level=2, cells=3, stats=True)
    assert tets_by_position(mesh.points, mesh.tets) == tets_by_position(points, tets)
    # The same members as --json (P5), the same values but the seconds.
    assert mesh.stats.keys() == stats.keys()
    assert mesh.stats["seconds"].keys() == stats["seconds"].keys() - {"write"}  # P5: nothing is written
    assert without_seconds(mesh.stats) == without_seconds(stats)


def test_file_and_arrays_equal_cli(cli, source, tmp_path):
    cube = source / "tests/stuff/good/cube.off"
    points, tets, _ = cli_mesh(cli, tmp_path, str(cube), "-L", "2", "--cells", "3", stats=False)
    expected = tets_by_position(points, tets)
    from_file = bccmis.stuff_file(str(cube), max_level=2, cells=3)
    assert tets_by_position(from_file.points, from_file.tets) == expected
    surface = meshio.read(cube)
    vertices = surface.points.astype(np.float64)
    faces = surface.cells_dict["triangle"]
    for dtype in (np.int16, np.uint8):
        f = np.asfortranarray(faces.astype(dtype))
        mesh = bccmis.stuff(vertices, f, max_level=2, cells=3)
        assert tets_by_position(mesh.points, mesh.tets) == expected


def test_arrays_are_views_owning_the_mesh():
    mesh = bccmis.stuff(bccmis.shapes.sphere(), max_level=2, cells=3)
    points, tets = mesh.points, mesh.tets
    assert points.dtype == np.float64 and points.shape[1] == 3
    assert tets.dtype == np.uint32 and tets.shape == (len(mesh), 4)
    assert mesh.levels.shape == (len(mesh),) and mesh.kinds.shape == (len(points),)
    assert not points.flags.writeable and not points.flags.owndata
    assert points.base is not None
    del mesh
    # The arrays keep the mesh alive: the sphere's points are still on or in it.
    assert np.all(np.linalg.norm(points, axis=1) <= 1 + 1e-12)
    assert tets.max() < len(points)


def test_meshio_round_trip(tmp_path):
    mesh = bccmis.stuff(bccmis.shapes.sphere(), max_level=2, cells=3)
    m = mesh.to_meshio()
    m.write(tmp_path / "a.vtu")
    back = meshio.read(tmp_path / "a.vtu")
    assert np.array_equal(back.points, mesh.points)
    assert np.array_equal(back.cells_dict["tetra"], mesh.tets)
    assert np.array_equal(back.cell_data["level"][0], mesh.levels)
    for ext in ("vtu", "msh", "mesh"):
        mesh.write(str(tmp_path / f"b.{ext}"))
        written = meshio.read(tmp_path / f"b.{ext}")
        assert np.array_equal(written.points, mesh.points), ext
        assert np.array_equal(written.cells_dict["tetra"], mesh.tets), ext
    mesh.write(str(tmp_path / "z.vtu"), compress=True)
    assert 'compressor="vtkZLibDataCompressor"' in (tmp_path / "z.vtu").read_text()
    written = meshio.read(tmp_path / "z.vtu")
    assert np.array_equal(written.points, mesh.points) and np.array_equal(written.cells_dict["tetra"], mesh.tets)
    mesh.write(str(tmp_path / "b.off"))
    surface = meshio.read(tmp_path / "b.off")
    assert len(surface.cells_dict["triangle"]) == len(mesh.boundary_faces)


def test_dihedral_angles_against_numpy():
    mesh = bccmis.stuff(bccmis.shapes.torus(), max_level=2, cells=4)
    angles = mesh.dihedral_angles()
    p = mesh.points[mesh.tets.astype(np.int64)]
    # The angle at edge (i, j) between the faces' normals, computed here independently.
    edges = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    for e, (i, j) in enumerate(edges):
        k, l = [v for v in range(4) if v not in (i, j)]
        a, b = p[:, i], p[:, j]
        n1 = np.cross(b - a, p[:, k] - a)
        n2 = np.cross(b - a, p[:, l] - a)
        cos = np.einsum("ij,ij->i", n1, n2) / np.linalg.norm(n1, axis=1) / np.linalg.norm(n2, axis=1)
        np.testing.assert_allclose(angles[:, e], np.degrees(np.arccos(np.clip(cos, -1, 1))), atol=1e-6)
    # S10's bounds on the angles of a stuffed mesh hold.
    assert mesh.dihedral_angles().min() > 9


def test_python_sphere_against_builtin():
    builtin = bccmis.stuff(bccmis.shapes.sphere(), max_level=3, cells=3)
    calls = []

    def sphere(points):
        calls.append(len(points))
        return np.linalg.norm(points, axis=1) - 1.0

    mine = bccmis.stuff(sphere, bounds=((-1, -1, -1), (1, 1, 1)), max_level=3, cells=3)
    assert set(calls) == {1}  # P3: one point at a time
    assert len(mine) == len(builtin)
    assert np.array_equal(np.sort(mine.levels), np.sort(builtin.levels))
    # Lattice vertices are the same doubles; cut points agree to the bisection.
    lattice = lambda m: sorted(map(tuple, m.points[m.kinds == 0]))
    assert lattice(mine) == lattice(builtin)
    # Every point of one within 1e-12 of a point of the other, matched in the
    # order of their positions rounded far above that.
    order = lambda p: p[np.lexsort(np.round(p, 6).T[::-1])]
    a, b = order(mine.points), order(builtin.points)
    assert a.shape == b.shape and np.abs(a - b).max() < 1e-12


def test_features_keep_a_turned_cube():
    """spec/stuffing.md S29-S33, spec/python.md P1: features are on for a
    triangle mesh; the creases and corners of the cube [0,2]^3 turned about
    no lattice direction are kept, so the volume is the cube's, 8."""
    a, b = 0.3, 0.2
    turn_z = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])
    turn_x = np.array([[1, 0, 0], [0, np.cos(b), -np.sin(b)], [0, np.sin(b), np.cos(b)]])
    corners = np.array([[2.0 * x, 2.0 * y, 2.0 * z] for z in (0, 1) for y in (0, 1) for x in (0, 1)])
    vertices = corners @ (turn_x @ turn_z).T
    faces = np.array([[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                      [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]])
    kept = bccmis.stuff(vertices, faces, max_level=2, stats=True, check=True)
    assert kept.stats["feature_corners_conformed"] == 8
    assert kept.stats["feature_curves_conformed"] == 12
    assert abs(kept.stats["volume"] - 8) < 1e-12
    cut = bccmis.stuff(vertices, faces, max_level=2, stats=True, features=False)
    assert "feature_edges" not in cut.stats
    assert cut.stats["volume"] < 8 - 1e-2
    with pytest.raises(ValueError, match="feature_angle"):
        bccmis.stuff(vertices, faces, feature_angle=181)
