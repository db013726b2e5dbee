#!/usr/bin/env python3
"""`bccmis stuff` by level (issue 29, "The mesher, streaming"; bench/RESULTS.md
section 19): one process per level on a shape, writing a binary file, and one
markdown table: level | leaves | tetrahedra | each phase's seconds | meshing |
statistics + write | tets/s (meshing) | peak MB | bytes/tet. Peak: the
process's maximum resident set (os.wait4), so each level is its own process.

    bench/stuff_scale.py BCCMIS [--levels 3..6] [--shape sphere] [--output vtu|msh] [--threads N] [--smoke]

--smoke: levels 2..3 and checks the table's sums (the phases add up to
meshing, the counts are positive); the bench-smoke test runs it.
"""
import json
import os
import subprocess
import sys
import tempfile

PHASES = ["lattice", "mesh", "cut", "warp", "stencils", "statistics", "write"]


def run_level(bccmis, shape, level, output, threads, work):
    out = os.path.join(work, "mesh." + output)
    cmd = [bccmis, "stuff", "--shape", shape, "-L", str(level), "--json", "-q", "--binary", "-o", out]
    if threads is not None:
        cmd += ["--threads", str(threads)]
    with tempfile.TemporaryFile(mode="w+") as stdout, tempfile.TemporaryFile(mode="w+") as stderr:
        proc = subprocess.Popen(cmd, stdout=stdout, stderr=stderr)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        stdout.seek(0)
        stderr.seek(0)
        if proc.returncode != 0:
            sys.exit("%s: exit %d: %s" % (" ".join(cmd), proc.returncode, stderr.read()))
        stats = json.loads(stdout.read())
    os.remove(out)
    return stats, usage.ru_maxrss * 1024  # bytes (Linux reports KB)


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    bccmis = args.pop(0)
    lo, hi, shape, output, threads, smoke = 3, 6, "sphere", "vtu", None, False
    while args:
        a = args.pop(0)
        if a == "--levels":
            lo, hi = (int(x) for x in args.pop(0).split(".."))
        elif a == "--shape":
            shape = args.pop(0)
        elif a == "--output":
            output = args.pop(0)
        elif a == "--threads":
            threads = int(args.pop(0))
        elif a == "--smoke":
            lo, hi, smoke = 2, 3, True
        else:
            sys.exit("unknown argument %r\n%s" % (a, __doc__))
    print("| L | leaves | tetrahedra | " + " | ".join(PHASES) +
          " | meshing | stats + write | M tets/s | peak MB | bytes/tet |")
    print("|" + "---|" * (len(PHASES) + 8))
    with tempfile.TemporaryDirectory() as work:
        for level in range(lo, hi + 1):
            stats, peak = run_level(bccmis, shape, level, output, threads, work)
            s = stats["seconds"]
            tets = stats["tetrahedra"]
            meshing = s["meshing"]
            after = s["statistics"] + s["write"]
            if smoke:
                summed = sum(s[p] for p in PHASES if p not in ("statistics", "write")) + s["input"]
                if tets <= 0 or stats["leaves"] <= 0 or abs(summed - meshing) > 1e-6 * max(1.0, meshing):
                    sys.exit("L%d: inconsistent: %d tets, %d leaves, phases %g against meshing %g" %
                             (level, tets, stats["leaves"], summed, meshing))
            print("| %d | %d | %d | %s | %.2f | %.2f | %.2f | %.0f | %.0f |" % (
                level, stats["leaves"], tets, " | ".join("%.2f" % s[p] for p in PHASES), meshing, after,
                tets / meshing / 1e6 if meshing > 0 else 0, peak / 1e6, peak / tets), flush=True)


if __name__ == "__main__":
    main()
