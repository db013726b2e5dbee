#!/usr/bin/env bash
# bccmis stuff against its peers (issue 20, "Against the meshers users would
# pick"; bench/RESULTS.md, section 14): on each input, `bccmis stuff` at one
# lattice level, then TetGen and CGAL Mesh_3 (bench/stuff_peers) at about the
# same number of tetrahedra, and one markdown table per input: mesher | time |
# tets | min dihedral | max dihedral | % below 10 deg | volume error. Time:
# wall seconds of the meshing (bccmis: seconds.meshing, input to stencils), with the CPU seconds
# in parentheses where the mesher reports them (stuff_peers does).
#
#   bench/stuff_compare.sh BCCMIS STUFF_PEERS [--max-level L] [--target-tets N] [INPUT.off ...]
#
#   BCCMIS       the bccmis binary (`bccmis stuff INPUT --max-level L --stats --json -o X.vtu`)
#   STUFF_PEERS  build/.../bench/stuff_peers
#   --max-level  bccmis's lattice level (default 5)
#   --target-tets  the tetrahedron count the peers aim at when bccmis stuff
#                fails or is missing (default 50000); otherwise bccmis's count
#   INPUT.off    closed surfaces; by default a sphere of radius 1 written by
#                `stuff_peers sphere-off 1 4` (5,120 triangles) and elephant.off
#                and fandisk.off from Debian's libcgal-demo
#                (/usr/share/doc/libcgal-dev/data.tar.gz, data/meshes/)
#
# Matching the size: the mean tetrahedron volume v = input volume / target.
# TetGen starts at -a 2v (its tetrahedra are mostly well below the bound) and
# CGAL at cell_size = the edge of a regular tetrahedron of volume v; when the
# first run's count is off by more than 10%, more runs (TetGen up to 7 in all,
# CGAL up to 4): the bound moved along a log-log secant (first step: TetGen
# count ~ 1/a, CGAL count ~ 1/size^3) until the target is bracketed, then
# bisected; the run closest to the target is reported (TetGen's count has a
# floor set by the input surface, which -q refines, and jumps with -a). A failing mesher gives a row saying
# so; the others still run.
set -uo pipefail
bccmis=${1:?usage: bench/stuff_compare.sh BCCMIS STUFF_PEERS [--max-level L] [--target-tets N] [INPUT.off ...]}
peers=${2:?usage: bench/stuff_compare.sh BCCMIS STUFF_PEERS [--max-level L] [--target-tets N] [INPUT.off ...]}
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
BENCH_DIR=$(cd "$(dirname "$0")" && pwd)
export BENCH_DIR
exec python3 - "$bccmis" "$peers" "$work" "$@" <<'PYTHON'
import math, os, subprocess, sys, tarfile, time

sys.path.insert(0, os.environ["BENCH_DIR"])
from json_tail import last_json  # noqa: E402

bccmis, peers, work = sys.argv[1:4]
args = sys.argv[4:]
max_level, target_default, inputs = 5, 50000, []
while args:
    a = args.pop(0)
    if a == "--max-level":
        max_level = int(args.pop(0))
    elif a == "--target-tets":
        target_default = int(args.pop(0))
    else:
        inputs.append(a)

if not inputs:
    sphere = f"{work}/sphere.off"
    subprocess.run([peers, "sphere-off", "1", "4", sphere], check=True)
    inputs.append(sphere)
    archive = "/usr/share/doc/libcgal-dev/data.tar.gz"
    try:
        with tarfile.open(archive) as tar:
            for name in ("elephant.off", "fandisk.off"):
                tar.extract(f"data/meshes/{name}", work)
                inputs.append(f"{work}/data/meshes/{name}")
    except (OSError, KeyError, tarfile.TarError) as e:
        print(f"stuff_compare: no libcgal-demo meshes ({archive}: {e}); install libcgal-demo", file=sys.stderr)


def run_json(cmd):
    """Runs cmd; returns its last stdout line that parses as a JSON object, or None."""
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=3600)
    except (OSError, subprocess.TimeoutExpired) as e:
        print(f"stuff_compare: {' '.join(cmd)}: {e}", file=sys.stderr)
        return None
    if p.returncode != 0:
        print(f"stuff_compare: {' '.join(cmd)}: exit status {p.returncode}\n{p.stderr.strip()[-2000:]}",
              file=sys.stderr)
        return None
    # The last JSON object on stdout (one line or pretty-printed; other
    # output around it is skipped).
    found = last_json(p.stdout)
    if found is None:
        print(f"stuff_compare: {' '.join(cmd)}: no JSON object on stdout", file=sys.stderr)
    return found


def seconds_of(r):
    s = r.get("seconds")
    # bccmis: the meshing phases (input to stencils), without --stats' own
    # statistics and the writing; the peers report their meshing alone.
    return s.get("meshing", s.get("total")) if isinstance(s, dict) else s


def input_volume(path):
    """The volume the closed surface encloses (OFF; polygons fanned), as stuff_peers computes it."""
    with open(path) as f:
        lines = [l.split("#")[0].split() for l in f]
    lines = [l for l in lines if l]
    head = lines.pop(0)
    counts = head[1:] if len(head) > 1 else lines.pop(0)
    nv, nf = int(counts[0]), int(counts[1])
    pts = [tuple(map(float, l[:3])) for l in lines[:nv]]
    vol = 0.0
    for l in lines[nv:nv + nf]:
        idx = [int(x) for x in l[1:1 + int(l[0])]]
        for k in range(1, len(idx) - 1):
            (ax, ay, az), (bx, by, bz), (cx, cy, cz) = pts[idx[0]], pts[idx[k]], pts[idx[k + 1]]
            vol += ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)
    return vol / 6


def matched(make_cmd, first, target, exponent, tries):
    """Runs at `first`, then while the count is off by more than 10% (at most
    `tries` runs): until the target is bracketed, a step along a log-log
    secant through the last two runs (the first step uses `exponent`,
    d log parameter / d log count), then bisection of the bracket in log
    space (TetGen's count jumps with -a); stops when two
    runs give the same count (a floor set by the surface). Returns the run
    nearest the target and all runs."""
    runs = []
    param = first
    for _ in range(tries):
        r = run_json(make_cmd(param))
        if r is None or r["tetrahedra"] <= 0:
            break
        runs.append((param, r))
        n = r["tetrahedra"]
        if abs(n / target - 1) <= 0.10:
            break
        # exponent < 0: a larger parameter gives fewer tetrahedra.
        many = [p for p, q in runs if q["tetrahedra"] > target]
        few = [p for p, q in runs if q["tetrahedra"] < target]
        if many and few:
            lo, hi = max(many), min(few)
            if lo < hi:
                param = math.sqrt(lo * hi)
                continue
        k = exponent
        if len(runs) >= 2:
            (p0, r0), (p1, r1) = runs[-2], runs[-1]
            n0, n1 = r0["tetrahedra"], r1["tetrahedra"]
            if abs(math.log(n1 / n0)) < 0.02:
                break
            if p1 != p0:
                k = math.log(p1 / p0) / math.log(n1 / n0)
            k = -min(max(-k, abs(exponent) / 4), abs(exponent) * 4)
        param = param * (target / n) ** k
    if not runs:
        return None, []
    best = min(runs, key=lambda pr: abs(math.log(pr[1]["tetrahedra"] / target)))
    return best, runs


def row(name, r):
    """One table row; a field the mesher did not report shows as '?'."""
    if r is None:
        return f"| {name} | failed | | | | | |"

    def fmt(key, f, scale=1.0):
        x = seconds_of(r) if key == "seconds" else r.get(key)
        return f.format(scale * x) if isinstance(x, (int, float)) else "?"

    cpu = f" (cpu {r['cpu_seconds']:.3f})" if isinstance(r.get("cpu_seconds"), (int, float)) else ""
    return (f"| {name} | {fmt('seconds', '{:.3f} s')}{cpu} | {fmt('tetrahedra', '{:,.0f}')} | "
            f"{fmt('min_dihedral', '{:.2f}')} | {fmt('max_dihedral', '{:.2f}')} | "
            f"{fmt('below10', '{:.3f}', 100)} | {fmt('volume_rel_error', '{:+.3g}%', 100)} |")


for path in inputs:
    vol = input_volume(path)
    cmd = [bccmis, "stuff", path, "--max-level", str(max_level), "--stats", "--json", "-o", f"{work}/stuff.vtu"]
    b = run_json(cmd)
    target = b["tetrahedra"] if b and isinstance(b.get("tetrahedra"), int) and b["tetrahedra"] > 0 else target_default
    v = vol / target
    tet_best, tet_runs = matched(lambda a: [peers, "tetgen", path, "--max-volume", f"{a:.6g}"], 2 * v, target, -1.0, 7)
    edge = (6 * math.sqrt(2) * v) ** (1 / 3)
    cgal_best, cgal_runs = matched(lambda s: [peers, "cgal", path, "--cell-size", f"{s:.6g}"], edge, target, -1 / 3, 4)
    print(f"\n### {path} (enclosed volume {vol:.6g}; target {target:,} tetrahedra"
          f"{'' if b else ', bccmis stuff failed'})\n")
    print("| mesher | time | tets | min dihedral | max dihedral | % below 10 deg | volume error |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    print(row(f"bccmis stuff --max-level {max_level}", b))
    print(row(f"TetGen -pq1.414 -a{tet_best[0]:.3g}" if tet_best else "TetGen", tet_best[1] if tet_best else None))
    print(row(f"CGAL Mesh_3 size {cgal_best[0]:.3g}" if cgal_best else "CGAL Mesh_3",
              cgal_best[1] if cgal_best else None))
    calib = [f"tetgen -a{a:.3g}: {r['tetrahedra']:,}" for a, r in tet_runs]
    calib += [f"cgal size {s:.3g}: {r['tetrahedra']:,}" for s, r in cgal_runs]
    print(f"\nruns: {'; '.join(calib)}")
    sys.stdout.flush()
PYTHON
