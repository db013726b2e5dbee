#!/bin/sh
# A deliberately wrong implementation: the literal reading of eq. (6) (erratum
# E1), which gives no midpoint node to a side on the domain boundary. Emulated
# by deleting, from the reference's final state, every node on the bottom
# boundary (y = 0) that is not a level-0 grid point, with its edges.
# Usage: missing_boundary_junction.sh BCCMIS TRACE
"$1" replay --quiet --check=none "$2" | awk '
  /^lattice / { S = 2 ^ ($4 + 1) }
  /^N / && $3 == 0 && $2 % S != 0 { dropped[$2 " 0"] = 1; ndropped++; next }
  /^C / {
    line = $1 " " $2 " " $3 " " $4 " :"
    for (i = 6; i < NF; i += 2) if (!(($i " " $(i + 1)) in dropped)) line = line " " $i " " $(i + 1)
    print line; next
  }
  /^end / { print "end " $2 " " ($3 - ndropped); next }
  { print }'
