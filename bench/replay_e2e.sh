#!/usr/bin/env bash
# End-to-end replay through the CLI (bench/RESULTS.md, "Replay output paths"):
# the uniform refinement trace of a 16 x 16 lattice to L = 5 (87,296 refines,
# 262,144 cells), replayed by the fast and the reference implementation with
# the decision log and the canonical state written to files. Reports CPU time
# (user + sys), wall time and peak RSS of each run (/usr/bin/time), the
# speed-up and the fast run's bytes per cell, and checks that both wrote the
# same bytes. With --3d, the same for a W x H x D lattice (default 4 4 4 4:
# 37,440 refines, 262,144 cells; bench/RESULTS.md section 23).
#
#   bench/replay_e2e.sh BCCMIS [W H L] [REPEATS]
#   bench/replay_e2e.sh BCCMIS --3d [W H D L] [REPEATS]
#
#   BCCMIS   the bccmis binary, e.g. build/release/tools/bccmis/bccmis
#   W H L    the lattice (default 16 16 5)
#   REPEATS  runs of each implementation; the medians are reported (default 3)
set -euo pipefail
usage="usage: bench/replay_e2e.sh BCCMIS [W H L | --3d W H D L] [REPEATS]"
bccmis=${1:?$usage}
shift
if [ "${1:-}" = "--3d" ]; then
  shift
  W=${1:-4} H=${2:-4} D=${3:-4} L=${4:-4} repeats=${5:-3}
  sizes="$W $H $D $L"
  targets=">= 30x"  # the 3D replay's target (bench/RESULTS.md section 23)
  cells=$((W * H * D * (1 << (3 * L))))
else
  W=${1:-16} H=${2:-16} L=${3:-5} repeats=${4:-3}
  sizes="$W $H $L"
  targets=">= 20x, <= 150 bytes per cell"
  cells=$((W * H * (1 << (2 * L))))
fi
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck disable=SC2086 # $sizes is the lattice's numbers, split on purpose
python3 "$here/make_uniform_trace.py" $sizes -o "$work/trace"

# One run: prints "cpu wall rss_kib".
run() {
  local impl=$1 out=$2
  /usr/bin/time -f '%U %S %e %M' -o "$work/time" \
    "$bccmis" replay --impl="$impl" --check=none --quiet "$work/trace" --log "$out.log" --state "$out.state"
  awk '{ printf "%.3f %.3f %d\n", $1 + $2, $3, $4 }' "$work/time"
}
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

declare -A cpu wall rss
for impl in fast reference; do
  : > "$work/$impl.runs"
  for ((k = 0; k < repeats; ++k)); do run "$impl" "$work/$impl" >> "$work/$impl.runs"; done
  cpu[$impl]=$(cut -d' ' -f1 "$work/$impl.runs" | median)
  wall[$impl]=$(cut -d' ' -f2 "$work/$impl.runs" | median)
  rss[$impl]=$(cut -d' ' -f3 "$work/$impl.runs" | median)
  echo "$impl: runs (cpu s, wall s, peak RSS KiB): $(tr '\n' ';' < "$work/$impl.runs")"
done
cmp -s "$work/fast.log" "$work/reference.log" || { echo "the decision logs differ" >&2; exit 1; }
cmp -s "$work/fast.state" "$work/reference.state" || { echo "the canonical states differ" >&2; exit 1; }
awk -v cf="${cpu[fast]}" -v cr="${cpu[reference]}" -v wf="${wall[fast]}" -v wr="${wall[reference]}" \
    -v rf="${rss[fast]}" -v rr="${rss[reference]}" -v cells="$cells" -v lat="$sizes" -v targets="$targets" 'BEGIN {
  printf "lattice %s: %d cells; same log and state from both\n", lat, cells
  printf "%-10s %10s %10s %14s %14s\n", "impl", "cpu s", "wall s", "peak RSS KiB", "bytes/cell"
  printf "%-10s %10.3f %10.3f %14d %14.1f\n", "fast", cf, wf, rf, rf * 1024 / cells
  printf "%-10s %10.3f %10.3f %14d %14.1f\n", "reference", cr, wr, rr, rr * 1024 / cells
  if (cf > 0 && wf > 0)
    printf "speed-up (cpu) %.1fx, (wall) %.1fx; fast peak RSS %.1f bytes per cell (targets: %s)\n",
           cr / cf, wr / wf, rf * 1024 / cells, targets
  else
    print "speed-up: the fast run took less than the timer resolution (a larger lattice measures it)"
}'
