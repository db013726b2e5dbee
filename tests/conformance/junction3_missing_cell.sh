#!/bin/sh
# A deliberately wrong 3D implementation: a junction with three cells (an
# edge midpoint on the domain boundary, where a refined cube meets a coarser
# one) loses one of them. Emulated on the reference's final state: every node
# with exactly three neighbors drops the edge to its last one (largest
# position), on both sides. 2D traces pass through unchanged.
# Usage: junction3_missing_cell.sh BCCMIS TRACE
out=$("$1" replay --quiet --check=none "$2") || exit $?
printf '%s\n' "$out" | awk '
  /^lattice / { three = NF == 5 }
  !three || !/^[CN] / { line[++n] = $0; next }
  /^N / && NF == 14 {
    cell = $12 " " $13 " " $14
    dropped[cell] = dropped[cell] " " $2 " " $3 " " $4 " "
    line[++n] = $1 " " $2 " " $3 " " $4 " : " $6 " " $7 " " $8 " " $9 " " $10 " " $11
    next
  }
  { line[++n] = $0 }
  END {
    for (i = 1; i <= n; ++i) {
      nf = split(line[i], f, " ")
      key = f[2] " " f[3] " " f[4]
      if (f[1] != "C" || !(key in dropped)) { print line[i]; continue }
      out = f[1] " " key " " f[5] " :"
      for (j = 7; j + 2 <= nf; j += 3)
        if (index(dropped[key], " " f[j] " " f[j + 1] " " f[j + 2] " ") == 0) out = out " " f[j] " " f[j + 1] " " f[j + 2]
      print out
    }
  }'
