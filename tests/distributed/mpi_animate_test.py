#!/usr/bin/env python3
"""bccmis-mpi stuff --animate against bccmis stuff --animate (spec/distributed.md D14, D15).

  mpi_animate_test.py frames MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      with --animate in STUFF_ARGS: every frame's union of pieces (-o OUT.pvtu:
      OUT_KKKK.pvtu, its pieces OUT_KKKK_RRRR.vtu) and every gathered frame
      (--gather -o OUT.vtu: OUT_KKKK.vtu) holds the serial frame's tetrahedra
      (by vertex positions, bit for bit, with their levels), and each OUT.pvd
      lists the frames as the serial .pvd does (timesteps 0 .. N); the pieces run with
      --json --compare and the gathered run with --stats --check (D17): each frame's tetrahedra the
      serial frame's cells, its leaves the serial --stats frame's, the check passing.
  mpi_animate_test.py steps MPIRUN BCCMIS BCCMIS_MPI RANKS -- STUFF_ARGS...
      the same, and D15's step of every frame after the first (rank 0's
      "forest: ..." line) both coarsened and refined leaves; with
      --repartition-threshold 1 in STUFF_ARGS, every step repartitioned.
  mpi_animate_test.py faults MPIRUN BCCMIS BCCMIS_MPI RANKS
      an empty frame (the sphere moved out of reach): bccmis stuff and the
      ranks refuse it with exit 2 and the same message (S26, D14), nothing
      written; D17's check of the moved forest, handed a wrong forest by its
      test hook (BCCMIS_TEST_CHECK_PREVIOUS_FRAME), exit 1 naming the frame,
      nothing written; the notice that the lattice fits the swept box, in
      bccmis stuff's words (S26, D14).
  mpi_animate_test.py signals MPIRUN BCCMIS BCCMIS_MPI RANKS
      D18: while the ranks stage their frames, SIGKILL to every rank leaves
      one hidden staging directory and nothing else, which the next run of
      the same outputs removes (saying so) before writing its own; SIGTERM
      to every rank leaves nothing.
  mpi_animate_test.py refusals MPIRUN BCCMIS BCCMIS_MPI RANKS
      the options D14 refuses with --animate, each by name: exit 2, D14 named,
      nothing written; --check without --gather (D17, naming D12).
"""
import collections
import fcntl
import json
import os
import re
import signal
import socket
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

import meshio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mpi_stuff_test import mpi, run, tets_of  # noqa: E402


def pvd_frames(path):
    """The (timestep, file) pairs a .pvd lists."""
    return [(int(d.get("timestep")), d.get("file")) for d in ET.parse(path).getroot().iter("DataSet")]


def pvtu_tets(work, index):
    sources = [p.get("Source") for p in ET.parse(os.path.join(work, index)).getroot().iter("Piece")]
    tets = []
    for source in sources:
        tets += tets_of(meshio.read(os.path.join(work, source)))
    return tets, len(sources)


FOREST = re.compile(r"frame (\d+)/\d+: \d+ tetrahedra; forest: (\d+) coarsened, (\d+) refined, "
                    r"(\d+) corrections, imbalance ([0-9.]+)(, repartitioned)?")


def frames(mpirun, bccmis, bccmis_mpi, ranks, args, work, steps=False):
    serial_args = [a for i, a in enumerate(args) if a != "--repartition-threshold"
                   and (i == 0 or args[i - 1] != "--repartition-threshold")]
    serial_table = run([bccmis, "stuff", *serial_args, "-q", "--stats", "-o", os.path.join(work, "serial.pvd")]).stdout
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, *([] if steps else ["-q"]), "--json", "--compare",
                                  "-o", os.path.join(work, "out.pvtu")])
    report = json.loads(r.stdout)
    if steps:
        forest = [m.groups() for m in FOREST.finditer(r.stderr)]
        frames_after_0 = int(args[args.index("--animate") + 1])
        if [int(g[0]) for g in forest] != list(range(1, frames_after_0 + 1)):
            sys.exit(f"FAIL: rank 0 reports the steps of frames {[g[0] for g in forest]}:\n{r.stderr}")
        for k, coarsened, refined, _, _, _ in forest:
            if int(coarsened) == 0 or int(refined) == 0:
                sys.exit(f"FAIL: frame {k}'s step coarsened {coarsened} and refined {refined} families: "
                         "the path does not exercise both")
        if "--repartition-threshold" in args and args[args.index("--repartition-threshold") + 1] == "1":
            if not all(g[5] for g in forest):
                sys.exit(f"FAIL: --repartition-threshold 1: a step with imbalance above 1 not repartitioned:\n"
                         f"{r.stderr}")
        print(f"{ranks} ranks: steps (coarsened, refined, corrections, imbalance, repartitioned): "
              f"{[(int(g[1]), int(g[2]), int(g[3]), float(g[4]), bool(g[5])) for g in forest]}")
    table = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *args, "-q", "--stats", "--check", "--gather",
                                      "-o", os.path.join(work, "whole.vtu")]).stdout
    serial = pvd_frames(os.path.join(work, "serial.pvd"))
    steps = [k for k, _ in serial]
    if len(serial) < 2 or steps != list(range(len(serial))):
        sys.exit(f"FAIL: the serial .pvd lists {serial}")
    for stem, ext in (("out", ".pvtu"), ("whole", ".vtu")):
        want = [(k, f"{stem}_{k:04d}{ext}") for k in steps]
        got = pvd_frames(os.path.join(work, stem + ".pvd"))
        if got != want:
            sys.exit(f"FAIL: {stem}.pvd lists {got}, expected {want}")
    counts, meshes = [], []
    for k, name in serial:
        want = collections.Counter(tets_of(meshio.read(os.path.join(work, name))))
        meshes.append(want)
        pieces, n = pvtu_tets(work, f"out_{k:04d}.pvtu")
        if collections.Counter(pieces) != want or len(pieces) != sum(want.values()):
            sys.exit(f"FAIL: {ranks} ranks: frame {k}: the union of its {n} pieces ({len(pieces)} tetrahedra) "
                     f"differs from the serial frame's {sum(want.values())} tetrahedra")
        whole = collections.Counter(tets_of(meshio.read(os.path.join(work, f"whole_{k:04d}.vtu"))))
        if whole != want:
            sys.exit(f"FAIL: {ranks} ranks: frame {k}: the gathered frame differs from the serial frame")
        counts.append(sum(want.values()))
    same_report(report, table, serial_table, counts)
    if meshes[0] == meshes[1]:
        sys.exit("FAIL: the serial frames 0 and 1 are the same mesh: the shape does not move")
    print(f"ok: {ranks} ranks: {len(serial)} frames ({counts} tetrahedra), pieces and gathered, "
          "are the serial frames; the .pvd files list them; --json and --stats report them (D17), --check passes")


#= spec/distributed.md#D17 type=test
def same_report(report, table, serial_table, counts):
    """D17: the --json frames (pieces run) and the --stats table (gathered, --check run) name the same
    forests, each frame's tetrahedra are the serial .vtu frame's cells (counted by meshio) and its leaves
    the serial --stats frame's leaves."""
    header, *rows = table.splitlines()
    names = header.split()
    if names != ["frame", "coarsened", "refined", "corrections", "imbalance", "repartitioned", "leaves",
                 "tetrahedra", "seconds"] or rows[-1].split()[0] != "mean_step_seconds":
        sys.exit(f"FAIL: the --stats table:\n{table}")
    text = [dict(zip(names, row.split())) for row in rows[:-1]]
    serial_rows = serial_table.splitlines()
    serial_names = serial_rows[0].split()
    serial = [dict(zip(serial_names, row.split())) for row in serial_rows[1:len(counts) + 1]]
    frames = report["frames"]
    if [f["frame"] for f in frames] != list(range(len(counts))) or len(text) != len(counts):
        sys.exit(f"FAIL: the reports list frames {[f['frame'] for f in frames]} and {len(text)} rows, "
                 f"the serial run {len(counts)}")
    for f, t, s, n in zip(frames, text, serial, counts):
        k = f["frame"]
        if f["tetrahedra"] != n or int(t["tetrahedra"]) != n:
            sys.exit(f"FAIL: frame {k}: --json {f['tetrahedra']}, --stats {t['tetrahedra']} tetrahedra, "
                     f"the serial frame's .vtu {n}")
        if f["leaves"] != int(s["leaves"]) or int(t["leaves"]) != f["leaves"]:
            sys.exit(f"FAIL: frame {k}: --json {f['leaves']}, --stats {t['leaves']} leaves, serial {s['leaves']}")
        for name in ("coarsened", "refined", "corrections"):
            if int(t[name]) != f[name]:
                sys.exit(f"FAIL: frame {k}: {name} {t[name]} (--stats) against {f[name]} (--json)")
        if int(t["repartitioned"]) != int(f["repartitioned"]) or float(t["imbalance"]) != f["imbalance"]:
            sys.exit(f"FAIL: frame {k}: the imbalance or repartition differ between --stats and --json")
        if (k == 0) != (f["coarsened"] == 0 and f["refined"] == 0) or not f["seconds"] > 0:
            sys.exit(f"FAIL: frame {k}: a step's counts or seconds: {f}")
    steps = [f["seconds"] for f in frames[1:]]
    if abs(report["mean_step_seconds"] - sum(steps) / len(steps)) > 1e-6 * report["mean_step_seconds"]:
        sys.exit(f"FAIL: mean_step_seconds {report['mean_step_seconds']}, the frames' {steps}")
    # --compare: every later frame also built from the brick and timed, the ratio of the means.
    scratch = [f["scratch_seconds"] for f in frames[1:]]
    if not all(t > 0 for t in scratch) or frames[0]["scratch_seconds"] != 0 or "scratch_seconds" in text[0]:
        sys.exit(f"FAIL: --compare: scratch seconds {[f['scratch_seconds'] for f in frames]}, the table {text[0]}")
    ratio = report["mean_scratch_seconds"] / report["mean_step_seconds"]
    if abs(report["speedup"] - ratio) > 1e-6 * ratio:
        sys.exit(f"FAIL: --compare: speedup {report['speedup']}, the means' ratio {ratio}")


def message(stderr, prefix):
    """The text after `prefix` on the line of stderr that starts with it."""
    lines = [line[len(prefix):] for line in stderr.splitlines() if line.startswith(prefix)]
    return lines[0] if len(lines) == 1 else None


#= spec/distributed.md#D14 type=test
#= spec/distributed.md#D17 type=test
def faults(mpirun, bccmis, bccmis_mpi, ranks, work):
    # D14: an empty frame refused as the serial animation refuses it, in its words.
    far = ["--shape", "sphere", "-L", "3", "--animate", "3", "--path", "1e9,0,0"]
    serial = run([bccmis, "stuff", *far, "-q", "-o", os.path.join(work, "serial.pvd")], expect=2)
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *far, "-q", "-o", os.path.join(work, "out.pvtu")], expect=2)
    want = message(serial.stderr, "bccmis: ")
    got = message(r.stderr, "bccmis-mpi stuff: rank 0: ")
    if want is None or not want.startswith("sphere r=1: frame 0: the mesh is empty: bad input for this level"):
        sys.exit(f"FAIL: bccmis stuff's empty frame:\n{serial.stderr}")
    if got != want:
        sys.exit(f"FAIL: the ranks' empty frame says {got!r}, bccmis stuff {want!r}")
    if os.listdir(work):
        sys.exit(f"FAIL: an empty frame left {os.listdir(work)}")
    # D17: the check of the moved forest against a wrong forest (frame k - 1's, by the test hook).
    hook = "BCCMIS_TEST_CHECK_PREVIOUS_FRAME"
    cmd = mpi(mpirun, ranks) + ["-x", hook, bccmis_mpi, "stuff", "--shape", "sphere", "-L", "2", "--animate", "1",
                                "--gather", "--check", "-q", "-o", os.path.join(work, "whole.vtu")]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, env={**os.environ, hook: "1"})
    says = ("frame 1: the moved forest differs from the forest built for the frame (",
            "; spec/distributed.md D15, D17)")
    line = message(p.stderr, "bccmis-mpi stuff: rank 0: ")
    if p.returncode != 1 or line is None or not line.startswith(says[0]) or not line.endswith(says[1]):
        sys.exit(f"FAIL: the check of a wrong forest: exit {p.returncode} (expected 1), stderr:\n{p.stderr}")
    if os.listdir(work):
        sys.exit(f"FAIL: a failed check left {os.listdir(work)}")
    # D14: the swept box's notice (S26) in bccmis stuff's words, from the one function.
    moving = ["--shape", "sphere", "-L", "2", "--animate", "1", "--stats"]
    notice = "--animate fits the lattice to the swept box: "
    serial = run([bccmis, "stuff", *moving])
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *moving])
    said = [line[len("bccmis stuff: "):] for line in serial.stderr.splitlines() if notice in line]
    heard = [line[len("bccmis-mpi stuff: "):] for line in r.stderr.splitlines() if notice in line]
    if len(said) != 1 or not said[0].startswith(notice):
        sys.exit(f"FAIL: bccmis stuff's swept box notice:\n{serial.stderr}")
    if heard != said:
        sys.exit(f"FAIL: the ranks' swept box notice {heard}, bccmis stuff's {said}")
    print(f"ok: {ranks} ranks: an empty frame refused in bccmis stuff's words ({want[:40]}...), a wrong forest "
          "refused by --check (exit 1), nothing written; the swept box's notice as bccmis stuff's")


STAGING = re.compile(r"\.out\.staging-(\d+)@[^/]+\.tmp-[A-Za-z0-9]{6}")


def ranks_of(bccmis_mpi, output):
    """The pids of the processes running bccmis_mpi with `output` among their arguments."""
    pids = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                argv = f.read().decode(errors="replace").split("\0")
        except OSError:
            continue
        if os.path.basename(argv[0]) == os.path.basename(bccmis_mpi) and output in argv:
            pids.append(int(pid))
    return pids


def signalled(mpirun, bccmis_mpi, ranks, work, sig):
    """Runs the ranks until every rank's temporaries are in the staging directory, then sends `sig` to
    every rank; what the run left in `work`."""
    output = os.path.join(work, "out.pvtu")
    frames = 2
    staged = (frames + 1) * ranks + frames + 2  # every rank's pieces, rank 0's frames and .pvd
    p = subprocess.Popen(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", "--shape", "sphere", "-L", "4", "--animate",
                                               str(frames), "-q", "-o", output],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 120
    while True:
        dirs = [d for d in os.listdir(work) if STAGING.fullmatch(d)]
        if len(dirs) == 1 and len(os.listdir(os.path.join(work, dirs[0]))) == staged:
            break
        if p.poll() is not None or time.monotonic() > deadline:
            p.kill()
            p.wait()
            sys.exit(f"FAIL: {sig.name}: the ranks' {staged} temporaries did not appear in one staging "
                     f"directory while they ran (exit {p.returncode}, {os.listdir(work)})")
        time.sleep(0.001)
    pids = ranks_of(bccmis_mpi, output)
    if len(pids) != ranks:
        p.kill()
        sys.exit(f"FAIL: found {len(pids)} ranks, not {ranks}")
    for pid in pids:
        os.kill(pid, sig)
    p.wait(timeout=120)
    if p.returncode == 0:
        sys.exit(f"FAIL: {sig.name} to the ranks: mpirun exited 0")
    return sorted(os.listdir(work))


#= spec/distributed.md#D18 type=test
def signals(mpirun, bccmis_mpi, ranks, work):
    left = signalled(mpirun, bccmis_mpi, ranks, work, signal.SIGTERM)
    if left:
        sys.exit(f"FAIL: SIGTERM to every rank left {left}")
    left = signalled(mpirun, bccmis_mpi, ranks, work, signal.SIGKILL)
    if len(left) != 1 or not STAGING.fullmatch(left[0]):
        sys.exit(f"FAIL: SIGKILL to every rank left {left}, not one staging directory")
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", "--shape", "sphere", "-L", "2", "--animate", "1",
                                  "-o", os.path.join(work, "out.pvtu")])
    says = f"bccmis-mpi stuff: removed {os.path.join(work, left[0])}, left by an interrupted run"
    if says not in r.stderr.splitlines():
        sys.exit(f"FAIL: the next run does not say '{says}':\n{r.stderr}")
    want = sorted(["out.pvd"] + [f"out_{k:04d}.pvtu" for k in range(2)] +
                  [f"out_{k:04d}_{q:04d}.vtu" for k in range(2) for q in range(ranks)])
    if sorted(os.listdir(work)) != want:
        sys.exit(f"FAIL: the next run left {sorted(os.listdir(work))}, expected {want}")
    # The lock decides, not the PID (PIDs are reused): a directory named after a live process (this test's) but
    # held by no lock is removed; one held by a lock is left and named, whatever its PID.
    host = socket.gethostname()
    free = os.path.join(work, f".out.staging-{os.getpid()}@{host}.tmp-AAAAAA")
    held = os.path.join(work, f".out.staging-{2**22 + 7}@{host}.tmp-BBBBBB")
    os.mkdir(free)
    os.mkdir(held)
    lock = os.open(held, os.O_RDONLY)
    fcntl.flock(lock, fcntl.LOCK_SH)
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", "--shape", "sphere", "-L", "2", "--animate", "1",
                                  "-o", os.path.join(work, "out.pvtu")])
    os.close(lock)
    lines = r.stderr.splitlines()
    if f"bccmis-mpi stuff: removed {free}, left by an interrupted run" not in lines or os.path.exists(free):
        sys.exit(f"FAIL: an unlocked staging directory named after a live process was not removed:\n{r.stderr}")
    if (f"bccmis-mpi stuff: {held}: left by process {2**22 + 7} on {host}, which may still be running: remove it "
            "once that run has ended") not in lines or not os.path.isdir(held):
        sys.exit(f"FAIL: a staging directory some process holds locked was not left and named:\n{r.stderr}")
    os.rmdir(held)
    print(f"ok: {ranks} ranks: SIGTERM to every rank left nothing, SIGKILL one staging directory, removed by the "
          "next run; a directory's lock, not its PID, says whether its run has ended")


def refusals(mpirun, bccmis_mpi, ranks, work):
    base = ["--shape", "sphere", "-L", "2", "--animate", "2", "-q"]
    out = ["-o", os.path.join(work, "out.pvtu")]
    cases = [(["--hausdorff"], out, "--hausdorff"),
             (["--features"], out, "the features"), (["--gather"], ["-o", os.path.join(work, "out.msh")], "--gather"),
             ([], ["-o", os.path.join(work, "out.vtu")], "-o FILE.pvtu")]
    for extra, output, says in cases:
        r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *base, *extra, *output], expect=2)
        if says not in r.stderr or "spec/distributed.md D14" not in r.stderr:
            sys.exit(f"FAIL: {extra} {output}: stderr does not name '{says}' and D14:\n{r.stderr}")
        if os.listdir(work):
            sys.exit(f"FAIL: {extra} {output}: a refused run left {os.listdir(work)}")
    # D17: --check needs the gathered frames (D12).
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *base, "--check", *out], expect=2)
    if "--check" not in r.stderr or "add --gather" not in r.stderr or "D12" not in r.stderr or os.listdir(work):
        sys.exit(f"FAIL: --animate --check without --gather: not refused naming D12:\n{r.stderr}")
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", "--shape", "sphere", "-L", "2", "--path", "1,0,0", *out],
            expect=2)
    if "--path and --compare apply with --animate" not in r.stderr or os.listdir(work):
        sys.exit(f"FAIL: --path without --animate: not refused as bccmis stuff refuses it:\n{r.stderr}")
    # D15: --repartition-threshold T, T a number >= 1, with --animate only.
    for value in ["0.99", "nan", "inf"]:
        r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", *base, "--repartition-threshold", value, *out], expect=2)
        if (f"--repartition-threshold: '{value}' is not a finite number >= 1" not in r.stderr or "D15" not in r.stderr
                or os.listdir(work)):
            sys.exit(f"FAIL: --repartition-threshold {value}: not refused naming it and D15:\n{r.stderr}")
    r = run(mpi(mpirun, ranks) + [bccmis_mpi, "stuff", "--shape", "sphere", "-L", "2", "--repartition-threshold", "2",
                                  *out], expect=2)
    if "--repartition-threshold applies with --animate" not in r.stderr or os.listdir(work):
        sys.exit(f"FAIL: --repartition-threshold without --animate: not refused:\n{r.stderr}")
    print(f"ok: {ranks} ranks: {len(cases)} options refused with --animate (D14), --check without --gather "
          "(D17), --path without it, "
          "bad --repartition-threshold values and the option without --animate (D15)")


def main():
    mode, mpirun, bccmis, bccmis_mpi, ranks = sys.argv[1:6]
    args = sys.argv[7:] if len(sys.argv) > 6 and sys.argv[6] == "--" else []
    with tempfile.TemporaryDirectory() as work:
        if mode in ("frames", "steps"):
            frames(mpirun, bccmis, bccmis_mpi, int(ranks), args, work, steps=mode == "steps")
        elif mode == "signals":
            signals(mpirun, bccmis_mpi, int(ranks), work)
        elif mode == "faults":
            faults(mpirun, bccmis, bccmis_mpi, int(ranks), work)
        else:
            refusals(mpirun, bccmis_mpi, int(ranks), work)


if __name__ == "__main__":
    main()
