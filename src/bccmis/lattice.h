// bccmis: the vocabulary every lattice speaks.
//
// The reference Graph (std::set, src/bccmis) and bccmis::fast::Lattice (flat
// arrays, src/bccmis/fast) are two lattices of the same kind: the adaptive
// BCC lattice of Erleben 2009 §2, stored as the bipartite node/center graph.
// Code that must run on every lattice (the trace stepper and replay, explore,
// the viewer, conformance, the apps, the benchmarks, the fuzz targets) is
// written once against the concept AdaptiveLattice below and reaches a
// lattice only through these free functions, found by argument-dependent
// lookup in the lattice's namespace:
//
//   L g(size);                     the initial lattice (throws LatticeError)
//   size_of(g)                     its LatticeSize
//   can_refine(g, c), can_coarsen(g, n)   the exact preconditions
//   refine(g, c), coarsen(g, n)    the operations; the result says whether it
//                                  was applied (refused) and what it touched:
//                                  Y and J_plus, or Y and J_minus
//   is_center(g, v), is_node(g, v), level_of(g, c)
//   neighbors(g, v)                N(v), sorted by position
//   cells(g), nodes(g)             C and N, sorted by position
//   cell_count(g), node_count(g)   |C| and |N|
//   write_canonical_state(out, g)  the canonical text of spec/formats.md
//
// contains(range, p) asks any of the point ranges above whether it holds p.
// The lattice geometry written over this vocabulary (angular order, edge
// and touching neighbors, refined_center_level) is bccmis/geometry.h.
//
// The point type and the dimension are properties of the lattice type
// (L::point_type, L::size_type, L::dimension), so a lattice of another
// dimension models the same concept with its own point type.
#pragma once

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <optional>
#include <ostream>
#include <ranges>
#include <sstream>
#include <string>
#include <type_traits>

#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis {

template <class L>
using point_type_t = typename L::point_type;

/// A range of points (a neighbour set, C, N, Y, J): iterable, sized.
template <class R, class P>
concept PointRange = std::ranges::sized_range<R> && std::convertible_to < std::ranges::range_reference_t<R>,
const P& > ;

// clang-format 14 cannot lay out requires-expressions; this one is kept as written.
// clang-format off
template <class L>
concept AdaptiveLattice =
    std::copy_constructible<L> &&
    requires(L& g, const L& cg, const typename L::point_type& p, const typename L::size_type& s, std::ostream& out) {
      { L::dimension } -> std::convertible_to<int>;
      L(s);
      { size_of(cg) } -> std::convertible_to<const typename L::size_type&>;
      { can_refine(cg, p) } -> std::same_as<std::optional<RefineRefusal>>;
      { can_coarsen(cg, p) } -> std::same_as<std::optional<CoarsenRefusal>>;
      { refine(g, p).refused } -> std::convertible_to<std::optional<RefineRefusal>>;
      { refine(g, p).applied() } -> std::same_as<bool>;
      { refine(g, p).Y } -> PointRange<typename L::point_type>;
      { refine(g, p).J_plus } -> PointRange<typename L::point_type>;
      { coarsen(g, p).refused } -> std::convertible_to<std::optional<CoarsenRefusal>>;
      { coarsen(g, p).applied() } -> std::same_as<bool>;
      { coarsen(g, p).Y } -> PointRange<typename L::point_type>;
      { coarsen(g, p).J_minus } -> PointRange<typename L::point_type>;
      { is_center(cg, p) } -> std::same_as<bool>;
      { is_node(cg, p) } -> std::same_as<bool>;
      { level_of(cg, p) } -> std::same_as<int>;
      { neighbors(cg, p) } -> PointRange<typename L::point_type>;
      { cells(cg) } -> PointRange<typename L::point_type>;
      { nodes(cg) } -> PointRange<typename L::point_type>;
      { cell_count(cg) } -> std::same_as<std::size_t>;
      { node_count(cg) } -> std::same_as<std::size_t>;
      write_canonical_state(out, cg);
    };
// clang-format on

/// Whether a range of points (a neighbor set, Y, J, C, N) holds p: its own
/// lookup where it has one (std::set, fast::SmallPoints), a scan otherwise.
template <class P, PointRange<P> R>
bool contains(const R& range, const P& p) {
  if constexpr (requires { range.contains(p); })
    return range.contains(p);
  else
    return std::ranges::find(range, p) != std::ranges::end(range);
}

/// The result types of refine and coarsen on lattice L.
template <AdaptiveLattice L>
using refine_result_t = decltype(refine(std::declval<L&>(), std::declval<const point_type_t<L>&>()));
template <AdaptiveLattice L>
using coarsen_result_t = decltype(coarsen(std::declval<L&>(), std::declval<const point_type_t<L>&>()));

/// The canonical text of any lattice, as a string.
template <AdaptiveLattice L>
std::string canonical_text(const L& g) {
  std::ostringstream out;
  write_canonical_state(out, g);
  return std::move(out).str();
}

// ---- The reference graph models the concept, in every dimension ------------

template <class P, class Size>
const Size& size_of(const BasicGraph<P, Size>& g) {
  return g.size;
}
template <class P, class Size>
bool is_center(const BasicGraph<P, Size>& g, const P& v) {
  return g.is_center(v);
}
template <class P, class Size>
bool is_node(const BasicGraph<P, Size>& g, const P& v) {
  return g.is_node(v);
}
/// Throws std::out_of_range if c is not a center.
template <class P, class Size>
int level_of(const BasicGraph<P, Size>& g, const P& c) {
  return g.level_of(c);
}
template <class P, class Size>
const std::set<P>& neighbors(const BasicGraph<P, Size>& g, const P& v) {
  return g.nbr(v);
}
template <class P, class Size>
const std::set<P>& cells(const BasicGraph<P, Size>& g) {
  return g.C;
}
template <class P, class Size>
const std::set<P>& nodes(const BasicGraph<P, Size>& g) {
  return g.N;
}
template <class P, class Size>
std::size_t cell_count(const BasicGraph<P, Size>& g) {
  return g.C.size();
}
template <class P, class Size>
std::size_t node_count(const BasicGraph<P, Size>& g) {
  return g.N.size();
}
/// canonical_state(g) written to `out` (spec/formats.md).
void write_canonical_state(std::ostream& out, const Graph& g);

static_assert(AdaptiveLattice<Graph>);

}  // namespace bccmis
