"""Every exception path of the module (spec/python.md P6, P7)."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import bccmis

TET = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
FACES = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def test_the_tetrahedron_meshes():
    assert len(bccmis.stuff(TET, FACES, max_level=3, cells=3)) > 0


def test_wrong_shapes():
    with pytest.raises(ValueError, match=r"vertices: expected an array of shape \(n, 3\), got shape \(4, 2\)"):
        bccmis.stuff(TET[:, :2], FACES)
    with pytest.raises(ValueError, match=r"faces: expected an array of shape \(m, 3\), got shape \(4, 4\)"):
        bccmis.stuff(TET, np.hstack([FACES, FACES[:, :1]]))
    with pytest.raises(ValueError, match=r"faces: dtype float64 is not an integer type"):
        bccmis.stuff(TET, FACES.astype(np.float64))


def test_not_finite():
    v = TET.copy()
    v[2, 1] = np.nan
    with pytest.raises(ValueError, match=r"vertices\[2, 1\] is nan"):
        bccmis.stuff(v, FACES)
    v[2, 1] = np.inf
    with pytest.raises(ValueError, match=r"vertices\[2, 1\] is inf"):
        bccmis.stuff(v, FACES)


def test_index_out_of_range():
    f = FACES.copy()
    f[3, 2] = 4
    with pytest.raises(ValueError, match=r"faces\[3, 2\] = 4: out of range for 4 vertices"):
        bccmis.stuff(TET, f)
    f[3, 2] = -1
    with pytest.raises(ValueError, match=r"faces\[3, 2\] = -1: out of range"):
        bccmis.stuff(TET, f)


def test_refused_shape_and_options():
    with pytest.raises(ValueError, match=r"10"):  # S2: N 2^L must exceed 10
        bccmis.stuff(bccmis.shapes.sphere(), max_level=1, cells=4)
    with pytest.raises(ValueError, match=r"sphere"):  # S1: r > 0
        bccmis.shapes.sphere(r=-1)
    with pytest.raises(ValueError, match=r"impl: expected 'fast' or 'reference', got 'quick'"):
        bccmis.stuff(bccmis.shapes.sphere(), impl="quick")
    with pytest.raises(ValueError, match=r"bounds"):
        bccmis.stuff(lambda p: p[:, 0])


def test_strict_refuses_an_open_mesh():
    with pytest.raises(ValueError, match=r"<array>"):
        bccmis.stuff(TET, FACES[:3], strict=True, max_level=3, cells=3)


def test_unreadable_file(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"nothing\.off"):
        bccmis.stuff_file(str(tmp_path / "nothing.off"))
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 x\n")
    with pytest.raises(ValueError, match=r"bad\.off:4:5: bad number 'x'"):
        bccmis.stuff_file(str(bad))


def test_a_raising_callable_and_progress():
    def broken(points):
        raise ZeroDivisionError("inside the shape")

    with pytest.raises(ZeroDivisionError, match="inside the shape"):
        bccmis.stuff(broken, bounds=((-1, -1, -1), (1, 1, 1)), max_level=2, cells=3)

    def wrong_length(points):
        return np.zeros(2)

    with pytest.raises(ValueError, match=r"expected 1 value for 1 point, got 2"):
        bccmis.stuff(wrong_length, bounds=((-1, -1, -1), (1, 1, 1)), max_level=2, cells=3)

    def stop(line):
        raise RuntimeError("stop at: " + line)

    with pytest.raises(RuntimeError, match=r"stop at: sphere r=1: lattice"):
        bccmis.stuff(bccmis.shapes.sphere(), max_level=2, cells=3, progress=stop)
    with pytest.raises(ValueError, match=r"stats: a Python shape"):
        bccmis.stuff(lambda p: p[:, 0], bounds=((-1, -1, -1), (1, 1, 1)), stats=True)


def test_write_unknown_extension_and_unwritable(tmp_path):
    mesh = bccmis.stuff(bccmis.shapes.sphere(), max_level=2, cells=3)
    with pytest.raises(ValueError, match=r"unknown format"):
        mesh.write(str(tmp_path / "a.stl"))
    with pytest.raises(FileNotFoundError):
        mesh.write(str(tmp_path / "no" / "a.vtu"))
    assert os.listdir(tmp_path) == []  # nothing half-written


def test_ctrl_c_interrupts_a_run():
    # P7: SIGINT while C++ works (no Python callback runs) ends the call at
    # the next progress line. First the lattice phase's seconds, from a run
    # stopped by its progress callback after that phase.
    shape = bccmis.shapes.torus()
    lines = []

    def record(line):
        lines.append(line)
        if len(lines) == 2:  # "N leaves (T s)"
            raise StopIteration

    with pytest.raises(StopIteration):
        bccmis.stuff(shape, max_level=4, progress=record)
    lattice = float(lines[1].split("(")[1].split(" s")[0])
    # SIGINT during the lattice phase: the call ends after it, before the
    # stuffing (about 6 times as long as the lattice phase at this level).
    threading.Timer(lattice / 4, os.kill, (os.getpid(), signal.SIGINT)).start()
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        bccmis.stuff(shape, max_level=4)
    assert time.monotonic() - t0 < 3 * lattice + 0.2
