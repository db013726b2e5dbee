"""The lattices from Python against the CLI's replay (spec/python.md P8)."""
import pathlib
import subprocess

import numpy as np
import pytest

import bccmis

CORPUS = pathlib.Path(__file__).resolve().parents[2] / "fuzz/corpus/fuzz_trace"


def cli_replay(cli, trace, impl):
    return subprocess.run([cli, "replay", "--quiet", "--check=none", "--impl", impl, str(trace)], capture_output=True,
                          text=True)


def corpus():
    return sorted(CORPUS.glob("*.trace"))


@pytest.mark.parametrize("trace", corpus(), ids=lambda p: p.name)
def test_replay_equals_cli(cli, trace):
    text = trace.read_bytes().decode("utf-8", errors="replace")
    for impl in ("reference", "fast"):
        run = cli_replay(cli, trace, impl)
        if run.returncode == 2:
            with pytest.raises(ValueError):
                bccmis.replay(text, impl=impl)
            continue
        assert run.returncode == 0, run.stderr
        g, log = bccmis.replay(text, impl=impl)
        assert log + g.canonical_state() == run.stdout


@pytest.mark.parametrize("trace", corpus(), ids=lambda p: p.name)
def test_operations_decide_as_cli(cli, trace):
    # Each refine and coarsen through the Lattice methods, decided as the CLI decides it.
    run = cli_replay(cli, trace, "reference")
    if run.returncode != 0:
        return
    lines = [l.split("#")[0].split() for l in trace.read_text().splitlines()]
    lines = [words for words in lines if words]
    size = [int(x) for x in lines[0][1:]]
    for impl in ("reference", "fast"):
        g = (bccmis.Lattice if len(size) == 3 else bccmis.Lattice3)(*size, impl=impl)
        decisions = []
        for words in lines[1:]:
            if words[0] not in ("refine", "coarsen"):
                continue
            p = tuple(int(x) for x in words[1:])
            ask = g.can_refine if words[0] == "refine" else g.can_coarsen
            act = g.refine if words[0] == "refine" else g.coarsen
            before = ask(p)
            code = act(p)
            assert code == before
            line = words[0] + " " + " ".join(map(str, p))
            decisions.append(line + (" ok" if code is None else " refused " + code))
        assert "".join(d + "\n" for d in decisions) + g.canonical_state() == run.stdout


def test_queries_against_the_canonical_state():
    g = bccmis.Lattice(2, 2, 3)
    assert g.refine((8, 8)) is None
    assert g.refine((8, 8)) == "no-such-cell"
    # The canonical state lists each center with its level, and every vertex's neighbors.
    state = g.canonical_state().splitlines()
    cells = [tuple(map(int, l.split()[1:3])) for l in state if l.startswith("C ")]
    levels = [int(l.split()[3]) for l in state if l.startswith("C ")]
    nodes = [tuple(map(int, l.split()[1:3])) for l in state if l.startswith("N ")]
    assert [tuple(p) for p in g.cells()] == cells
    assert list(g.levels()) == levels
    assert [tuple(p) for p in g.nodes()] == nodes
    line = next(l for l in state if l.startswith("C 4 4 "))
    nbrs = list(map(int, line.split(":")[1].split()))
    assert g.neighbors((4, 4)).ravel().tolist() == nbrs
    with pytest.raises(ValueError, match=r"not a vertex"):
        g.neighbors((1, 2))
    assert g.coarsen((8, 8)) is None and g.check() is None


def test_check_raises_with_code_and_positions(cli, source):
    for name in ("broken.state", "broken3d.state"):
        text = (source / "tests/cli" / name).read_text()
        run = subprocess.run([cli, "check", str(source / "tests/cli" / name)], capture_output=True, text=True)
        assert run.returncode == 1
        with pytest.raises(bccmis.InvariantError) as e:
            bccmis.parse_state(text).check()
        assert e.value.code in run.stderr
        assert str(e.value) in run.stderr
        assert len(e.value.positions) > 0


def test_tetrahedra_3d():
    g = bccmis.Lattice3(1, 1, 1, 2)
    t = g.tetrahedra()
    assert t.shape == (24, 4, 3)  # spec/mesh3d.md: one cube, 6 faces x 4
    # Positively oriented and filling the cube of side 2^(L+1) = 8.
    v = t[:, 1:] - t[:, :1]
    six = np.linalg.det(v.astype(float))
    assert np.all(six > 0) and round(six.sum()) == 6 * 8**3
