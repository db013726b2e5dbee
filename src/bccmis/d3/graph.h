// bccmis::d3: the data of the 3D lattice (spec/lattice3d.md §1), nothing else.
//
// The same bipartite graph as the 2D Graph (bccmis/graph.h): node vertices
// N (every corner of every leaf cube), cell-center vertices C (the leaves of
// a forest of octrees), one neighbor set N(v) per vertex holding vertices of
// the other kind, and the level of every center. A vertex is named by its
// integer position, which it keeps when refine or coarsen changes its kind;
// the operations read positions only where spec/choices3d.toml says so
// (entries with kind = "position").
#pragma once

#include <compare>
#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "bccmis/graph.h"  // LatticeError, kMaxDomainSide

namespace bccmis::d3 {

/// A lattice position in integer coordinates, ordered by (x, y, z).
struct Point3 {
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  friend auto operator<=>(const Point3&, const Point3&) = default;
  friend bool operator==(const Point3&, const Point3&) = default;
};

using PointSet3 = std::set<Point3>;

/// "(x, y, z)": how messages name a position.
std::string to_string(const Point3& p);

/// The size of a 3D lattice: W x H x D level-0 cubes, at most L refinements
/// deep. Level-0 cubes have side S = 2^(L+1); a level-l cube has side
/// 2^(L+1-l), so every center, corner, edge midpoint and face center down to
/// level L is an integer point.
struct LatticeSize3 {
  std::int64_t W = 1;
  std::int64_t H = 1;
  std::int64_t D = 1;
  int L = 0;
  friend bool operator==(const LatticeSize3&, const LatticeSize3&) = default;
};

/// Throws bccmis::LatticeError unless W, H, D >= 1, L >= 0 and the extents
/// W*S, H*S, D*S are at most 2^62. The message names the offending value.
void validate_lattice_size(const LatticeSize3& size);

/// Side of a level-0 cube: S = 2^(L+1).
std::int64_t level0_side(const LatticeSize3& size);

/// Side of a level-`level` cube: 2^(L+1-level).
std::int64_t cell_side(const LatticeSize3& size, int level);

/// The graph of spec/lattice3d.md §1: N, C, N(·) and the level of every center.
struct Graph3 {
  using point_type = Point3;
  using size_type = LatticeSize3;
  static constexpr int dimension = 3;

  Graph3() = default;
  /// The initial lattice, make_lattice(size).
  explicit Graph3(const LatticeSize3& size);

  LatticeSize3 size;
  PointSet3 N;                            ///< node vertices
  PointSet3 C;                            ///< cell-center vertices
  std::map<Point3, PointSet3> neighbors;  ///< N(v) for every v in N ∪ C
  std::map<Point3, int> level;            ///< refinement level of every c in C

  /// N(v); the empty set for a vertex not in the graph.
  const PointSet3& nbr(const Point3& v) const;
  bool is_node(const Point3& v) const { return N.count(v) != 0; }
  bool is_center(const Point3& v) const { return C.count(v) != 0; }
  /// Level of center c; throws std::out_of_range if c is not a center.
  int level_of(const Point3& c) const { return level.at(c); }

  friend bool operator==(const Graph3&, const Graph3&) = default;
};

/// The initial lattice: W x H x D level-0 cubes; nodes at the grid points,
/// each center joined to its 8 corners. Throws LatticeError on an invalid size.
Graph3 make_lattice(const LatticeSize3& size);

}  // namespace bccmis::d3
