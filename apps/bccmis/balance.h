// bccmis apps: balanced refinement and coarsening sweeps on top of the public
// operations (refine, coarsen, can_refine, can_coarsen).
//
// The paper (§2.1 ¶1) refuses to refine a cell that has a coarser edge-
// neighbour and leaves the cascade to the user; refine_balanced is that
// cascade. coarsen_where is the matching sweep for coarsening. Both use only
// the public API of the reference core (spec/apps.md, "Balanced refinement").
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis {

/// The cells sharing (part of) a side with cell c: eq. (3)'s X,
/// (∪_{b_i ≠ b_j ∈ 𝒩(c)} 𝒩(b_i) ∩ 𝒩(b_j)) \ {c}. Empty if c is not a center.
VertexSet edge_neighbors(const Graph& g, const Point& c);

/// What refine_balanced(g, c) did.
struct BalancedRefineResult {
  /// Empty when c was refined. Only `NoSuchCell` or `MaxLevel`: a coarser
  /// neighbour never stops the cascade.
  std::optional<RefineRefusal> refused;
  /// The centers refined, in order: the cascade first (coarsest first along
  /// each chain), c last. Empty when refused.
  std::vector<Point> refined;
  bool applied() const { return !refused; }
};

/// Refines cell c even when an edge-neighbour is coarser, by first refining
/// that neighbour (recursively: the neighbour's coarser neighbours first).
/// Only cells that any balanced lattice with c refined must refine are
/// refined, so the leaf set reached by a set of requests does not depend on
/// their order (tests/apps_balance_test.cpp checks this against a geometric
/// closure). A refused call changes nothing.
BalancedRefineResult refine_balanced(Graph& g, const Point& c);

/// Decides whether the four cells around refined center n may be merged.
/// Called only when can_coarsen(g, n) is empty.
using CoarsenPredicate = std::function<bool(const Graph& g, const Point& n)>;

/// One pass over the refined centers, finest level first, then in sorted
/// (x, y) order: coarsens every n for which
/// can_coarsen(g, n) is empty (re-tested at n, after the pass's earlier
/// coarsenings) and `allow(g, n)` is true. Returns the number of coarsenings.
std::size_t coarsen_sweep(Graph& g, const CoarsenPredicate& allow);

/// Repeats coarsen_sweep until a pass coarsens nothing. Returns the total
/// number of coarsenings. With `allow` always true the result is the initial
/// lattice; in general it is the coarsest lattice reachable by legal
/// coarsenings the predicate allows.
std::size_t coarsen_where(Graph& g, const CoarsenPredicate& allow);

/// The boundary nodes 𝒩(n) that the merged cell centered at n would have
/// after coarsen(g, n), computed without changing g: the four corners of the
/// merged cell and those side midpoints that keep at least two cells outside
/// the four children (spec/errata.toml E2). Precondition: can_coarsen(g, n)
/// is empty.
VertexSet boundary_after_coarsen(const Graph& g, const Point& n);

}  // namespace bccmis
