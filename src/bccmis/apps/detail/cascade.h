// bccmis apps, internal: the balance cascade (spec/apps.md "Balanced
// refinement", spec/lattice3d.md §8) written once over every lattice of every
// dimension: the reference Graph and bccmis::fast::Lattice in 2D, d3::Graph3
// and bccmis::fast::Lattice3 in 3D. A lattice is reached only through the vocabulary of bccmis/lattice.h
// and the neighbour queries of bccmis/geometry.h, which read the graph alone
// (no positions): the edge-neighbours of c are the cells sharing two or more
// nodes with c (eq. 3's X; in 3D the face-or-edge neighbours), the touching
// neighbours the cells sharing at least one.
//
// balance.cpp instantiates these templates for Graph and fast::Lattice,
// balance3.cpp for d3::Graph3 and fast::Lattice3.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/geometry.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis::detail {

/// Calls f(x) for every neighbor x of center c under mode b (x may repeat):
/// edge, the cells sharing two or more nodes with c (eq. 3's X: across a side
/// piece in 2D, a face or edge piece in 3D); corner, every cell touching c.
template <AdaptiveLattice Lat, class F>
void for_each_neighbor(const Lat& g, const point_type_t<Lat>& c, Balance b, const F& f) {
  if (b == Balance::Corner)
    for_each_touching_neighbor(g, c, f);
  else
    for_each_edge_neighbor(g, c, f);
}

/// The smallest (by position) neighbor of c under mode b that is coarser
/// than c, i.e. the first coarser element of the neighbour set.
template <AdaptiveLattice Lat>
std::optional<point_type_t<Lat>> coarser_neighbor(const Lat& g, const point_type_t<Lat>& c, Balance b) {
  using P = point_type_t<Lat>;
  const int l = level_of(g, c);
  std::optional<P> best;
  for_each_neighbor(g, c, b, [&](const P& x) {
    if (level_of(g, x) < l && (!best || x < *best)) best = x;
  });
  return best;
}

/// can_refine(g, c), and in corner mode also `CoarserNeighbor` when a cell
/// touching c only at a corner is coarser than c.
template <AdaptiveLattice Lat>
std::optional<RefineRefusal> can_refine_under(const Lat& g, const point_type_t<Lat>& c, Balance b) {
  const std::optional<RefineRefusal> why = can_refine(g, c);
  if (why || b == Balance::Edge) return why;
  if (coarser_neighbor(g, c, Balance::Corner)) return RefineRefusal::CoarserNeighbor;
  return std::nullopt;
}

// Precondition: c is a center below the maximum level. Every coarser
// neighbor x has level(x) < level(c), so the recursion depth is at most L.
template <AdaptiveLattice Lat>
void cascade(Lat& g, const point_type_t<Lat>& c, Balance b, std::vector<point_type_t<Lat>>& refined) {
  while (can_refine_under(g, c, b) == RefineRefusal::CoarserNeighbor) {
    const std::optional<point_type_t<Lat>> x = coarser_neighbor(g, c, b);
    if (!x) break;  // the refine below reports the inconsistency
    cascade(g, *x, b, refined);
  }
  if (!refine(g, c).applied())
    throw std::logic_error("refine_balanced: refine" + to_string(c) + " refused with " +
                           std::string(code(*can_refine(g, c))) + " after its cascade");
  refined.push_back(c);
}

/// refine_balanced of balance.h and balance3.h.
template <AdaptiveLattice Lat>
BasicBalancedRefineResult<point_type_t<Lat>> refine_balanced(Lat& g, const point_type_t<Lat>& c, Balance b) {
  BasicBalancedRefineResult<point_type_t<Lat>> result;
  if (const std::optional<RefineRefusal> why = can_refine(g, c);
      why == RefineRefusal::NoSuchCell || why == RefineRefusal::MaxLevel) {
    result.refused = why;
    return result;
  }
  cascade(g, c, b, result.refined);
  return result;
}

/// The first pair (c, x) of touching cells, c in the lattice's order, whose
/// levels differ by more than one (x the finer); empty when corner-balanced.
template <AdaptiveLattice Lat>
auto find_corner_imbalance(const Lat& g) -> std::optional<std::pair<point_type_t<Lat>, point_type_t<Lat>>> {
  using P = point_type_t<Lat>;
  for (const P& c : cells(g)) {
    const int l = level_of(g, c);
    std::optional<P> finer;
    for_each_touching_neighbor(g, c, [&](const P& x) {
      if (level_of(g, x) > l + 1 && (!finer || x < *finer)) finer = x;
    });
    if (finer) return std::make_pair(c, *finer);
  }
  return std::nullopt;
}

}  // namespace bccmis::detail
