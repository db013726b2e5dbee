#!/usr/bin/env bash
# Strong scaling of bccmis-mpi stuff against bccmis stuff (spec/distributed.md,
# bench/RESULTS.md section 20): wall seconds, CPU seconds and peak RSS of each
# rank (/usr/bin/time -v inside mpirun), and whether --gather's file equals
# the serial file byte for byte.
#   bench/stuff_mpi_scaling.sh BUILD_DIR "RANKS..." STUFF_ARGS...
#   bench/stuff_mpi_scaling.sh build/release "1 2" --shape torus -L 5
set -euo pipefail
build=$1 ranks=$2
shift 2
bccmis=$build/tools/bccmis/bccmis
bccmis_mpi=$build/tools/bccmis-mpi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One line of a run: wall seconds, then "user + sys, peak MB" for each rank.
report() {
  local label=$1 wall=$2
  shift 2
  local ranks_text=""
  for log in "$@"; do
    user=$(sed -n 's/.*User time (seconds): //p' "$log")
    sys=$(sed -n 's/.*System time (seconds): //p' "$log")
    kb=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$log")
    ranks_text+="${ranks_text:+; }$user + $sys s, $((kb / 1024)) MB"
  done
  echo "| $label | $wall | $ranks_text |"
}
echo "| run | wall s | per rank: user + sys, peak RSS |"
echo "|---|---:|---|"
start=$(date +%s.%N)
/usr/bin/time -v -o "$work/serial.time" "$bccmis" stuff "$@" --no-features --binary -q -o "$work/serial.vtu"
report "bccmis stuff" "$(echo "$(date +%s.%N) - $start" | bc | xargs printf %.1f)" "$work/serial.time"
for p in $ranks; do
  for mode in gather pvtu; do
    rm -f "$work"/rank*.time
    out=$([ $mode = gather ] && echo "--gather -o $work/g.vtu" || echo "-o $work/p.pvtu")
    start=$(date +%s.%N)
    # shellcheck disable=SC2086,SC2016
    mpirun --allow-run-as-root --oversubscribe -n "$p" sh -c \
      '/usr/bin/time -v -o "$0/rank$OMPI_COMM_WORLD_RANK.time" "$@"' "$work" \
      "$bccmis_mpi" stuff "$@" --no-features --binary -q $out
    wall=$(echo "$(date +%s.%N) - $start" | bc | xargs printf %.1f)
    same=""
    [ $mode = gather ] && { cmp -s "$work/serial.vtu" "$work/g.vtu" && same=" (= serial)" || same=" (DIFFERS)"; }
    report "bccmis-mpi, $p rank$([ "$p" = 1 ] || echo s), $mode$same" "$wall" $(ls "$work"/rank*.time | sort -V)
  done
done
