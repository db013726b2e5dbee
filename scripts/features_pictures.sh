#!/usr/bin/env bash
# The README's pictures of sharp features (spec/stuffing.md S29-S35): CGAL's
# fandisk stuffed at level 4 with features (the default for a mesh file) and
# with --no-features, the boundary of each, and the dihedral-angle histogram
# of the mesh with features; then the numbers the README quotes, from the
# run with features (--stats).
#
#   scripts/features_pictures.sh [BCCMIS [FANDISK.off]]
#
#   BCCMIS       the bccmis binary (default build/release/tools/bccmis/bccmis)
#   FANDISK.off  default: data/meshes/fandisk.off from Debian's libcgal-demo
#                (/usr/share/doc/libcgal-dev/data.tar.gz)
# Writes docs/stuff-fandisk-features.svg, docs/stuff-fandisk-no-features.svg
# and docs/stuff-fandisk-angles.svg.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bccmis=$(realpath "${1:-$root/build/release/tools/bccmis/bccmis}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ $# -ge 2 ]]; then
  cp "$2" "$work/fandisk.off"
else
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$work" --strip-components=2 data/meshes/fandisk.off
fi
cd "$work"  # the SVGs' titles name the .mesh files, not this directory
"$bccmis" stuff fandisk.off -L 4 --check --stats -o fandisk.mesh |
  grep -E '^(tetrahedra|volume_rel_error|min_dihedral|max_dihedral|feature_(corners|curves)(_conformed)?|feature_distance) '
"$bccmis" stuff fandisk.off -L 4 --no-features --stats -o fandisk-no-features.mesh |
  grep -E '^(volume_rel_error|min_dihedral|max_dihedral) ' | sed 's/^/no-features /'
"$bccmis" render fandisk.mesh -o "$root/docs/stuff-fandisk-features.svg"
"$bccmis" render fandisk-no-features.mesh -o "$root/docs/stuff-fandisk-no-features.svg"
"$bccmis" render fandisk.mesh --histogram -o "$root/docs/stuff-fandisk-angles.svg"
