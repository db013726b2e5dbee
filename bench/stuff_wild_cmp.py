#!/usr/bin/python3
"""Two builds of `bccmis stuff` on every triangle file of CGAL's data/meshes
(OFF, STL, PLY; libcgal-demo's data.tar.gz), byte for byte: each build meshes
each file at one level on one thread (`-L L --threads 1 -q -o NAME.vtu`), and
the script prints, per build, the files meshed (exit 0), refused (exit 2),
otherwise ended, and the total CPU seconds (user + system, /usr/bin/time);
then the files whose exit codes differ and the meshed files whose .vtu
differ (with both CPU times). A change that keeps every decision keeps the
bytes.

    bench/stuff_wild_cmp.py OLD_BCCMIS NEW_BCCMIS --meshes data/meshes --level 3 --out /tmp/cmp
"""
import argparse
import concurrent.futures
import filecmp
import glob
import os
import subprocess


def run(binary, mesh, vtu, level, timeout):
    try:
        p = subprocess.run(["/usr/bin/time", "-f", "%U %S", binary, "stuff", mesh, "-L", str(level), "--threads", "1",
                            "-q", "-o", vtu], capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", float(timeout)
    return p.returncode, sum(float(x) for x in p.stderr.strip().splitlines()[-1].split())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--meshes", default="/tmp/cgaldata/data/meshes")
    ap.add_argument("--level", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--out", default="/tmp/stuff_wild_cmp")
    args = ap.parse_args()
    meshes = sorted(f for f in glob.glob(os.path.join(args.meshes, "*"))
                    if f.rsplit(".", 1)[-1].lower() in ("off", "stl", "ply"))
    results = {}
    for tag, binary in (("old", args.old), ("new", args.new)):
        os.makedirs(os.path.join(args.out, tag), exist_ok=True)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
            jobs = {m: ex.submit(run, binary, m, os.path.join(args.out, tag, os.path.basename(m) + ".vtu"), args.level,
                                 args.timeout) for m in meshes}
            results[tag] = {os.path.basename(m): j.result() for m, j in jobs.items()}
        rows = results[tag].values()
        print(f"{tag}: {len(meshes)} files, {sum(rc == 0 for rc, _ in rows)} meshed, "
              f"{sum(rc == 2 for rc, _ in rows)} refused, {sum(rc not in (0, 2) for rc, _ in rows)} otherwise, "
              f"CPU {sum(cpu for _, cpu in rows):.1f} s")
    old, new = results["old"], results["new"]
    print("exit codes differ:", [(f, old[f][0], new[f][0]) for f in old if old[f][0] != new[f][0]] or "none")
    differ = [f for f in old if old[f][0] == 0 and new[f][0] == 0 and not filecmp.cmp(
        os.path.join(args.out, "old", f + ".vtu"), os.path.join(args.out, "new", f + ".vtu"), shallow=False)]
    same = sum(old[f][0] == 0 and new[f][0] == 0 for f in old) - len(differ)
    print(f"meshed by both: {same} the same bytes, {len(differ)} different")
    for f in differ:
        print(f"  {f}: CPU {old[f][1]:.2f} s -> {new[f][1]:.2f} s")


if __name__ == "__main__":
    main()
