#!/usr/bin/env python3
"""bccmis-mpi stuff against bccmis stuff (spec/distributed.md).

  mpi_stuff_test.py gather|gather-every-format MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      --gather --no-features's binary .vtu (every format: also ASCII .vtu and .msh, then one run
      writing .vtu, .msh, .mesh, .off and .obj at once) equals bccmis stuff --no-features's byte
      for byte (D1, D5).
  mpi_stuff_test.py whole|whole-check|whole-check-warns MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      --gather (whole-check: --gather --check) writes bccmis stuff's file byte for byte with
      the features on as there (a triangle-mesh INPUT's by default, D12), and
      prints bccmis stuff's warning lines on stderr (D13; whole-check-warns: --check, and
      the serial command must print some);
      --check without --gather (and, for an INPUT, the features) exit 2
      naming D12 and leave no .pvtu.
  mpi_stuff_test.py stats-features MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      one run of --gather --check --stats --json -o FILE.vtu with the features on (D13):
      the file is bccmis stuff's bytes, the JSON equals bccmis stuff's on every member
      but the seconds (D11's phases) and warped (null), the feature members included,
      and the warning lines on stderr are bccmis stuff's.
  mpi_stuff_test.py pvtu MPIRUN BCCMIS BCCMIS_MPI RANKS[:PIECES] -- STUFF_ARGS...
      the .pvtu lists the pieces written (one a rank with tetrahedra); they, read by meshio, hold the serial
      mesh's tetrahedra (by vertex positions, bit for bit, with their levels)
      and each boundary vertex at one position; every triangle lies in one
      tetrahedron (the serial boundary) or two, and some interior triangles
      join tetrahedra of two pieces (D3, D7); the point data global_id is one
      number a position across the pieces, 0 .. n-1 over the serial mesh's
      vertices, and on one rank the serial numbering (D7). With PIECES, exactly that many
      pieces (fewer than RANKS: a rank whose leaves make no tetrahedron writes
      none, D1).
  mpi_stuff_test.py stats MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      --stats and --stats --json (no -o, then with a .pvtu) print bccmis stuff
      --no-features's statistics (D11): every line and member but the
      seconds and warped exactly, the volume and its relative error to a
      relative 1e-12 (summed in another order); warped is not computed ("-",
      null); the seconds name D11's phases.
  mpi_stuff_test.py notices MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      a cube written with a duplicated face and a repeated vertex (a soup S21-S22 repairs): the
      notice lines on stderr (the flaws, the welded vertices) are bccmis stuff's, each once (D1).
  mpi_stuff_test.py hausdorff MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      --gather --stats --hausdorff (text, then --json) print bccmis stuff's statistics with the
      sampled Hausdorff distance: the hausdorff lines and member, and every other line and member
      but the seconds and warped, exactly (D12, D13); without --gather, exit 2 naming D12.
  mpi_stuff_test.py stats-check MPIRUN BCCMIS BCCMIS_MPI RANKS -- [--failing] STUFF_ARGS...
      --gather --stats --check -o FILE.vtu against bccmis stuff --stats --check (D11, D12): passing
      (--no-features), the statistics lines in the serial order (D11's rules); --failing (a mesh the
      checker refuses), exit 1 on both, no statistics and no file on either, the same message.
  mpi_stuff_test.py memory MPIRUN BCCMIS BCCMIS_MPI RANKS -- PER_RANK RANK0 STUFF_ARGS...
      D16 on its line: --memory-limit PER_RANK (GB, every rank's estimate of a .pvtu run) meshes, one
      byte less refuses (exit 2), each rank's line naming it, nothing written; with --gather, RANK0 (rank 0's
      estimate, the whole mesh beside its share) meshes, one byte less refuses rank 0 alone.
  mpi_stuff_test.py errors MPIRUN BCCMIS BCCMIS_MPI RANKS
      the option D1 refuses (by name), --crease-cuts without --gather (D12, D16), an unreadable input, an unwritable output directory,
      and one rank that cannot put its piece in place: exit 2, a message, no .pvtu (D1, D6).
"""
import collections
import json
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

import meshio


def run(cmd, expect=0):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if r.returncode != expect:
        sys.exit(f"FAIL: {' '.join(cmd)}: exit {r.returncode}, expected {expect}\n{r.stderr}")
    return r


def mpi(mpirun, ranks):
    return [mpirun, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)]


def tets_of(mesh):
    """The tetrahedra as sorted tuples of vertex positions, with the level."""
    points = [tuple(map(float, p)) for p in mesh.points]
    cells = mesh.cells_dict["tetra"]
    levels = mesh.cell_data_dict["level"]["tetra"]
    return [(tuple(sorted(points[v] for v in t)), int(l)) for t, l in zip(cells, levels)]


def gather(mpirun, bccmis, bccmis_mpi, ranks, args, work, every_format):
    formats = ((".vtu", ["--binary"]), (".vtu", []), (".msh", [])) if every_format else ((".vtu", ["--binary"]),)
    for ext, extra in formats:
        serial, together = os.path.join(work, "serial" + ext), os.path.join(work, "gathered" + ext)
        run([bccmis, "stuff", *args, *extra, "--no-features", "-q", "-o", serial])
        run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "--no-features", "-q", "--gather", "-o", together])
        a, b = open(serial, "rb").read(), open(together, "rb").read()
        if a != b:
            sys.exit(f"FAIL: {ranks} ranks, {ext} {extra}: the gathered file differs from bccmis stuff's "
                     f"({len(a)} and {len(b)} bytes)")
    if every_format:  # D1: several outputs at once, the boundary surface (.off, .obj) among them
        exts = (".vtu", ".msh", ".mesh", ".off", ".obj")
        outs = lambda stem: [a for e in exts for a in ("-o", os.path.join(work, stem + e))]
        run([bccmis, "stuff", *args, "--no-features", "--surface-vertices", "all", "-q", *outs("serial_all")])
        run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, "--no-features", "--surface-vertices", "all", "-q",
                                  "--gather", *outs("gathered_all")])
        for e in exts:
            if open(os.path.join(work, "serial_all" + e), "rb").read() != open(
                    os.path.join(work, "gathered_all" + e), "rb").read():
                sys.exit(f"FAIL: {ranks} ranks: --gather with {len(exts)} outputs: its {e} differs from bccmis stuff's")
        formats += tuple((e, ["(with the others)"]) for e in exts)
    print(f"ok: {ranks} ranks: --gather writes bccmis stuff's bytes ({', '.join(e + ' ' + ' '.join(x) for e, x in formats)})")


def pvtu(mpirun, bccmis, bccmis_mpi, ranks, pieces, args, work):
    serial_path, index = os.path.join(work, "serial.vtu"), os.path.join(work, "out.pvtu")
    run([bccmis, "stuff", *args, "--no-features", "-q", "-o", serial_path])
    run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, "--no-features", "-q", "-o", index])
    # A rank whose leaves make no tetrahedron writes no piece (D1).
    sources = [p.get("Source") for p in ET.parse(index).getroot().iter("Piece")]
    written = sorted(f for f in os.listdir(work) if f.startswith("out_"))
    if not sources or sources != written or any(s not in [f"out_{r:04d}.vtu" for r in range(ranks)] for s in sources):
        sys.exit(f"FAIL: the .pvtu lists {sources}, the directory holds {written}")
    if pieces is not None and len(sources) != pieces:
        sys.exit(f"FAIL: {len(sources)} pieces, expected {pieces}")
    serial = tets_of(meshio.read(serial_path))
    union, piece_of = [], []
    for r, source in enumerate(sources):
        t = tets_of(meshio.read(os.path.join(work, source)))
        if not t:
            sys.exit(f"FAIL: piece {r} is empty")
        union += t
        piece_of += [r] * len(t)
    if collections.Counter(union) != collections.Counter(serial):
        sys.exit(f"FAIL: the pieces hold {len(union)} tetrahedra, the serial mesh {len(serial)}; "
                 f"{len(set(union) ^ set(serial))} differ by vertex positions or level")
    triangles = collections.defaultdict(list)
    for (corners, _), r in zip(union, piece_of):
        for skip in range(4):
            triangles[tuple(c for i, c in enumerate(corners) if i != skip)].append(r)
    over = [t for t, rs in triangles.items() if len(rs) > 2]
    across = sum(1 for rs in triangles.values() if len(rs) == 2 and rs[0] != rs[1])
    boundary = sum(1 for rs in triangles.values() if len(rs) == 1)
    serial_triangles = collections.Counter()
    for corners, _ in serial:
        for skip in range(4):
            serial_triangles[tuple(c for i, c in enumerate(corners) if i != skip)] += 1
    serial_boundary = sum(1 for n in serial_triangles.values() if n == 1)
    if over:
        sys.exit(f"FAIL: {len(over)} triangles lie in more than two tetrahedra, e.g. {over[0]}")
    if boundary != serial_boundary:
        sys.exit(f"FAIL: {boundary} triangles in one tetrahedron across the pieces, {serial_boundary} in the serial mesh")
    if ranks > 1 and across == 0:
        sys.exit("FAIL: no interior triangle joins two pieces: the partition is not exercised")
    # D7: one global_id a position across the pieces, 0 .. n-1, and on one
    # rank the serial numbering.
    serial_mesh = meshio.read(serial_path)
    serial_index = {tuple(map(float, p)): i for i, p in enumerate(serial_mesh.points)}
    id_of = {}
    for source in sources:
        piece = meshio.read(os.path.join(work, source))
        for p, i in zip(piece.points, piece.point_data["global_id"]):
            key = tuple(map(float, p))
            if id_of.setdefault(key, int(i)) != int(i):
                sys.exit(f"FAIL: the vertex at {key} has global_id {id_of[key]} and {int(i)} in two pieces")
    if sorted(id_of.values()) != list(range(len(serial_index))) or set(id_of) != set(serial_index):
        sys.exit(f"FAIL: the global_ids are not 0 .. {len(serial_index) - 1} over the serial mesh's vertices")
    if ranks == 1 and any(id_of[k] != i for k, i in serial_index.items()):
        sys.exit("FAIL: on one rank the global_ids are not the serial numbering")
    print(f"ok: {ranks} ranks, {len(sources)} pieces: {len(union)} tetrahedra as in the serial mesh; {across} interior triangles "
          f"join two pieces, none lies in three tetrahedra; {boundary} boundary triangles")


ROUNDED = ("volume", "volume_rel_error")  # D11: sums in another order
RANK_PHASES = ["input", "forest", "pieces", "statistics", "write"]
NOT_COMPUTED = ("warped",)  # D11


def close(a, b):
    return abs(a - b) <= 1e-12 * max(abs(a), abs(b))


def same_stats_lines(got, want, where):
    """D11: --stats' `name value` lines as the serial ones, in order, but the seconds,
    warped ("-") and the rounded sums (to a relative 1e-12)."""
    strip = lambda lines: [l for l in lines if not l.startswith("seconds_")]
    if [l.split()[0] for l in strip(got)] != [l.split()[0] for l in strip(want)]:
        sys.exit(f"FAIL: {where}: the --stats lines differ:\n{strip(got)}\n{strip(want)}")
    for g, w in zip(strip(got), strip(want)):
        name = w.split()[0]
        if name in NOT_COMPUTED:
            if g != name + " -":
                sys.exit(f"FAIL: {where}: '{g}', expected '{name} -'")
        elif name in ROUNDED:
            if not close(float(g.split()[1]), float(w.split()[1])):
                sys.exit(f"FAIL: {where}: '{g}', serial '{w}'")
        elif g != w:
            sys.exit(f"FAIL: {where}: '{g}', serial '{w}'")


def stats_check(mpirun, bccmis, bccmis_mpi, ranks, args, work):
    serial_path, together = os.path.join(work, "serial.vtu"), os.path.join(work, "gathered.vtu")
    failing = args[0] == "--failing"
    args = args[1:] if failing else args
    extra = ["--stats", "--check"] + (["--no-features"] if not failing else [])
    said = run([bccmis, "stuff", *args, *extra, "-o", serial_path], expect=1 if failing else 0)
    got = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "--gather", "-o", together],
              expect=1 if failing else 0)
    if failing:
        # D12: the checker's problem, exit 1, as bccmis stuff: no statistics, no file, the same message.
        want = [l.split(": ", 1)[1] for l in said.stderr.splitlines() if l.startswith("bccmis: ")]
        have = [l.split(": ", 2)[2] for l in got.stderr.splitlines() if l.startswith("bccmis-mpi stuff: rank ")]
        if said.stdout or got.stdout or os.path.exists(serial_path) or os.path.exists(together):
            sys.exit(f"FAIL: {ranks} ranks: a failed --check printed statistics or left a file:\n{got.stdout}")
        if len(want) != 1 or have != want:
            sys.exit(f"FAIL: {ranks} ranks: the failed --check says {have}, bccmis stuff {want}")
        print(f"ok: {ranks} ranks: --stats --check failing: exit 1 as bccmis stuff, no statistics, '{want[0]}'")
        return
    same_stats_lines(got.stdout.splitlines(), said.stdout.splitlines(), f"{ranks} ranks --stats --check")
    print(f"ok: {ranks} ranks: --gather --stats --check prints bccmis stuff's statistics in its order")


def stats(mpirun, bccmis, bccmis_mpi, ranks, args, work):
    serial_text = run([bccmis, "stuff", *args, "--no-features", "--stats", "-q"]).stdout
    serial_json = json.loads(run([bccmis, "stuff", *args, "--no-features", "--stats", "--json", "-q"]).stdout)
    mpi_run = mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, "--no-features", "-q"]
    index = os.path.join(work, "out.pvtu")
    for extra in ([], ["-o", index]):
        # Text: `name value` lines, in order.
        got = run(mpi_run + ["--stats", *extra]).stdout.splitlines()
        same_stats_lines(got, serial_text.splitlines(), f"{ranks} ranks {extra}")
        if [l.split()[0] for l in got if l.startswith("seconds_")] != ["seconds_" + p for p in RANK_PHASES]:
            sys.exit(f"FAIL: {ranks} ranks {extra}: the seconds' phases: {got}")
        # JSON: the same members in the same order.
        j = json.loads(run(mpi_run + ["--stats", "--json", *extra]).stdout)
        if list(j) != list(serial_json):
            sys.exit(f"FAIL: {ranks} ranks {extra}: the JSON members {list(j)}, serial {list(serial_json)}")
        for k, w in serial_json.items():
            if k == "seconds":
                if list(j[k]) != RANK_PHASES + ["meshing", "total"]:
                    sys.exit(f"FAIL: {ranks} ranks {extra}: the seconds' phases {list(j[k])}")
            elif k in NOT_COMPUTED:
                if j[k] is not None:
                    sys.exit(f"FAIL: {ranks} ranks {extra}: {k} {j[k]}, expected null")
            elif k in ROUNDED:
                if not close(j[k], w):
                    sys.exit(f"FAIL: {ranks} ranks {extra}: {k} {j[k]}, serial {w}")
            elif j[k] != w:
                sys.exit(f"FAIL: {ranks} ranks {extra}: {k} {j[k]}, serial {w}")
    if not os.path.exists(index):
        sys.exit(f"FAIL: {ranks} ranks: --stats -o {index} wrote no .pvtu")
    print(f"ok: {ranks} ranks: --stats and --json as bccmis stuff's ({serial_json['tetrahedra']} tetrahedra, "
          f"{serial_json['boundary_triangles']} boundary triangles)")


def hausdorff(mpirun, bccmis, bccmis_mpi, ranks, args, work):
    serial = [bccmis, "stuff", *args, "--stats", "--hausdorff", "-q"]
    gathered = mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, "--gather", "--stats", "--hausdorff", "-q"]
    # Text: the same lines in the same order, but the seconds and warped (D11).
    want, got = run(serial).stdout.splitlines(), run(gathered).stdout.splitlines()
    compared = lambda lines: [l for l in lines if not l.startswith("seconds_") and l.split()[0] not in NOT_COMPUTED]
    if compared(got) != compared(want):
        sys.exit(f"FAIL: {ranks} ranks: --gather --stats --hausdorff:\n{compared(got)}\nserial:\n{compared(want)}")
    distances = [l for l in want if l.startswith("hausdorff")]
    if len(distances) != 5:
        sys.exit(f"FAIL: bccmis stuff --hausdorff printed no distance: {want}")
    # JSON: the same members; every one but the seconds and warped equal.
    j = json.loads(run(gathered + ["--json"]).stdout)
    w = json.loads(run(serial + ["--json"]).stdout)
    if list(j) != list(w):
        sys.exit(f"FAIL: {ranks} ranks: the JSON members {list(j)}, serial {list(w)}")
    for k in w:
        if k not in ("seconds",) + NOT_COMPUTED and j[k] != w[k]:
            sys.exit(f"FAIL: {ranks} ranks: {k} {j[k]}, serial {w[k]}")
    # Without --gather no rank holds the boundary: refused, naming D12.
    r = run(gathered[:gathered.index("--gather")] + gathered[gathered.index("--gather") + 1:], expect=2)
    if "--hausdorff run on the mesh gathered on rank 0: add --gather (spec/distributed.md D12)" not in r.stderr:
        sys.exit(f"FAIL: --hausdorff without --gather: no D12 refusal:\n{r.stderr}")
    print(f"ok: {ranks} ranks: --gather --stats --hausdorff as bccmis stuff's ({distances}); refused without --gather")


def warnings_of(stderr, tool):
    """The warnings a run printed on stderr (D13: as bccmis stuff prints them)."""
    head = tool + ": warning: "
    return [l[len(head):] for l in stderr.splitlines() if l.startswith(head)]


def same_warnings(serial, got, ranks, required):
    want = warnings_of(serial.stderr, "bccmis stuff")
    have = warnings_of(got.stderr, "bccmis-mpi stuff")
    if have != want:
        sys.exit(f"FAIL: {ranks} ranks: the warnings on stderr {have}, bccmis stuff's {want}\n{got.stderr}")
    if required and not want:
        sys.exit(f"FAIL: bccmis stuff printed no warning here:\n{serial.stderr}")
    return want


def whole(mpirun, bccmis, bccmis_mpi, ranks, args, work, check, warns=False):
    serial, together = os.path.join(work, "serial.vtu"), os.path.join(work, "gathered.vtu")
    extra = ["--check"] if check else []
    said = run([bccmis, "stuff", *args, *extra, "-o", serial])
    a = open(serial, "rb").read()
    got = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "--gather", "-o", together])
    b = open(together, "rb").read()
    if a != b:
        sys.exit(f"FAIL: {ranks} ranks {extra}: the gathered file differs from bccmis stuff's "
                 f"({len(a)} and {len(b)} bytes)")
    warned = same_warnings(said, got, ranks, warns)
    index = os.path.join(work, "out.pvtu")
    refusals = [["--check", "--no-features"]] + ([[]] if not args[0].startswith("-") else [])
    for extra in refusals:
        r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "-q", "-o", index], expect=2)
        if "spec/distributed.md D12" not in r.stderr or os.path.exists(index):
            sys.exit(f"FAIL: {extra} without --gather: no D12 refusal, or a .pvtu left:\n{r.stderr}")
    print(f"ok: {ranks} ranks: --gather{' --check' if check else ''} writes bccmis stuff's bytes ({len(a)}) "
          f"and its {len(warned)} warning(s); {len(refusals)} refusal(s) without --gather")


def stats_features(mpirun, bccmis, bccmis_mpi, ranks, args, work):
    serial, together = os.path.join(work, "serial.vtu"), os.path.join(work, "gathered.vtu")
    extra = ["--check", "--stats", "--json"]
    said = run([bccmis, "stuff", *args, *extra, "-o", serial])
    want = json.loads(said.stdout)
    if "feature_edges" not in want or want["feature_edges"] == 0:
        sys.exit(f"FAIL: bccmis stuff found no features here: {said.stdout}")
    if "--crease-cuts" in args and not want.get("crease_cuts_kept"):  # D16: rank 0 keeps S35.8's B or C
        sys.exit(f"FAIL: bccmis stuff kept the mesh without placement here (candidate A): {said.stdout}")
    got = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "--gather", "-o", together])
    if open(serial, "rb").read() != open(together, "rb").read():
        sys.exit(f"FAIL: {ranks} ranks: the gathered file differs from bccmis stuff's")
    j = json.loads(got.stdout)
    if list(j) != list(want):
        sys.exit(f"FAIL: {ranks} ranks: the JSON members {list(j)}, serial {list(want)}")
    for k, w in want.items():
        if k == "seconds":
            if list(j[k]) != RANK_PHASES + ["meshing", "total"]:
                sys.exit(f"FAIL: {ranks} ranks: the seconds' phases {list(j[k])}")
        elif k in NOT_COMPUTED:
            if j[k] is not None:
                sys.exit(f"FAIL: {ranks} ranks: {k} {j[k]}, expected null")
        elif j[k] != w:  # D13: the conformed mesh's numbers, bit for bit (the volume too)
            sys.exit(f"FAIL: {ranks} ranks: {k} {j[k]}, serial {w}")
    warned = same_warnings(said, got, ranks, False)
    print(f"ok: {ranks} ranks: --gather --check --stats --json with the features: bccmis stuff's bytes, JSON "
          f"({want['tetrahedra']} tetrahedra, {want['feature_edges']} feature edges) and {len(warned)} warning(s)")


# A unit cube, outward faces, with vertex 8 a copy of vertex 0 (used by one
# face: welded, S22) and the face 4 5 6 twice (a duplicate face, S21).
FLAWED_CUBE = """OFF
9 13 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
0 0 0
3 0 3 2
3 0 2 1
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 3 7 6
3 3 6 2
3 0 4 7
3 8 7 3
3 1 2 6
3 1 6 5
3 4 5 6
"""


def notice_lines(stderr, tool, path):
    """The input's notices (D1: as bccmis stuff prints them), without the tool's name."""
    head = f"{tool}: {path}: "
    return [l[len(tool) + 2:] for l in stderr.splitlines() if l.startswith(head)]


def notices(mpirun, bccmis, bccmis_mpi, ranks, args, work):
    cube = os.path.join(work, "flawed_cube.off")
    with open(cube, "w") as f:
        f.write(FLAWED_CUBE)
    serial = run([bccmis, "stuff", cube, *args, "--no-features", "-o", os.path.join(work, "serial.vtu")])
    got = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", cube, *args, "--no-features", "-o",
                                    os.path.join(work, "out.pvtu")])
    want = notice_lines(serial.stderr, "bccmis stuff", cube)
    have = notice_lines(got.stderr, "bccmis-mpi stuff", cube)
    if len(want) != 2 or "duplicate face" not in want[0] or "welded" not in want[1]:
        sys.exit(f"FAIL: bccmis stuff's notices on the flawed cube: {want}\n{serial.stderr}")
    if have != want:
        sys.exit(f"FAIL: {ranks} ranks: the notices {have}, bccmis stuff's {want}\n{got.stderr}")
    print(f"ok: {ranks} ranks: bccmis stuff's {len(want)} notice lines, once: {want}")


def errors(mpirun, bccmis, bccmis_mpi, ranks, work):
    def refused(args, index, says, no_features=True):
        extra = ["--no-features"] if no_features else []
        r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "-o", index], expect=2)
        if says not in r.stderr:
            sys.exit(f"FAIL: {args}: stderr does not say '{says}':\n{r.stderr}")
        if os.path.exists(index):
            sys.exit(f"FAIL: {args}: a failed run left {index}")
        left = [f for f in os.listdir(work) if f.startswith(".") or f.endswith(".pvtu")]
        if left:
            sys.exit(f"FAIL: {args}: a failed run left {left}")
    index = os.path.join(work, "out.pvtu")
    # D1: the option not split over ranks, refused by name before any work;
    # D16: --crease-cuts (the features) without --gather, as the features (D12).
    refused(["--shape", "sphere", "-L", "2", "--impl", "reference"], index,
            "--impl reference is not supported on several ranks yet (spec/distributed.md D1)")
    refused(["--shape", "sphere", "-L", "2", "--crease-cuts", "0.25"], index,
            "run on the mesh gathered on rank 0: add --gather", no_features=False)  # which excludes --no-features
    refused([os.path.join(work, "missing.off"), "-L", "2"], index, "missing.off")
    refused(["--shape", "sphere", "-L", "2"], os.path.join(work, "no_such_dir", "out.pvtu"), "no_such_dir")
    # S21 as bccmis stuff says it: an open flat square (a soup with four
    # border edges) encloses no volume at any level.
    square = os.path.join(work, "square.off")
    with open(square, "w") as f:
        f.write("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
    says = "square.off: encloses no volume (the winding number is below 1/2 at every lattice vertex)"
    serial = run([bccmis, "stuff", square, "-L", "2", "-o", os.path.join(work, "serial.vtu")], expect=2)
    if says not in serial.stderr:
        sys.exit(f"FAIL: bccmis stuff on the square does not say '{says}':\n{serial.stderr}")
    refused([square, "-L", "2"], index, says)
    # Rank 1 (the last rank when there is one) cannot put its piece in place:
    # its target is a directory. Every rank exits 2 and no .pvtu is written.
    last = ranks - 1
    os.mkdir(os.path.join(work, f"out_{last:04d}.vtu"))
    refused(["--shape", "sphere", "-L", "2"], index, f"rank {last}")
    print(f"ok: {ranks} ranks: D1's refused option, --crease-cuts without --gather, an unreadable input, an unwritable directory, a soup enclosing no volume and one "
          "rank's failed piece exit 2 with no .pvtu")


def memory(mpirun, bccmis, bccmis_mpi, ranks, args, work, per_rank, rank0):
    """D16 on its line: --memory-limit (GB, per rank) equal to a rank's estimate."""
    def limited(gigabytes, extra, out, expect):
        r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *extra, "--memory-limit", gigabytes, "-q", "-o", out],
                expect=expect)
        if expect == 0 and not os.path.exists(out):
            sys.exit(f"FAIL: --memory-limit {gigabytes} {extra}: nothing written")
        if expect == 2 and (os.path.exists(out) or os.listdir(work)):
            sys.exit(f"FAIL: --memory-limit {gigabytes} {extra}: a refused run left {os.listdir(work)}")
        if expect == 0:
            for f in os.listdir(work):
                os.remove(os.path.join(work, f))
        return r.stderr
    index, gathered = os.path.join(work, "out.pvtu"), os.path.join(work, "out.vtu")
    # Pieces: every rank's share, 3700 bytes per estimated leaf over the ranks.
    limited(per_rank, [], index, 0)
    said = limited(below(per_rank), [], index, 2)
    # Every rank fails and prints its line; mpirun may drop a line of a rank it
    # ends first, so at least one, each naming its own rank.
    named = [r for r in range(ranks) if f"bccmis-mpi stuff: rank {r}: max level" in said]
    if not named or any(f"GB on rank {r} by D16's estimate" not in said for r in named):
        sys.exit(f"FAIL: one byte below every rank's estimate: no rank named, or a line naming another:\n{said}")
    # --gather: rank 0 also holds the whole mesh; the other ranks their share.
    limited(rank0, ["--gather"], gathered, 0)
    said = limited(below(rank0), ["--gather"], gathered, 2)
    named = [r for r in range(ranks) if f"bccmis-mpi stuff: rank {r}: " in said]
    if named != [0] or "and 4 x 420 for the mesh gathered on rank 0" not in said:
        sys.exit(f"FAIL: one byte below rank 0's estimate with --gather: ranks {named} refused:\n{said}")
    print(f"ok: {ranks} ranks: --memory-limit {per_rank} GB meshes, one byte less refuses every rank; with --gather "
          f"{rank0} GB meshes, one byte less refuses rank 0 alone")


def below(gigabytes):
    """One byte less than `gigabytes` (a decimal number of whole bytes), as a decimal string."""
    return f"{(round(float(gigabytes) * 1e9) - 1) / 1e9:.10f}"


def main():
    mode, mpirun, bccmis, bccmis_mpi, ranks = sys.argv[1:6]
    args = sys.argv[7:] if len(sys.argv) > 6 and sys.argv[6] == "--" else []
    with tempfile.TemporaryDirectory() as work:
        if mode in ("gather", "gather-every-format"):
            gather(mpirun, bccmis, bccmis_mpi, int(ranks), args, work, mode == "gather-every-format")
        elif mode in ("whole", "whole-check", "whole-check-warns"):
            whole(mpirun, bccmis, bccmis_mpi, int(ranks), args, work, mode != "whole", mode == "whole-check-warns")
        elif mode == "stats-features":
            stats_features(mpirun, bccmis, bccmis_mpi, int(ranks), args, work)
        elif mode == "stats-check":
            stats_check(mpirun, bccmis, bccmis_mpi, int(ranks), args, work)
        elif mode == "hausdorff":
            hausdorff(mpirun, bccmis, bccmis_mpi, int(ranks), args, work)
        elif mode == "notices":
            notices(mpirun, bccmis, bccmis_mpi, int(ranks), args, work)
        elif mode == "memory":
            per_rank, rank0, *rest = args
            memory(mpirun, bccmis, bccmis_mpi, int(ranks), rest, work, per_rank, rank0)
        elif mode == "stats":
            stats(mpirun, bccmis, bccmis_mpi, int(ranks), args, work)
        elif mode == "pvtu":
            count, _, pieces = ranks.partition(":")
            pvtu(mpirun, bccmis, bccmis_mpi, int(count), int(pieces) if pieces else None, args, work)
        else:
            errors(mpirun, bccmis, bccmis_mpi, int(ranks), work)


if __name__ == "__main__":
    main()
