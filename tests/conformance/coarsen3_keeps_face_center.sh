#!/bin/sh
# A deliberately wrong 3D implementation: coarsen keeps the center of the
# cube's +x face as a node (joined to the coarsened center) where it should
# remove it. Emulated on the reference's final state: for every accepted
# coarsen whose center is still a leaf, the face center (x + h, y, z), h half
# the cube's side, is added back when it is not a node. 2D traces pass
# through unchanged. Usage: coarsen3_keeps_face_center.sh BCCMIS TRACE
out=$("$1" replay --quiet --check=none "$2") || exit $?
printf '%s\n' "$out" | awk '
  # Whether position a (three fields "x y z") sorts before b.
  function before(a, b,   p, q) {
    split(a, p, " "); split(b, q, " ")
    if (p[1] != q[1]) return p[1] + 0 < q[1] + 0
    if (p[2] != q[2]) return p[2] + 0 < q[2] + 0
    return p[3] + 0 < q[3] + 0
  }
  /^coarsen [0-9-]+ [0-9-]+ [0-9-]+ ok$/ { coarsened[$2 " " $3 " " $4] = 1 }
  /^lattice / { three = NF == 5; L = $5 }
  !three || !/^[CN] |^end / { line[++n] = $0; next }
  /^C / { key = $2 " " $3 " " $4; level[key] = $5; cline[key] = ++n; line[n] = $0; next }
  /^N / { key = $2 " " $3 " " $4; isnode[key] = 1; nkeys[++nn] = key; nline[key] = $0; next }
  /^end / { cells = $2; nodes = $3; next }
  END {
    for (c in coarsened) {
      if (!(c in level)) continue
      split(c, p, " ")
      f = (p[1] + 2 ^ (L - level[c])) " " p[2] " " p[3]
      if (f in isnode) continue
      isnode[f] = 1; nline[f] = "N " f " : " c; nodes++
      # f into the sorted node list, and into the sorted neighbors of c.
      for (i = ++nn; i > 1 && before(f, nkeys[i - 1]); --i) nkeys[i] = nkeys[i - 1]
      nkeys[i] = f
      nq = split(line[cline[c]], q, " ")
      m = 0
      for (j = 7; j + 2 <= nq; j += 3) nb[++m] = q[j] " " q[j + 1] " " q[j + 2]
      for (i = ++m; i > 1 && before(f, nb[i - 1]); --i) nb[i] = nb[i - 1]
      nb[i] = f
      s = "C " c " " level[c] " :"
      for (i = 1; i <= m; ++i) s = s " " nb[i]
      line[cline[c]] = s
    }
    for (i = 1; i <= n; ++i) print line[i]
    if (!three) exit
    for (i = 1; i <= nn; ++i) print nline[nkeys[i]]
    print "end " cells " " nodes
  }'
