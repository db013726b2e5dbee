#!/usr/bin/python3
"""bccmis stuff on the triangle files people have (issue 27, "Meshes in the
wild"): every mesh in Debian's libcgal-demo data (data/meshes/*.off, .stl,
.ply, .obj in /usr/share/doc/libcgal-dev/data.tar.gz; about 140 files, many
open, self-intersecting, degenerate or inconsistently oriented), meshed by
`bccmis stuff` (the default path, and `--strict` when the CLI has it), TetGen
(`tetgen -pq1.414`) and CGAL Mesh_3 (`stuff_peers cgal`), each run with a
timeout and a memory cap; every run classified:
  meshed   exit 0 and a mesh that passes the checks (bccmis: its own --check,
           i.e. exact positive orientation, conformity, closed boundary on
           the surface, dihedral bounds; peers: tetrahedra > 0 and every one
           positively oriented, computed here from their output);
  refused  the mesher declined the input (bccmis: exit 2; TetGen: a nonzero
           exit with a message; CGAL: stuff_peers' exit 1 with a message,
           not a failed CGAL assertion), with the first line of the message;
  failed   a crash (a signal, e.g. Debian's tetgen aborting on an uncaught
           `int` exception, its error path, with no message; another exit
           status), a timeout, out of memory, no tetrahedra (e.g. TetGen
           removing every tetrahedron of an open input as exterior), or a
           mesh failing the checks.
And for every meshed run, an INDEPENDENT volume check (wildmesh.py): the
volume V of the solid {q : w(q) >= 1/2}, w the generalized winding number of
the input triangles (Van Oosterom-Strackee solid angles, numpy; -w for a
surface whose signed volume is negative, i.e. oriented inward as a whole:
today's bccmis meshes those, e.g. tetrahedron.off, as the solid they bound),
estimated by stratified uniform sampling of the bounding box (fixed seed) with its
binomial standard error sigma (an upper bound for stratified sampling),
against the mesh's volume (bccmis: read from its .vtu; peers: from their
tetrahedra). "vol ok" when |V_mesh - V| <= (A + A_holes) * h + 3 sigma:
  - bccmis's mesh boundary lies within about h of the surface {w = 1/2}
    (h = the finest lattice side: the boundary vertices are cut points on,
    or lattice vertices warped onto, the surface, and every boundary
    triangle lies in the band of finest cells the surface crosses);
  - the region between two surfaces S and M with M within distance d of S
    is swept by segments of length <= d along S's normals, so to first order
    in d * curvature |V_mesh - V| <= d * area(S);
  - area(S) <= A + A_holes: the triangles' area A (parts of the input inside
    the solid, e.g. at self-intersections or duplicate faces, only add to A)
    plus, for an open input, the fans closing its border loops (S spans the
    holes; exact for planar holes);
  - sigma: the sampling error, 3 sigma for a 99.7% bound.
  For the peers the same bound with h = their size parameter (CGAL's cell
  and facet size; TetGen keeps the input's facets); reported, not used to
  classify. "vol off" for bccmis counts as a failure. Files over
  --max-wn-triangles triangles are "not estimated" (the sampling costs
  points x triangles).

Sizes: bccmis at --level L; h = the finest side it prints (else the
longest bounding-box side / (4 * 2^L - 10), the fit of the default 4 cells).
The peers at a comparable size, not matched (matching costs several runs a
file; bench/stuff_compare.sh does that for clean inputs): CGAL with
cell_size = facet_size = h, facet_distance h / 20; TetGen with -a h^3.
PLY files are given to the peers as OFF.

Output (in --out DIR, default build/stuff_wild): table.md (a row per
file: triangles, flaws found here and in bccmis's JSON, per mesher the
result, tetrahedra, min-max dihedral, seconds, volume against the winding
number volume, then a summary line per mesher) and runs.jsonl (one JSON object
a file). The table is also printed.

  /usr/bin/python3 bench/stuff_wild.py --bccmis build/release/tools/bccmis/bccmis \\
      --peers build/release/bench/stuff_peers [--level 3] [--timeout 60] \\
      [--memory-gb 4] [--only PATTERN] [--out DIR] [--jobs 1] [--no-peers] \\
      [--stats] [--reuse RUNS.jsonl] [--peers-from RUNS.jsonl]

  --only PATTERN   a regular expression searched in the file names (e.g. 'cube|sphere')
  --jobs N         files in parallel (each run is single-threaded)
  --no-peers       bccmis alone; --reuse RUNS.jsonl then adds the peers to
                   that run's bccmis results without running bccmis again
  --peers-from RUNS.jsonl
                   the reverse: bccmis runs, TetGen's and CGAL's runs are
                   taken from that earlier run (they do not change with
                   bccmis)
  --stats          pass --stats to bccmis too (its JSON then has the counts,
                   angles, Hausdorff distance; slower)
On 2 shared cores (load ~10) with --jobs 2: about 5 minutes for bccmis and
the winding numbers at -L 3, about 17 more for the peers.
Needs numpy (Debian's python3-numpy: /usr/bin/python3) and tetgen.
"""
import argparse
import concurrent.futures
import datetime
import json
import math
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tarfile
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
try:
    import numpy as np  # noqa: F401
except ImportError:
    sys.exit("stuff_wild: needs numpy; run with /usr/bin/python3 (Debian's python3-numpy)")
import wildmesh as W  # noqa: E402
from json_tail import last_json  # noqa: E402

ARCHIVE = "/usr/share/doc/libcgal-dev/data.tar.gz"
MESH_EXT = (".off", ".stl", ".ply", ".obj")


def run(cmd, timeout, memory_gb, cwd=None):
    """Runs cmd in its own process group under an address-space cap; kills the
    group on timeout. Returns (status, stdout, stderr, seconds); status is
    the exit code, -signal, or 'timeout'."""
    def limit():
        cap = int(memory_gb * 2**30)
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    start = time.monotonic()
    try:
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace",
                             preexec_fn=limit, start_new_session=True, cwd=cwd)
    except OSError as e:
        return 127, "", str(e), 0.0
    try:
        out, err = p.communicate(timeout=timeout)
        status = p.returncode
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = p.communicate()
        status = "timeout"
    return status, out, err, time.monotonic() - start




def first_line(text, drop=()):
    for l in text.splitlines():
        l = l.strip()
        if l and not any(l.startswith(d) for d in drop):
            return l[:160]
    return ""


OOM = re.compile(r"bad_alloc|out of memory|Cannot allocate|std::length_error", re.I)


def failure(status, err):
    if status == "timeout":
        return "timeout"
    if OOM.search(err):
        return "out of memory"
    if isinstance(status, int) and status < 0 and "terminate called" in err:
        return "crash (%s)" % first_line(err[err.find("terminate called"):])
    if isinstance(status, int) and status < 0:
        return "crash (signal %d %s)" % (-status, signal.Signals(-status).name if -status in
                                         signal.valid_signals() else "")
    return "exit %s: %s" % (status, first_line(err))


def volume_verdict(r, ref, h):
    """Adds the volume comparison to a meshed run r."""
    if ref is None or r.get("volume") is None:
        r["volume_check"] = "not estimated"
        return
    tol = (ref["area"] + ref["cap_area"]) * h + 3 * ref["sigma"]
    diff = r["volume"] - ref["volume"]
    r["volume_diff"], r["volume_tolerance"] = diff, tol
    r["volume_check"] = "ok" if abs(diff) <= tol else "off"


def quality_verdict(r, q, not_positive):
    """Records in r the quality q of a mesher's output read back: failed
    with no tetrahedra or with some not positive (the reason `not_positive`
    % their count), else meshed; True when meshed."""
    r.update(q)
    if q["tetrahedra"] == 0:
        r.update(result="failed", reason="no tetrahedra")
    elif q["inverted"]:
        r.update(result="failed", reason=not_positive % q["inverted"])
    else:
        r["result"] = "meshed"
        return True
    return False


def run_bccmis(bccmis, path, level, strict, args, work, ref, fl):
    out = os.path.join(work, "bccmis%s.vtu" % ("_strict" if strict else ""))
    cmd = [bccmis, "stuff", path, "-L", str(level), "--check", "-o", out]
    if args.stats:  # --json implies --stats (spec/cli.md)
        cmd.insert(-2, "--json")
    if strict:
        cmd.insert(3, "--strict")
    status, so, se, secs = run(cmd, args.timeout, args.memory_gb)
    topology = [line for line in se.splitlines() if "the mesh's boundary has" in line]
    if status == 1 and topology:
        # S27: under --check a boundary whose topology differs from the input's
        # at this level is exit 1, after the geometric checks (S11) passed;
        # the same run without --check writes that mesh, checked below.
        cmd = [c for c in cmd if c != "--check"]
        status, so, se, secs = run(cmd, args.timeout, args.memory_gb)
    r = {"mesher": "bccmis" + (" --strict" if strict else ""), "command": " ".join(cmd[1:]), "seconds": secs,
         "status": status, "last_stderr": (se.strip().splitlines() or [""])[-1][:200]}
    if status == 0 and topology:
        r["topology"] = topology[0].split(": ", 2)[-1]
    j = last_json(so)
    if j:
        r["json"] = {k: v for k, v in j.items() if k not in ("dihedral_histogram",)}
    m = re.search(r"finest side ([0-9.eE+-]+)", se)
    r["h"] = float(m.group(1)) if m else None
    if status == 0:
        try:
            q = W.tet_quality(*W.vtu_tets(out))
        except (OSError, W.ReadError, KeyError, ValueError) as e:
            r.update(result="failed", reason="output unreadable: %s" % e)
            return r
        if quality_verdict(r, q, "%d tetrahedra not positive (read back)"):
            h = r["h"] or fl["fallback_h"]
            volume_verdict(r, ref, h)
            if r["volume_check"] == "off":
                r.update(result="failed", reason="volume off")
    elif status == 2:
        # The error line ("bccmis: ..."), not the report of the flaws found before it.
        errors = [line for line in se.splitlines() if line.startswith("bccmis: ")]
        r.update(result="refused", reason=errors[-1] if errors else first_line(se, drop=("bccmis stuff: mesh ",)))
    elif status == 1:
        r.update(result="failed", reason="check: " + first_line(se, drop=("bccmis stuff: ",)) or "exit 1")
    else:
        r.update(result="failed", reason=failure(status, se))
    try:
        os.remove(out)
    except OSError:
        pass
    return r


def run_tetgen(off, h, args, work, ref):
    d = os.path.join(work, "tetgen")
    os.makedirs(d, exist_ok=True)
    inp = os.path.join(d, "in.off")
    shutil.copyfile(off, inp)
    # stdbuf: TetGen aborts (an uncaught exception) on some inputs; its
    # progress lines before that still arrive.
    cmd = ["stdbuf", "-oL", "tetgen", "-pq1.414", "-a%.6g" % (h ** 3), inp]
    status, so, se, secs = run(cmd, args.timeout, args.memory_gb, cwd=d)
    r = {"mesher": "tetgen", "command": "tetgen -pq1.414 -a%.3g" % (h ** 3), "seconds": secs}
    if status == 0 and not os.path.exists(os.path.join(d, "in.1.ele")):
        r.update(result="failed", reason="no tetrahedra (%s)" % (
            "all removed as exterior" if re.search(r"Mesh tetrahedra: 0", so) else "no .ele written"))
    elif status == 0:
        try:
            q = W.tet_quality(*W.tetgen_tets(os.path.join(d, "in.1")))
            if quality_verdict(r, q, "%d tetrahedra not positive"):
                volume_verdict(r, ref, h)
        except (OSError, IndexError, ValueError) as e:
            r.update(result="failed", reason="output unreadable: %s" % e)
    elif isinstance(status, int) and status > 0 and not OOM.search(se + so):
        # TetGen prints its diagnosis on stdout ("A self-intersection was detected." etc.).
        msg = [l.strip() for l in so.splitlines() if re.search(r"error|intersect|invalid|fail|degenerate|"
                                                                 r"duplicate|overlap|not", l, re.I)]
        r.update(result="refused", reason="exit %d: %s" % (status, (msg[0] if msg else first_line(se) or
                                                                  first_line(so.splitlines()[-1] if so else ""))[:160]))
    else:
        r.update(result="failed", reason=failure(status, se + so))
    shutil.rmtree(d, ignore_errors=True)
    return r


def run_cgal(peers, off, h, args, ref):
    cmd = [peers, "cgal", off, "--cell-size", "%.6g" % h]
    status, so, se, secs = run(cmd, args.timeout, args.memory_gb)
    r = {"mesher": "cgal", "command": "stuff_peers cgal --cell-size %.3g" % h, "seconds": secs}
    j = last_json(so)
    if status == 0 and j:
        r.update({k: j.get(k) for k in ("tetrahedra", "volume", "inverted", "min_dihedral", "max_dihedral")})
        r["mesh_seconds"] = j.get("seconds")
        if not j.get("tetrahedra"):
            r.update(result="failed", reason="no tetrahedra")
        elif j.get("inverted"):
            r.update(result="failed", reason="%d tetrahedra not positive" % j["inverted"])
        else:
            r["result"] = "meshed"
            volume_verdict(r, ref, h)
    elif status == 1 and "stuff_peers:" in se and not OOM.search(se):
        msg = first_line(se, drop=("stuff_peers: warning",))
        expr = re.search(r"Expr: (.*)", se)
        if expr:
            msg += " " + expr.group(1).strip()
        # CGAL's failed assertions are internal errors; its preconditions and
        # stuff_peers' own messages decline the input.
        r.update(result="failed" if "assertion violation" in msg else "refused", reason=msg[:160])
    else:
        r.update(result="failed", reason=failure(status, se))
    return r


def short_paths(rec, path):
    d = os.path.dirname(path) + os.sep
    for m in ("bccmis", "bccmis_strict", "tetgen", "cgal"):
        r = rec.get(m)
        if r and "reason" in r:
            r["reason"] = r["reason"].replace(d, "")
        if r and "command" in r:
            r["command"] = r["command"].replace(d, "")
    return rec


def one_file(path, args, has_strict, reuse=None, peers_from=None):
    """All runs on one file; with reuse (a record of an earlier run), its
    flaws, winding-number volume and bccmis runs are taken and only the
    peers run; with peers_from (a record of an earlier run), its peers'
    runs are taken and only bccmis runs."""
    name = os.path.basename(path)
    rec = {"file": name}
    work = tempfile.mkdtemp(prefix="stuff_wild.")
    try:
        try:
            pts, tris = W.read_mesh(path)
        except (W.ReadError, OSError) as e:
            pts, tris = None, None
            rec["read_error"] = str(e)
        if reuse is not None:
            rec.update({k: v for k, v in reuse.items() if k not in ("tetgen", "cgal")})
            if pts is not None and len(tris) and rec["winding"] is not None and W.signed_volume(pts, tris) < 0:
                # Earlier runs took w >= 1/2 for inward surfaces too: estimate again.
                ref = rec["winding"]
                vol, sigma, npts, box = W.winding_volume(pts, tris, ref["points"], seed=args.seed)
                ref.update(volume=vol, sigma=sigma, points=npts)
                for m in ("bccmis", "bccmis_strict"):
                    r = rec.get(m)
                    if r and (r["result"] == "meshed" or r.get("reason") == "volume off"):
                        r["result"] = "meshed"
                        r.pop("reason", None)
                        volume_verdict(r, ref, r.get("h") or rec["flaws"]["fallback_h"])
                        if r["volume_check"] == "off":
                            r.update(result="failed", reason="volume off")
        else:
            fl = W.flaws(pts, tris) if pts is not None else {"triangles": None}
            ext = np.ptp(pts[np.isfinite(pts).all(axis=1)], axis=0) if pts is not None and len(pts) else np.zeros(3)
            longest = float(ext.max()) if len(ext) else 0.0
            fl["fallback_h"] = longest / (4 * 2 ** args.level - 10) if longest > 0 else None
            rec["flaws"] = fl
            ref = None
            if pts is not None and 0 < len(tris) <= args.max_wn_triangles:
                n = int(min(args.wn_points, max(512, args.wn_pairs // max(len(tris), 1))))
                t0 = time.monotonic()
                vol, sigma, npts, box = W.winding_volume(pts, tris, n, seed=args.seed)
                ref = {"volume": vol, "sigma": sigma, "points": npts, "area": fl["area"],
                       "cap_area": fl["cap_area"], "seconds": time.monotonic() - t0}
            rec["winding"] = ref
            rec["bccmis"] = run_bccmis(args.bccmis, path, args.level, False, args, work, ref, fl)
            if has_strict:
                rec["bccmis_strict"] = run_bccmis(args.bccmis, path, args.level, True, args, work, ref, fl)
        fl, ref = rec["flaws"], rec["winding"]
        h = rec["bccmis"].get("h") or fl["fallback_h"]
        if peers_from is not None:
            for m in ("tetgen", "cgal"):
                if m in peers_from:
                    rec[m] = peers_from[m]
        elif not args.no_peers:
            if pts is None or not h or len(tris) == 0:
                for m in ("tetgen", "cgal"):
                    rec[m] = {"mesher": m, "result": "refused", "reason": "not run: %s" %
                              rec.get("read_error", "no triangles" if pts is not None else "no extent")}
            else:
                off = path
                if not path.lower().endswith(".off"):
                    off = os.path.join(work, "input.off")
                    W.write_off(off, pts, tris)
                rec["tetgen"] = run_tetgen(off, h, args, work, ref)
                rec["cgal"] = run_cgal(args.peers, off, h, args, ref)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return short_paths(rec, path)


def flaw_text(rec):
    fl = rec["flaws"]
    if fl.get("triangles") is None:
        return "unreadable"
    parts = []
    for key, label in (("border_edges", "border"), ("nonmanifold_edges", "nonmanifold"),
                       ("misoriented_edges", "misoriented"), ("zero_area", "zero-area"),
                       ("nonfinite_points", "nan")):
        if fl.get(key):
            parts.append("%s %d" % (label, fl[key]))
    j = rec["bccmis"].get("json") or {}
    rep = j.get("flaws")
    if rep:
        parts.append("bccmis: " + json.dumps(rep, separators=(",", ":"))[:120])
    return ", ".join(parts) or "-"


def cell(r):
    if r is None:
        return "-"
    res = r["result"]
    if res != "meshed":
        reason = r.get("reason", "").replace("|", "/")
        return "**%s** %s" % (res, reason) if res == "failed" else "%s: %s" % (res, reason)
    s = "%s tets, %.1f-%.1f deg, %.1f s" % ("{:,}".format(r["tetrahedra"]), r["min_dihedral"] or 0,
                                            r["max_dihedral"] or 0, r["seconds"])
    if r.get("volume_check") in ("ok", "off"):
        s += ", vol %.4g (%s)" % (r["volume"], r["volume_check"])
    return s


def bccmis_cell(r, ref):
    res = r["result"]
    if res == "meshed" or r.get("reason") == "volume off":
        s = "%s%s tets, %.2f-%.2f deg, %.1f s" % ("**failed** volume off: " if res != "meshed" else "",
                                                  "{:,}".format(r["tetrahedra"]), r["min_dihedral"],
                                                  r["max_dihedral"], r["seconds"])
        if ref and r.get("volume_diff") is not None:
            s += ", vol %.4g vs %.4g +- %.2g (tol %.2g)" % (r["volume"], ref["volume"], ref["sigma"],
                                                           r["volume_tolerance"])
        else:
            s += ", vol %.4g (w: not estimated)" % r["volume"]
        if r.get("topology"):
            s += "; topology at this level: %s" % r["topology"]
        return s
    return cell(r)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bccmis", default=os.path.join(here, "..", "build", "release", "tools", "bccmis", "bccmis"))
    ap.add_argument("--peers", default=os.path.join(here, "..", "build", "release", "bench", "stuff_peers"))
    ap.add_argument("--archive", default=ARCHIVE)
    ap.add_argument("--level", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--memory-gb", type=float, default=4)
    ap.add_argument("--only", default=None, help="regular expression searched in the file names")
    ap.add_argument("--out", default=os.path.join(here, "..", "build", "stuff_wild"))
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--no-peers", action="store_true")
    ap.add_argument("--stats", action="store_true", help="also pass --stats to bccmis (slower: Hausdorff distance)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--reuse", default=None, help="runs.jsonl of an earlier run at the same level: its bccmis runs "
                    "and winding-number volumes are taken, only the peers run")
    ap.add_argument("--peers-from", default=None, help="runs.jsonl of an earlier run at the same level: its "
                    "TetGen and CGAL runs are taken, only bccmis runs (the peers do not change with bccmis)")
    ap.add_argument("--wn-points", type=int, default=8000, help="sample points at most")
    ap.add_argument("--wn-pairs", type=int, default=10_000_000,
                    help="points x triangles budget (the sample shrinks to it, to 512 points at least)")
    ap.add_argument("--max-wn-triangles", type=int, default=200_000)
    args = ap.parse_args()

    helptext = run([args.bccmis, "stuff", "--help"], 30, 4)[1]
    if "Usage" not in helptext:
        sys.exit("stuff_wild: %s stuff --help failed" % args.bccmis)
    has_strict = "--strict" in helptext
    if not args.no_peers and not shutil.which("tetgen"):
        sys.exit("stuff_wild: no tetgen (apt-get install tetgen) ; or --no-peers")

    def runs_by_file(path):
        with open(path) as f:
            return {r["file"]: r for r in map(json.loads, f)}

    reused = runs_by_file(args.reuse) if args.reuse else {}
    peers_from = runs_by_file(args.peers_from) if args.peers_from else {}
    if args.peers_from:
        args.no_peers = False
    data = tempfile.mkdtemp(prefix="stuff_wild_data.")
    try:
        with tarfile.open(args.archive) as tar:
            members = [m for m in tar.getmembers() if m.isfile() and m.name.startswith("data/meshes/")
                       and m.name.lower().endswith(MESH_EXT) and "/" not in m.name[len("data/meshes/"):]]
            if args.only:
                members = [m for m in members if re.search(args.only, os.path.basename(m.name))]
            tar.extractall(data, members=members)
        files = sorted(os.path.join(data, m.name) for m in members)
        os.makedirs(args.out, exist_ok=True)
        started = time.monotonic()
        recs = {}
        with open(os.path.join(args.out, "runs.jsonl"), "w") as jl:
            with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as ex:
                futs = {ex.submit(one_file, f, args, has_strict, reused.get(os.path.basename(f)),
                                  peers_from.get(os.path.basename(f)) if args.peers_from else None): f for f in files}
                for fut in concurrent.futures.as_completed(futs):
                    rec = fut.result()
                    recs[rec["file"]] = rec
                    jl.write(json.dumps(rec) + "\n")
                    jl.flush()
                    print("stuff_wild: %-36s bccmis %-8s tetgen %-8s cgal %-8s" % (
                        rec["file"], rec["bccmis"]["result"], rec.get("tetgen", {}).get("result", "-"),
                        rec.get("cgal", {}).get("result", "-")), file=sys.stderr, flush=True)
        elapsed = time.monotonic() - started
    finally:
        shutil.rmtree(data, ignore_errors=True)

    meshers = ["bccmis"] + (["bccmis_strict"] if has_strict else []) + ([] if args.no_peers else ["tetgen", "cgal"])
    titles = {"bccmis": "bccmis stuff -L %d" % args.level, "bccmis_strict": "bccmis --strict",
              "tetgen": "TetGen -pq1.414 -a h^3", "cgal": "CGAL Mesh_3 size h"}
    lines = ["# bccmis stuff on libcgal-demo's meshes (bench/stuff_wild.py)", "",
             "%s; `%s`; level %d, timeout %g s, memory cap %g GB; %d files in %.0f s (%s)." % (
                 datetime.date.today().isoformat(), " ".join([os.path.relpath(args.bccmis)] + ["stuff", "FILE", "-L",
                                                                                                  str(args.level), "--check"]),
                 args.level, args.timeout, args.memory_gb, len(recs), elapsed,
                 "strict option present" if has_strict else "no --strict: today's default is strict"),
             "Flaws counted here: border (edges used once), nonmanifold (3+ faces), misoriented (two faces "
             "traverse the edge the same way), zero-area faces; self-intersections are only known from the "
             "meshers' messages. vol: the mesh's volume against the winding-number volume of the input "
             "+- its standard error, tolerance (A + A_holes) h + 3 sigma.", "",
             "| file | triangles | flaws | " + " | ".join(titles[m] for m in meshers) + " |",
             "|---|---:|---|" + "---|" * len(meshers)]
    for name in sorted(recs):
        rec = recs[name]
        tri = rec["flaws"].get("triangles")
        row = ["`%s`" % name, "{:,}".format(tri) if tri is not None else "?", flaw_text(rec)]
        for m in meshers:
            row.append(bccmis_cell(rec[m], rec["winding"]) if m.startswith("bccmis") else cell(rec.get(m)))
        lines.append("| " + " | ".join(row) + " |")
    lines.append("")
    for m in meshers:
        counts = {k: sum(1 for r in recs.values() if r.get(m, {}).get("result") == k)
                  for k in ("meshed", "refused", "failed")}
        vol_off = sum(1 for r in recs.values() if r.get(m, {}).get("volume_check") == "off")
        topo = sum(1 for r in recs.values() if r.get(m, {}).get("result") == "meshed" and r[m].get("topology"))
        reasons = {}
        for r in recs.values():
            x = r.get(m, {})
            if x.get("result") == "failed":
                k = re.sub(r"\d+", "N", x.get("reason", ""))[:40]
                reasons[k] = reasons.get(k, 0) + 1
        lines.append("- **%s**: %d meshed%s, %d refused, %d failed of %d%s%s" % (
            titles[m], counts["meshed"],
            " (%d of them with a boundary whose topology differs from the input's at this level, S27: "
            "exit 1 under --check, meshed and checked here without it)" % topo if topo else "",
            counts["refused"], counts["failed"], len(recs),
            "; volume off the winding-number volume: %d" % vol_off if vol_off else "",
            " (failures: %s)" % "; ".join("%s x%d" % kv for kv in sorted(reasons.items())) if reasons else ""))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "table.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
