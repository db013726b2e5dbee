// bccmis apps: the balance cascade on the 3D lattice (spec/lattice3d.md §8).
//
// The same cascade as the 2D refine_balanced (balance.h), instantiated for
// d3::Graph3 and fast::Lattice3 from the one template (apps/detail/cascade.h),
// on the public 3D operations (d3/ops.h) and the neighbour queries of the
// graph alone:
//
//   edge   (the core's rule, p8est's P8EST_CONNECT_EDGE): the face-or-edge
//          neighbours of c, the cells sharing two or more nodes with c
//          (eq. 3's X of spec/lattice3d.md §2);
//   corner (P8EST_CONNECT_FULL): every cell sharing a node with c, so cells
//          meeting c at a corner point only count too.
#pragma once

#include <optional>
#include <utility>

#include "bccmis/apps/balance.h"
#include "bccmis/d3/graph.h"
#include "bccmis/fast/lattice3.h"

namespace bccmis::d3 {

/// What refine_balanced(g, c) did on the 3D lattice.
using BalancedRefineResult3 = BasicBalancedRefineResult<Point3>;

/// The face-or-edge neighbours of cell c: eq. (3)'s X, the cells other than
/// c sharing two or more nodes with it. Empty if c is not a center.
PointSet3 edge_neighbors(const Graph3& g, const Point3& c);

/// The cells touching cell c at all (sharing at least one node with it).
PointSet3 touching_neighbors(const Graph3& g, const Point3& c);

/// can_refine(g, c), and in corner mode also `CoarserNeighbor` when a cell
/// touching c only at a corner point is coarser than c.
std::optional<RefineRefusal> can_refine_under(const Graph3& g, const Point3& c, Balance b);

/// Refines cell c even when a neighbour under mode b is coarser, by first
/// refining that neighbour (recursively: its coarser neighbours first; the
/// smallest coarser neighbour by position first). Only cells that every
/// balanced lattice with c refined must refine are refined, so the leaf set
/// reached by a set of requests is the smallest balanced refinement holding
/// them, whatever their order. Refused (changing nothing) only with
/// `NoSuchCell` or `MaxLevel`. In corner mode g must be corner-balanced.
BalancedRefineResult3 refine_balanced(Graph3& g, const Point3& c, Balance b = Balance::Edge);

/// The same cascade on the fast 3D lattice: the same refines in the same
/// order, so the same leaf set and canonical state as on Graph3.
BalancedRefineResult3 refine_balanced(fast::Lattice3& g, const Point3& c, Balance b = Balance::Edge);

/// The first pair of touching cells (in sorted order of the first; the
/// second the smallest such) whose levels differ by more than one; empty for
/// a corner-balanced lattice. Assumes g is edge-balanced.
std::optional<std::pair<Point3, Point3>> find_corner_imbalance(const Graph3& g);

}  // namespace bccmis::d3
