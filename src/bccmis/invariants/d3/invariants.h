// bccmis::d3 invariants: an independent checker for the 3D lattice graph of
// spec/lattice3d.md and for a tetrahedral mesh of it.
//
// Written from spec/lattice3d.md and the cube geometry only: it includes
// nothing of src/bccmis/d3/ but graph.h (the data types) and never calls
// refine/coarsen, so a bug in the 3D operations cannot hide behind the same
// bug here. The layers (spec/invariants.md, section "3D", lists every code):
//   1. combinatorial: partition, bipartite, symmetry, existence, level entries;
//   2. structural:    each cell lists its 8 corners and only edge midpoints and
//                     face centers; every node's cardinality by its role (F1-F3);
//   3. grading:       face-or-edge neighbours differ by <= 1 level (§2);
//   4. geometry:      levels, positions, the leaves tile the box, and every
//                     N(n) is the set of leaves containing n (point location);
//   5. mesh:          check_mesh, a list of tetrahedra against the graph.
// Layer 6, CGAL as a second referee of a mesh, is the optional library
// bccmis::tetrahedralization_check (../cgal/d3/tetrahedralization_check.h).
// Layers 1-4 take O(size * log size * L) time.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/invariants/violation.h"

namespace bccmis::d3 {

/// The first broken invariant, named precisely: positions as (x, y, z),
/// `section` a spec anchor, e.g. "spec/lattice3d.md §3 F2", `layer` 1..6
/// (6: the CGAL layer).
using Violation = BasicViolation<Point>;

/// "message [section]" on one line (the message already starts with the code).
std::string to_string(const Violation& v);

/// The first violation of layers 1..depth (depth is clamped to 0..4), each
/// layer only after the lower ones passed. Deterministic: every layer visits
/// vertices in sorted (x, y, z) order. Empty when the graph is valid.
std::optional<Violation> find_violation(const Graph& g, int depth = 4);

/// find_violation(g, depth) is empty.
bool is_valid(const Graph& g, int depth = 4);

/// Runs exactly one layer (1..4), assuming the lower layers passed; the
/// result is unspecified (but safe) when that assumption fails. Throws
/// std::invalid_argument for another layer number.
std::optional<Violation> check_layer(const Graph& g, int layer);

/// A tetrahedron: four positions, positively oriented
/// (det[b - a, c - a, d - a] > 0).
using Tet = std::array<Point, 4>;

/// Layer 5: the first problem of a tetrahedral mesh of g (spec/invariants.md,
/// "3D layer 5"), assuming g passed layers 1-4; checks the lattice size
/// first, so it is safe on any graph. Orientation and volumes are exact; the
/// dihedral-angle bounds [45°, 120°] are checked in double precision with a
/// tolerance of 1e-9 degrees.
std::optional<Violation> check_mesh(const Graph& g, std::span<const Tet> tets);

}  // namespace bccmis::d3
