// bccmis (this folder holds the reference core: points and sizes, the graph,
// refine, coarsen and balance, the formats): balanced refinement, the core's
// third verb beside refine and coarsen (spec/apps.md "Balanced refinement",
// spec/lattice3d.md §8), written once over every lattice of every dimension:
// the reference Graph and fast::Lattice in 2D, d3::Graph and
// d3::fast::Lattice in 3D.
//
// The paper (§2.1 ¶1) refuses to refine a cell that has a coarser edge-
// neighbor and leaves the cascade to the user; refine_balanced is that
// cascade. A lattice is reached only through the vocabulary of
// bccmis/lattice.h and the neighbour queries of bccmis/geometry.h, which
// read the graph alone (no positions).
//
// Two balance modes. Edge (the core's rule, eq. 3's formula, erratum E4;
// p4est's P4EST_CONNECT_FACE, p8est's P8EST_CONNECT_EDGE): the edge-
// neighbours of c, the cells sharing two or more nodes with c (eq. 3's X:
// across a side piece in 2D, a face or edge piece in 3D), differ from c by
// at most one level. Corner (eq. 3's text reading; P4EST_CONNECT_FULL,
// P8EST_CONNECT_FULL): every cell touching c, at a corner point too. The
// core's operations only guard edge balance; in corner mode the functions
// here add the corner guards, the cascade follows them, and
// find_corner_imbalance is the matching check.
#pragma once

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/geometry.h"
#include "bccmis/graph.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis {

/// Which neighbors the 2:1 level rule covers.
enum class Balance {
  Edge,    ///< `edge`: cells sharing a piece of side (the core's rule)
  Corner,  ///< `corner`: cells touching at a side or at a corner point
};

/// `edge` or `corner`; empty for anything else.
inline std::optional<Balance> parse_balance(std::string_view text) {
  if (text == "edge") return Balance::Edge;
  if (text == "corner") return Balance::Corner;
  return std::nullopt;
}

inline std::string_view name(Balance b) { return b == Balance::Edge ? "edge" : "corner"; }

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

namespace d3 {
/// What refine_balanced(g, c) did on the 3D lattice.
using BalancedRefineResult = BasicBalancedRefineResult<Point>;
}  // namespace d3

namespace detail {

/// Calls f(x) for every neighbor x of center c under mode b (x may repeat).
template <AdaptiveLattice Lat, class F>
void for_each_neighbor(const Lat& g, const point_type_t<Lat>& c, Balance b, const F& f) {
  if (b == Balance::Corner)
    for_each_touching_neighbor(g, c, f);
  else
    for_each_edge_neighbor(g, c, f);
}

/// The neighbors of c under mode b, sorted; empty if c is not a center.
template <AdaptiveLattice Lat>
std::set<point_type_t<Lat>> neighbors_under(const Lat& g, const point_type_t<Lat>& c, Balance b) {
  using P = point_type_t<Lat>;
  std::set<P> X;
  if (is_center(g, c)) for_each_neighbor(g, c, b, [&](const P& x) { X.insert(x); });
  return X;
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

}  // namespace detail

/// The cells sharing (part of) a side with cell c: eq. (3)'s X,
/// (∪_{b_i ≠ b_j ∈ 𝒩(c)} 𝒩(b_i) ∩ 𝒩(b_j)) \ {c}; in 3D the face-or-edge
/// neighbours, the cells other than c sharing two or more nodes with it.
/// Empty if c is not a center.
template <AdaptiveLattice Lat>
std::set<point_type_t<Lat>> edge_neighbors(const Lat& g, const point_type_t<Lat>& c) {
  return detail::neighbors_under(g, c, Balance::Edge);
}

/// The cells touching cell c at all (sharing at least one node with it):
/// (∪_{b ∈ 𝒩(c)} 𝒩(b)) \ {c}. Empty if c is not a center.
template <AdaptiveLattice Lat>
std::set<point_type_t<Lat>> touching_neighbors(const Lat& g, const point_type_t<Lat>& c) {
  return detail::neighbors_under(g, c, Balance::Corner);
}

/// can_refine(g, c), and in corner mode also `CoarserNeighbor` when a cell
/// touching c only at a corner point is coarser than c.
template <AdaptiveLattice Lat>
std::optional<RefineRefusal> can_refine_under(const Lat& g, const point_type_t<Lat>& c, Balance b) {
  const std::optional<RefineRefusal> why = can_refine(g, c);
  if (why || b == Balance::Edge) return why;
  if (detail::coarser_neighbor(g, c, Balance::Corner)) return RefineRefusal::CoarserNeighbor;
  return std::nullopt;
}

namespace detail {

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

}  // namespace detail

/// Refines cell c even when a neighbor under mode b (an edge-neighbor; in
/// corner mode any touching cell) is coarser, by first refining that
/// neighbor (recursively: its coarser neighbors first; the smallest coarser
/// neighbor by position first). Only cells that every balanced lattice with
/// c refined must refine are refined, so the leaf set reached by a set of
/// requests is the smallest balanced refinement holding them, whatever their
/// order (tests/balance_test.cpp and tests/d3/balance_test.cpp check
/// this against a geometric closure). Every lattice of one dimension refines
/// the same cells in the same order. Refused (changing nothing) only with
/// `NoSuchCell` or `MaxLevel`. In corner mode g must be corner-balanced.
template <AdaptiveLattice Lat>
BasicBalancedRefineResult<point_type_t<Lat>> refine_balanced(Lat& g, const point_type_t<Lat>& c,
                                                             Balance b = Balance::Edge) {
  BasicBalancedRefineResult<point_type_t<Lat>> result;
  if (const std::optional<RefineRefusal> why = can_refine(g, c);
      why == RefineRefusal::NoSuchCell || why == RefineRefusal::MaxLevel) {
    result.refused = why;
    return result;
  }
  detail::cascade(g, c, b, result.refined);
  return result;
}

/// The first pair (c, x) of touching cells, c in the lattice's order, x the
/// smallest such, whose levels differ by more than one (x the finer); empty
/// for a corner-balanced lattice. Assumes g is edge-balanced (passes the
/// checker).
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

namespace d3 {
// The 3D lattice's names for the cascade (bccmis::d3::refine_balanced, ...).
using bccmis::can_refine_under;
using bccmis::edge_neighbors;
using bccmis::find_corner_imbalance;
using bccmis::refine_balanced;
using bccmis::touching_neighbors;
}  // namespace d3

}  // namespace bccmis
