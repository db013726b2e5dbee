#!/usr/bin/env bash
# --animate on MPI ranks against the serial animation (spec/distributed.md
# D14, bench/RESULTS.md section 42): CPU seconds a frame (user + sys, which
# a loaded machine inflates less than wall seconds). A frame's cost is the
# difference between a run of N frames and one of 1, over N - 1 (the
# start-up, the fit and frame 0 cancel; the frames' files written
# included), summed over the ranks (/usr/bin/time inside mpirun). The serial
# frame from scratch is what --compare adds to a frame (it stuffs every
# frame again from scratch, writing nothing). Serial runs on one thread, as
# a rank stuffs on one (D1). After the table, rank 0's line of each step of
# the N-frame runs (D15: families coarsened, leaves refined, partition
# corrections, imbalance, repartitioned); MPI_ARGS (environment) go to
# bccmis-mpi only, e.g. MPI_ARGS="--repartition-threshold 1".
#   bench/stuff_mpi_animate.sh BUILD_DIR N "RANKS..." STUFF_ARGS...
#   bench/stuff_mpi_animate.sh build/release 4 "1 2" --shape sphere -L 5
set -euo pipefail
build=$1 frames=$2 ranks=$3
shift 3
bccmis=$build/tools/bccmis/bccmis
bccmis_mpi=$build/tools/bccmis-mpi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# CPU seconds (user + sys) of the logs given, summed.
cpu() { cat "$@" | awk '{ s += $1 + $2 } END { printf "%.3f", s }'; }
per_frame() { echo "($1 - $2) / ($frames - 1)" | bc -l | xargs printf %.3f; }
serial_cpu() {
  /usr/bin/time -f "%U %S" -o "$work/serial.time" "$bccmis" stuff "${@:2}" --animate "$1" --threads 1 --binary -q \
    -o "$work/s$1.pvd"
  cpu "$work/serial.time"
}
mpi_cpu() {
  local p=$1 n=$2
  shift 2
  rm -f "$work"/rank*.time
  # shellcheck disable=SC2016
  # shellcheck disable=SC2086
  mpirun --allow-run-as-root --oversubscribe -n "$p" sh -c \
    '/usr/bin/time -f "%U %S" -o "$0/rank$OMPI_COMM_WORLD_RANK.time" "$@"' "$work" \
    "$bccmis_mpi" stuff "$@" ${MPI_ARGS:-} --animate "$n" --binary -o "$work/p$n.pvtu" 2> "$work/steps_${p}_$n.log"
  cpu "$work"/rank*.time
}
step=$(per_frame "$(serial_cpu "$frames" "$@")" "$(serial_cpu 1 "$@")")
with_scratch=$(per_frame "$(serial_cpu "$frames" "$@" --compare)" "$(serial_cpu 1 "$@" --compare)")
echo "| run | CPU s a frame |"
echo "|---|---:|"
echo "| bccmis stuff --animate: S15-S16's step, its .vtu written | $step |"
echo "| bccmis stuff: a frame from scratch (what --compare adds) | $(echo "$with_scratch - $step" | bc -l | xargs printf %.3f) |"
for p in $ranks; do
  echo "| bccmis-mpi stuff --animate, $p rank$([ "$p" = 1 ] || echo s), its .pvtu written, all ranks' CPU | $(per_frame "$(mpi_cpu "$p" "$frames" "$@")" "$(mpi_cpu "$p" 1 "$@")") |"
done
for p in $ranks; do
  echo
  echo "$p rank(s), the steps of the $frames-frame run:"
  grep -o 'frame [0-9]*/[0-9]*: .*forest: .*' "$work/steps_${p}_$frames.log" || true
done
