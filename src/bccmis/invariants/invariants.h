// bccmis invariants: an independent checker for the graph of Erleben 2009, §2.
//
// The checker is the project's judge. It is written from the paper and from
// the lattice geometry only: it never includes the operations' helpers
// (set_ops.h, geometry.h) and never calls refine/coarsen, so a bug in the
// operations cannot hide behind the same bug in the checker.
//
// The checks run in layers; a layer runs only after every lower layer passed
// (spec/invariants.md gives every code, its paper anchor and the derivations):
//   1. combinatorial: partition, bipartite, symmetry, existence, level entries;
//   2. structural:    each cell lists its 4 corners and only side midpoints;
//                     exact node degree per kind (1, 2, 3 or 4);
//   3. grading:       edge-neighboring cells (eq. 3's X) differ by <= 1 level;
//   4. geometry:      levels, positions, and the cells tile the domain;
//   5. triangulation: CGAL cross-check, a separate target
//                     (src/bccmis/invariants/cgal/bccmis/triangulation_check.h).
// Layers 1-4 take O(size * log size) time (O(size * L) for the tiling walk).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/invariants/violation.h"

namespace bccmis {

/// The first broken invariant, named precisely. `where` holds the vertices
/// (or, for "coverage", the uncovered cell's center) involved; `section` is
/// the paper anchor, e.g. "§2", "§2.1 ¶2"; `layer` is 1..5, 0 for the
/// operation contracts of checked.h.
using Violation = BasicViolation<Point>;

/// "message [paper §x]" on one line (the message already starts with the code).
std::string to_string(const Violation& v);

/// The first violation of layers 1..depth (depth is clamped to 0..4), each
/// layer only after the lower ones passed. Deterministic: every layer visits
/// vertices in sorted (x, y) order. Empty when the graph is valid.
std::optional<Violation> find_violation(const Graph& g, int depth = 4);

/// find_violation(g, depth) is empty.
bool is_valid(const Graph& g, int depth = 4);

/// Runs exactly one layer (1..4), assuming the lower layers passed. For tests
/// and tools that want to exercise one layer on a state a lower layer would
/// reject; the result is unspecified (but safe) when that assumption fails.
std::optional<Violation> check_layer(const Graph& g, int layer);

/// Thrown by the checked wrappers; what() is "<context>: <to_string(violation)>".
struct ViolationError : std::runtime_error {
  ViolationError(Violation v, std::string context);
  Violation violation;
  std::string context;  ///< e.g. "after refine (4, 4)"
};

}  // namespace bccmis
