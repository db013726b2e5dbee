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

#include "bccmis/d3/point.h"
#include "bccmis/graph.h"

namespace bccmis::d3 {

/// The graph of spec/lattice3d.md §1: N, C, N(·) and the level of every
/// center; the 2D graph's data (bccmis/graph.h) on 3D points.
using Graph = BasicGraph<Point, LatticeSize>;

/// The initial lattice: W x H x D level-0 cubes; nodes at the grid points,
/// each center joined to its 8 corners. Throws LatticeError on an invalid size.
Graph make_lattice(const LatticeSize& size);

}  // namespace bccmis::d3

namespace bccmis {
extern template struct BasicGraph<d3::Point, d3::LatticeSize>;
}  // namespace bccmis
