// bccmis: the geometry of the 2D lattice that the operations, the tools and
// the apps share, written once for every lattice (bccmis/lattice.h):
//
//   midpoint, are_side_adjacent     the position computations of the
//                                   operations where the paper's sets cannot
//                                   decide (each use is listed in
//                                   spec/errata.toml, kind = "position")
//   refined_center_level            which positions can be coarsened
//   angle_less, in_angular_order,   the boundary of a cell in
//   boundary_in_angular_order       counter-clockwise order: the hull of eq. (1)
//   for_each_edge_neighbor,         the cells across a side piece of a cell
//   for_each_touching_neighbor      (eq. 3's X) and every cell touching it
//
// The checker (bccmis/invariants) keeps its own, independent geometry.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <iterator>
#include <optional>
#include <type_traits>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/lattice.h"

namespace bccmis {

/// The midpoint of a and b. Callers only pass points whose coordinate
/// differences are even; written to avoid overflow near 2^62.
inline Point midpoint(const Point& a, const Point& b) { return {a.x + (b.x - a.x) / 2, a.y + (b.y - a.y) / 2}; }

/// Two corners of one cell are the ends of a side (not a diagonal) iff they
/// share a coordinate.
inline bool are_side_adjacent(const Point& a, const Point& b) { return a != b && (a.x == b.x || a.y == b.y); }

/// The level of the refined cell whose center would be at `p`, judged from the
/// position alone: a center of a level-l cell with l < L has both coordinates
/// odd multiples of 2^(L-l). Empty for any other position (grid nodes, side
/// midpoints, level-L centers, points outside the domain). spec/errata.toml E7.
inline std::optional<int> refined_center_level(const LatticeSize& size, const Point& p) {
  const std::int64_t S = level0_side(size);
  // Strictly inside the domain; W*S <= 2^62 so the products do not overflow.
  if (p.x <= 0 || p.y <= 0 || p.x >= size.W * S || p.y >= size.H * S) return std::nullopt;
  // A level-l center has both coordinates odd multiples of 2^(L-l).
  const int tx = std::countr_zero(static_cast<std::uint64_t>(p.x));
  const int ty = std::countr_zero(static_cast<std::uint64_t>(p.y));
  if (tx != ty) return std::nullopt;
  const int l = size.L - tx;
  if (l < 0 || l >= size.L) return std::nullopt;  // grid node (l < 0) or level-L center
  return l;
}

// ---- The boundary of a cell in angular order ---------------------------------------

/// Directions from a cell's center to its boundary nodes (multiples of 45
/// degrees) in counter-clockwise order, starting just above -pi: true iff u
/// comes before v. Exact (compares signs only).
///
/// Counter-clockwise order of directions in atan2 order, (-pi, pi]: first the
/// directions with y < 0 or along +x, then the others; within each half, u
/// comes before v iff v is counter-clockwise of u. The boundary nodes of a
/// cell lie at its corners and side midpoints, so their directions from the
/// center are multiples of 45 degrees and the signs of the components decide
/// the order exactly (no overflow for any coordinates).
inline bool angle_less(const Point& u, const Point& v) {
  auto sgn = [](std::int64_t a) { return static_cast<int>(a > 0) - static_cast<int>(a < 0); };
  const int ux = sgn(u.x), uy = sgn(u.y), vx = sgn(v.x), vy = sgn(v.y);
  auto half = [](int x, int y) { return (y < 0 || (y == 0 && x > 0)) ? 0 : 1; };
  if (half(ux, uy) != half(vx, vy)) return half(ux, uy) < half(vx, vy);
  return ux * vy - uy * vx > 0;
}

/// The points of `boundary` (the boundary nodes of a cell centered at c) in
/// counter-clockwise order around c, starting from the lower-left corner.
template <PointRange<Point> R>
std::vector<Point> in_angular_order(const Point& c, const R& boundary) {
  std::vector<Point> ring(std::ranges::begin(boundary), std::ranges::end(boundary));
  std::sort(ring.begin(), ring.end(), [&](const Point& p, const Point& q) {
    return angle_less({p.x - c.x, p.y - c.y}, {q.x - c.x, q.y - c.y});
  });
  return ring;
}

/// The boundary nodes of cell c in counter-clockwise order around c, starting
/// from the lower-left corner: the hull of eq. (1) is the polygon through them.
template <AdaptiveLattice L>
requires std::same_as<point_type_t<L>, Point> std::vector<Point> boundary_in_angular_order(const L& g, const Point& c) {
  return in_angular_order(c, neighbors(g, c));
}

// ---- Neighbor cells (the balance conditions) -----------------------------------------

/// Calls f(x) for every cell x across a side piece of cell c: eq. (3)'s X
/// (erratum E4), the cells the §2.1 level test looks at. Two boundary nodes
/// of c share a second cell exactly when they are the ends of one side piece
/// of c (a corner and a corner, or a corner and a junction). x may repeat.
template <AdaptiveLattice L, class F>
void for_each_edge_neighbor(const L& g, const point_type_t<L>& c, const F& f) {
  const auto& B = neighbors(g, c);  // the set itself (reference) or a copy kept alive (fast)
  using Set = decltype(neighbors(g, c));
  if constexpr (std::is_reference_v<Set>) {
    for (auto bi = std::ranges::begin(B); bi != std::ranges::end(B); ++bi) {
      const auto& Ni = neighbors(g, *bi);
      for (auto bj = std::next(bi); bj != std::ranges::end(B); ++bj) {
        const auto& Nj = neighbors(g, *bj);
        for (const auto& x : Ni)
          if (x != c && contains(Nj, x)) f(x);
      }
    }
  } else {
    // A lattice that builds a neighbour set on each request (the fast
    // lattices): each boundary node's set built once, not once per pair
    // (spec/stuffing.md S28c); the same pairs, the same calls of f in the
    // same order.
    std::vector<std::remove_cvref_t<Set>> N;
    for (const auto& b : B) N.push_back(neighbors(g, b));
    for (std::size_t i = 0; i < N.size(); ++i)
      for (std::size_t j = i + 1; j < N.size(); ++j)
        for (const auto& x : N[i])
          if (x != c && contains(N[j], x)) f(x);
  }
}

/// Calls f(x) for every cell x touching cell c (sharing a side piece or only
/// a corner): it meets c's boundary at a corner of c or along a side piece
/// whose ends are boundary nodes of c, so it lists one. x may repeat.
template <AdaptiveLattice L, class F>
void for_each_touching_neighbor(const L& g, const point_type_t<L>& c, const F& f) {
  for (const auto& p : neighbors(g, c))
    for (const auto& x : neighbors(g, p))
      if (x != c) f(x);
}

}  // namespace bccmis
