// bccmis apps: balanced refinement and coarsening sweeps on top of the public
// operations (refine, coarsen, can_refine, can_coarsen).
//
// The paper (§2.1 ¶1) refuses to refine a cell that has a coarser edge-
// neighbor and leaves the cascade to the user; refine_balanced is that
// cascade. coarsen_where is the matching sweep for coarsening. Both use only
// the public API of the reference core (spec/apps.md, "Balanced refinement").
//
// Two balance modes. Edge (the core's, eq. 3's formula, erratum E4): cells
// sharing a piece of side differ by at most one level. Corner (eq. 3's text
// reading): cells touching at all, at a corner point too, differ by at most
// one level. The core's operations only guard edge balance; in corner mode
// the functions here add the corner guards, the cascade follows them, and
// find_corner_imbalance is the matching check.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis {

namespace fast {
class Lattice;
}

/// Which neighbors the 2:1 level rule covers.
enum class Balance {
  Edge,    ///< `edge`: cells sharing a piece of side (the core's rule)
  Corner,  ///< `corner`: cells touching at a side or at a corner point
};

/// `edge` or `corner`; empty for anything else.
std::optional<Balance> parse_balance(std::string_view name);
std::string_view name(Balance b);

/// The cells sharing (part of) a side with cell c: eq. (3)'s X,
/// (∪_{b_i ≠ b_j ∈ 𝒩(c)} 𝒩(b_i) ∩ 𝒩(b_j)) \ {c}. Empty if c is not a center.
PointSet edge_neighbors(const Graph& g, const Point& c);

/// The cells touching cell c at all (edge-neighbors and cells meeting c at
/// a corner point only): (∪_{b ∈ 𝒩(c)} 𝒩(b)) \ {c}.
PointSet touching_neighbors(const Graph& g, const Point& c);

/// can_refine(g, c), and in corner mode also `CoarserNeighbor` when a cell
/// touching c only at a corner is coarser than c.
std::optional<RefineRefusal> can_refine_under(const Graph& g, const Point& c, Balance b);

/// can_coarsen(g, n), and in corner mode also `FinerNeighbor` when a cell
/// touching the merged cell at a corner point is finer than n's children.
std::optional<CoarsenRefusal> can_coarsen_under(const Graph& g, const Point& n, Balance b);

/// What refine_balanced(g, c) did, on a lattice with point type P.
template <class P>
struct BasicBalancedRefineResult {
  /// Empty when c was refined. Only `NoSuchCell` or `MaxLevel`: a coarser
  /// neighbor never stops the cascade.
  std::optional<RefineRefusal> refused;
  /// The centers refined, in order: the cascade first (coarsest first along
  /// each chain), c last. Empty when refused.
  std::vector<P> refined;
  bool applied() const { return !refused; }
};
/// What refine_balanced(g, c) did on a 2D lattice.
using BalancedRefineResult = BasicBalancedRefineResult<Point>;

/// Refines cell c even when a neighbor (an edge-neighbor; in corner mode
/// any touching cell) is coarser, by first refining that neighbor
/// (recursively: the neighbor's coarser neighbors first). Only cells that
/// every balanced lattice with c refined must refine are refined, so the
/// leaf set reached by a set of requests does not depend on their order
/// (tests/apps_balance_test.cpp checks this against a geometric closure). A
/// refused call changes nothing. In corner mode g must be corner-balanced.
BalancedRefineResult refine_balanced(Graph& g, const Point& c, Balance b = Balance::Edge);
/// The same cascade on the fast implementation (src/bccmis/fast): the same cells
/// refined in the same order.
BalancedRefineResult refine_balanced(fast::Lattice& g, const Point& c, Balance b = Balance::Edge);

/// Decides whether the four cells around refined center n may be merged.
/// Called only when can_coarsen_under(g, n, mode) is empty.
using CoarsenPredicate = std::function<bool(const Graph& g, const Point& n)>;

/// One pass over the refined centers, finest level first, then in sorted
/// (x, y) order: coarsens every n for which can_coarsen_under(g, n, b) is
/// empty (re-tested at n, after the pass's earlier coarsenings) and
/// `allow(g, n)` is true. Returns the number of coarsenings.
std::size_t coarsen_sweep(Graph& g, const CoarsenPredicate& allow, Balance b = Balance::Edge);

/// Repeats coarsen_sweep until a pass coarsens nothing. Returns the total
/// number of coarsenings. With `allow` always true the result is the initial
/// lattice; in general it is the coarsest lattice reachable by legal
/// coarsenings the predicate allows.
std::size_t coarsen_where(Graph& g, const CoarsenPredicate& allow, Balance b = Balance::Edge);

/// The boundary nodes 𝒩(n) that the merged cell centered at n would have
/// after coarsen(g, n), computed without changing g: the four corners of the
/// merged cell and those side midpoints that keep at least two cells outside
/// the four children (spec/errata.toml E2). Precondition: can_coarsen(g, n)
/// is empty.
PointSet boundary_after_coarsen(const Graph& g, const Point& n);

/// The first pair of touching cells (in sorted order of the first) whose
/// levels differ by more than one; empty for a corner-balanced lattice.
/// Assumes g passes the checker (edge balance included).
std::optional<std::pair<Point, Point>> find_corner_imbalance(const Graph& g);

}  // namespace bccmis
