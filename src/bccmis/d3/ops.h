// bccmis::d3: refine (spec/lattice3d.md §4) and coarsen (§5) on the 3D graph.
//
// Both are written as the numbered set equations of spec/equations3d.toml
// (namespace bccmis3d). They return the decision and the sets they touched,
// with the refusal enums and codes of 2D (bccmis/ops.h); a refused call
// changes nothing, and a call that throws leaves the graph as it was.
#pragma once

#include <optional>

#include "bccmis/d3/graph.h"
#include "bccmis/ops.h"

namespace bccmis::d3 {

/// What refine(c) did: the decision, the 8 new centers Y and the new nodes J+.
using RefineResult = BasicRefineResult<PointSet>;
/// What coarsen(n) did: the decision, the 8 deleted centers Y and the deleted nodes J-.
using CoarsenResult = BasicCoarsenResult<PointSet>;

/// Empty when refine(g, c) would be applied, otherwise the first failing
/// reason: no-such-cell, max-level, coarser-neighbor.
std::optional<RefineRefusal> can_refine(const Graph& g, const Point& c);

/// Empty when coarsen(g, n) would be applied, otherwise the first failing
/// reason: no-such-node, not-a-refined-center, children-refined, finer-neighbor.
std::optional<CoarsenRefusal> can_coarsen(const Graph& g, const Point& n);

/// §4: split cell c into its 8 children of the next level.
RefineResult refine(Graph& g, const Point& c);

/// §5: merge the 8 cells around node n into one cell centered at n.
CoarsenResult coarsen(Graph& g, const Point& n);

/// The level of the refined cell whose center would be at `p`, judged from
/// the position alone (Q4): a center of a level-l cube with l < L lies
/// strictly inside the domain and has all three coordinates odd multiples of
/// 2^(L-l). Empty for any other position.
std::optional<int> refined_center_level(const LatticeSize& size, const Point& p);

}  // namespace bccmis::d3
