#!/bin/sh
# spec/distributed.md D16: each rank's memory estimate (--memory-limit's)
# against its measured peak resident memory (VmHWM, GNU time's %M).
#
#   bench/stuff_mpi_memory.sh BUILD "LEVELS" "RANKS" STUFF_ARGS...
#   bench/stuff_mpi_memory.sh build/release "5 6" "1 2" --shape sphere
#
# For each level, rank count and output (.pvtu pieces, then --gather .vtu):
# the estimate each rank prints when refused (a limit of 1 byte), then each
# rank's peak in a run without a limit. One line a rank:
#   level ranks output rank estimate_GB peak_MB
set -eu
build=$1 levels=$2 ranks=$3
shift 3
mpi="mpirun --allow-run-as-root --oversubscribe"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for L in $levels; do
  for n in $ranks; do
    for out in pvtu gather; do
      if [ "$out" = pvtu ]; then o="-o $work/p.pvtu"; else o="--gather -o $work/g.vtu"; fi
      $mpi -n "$n" "$build/tools/bccmis-mpi" stuff "$@" -L "$L" --memory-limit 1e-9 $o 2>&1 |
        sed -n 's/^bccmis-mpi stuff: rank \([0-9]*\): .* leaves, \([0-9.e+-]*\) GB on rank.*/\1 \2/p' | sort -n > "$work/estimate"
      $mpi -n "$n" sh -c "/usr/bin/time -f \"\$OMPI_COMM_WORLD_RANK %M\" \"$build/tools/bccmis-mpi\" stuff $* -L $L -q $o" 2>&1 |
        grep -E '^[0-9]+ [0-9]+$' | sort -n > "$work/peak"
      join "$work/estimate" "$work/peak" | while read -r r e kb; do
        echo "$L $n $out $r $e $(awk "BEGIN { printf \"%.0f\", $kb * 1024 / 1e6 }")"
      done
      rm -rf "$work"/p* "$work"/g*
    done
  done
done
