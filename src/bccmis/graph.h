// bccmis: the data of the paper's §2 graph representation, nothing else.
//
// Erleben 2009, §2: the vertices of the triangulation are split into node
// vertices N and cell-center vertices C (N ∩ C = ∅); every vertex v stores a
// neighbor set 𝒩(v) of vertices of the other kind. Centers also carry the
// refinement level of their cell (used by the §2.1 level test).
//
// Point identity. A vertex is named by its integer lattice position
// (spec/formats.md, "Coordinates"). A position is never both a node and a
// center, and the paper's operations keep a vertex's identity when they change
// its kind (eq. 4g/4h turns c into a node; eq. 9d/9e turns n into a center), so
// the position is a stable, implementation-independent id. The operations only
// *use* positions where the paper's sets cannot decide; each such use is listed
// in spec/errata.toml (entries with kind = "position").
#pragma once

#include <map>
#include <set>

#include "bccmis/point.h"

namespace bccmis {

// Point, LatticeSize, LatticeError, validate_lattice_size, level0_side and
// cell_side: bccmis/point.h, one source for every dimension.

/// The graph of §2 on the lattice of point type P and size type Size (one
/// source for every dimension: Graph in 2D, d3::Graph in 3D): N, C, 𝒩(·)
/// and the level of every center.
///
/// Invariants the operations maintain are checked by invariants/ (never
/// assumed here): see spec/invariants.md.
template <class P, class Size>
struct BasicGraph {
  using point_type = P;
  using size_type = Size;
  static constexpr int dimension = P::dimension;

  BasicGraph() = default;
  /// The initial lattice, make_lattice(size).
  explicit BasicGraph(const Size& size);

  Size size;
  std::set<P> N;                       ///< node vertices
  std::set<P> C;                       ///< cell-center vertices
  std::map<P, std::set<P>> neighbors;  ///< 𝒩(v) for every v in N ∪ C
  std::map<P, int> level;              ///< refinement level of every c in C

  /// 𝒩(v); the empty set for a vertex not in the graph.
  const std::set<P>& nbr(const P& v) const;
  bool is_node(const P& v) const { return N.count(v) != 0; }
  bool is_center(const P& v) const { return C.count(v) != 0; }
  /// Level of center c; throws std::out_of_range if c is not a center.
  int level_of(const P& c) const { return level.at(c); }

  friend bool operator==(const BasicGraph&, const BasicGraph&) = default;
};

// make_lattice(size) is found by argument-dependent lookup in the size's
// namespace: the layout of the initial lattice is per dimension.
template <class P, class Size>
BasicGraph<P, Size>::BasicGraph(const Size& initial) : BasicGraph(make_lattice(initial)) {}

template <class P, class Size>
const std::set<P>& BasicGraph<P, Size>::nbr(const P& v) const {
  static const std::set<P> kEmpty;
  auto it = neighbors.find(v);
  return it == neighbors.end() ? kEmpty : it->second;
}

/// The 2D graph of §2.
using Graph = BasicGraph<Point, LatticeSize>;

/// The initial lattice: W x H level-0 cells; nodes at the grid points, each
/// center joined to its 4 corners. Throws LatticeError on an invalid size.
Graph make_lattice(const LatticeSize& size);

extern template struct BasicGraph<Point, LatticeSize>;

}  // namespace bccmis
