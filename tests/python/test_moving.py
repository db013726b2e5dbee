"""A moving shape against `bccmis stuff --animate` (spec/python.md P9)."""
import subprocess

import meshio
import pytest

import bccmis


def tets_by_position(points, tets):
    return sorted(tuple(sorted(tuple(points[v]) for v in t)) for t in tets)


def test_frames_equal_cli(cli, tmp_path):
    subprocess.run([cli, "stuff", "--shape", "torus", "-L", "2", "--animate", "2", "--path", "1,0,0", "-o",
                    str(tmp_path / "a.pvd"), "-q"], check=True)
    frame = lambda k: meshio.read(tmp_path / f"a_000{k}.vtu")
    moving = bccmis.MovingShape(bccmis.shapes.torus(), (1, 0, 0), max_level=2)
    f = frame(0)
    assert tets_by_position(moving.mesh.points, moving.mesh.tets) == tets_by_position(f.points, f.cells_dict["tetra"])
    for k, x in ((1, 0.5), (2, 1.0)):
        mesh, report = moving.move((x, 0, 0))
        f = frame(k)
        assert tets_by_position(mesh.points, mesh.tets) == tets_by_position(f.points, f.cells_dict["tetra"])
        assert report["refines"] + report["coarsens"] > 0 and report["leaves"] > 0
    with pytest.raises(ValueError, match=r"offset: outside the box the path sweeps"):
        moving.move((1.5, 0, 0))
