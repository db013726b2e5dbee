#!/usr/bin/env bash
# bccmis stuff with and without sharp features (spec/stuffing.md S29-S34;
# bench/RESULTS.md, "Sharp features"): on each input and level, one run with
# features (the default for a mesh file) and one with --no-features, and one
# markdown row each: input | level | features | time | tets | min dihedral |
# max dihedral | % below 10 deg | volume error | Hausdorff from boundary |
# from surface | feature distance (S33; not measured without features) |
# corners and curves conformed | crease_cuts_placed and crease_cuts_kept
# (S35.8: the vertices placed on the creases in B and in the mesh kept; "-"
# without --crease-cuts in FEATURE_FLAGS).
# Time: seconds.meshing (input to stencils, with the features phase).
#
#   bench/stuff_features.sh BCCMIS LEVELS INPUT.off ...
#
#   BCCMIS   the bccmis binary; LEVELS e.g. "4 5"
#   FEATURE_FLAGS (environment, optional) more options for the run with
#            features, e.g. "--crease-cuts 0.25" (S35.7)
set -euo pipefail
bccmis=$1
levels=$2
shift 2
echo "| input | L | features | time s | tets | min dih | max dih | % < 10 | volume error | H from boundary | H from surface | feature distance | corners | curves | crease cuts placed | crease cuts kept |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for input in "$@"; do
  for level in $levels; do
    on=$("$bccmis" stuff "$input" -L "$level" --json --hausdorff -q ${FEATURE_FLAGS:-})
    off=$("$bccmis" stuff "$input" -L "$level" --json --hausdorff -q --no-features)
    python3 - "$input" "$level" "$on" "$off" <<'PY'
import json, sys
name, level, on, off = sys.argv[1].split("/")[-1], sys.argv[2], json.loads(sys.argv[3]), json.loads(sys.argv[4])
def row(s, features):
    h = s["hausdorff"]
    corners = "%d/%d" % (s["feature_corners_conformed"], s["feature_corners"]) if features else "-"
    curves = "%d/%d" % (s["feature_curves_conformed"], s["feature_curves"]) if features else "-"
    distance = "%.3g" % s["feature_distance"] if features else "-"
    placed, kept = s.get("crease_cuts_placed", "-"), s.get("crease_cuts_kept", "-")  # S35.8, with --crease-cuts
    print("| %s | %s | %s | %.2f | %d | %.2f | %.2f | %.3f | %+.4f%% | %.3g | %.3g | %s | %s | %s | %s | %s |" % (
        name, level, "on" if features else "off", s["seconds"]["meshing"], s["tetrahedra"], s["min_dihedral"],
        s["max_dihedral"], 100 * s["below10"], 100 * s["volume_rel_error"], h["from_boundary"], h["from_surface"],
        distance, corners, curves, placed, kept))
row(on, True)
row(off, False)
PY
  done
done
