#!/usr/bin/env bash
# The peers of bccmis stuff with sharp features (bench/RESULTS.md, section 24):
# TetGen -pq1.414 and CGAL Mesh_3 with its features protected, each run by
# bench/stuff_peers and measured by the functions that measure bccmis's own
# mesh (stuff/measure_mesh.h: spec/stuffing.md S13, S29, S33), one markdown
# row per run in bench/stuff_features.sh's columns: input | mesher | time |
# tets | min dihedral | max dihedral | % below 10 deg | volume error |
# Hausdorff from boundary | from surface | feature distance.
# Time: wall seconds of the meshing (CPU seconds in parentheses).
#
#   bench/stuff_features_peers.sh STUFF_PEERS INPUT.off:V:S ...
#
#   STUFF_PEERS  the stuff_peers binary; V TetGen's -a (largest volume), S
#   CGAL's cell size (facet and cell size S, protecting balls S / 2).
set -euo pipefail
peers=$1
shift
echo "| input | mesher | time s | tets | min dih | max dih | % < 10 | volume error | H from boundary | H from surface | feature distance |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for spec in "$@"; do
  IFS=: read -r input volume size <<<"$spec"
  tetgen=$("$peers" tetgen "$input" --max-volume "$volume")
  cgal=$("$peers" cgal "$input" --cell-size "$size" --features)
  python3 - "$input" "$volume" "$size" "$tetgen" "$cgal" <<'PY'
import json, sys
name, volume, size = sys.argv[1].split("/")[-1], sys.argv[2], sys.argv[3]
def row(s, mesher):
    h = s["hausdorff"]
    print("| %s | %s | %.2f (%.2f) | %d | %.2f | %.2f | %.3f | %+.4f%% | %.3g | %.3g | %.3g |" % (
        name, mesher, s["seconds"], s["cpu_seconds"], s["tetrahedra"], s["min_dihedral"], s["max_dihedral"],
        100 * s["below10"], 100 * s["volume_rel_error"], h["from_boundary"], h["from_surface"], s["feature_distance"]))
row(json.loads(sys.argv[4]), "TetGen -pq1.414 -a" + volume)
row(json.loads(sys.argv[5]), "CGAL Mesh_3 + features, S " + size)
PY
done
