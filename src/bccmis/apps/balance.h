// bccmis apps: balanced coarsening sweeps on top of the public operations
// (coarsen, can_coarsen) and the core's balance modes and cascade
// (bccmis/balance.h: Balance, refine_balanced, find_corner_imbalance).
//
// coarsen_where is the sweep matching refine_balanced for coarsening; in
// corner mode the functions here add the corner guards the core's coarsen
// does not have (spec/apps.md, "Balanced refinement").
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <utility>

#include "bccmis/balance.h"
#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis {

namespace fast {
class Lattice;
}

/// can_coarsen(g, n), and in corner mode also `FinerNeighbor` when a cell
/// touching the merged cell at a corner point is finer than n's children.
std::optional<CoarsenRefusal> can_coarsen_under(const Graph& g, const Point& n, Balance b);

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

}  // namespace bccmis
