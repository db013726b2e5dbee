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

#include <map>

#include "bccmis/d3/point.h"

namespace bccmis::d3 {

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
