// bccmis::p4est_bridge, 3D: exchange leaf sets between a 3D bccmis lattice
// (d3::Graph3) and a p8est forest of octrees (spec/p4est.md "3D: p8est").
//
// A W x H x D lattice of depth L is a p8est forest on the W x H x D brick
// connectivity (p8est_connectivity_new_brick(W, H, D, 0, 0, 0)): each
// level-0 cube is one tree, each leaf cube of the lattice one leaf octant,
// with the same level. Coordinates:
//
//   bccmis unit:   a level-0 cube has side S = 2^(L+1) (d3/point.h);
//   p8est unit:    a tree has side P8EST_ROOT_LEN = 2^19 (P8EST_MAXLEVEL);
//   scale:         one bccmis unit is 2^(18-L) octant units, so L <= 18
//                  (P8EST_QMAXLEVEL);
//   cube (i,j,k):  the level-0 cube with lowest corner (i S, j S, k S) is the
//                  tree whose first vertex (tree_to_vertex[8t]) is at
//                  (i, j, k), read from the connectivity's vertex coordinates;
//   a leaf:        center c, level l, side s = 2^(L+1-l) is the octant
//                  x = (c.x - s/2 - i S) 2^(18-L), likewise y and z, level l.
//
// Balance: the core's 3D balance (2:1 across faces and edges, spec/
// lattice3d.md §2) is P8EST_CONNECT_EDGE; the apps' Balance::Corner is
// P8EST_CONNECT_FULL.
//
// Import refines every proper ancestor of the forest's leaves, coarsest
// first, with the 3D core's refine, which refuses exactly when the forest is
// not edge balanced, and then runs the 3D checker. Session, ImportError and
// the error conventions are those of the 2D bridge (bridge.h).
#pragma once

#include <p8est.h>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/p4est/bridge.h"

namespace bccmis::p4est_bridge {

/// A leaf of a 3D bccmis lattice: a cube center and its level.
struct Leaf3 {
  d3::Point3 center;
  int level = 0;
  friend auto operator<=>(const Leaf3&, const Leaf3&) = default;
  friend bool operator==(const Leaf3&, const Leaf3&) = default;
};

/// A leaf octant of a p8est forest, in p8est's own numbers. Plain int32
/// fields, so it can be sent with MPI.
struct Quadrant3 {
  std::int32_t tree = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::int32_t z = 0;
  std::int32_t level = 0;
  friend auto operator<=>(const Quadrant3&, const Quadrant3&) = default;
  friend bool operator==(const Quadrant3&, const Quadrant3&) = default;
};

struct Connectivity3Deleter {
  void operator()(p8est_connectivity_t* c) const noexcept;
};
struct Forest3Deleter {
  void operator()(p8est_t* p) const noexcept;
};
using Forest3Ptr = std::unique_ptr<p8est_t, Forest3Deleter>;

/// The W x H x D brick connectivity of a 3D lattice and the coordinate mapping.
class Brick3 {
 public:
  /// Throws LatticeError on an invalid size and std::invalid_argument when
  /// L > P8EST_QMAXLEVEL or W H D does not fit p8est's tree index.
  explicit Brick3(const d3::LatticeSize3& size);

  const d3::LatticeSize3& size() const { return size_; }
  p8est_connectivity_t* connectivity() const { return conn_.get(); }

  /// The tree of level-0 cube (i, j, k), 0 <= i < W, 0 <= j < H, 0 <= k < D.
  std::int32_t tree(std::int64_t i, std::int64_t j, std::int64_t k) const;

  /// The octant of a leaf. Precondition: a cube of this lattice.
  Quadrant3 to_quadrant(const Leaf3& leaf) const;
  /// The leaf of an octant. Throws ImportError when the tree index is out of
  /// range, the level is negative or deeper than L, or the coordinates are
  /// not those of a level-l octant inside the tree.
  Leaf3 to_leaf(const Quadrant3& q) const;

 private:
  d3::LatticeSize3 size_;
  std::unique_ptr<p8est_connectivity_t, Connectivity3Deleter> conn_;
  std::vector<std::int32_t> tree_of_cube_;  // (k H + j) W + i -> tree
  std::vector<std::int64_t> cube_of_tree_;  // tree -> (k H + j) W + i
  int shift_ = 0;                           // 18 - L
};

/// The leaves of g (its cells and their levels), sorted.
std::vector<Leaf3> leaves(const d3::Graph3& g);

/// The forest on brick.connectivity() whose leaves are `leaves` (recursive
/// p8est_refine from the level-0 forest, partitioned over `comm` as
/// p8est_new does; every rank passes the same leaves). Throws ImportError
/// when the leaves do not tile the lattice.
Forest3Ptr make_forest(const Brick3& brick, std::span<const Leaf3> leaves, sc_MPI_Comm comm);

/// make_forest(brick, leaves(g), comm).
Forest3Ptr export_forest(const Brick3& brick, const d3::Graph3& g, sc_MPI_Comm comm);

/// This rank's leaf octants, in p8est's order (tree, then Morton order).
std::vector<Quadrant3> local_quadrants(const p8est_t* forest);

/// Every rank's leaf octants on rank `root` (empty on the other ranks), in
/// the global order. Collective over the forest's communicator.
std::vector<Quadrant3> gather_quadrants(const p8est_t* forest, int root = 0);

/// Builds the 3D graph whose leaves are the given octants and checks it:
/// throws ImportError when an octant is invalid (Brick3::to_leaf), when two
/// leaves overlap, when part of the domain is not covered, when the leaf set
/// is not edge balanced (2:1 across faces and edges), or when the 3D checker
/// (invariants/d3/) finds a violation in the result.
d3::Graph3 import_quadrants(const Brick3& brick, std::span<const Quadrant3> quadrants);

/// The same from leaves in bccmis coordinates (also refused: a center that
/// is not the center of a level-l cube of the lattice).
d3::Graph3 import_leaves(const d3::LatticeSize3& size, std::span<const Leaf3> leaves);

/// import_quadrants of a forest held entirely by this rank; throws
/// ImportError otherwise.
d3::Graph3 import_forest(const Brick3& brick, const p8est_t* forest);

}  // namespace bccmis::p4est_bridge
