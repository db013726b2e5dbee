// bccmis::p4est_bridge: exchange leaf sets between a bccmis lattice and a p4est
// forest of quadtrees (issue 10; spec/p4est.md).
//
// A W x H lattice of depth L is a p4est forest on the W x H brick
// connectivity (p4est_connectivity_new_brick(W, H, 0, 0)): each level-0 cell
// is one tree, and each leaf cell of the lattice is one leaf quadrant, with
// the same level. Coordinates (spec/p4est.md has the derivation):
//
//   bccmis unit:   a level-0 cell has side S = 2^(L+1) (graph.h);
//   p4est unit:    a tree has side P4EST_ROOT_LEN = 2^30 (P4EST_MAXLEVEL);
//   scale:         one bccmis unit is 2^(29-L) quadrant units, so L <= 29
//                  (P4EST_QMAXLEVEL);
//   cell (i, j):   the level-0 cell with lower-left corner (i S, j S) is the
//                  tree whose first vertex (tree_to_vertex[4t]) is at (i, j),
//                  read from the connectivity's vertex coordinates (the brick
//                  numbers its trees along a space-filling curve, not row by
//                  row);
//   a leaf:        center (cx, cy), level l, side s = 2^(L+1-l) is the
//                  quadrant x = (cx - s/2 - i S) 2^(29-L), likewise y, level l.
//
// Balance: the core's edge balance (eq. 3, erratum E4) is p4est's
// P4EST_CONNECT_FACE; the apps' Balance::Corner is P4EST_CONNECT_FULL.
//
// Export builds a forest with the lattice's leaves; import builds the graph
// from a forest's leaves (refining every proper ancestor, coarsest first,
// with the core's refine, which refuses exactly when the forest is not face
// balanced) and then runs the checker. Import never trusts its input: an
// unbalanced forest, a leaf deeper than L, overlapping or missing leaves are
// refused with an ImportError that says which.
#pragma once

#include <p4est.h>

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "bccmis/graph.h"

// (Not `bccmis::p4est`: under `using namespace bccmis` that name would clash
// with p4est's own `struct p4est`.)
namespace bccmis::p4est_bridge {

/// A leaf of a bccmis lattice: a cell center and its level.
struct Leaf {
  Point center;
  int level = 0;
  friend auto operator<=>(const Leaf&, const Leaf&) = default;
  friend bool operator==(const Leaf&, const Leaf&) = default;
};

/// A leaf quadrant of a p4est forest, in p4est's own numbers: tree index and
/// quadrant coordinates. Plain int32 fields, so it can be sent with MPI.
struct Quadrant {
  std::int32_t tree = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::int32_t level = 0;
  friend auto operator<=>(const Quadrant&, const Quadrant&) = default;
  friend bool operator==(const Quadrant&, const Quadrant&) = default;
};

/// A forest or a leaf list that is not a valid bccmis lattice. what() names
/// the reason and the first offending leaf.
struct ImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Initializes MPI (singleton MPI_Init when not started by mpirun), libsc and
/// p4est with log level SC_LP_ERROR, once per process; finalizes at exit of
/// the last Session. Safe to create when MPI is already initialized.
class Session {
 public:
  Session(int* argc = nullptr, char*** argv = nullptr);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

struct ConnectivityDeleter {
  void operator()(p4est_connectivity_t* c) const noexcept;
};
struct ForestDeleter {
  void operator()(p4est_t* p) const noexcept;
};
using ForestPtr = std::unique_ptr<p4est_t, ForestDeleter>;

/// The W x H brick connectivity of a lattice and the coordinate mapping.
class Brick {
 public:
  /// Throws LatticeError on an invalid size and std::invalid_argument when
  /// L > P4EST_QMAXLEVEL or W, H do not fit p4est's tree index.
  explicit Brick(const LatticeSize& size);

  const LatticeSize& size() const { return size_; }
  p4est_connectivity_t* connectivity() const { return conn_.get(); }

  /// The tree of level-0 cell (i, j), 0 <= i < W, 0 <= j < H.
  std::int32_t tree(std::int64_t i, std::int64_t j) const;

  /// The quadrant of a leaf. Precondition: a cell of this lattice.
  Quadrant to_quadrant(const Leaf& leaf) const;
  /// The leaf of a quadrant. Throws ImportError when the tree index is out of
  /// range, the level is negative or above L, or the coordinates are not
  /// those of a level-l quadrant inside the tree.
  Leaf to_leaf(const Quadrant& q) const;

 private:
  LatticeSize size_;
  std::unique_ptr<p4est_connectivity_t, ConnectivityDeleter> conn_;
  std::vector<std::int32_t> tree_of_cell_;  // j * W + i -> tree
  std::vector<std::int64_t> cell_of_tree_;  // tree -> j * W + i
  int shift_ = 0;                           // 29 - L
};

/// The leaves of g (its cells and their levels), sorted.
std::vector<Leaf> leaves(const Graph& g);

/// The forest on brick.connectivity() whose leaves are `leaves` (built by
/// recursive p4est_refine from the level-0 forest, partitioned over `comm`
/// as p4est_new does; every rank passes the same leaves). Throws
/// ImportError when the leaves do not tile the lattice.
ForestPtr make_forest(const Brick& brick, std::span<const Leaf> leaves, sc_MPI_Comm comm);

/// make_forest(brick, leaves(g), comm).
ForestPtr export_forest(const Brick& brick, const Graph& g, sc_MPI_Comm comm);

/// This rank's leaf quadrants, in p4est's order (tree, then Morton order).
std::vector<Quadrant> local_quadrants(const p4est_t* forest);

/// Every rank's leaf quadrants on rank `root` (empty on the other ranks), in
/// the global order. Collective over the forest's communicator.
std::vector<Quadrant> gather_quadrants(const p4est_t* forest, int root = 0);

/// Builds the graph whose leaves are the given quadrants and checks it:
/// throws ImportError when a quadrant is invalid (Brick::to_leaf), when two
/// leaves overlap, when a part of the domain is not covered, when the leaf
/// set is not face balanced (2:1 across every edge), or when the checker
/// (invariants/) finds a violation in the result.
Graph import_quadrants(const Brick& brick, std::span<const Quadrant> quadrants);

/// The same from leaves in bccmis coordinates (also refused: a center that
/// is not the center of a level-l cell of the lattice).
Graph import_leaves(const LatticeSize& size, std::span<const Leaf> leaves);

/// import_quadrants of a forest held entirely by this rank (one rank, or
/// after p4est_partition to one rank); throws ImportError otherwise.
Graph import_forest(const Brick& brick, const p4est_t* forest);

}  // namespace bccmis::p4est_bridge
