// bccmis::p4est_bridge: exchange leaf sets between a bccmis lattice and a
// p4est forest of quadtrees (issue 10; spec/p4est.md), and between a 3D
// lattice (d3::Graph) and a p8est forest of octrees (spec/p4est.md "3D:
// p8est"). One source for both dimensions (issue 26), as p4est compiles p8est
// from the same files: the algorithms are templates over Dim = 2, 3, written
// once against the traits P4<Dim> (p4est or p8est types, constants and
// functions) and instantiated for both in bridge.cpp.
//
// A W x H lattice of depth L is a p4est forest on the W x H brick
// connectivity (p4est_connectivity_new_brick(W, H, 0, 0)); a W x H x D 3D
// lattice a p8est forest on the W x H x D brick
// (p8est_connectivity_new_brick(W, H, D, 0, 0, 0)). Each level-0 cell (cube)
// is one tree, and each leaf cell of the lattice one leaf quadrant (octant),
// with the same level. Coordinates (spec/p4est.md has the derivation):
//
//   bccmis unit:   a level-0 cell has side S = 2^(L+1) (graph.h, d3/point.h);
//   p4est unit:    a tree has side P4EST_ROOT_LEN = 2^30 (P4EST_MAXLEVEL),
//                  in 3D P8EST_ROOT_LEN = 2^19 (P8EST_MAXLEVEL);
//   scale:         one bccmis unit is 2^(Q-L) quadrant units, Q =
//                  P4EST_QMAXLEVEL = 29 (3D: P8EST_QMAXLEVEL = 18), so L <= Q;
//   cell (i, j):   the level-0 cell with lower-left corner (i S, j S) is the
//                  tree whose first vertex (tree_to_vertex[4t], 3D: [8t]) is
//                  at (i, j) (3D: (i, j, k)), read from the connectivity's
//                  vertex coordinates (the brick numbers its trees along a
//                  space-filling curve, not row by row);
//   a leaf:        center c, level l, side s = 2^(L+1-l) is the quadrant
//                  x = (c.x - s/2 - i S) 2^(Q-L), likewise y (and z), level l.
//
// Balance: the core's edge balance (eq. 3, erratum E4) is p4est's
// P4EST_CONNECT_FACE; the 3D core's balance (2:1 across faces and edges,
// spec/lattice3d.md §2) is P8EST_CONNECT_EDGE; the apps' Balance::Corner is
// P4EST_CONNECT_FULL (P8EST_CONNECT_FULL).
//
// Export builds a forest with the lattice's leaves; import builds the graph
// from a forest's leaves (refining every proper ancestor, coarsest first,
// with the core's refine, which refuses exactly when the forest is not face
// (3D: edge) balanced) and then runs the checker. Import never trusts its
// input: an unbalanced forest, a leaf deeper than L, overlapping or missing
// leaves are refused with an ImportError that says which.
//
// Names: the templates LeafOf<Dim>, QuadrantOf<Dim>, BrickOf<Dim>,
// ForestPtrOf<Dim>; the 2D Leaf, Quadrant, Brick, ForestPtr and the 3D
// Leaf3, Quadrant3, Brick3, Forest3Ptr are their instantiations.
#pragma once

#include <p4est_extended.h>
#include <p8est_extended.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/graph.h"

// (Not `bccmis::p4est`: under `using namespace bccmis` that name would clash
// with p4est's own `struct p4est`.)
namespace bccmis::p4est_bridge {

/// A leaf quadrant (octant) of a p4est (p8est) forest, in its own numbers:
/// tree index and coordinates. Plain int32 fields, so it can be sent with MPI.
template <int Dim>
struct QuadrantOf;

template <>
struct QuadrantOf<2> {
  std::int32_t tree = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::int32_t level = 0;
  friend auto operator<=>(const QuadrantOf&, const QuadrantOf&) = default;
  friend bool operator==(const QuadrantOf&, const QuadrantOf&) = default;
};

template <>
struct QuadrantOf<3> {
  std::int32_t tree = 0;
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::int32_t z = 0;
  std::int32_t level = 0;
  friend auto operator<=>(const QuadrantOf&, const QuadrantOf&) = default;
  friend bool operator==(const QuadrantOf&, const QuadrantOf&) = default;
};

/// The dimension traits: P4<2> is p4est and the 2D core, P4<3> is p8est and
/// the 3D core. Code written once over Dim reads every dimension-dependent
/// type, constant, function and word of its messages from here.
template <int Dim>
struct P4;

template <>
struct P4<2> {
  static constexpr int kDim = 2;
  using Point = bccmis::Point;
  using LatticeSize = bccmis::LatticeSize;
  using Graph = bccmis::Graph;
  using forest_t = p4est_t;
  using connectivity_t = p4est_connectivity_t;
  using quadrant_t = p4est_quadrant_t;
  using tree_t = p4est_tree_t;
  using connect_type_t = p4est_connect_type_t;
  using refine_t = p4est_refine_t;
  using coarsen_t = p4est_coarsen_t;

  static constexpr int kMaxLevel = P4EST_MAXLEVEL;
  static constexpr int kQMaxLevel = P4EST_QMAXLEVEL;
  static constexpr std::int64_t kRootLen = P4EST_ROOT_LEN;
  /// The core's balance (edge balance, eq. 3) and the apps' Balance::Corner.
  static constexpr connect_type_t kConnectCore = P4EST_CONNECT_FACE;
  static constexpr connect_type_t kConnectFull = P4EST_CONNECT_FULL;

  static constexpr auto new_ext = &p4est_new_ext;
  static constexpr auto refine_ext = &p4est_refine_ext;
  static constexpr auto coarsen_ext = &p4est_coarsen_ext;
  static constexpr auto balance = &p4est_balance;
  static constexpr auto partition = &p4est_partition;
  static constexpr auto is_balanced = &p4est_is_balanced;
  static constexpr auto destroy = &p4est_destroy;
  static constexpr auto memory_used = &p4est_memory_used;
  static constexpr auto connectivity_destroy = &p4est_connectivity_destroy;
  static constexpr auto connectivity_memory_used = &p4est_connectivity_memory_used;
  static constexpr auto qcoord_to_vertex = &p4est_qcoord_to_vertex;
  /// p4est_connectivity_new_brick(W, H, 0, 0): the brick of n = {W, H} trees.
  static connectivity_t* new_brick(const std::array<int, 2>& n) {
    return p4est_connectivity_new_brick(n[0], n[1], 0, 0);
  }
  static tree_t* tree_at(sc_array_t* trees, p4est_topidx_t t) { return p4est_tree_array_index(trees, t); }
  static quadrant_t* quadrant_at(sc_array_t* quadrants, std::size_t k) {
    return p4est_quadrant_array_index(quadrants, k);
  }
  /// Tree index and a p4est quadrant, as a QuadrantOf<2>.
  static QuadrantOf<2> quadrant(p4est_topidx_t tree, const quadrant_t& q) { return {tree, q.x, q.y, q.level}; }

  static std::array<std::int64_t, 2> axes(const Point& p) { return {p.x, p.y}; }
  static Point point(const std::array<std::int64_t, 2>& a) { return {a[0], a[1]}; }
  /// The level-0 cells along each axis: {W, H}.
  static std::array<std::int64_t, 2> cells(const LatticeSize& s) { return {s.W, s.H}; }

  // The words of the messages.
  static constexpr const char* kP4est = "p4est";    // the library
  static constexpr const char* kMaxName = "P4EST";  // its macros
  static constexpr const char* kGrid = "W x H";     // the brick's sizes
  static constexpr const char* kCell = "cell";      // a lattice cell
  static constexpr const char* kSquare = "square";  // a unit tree
  static constexpr const char* kQuadrant = "quadrant";
  static constexpr const char* kWhich = "";  // before lattice, graph, forest, brick
  static constexpr const char* kBalanced = "face balanced (2:1 across faces)";
  static constexpr const char* kNeighbor = "an edge-neighbor";
};

template <>
struct P4<3> {
  static constexpr int kDim = 3;
  using Point = d3::Point;
  using LatticeSize = d3::LatticeSize;
  using Graph = d3::Graph;
  using forest_t = p8est_t;
  using connectivity_t = p8est_connectivity_t;
  using quadrant_t = p8est_quadrant_t;
  using tree_t = p8est_tree_t;
  using connect_type_t = p8est_connect_type_t;
  using refine_t = p8est_refine_t;
  using coarsen_t = p8est_coarsen_t;

  static constexpr int kMaxLevel = P8EST_MAXLEVEL;
  static constexpr int kQMaxLevel = P8EST_QMAXLEVEL;
  static constexpr std::int64_t kRootLen = P8EST_ROOT_LEN;
  /// The 3D core's balance (faces and edges) and the apps' Balance::Corner.
  static constexpr connect_type_t kConnectCore = P8EST_CONNECT_EDGE;
  static constexpr connect_type_t kConnectFull = P8EST_CONNECT_FULL;

  static constexpr auto new_ext = &p8est_new_ext;
  static constexpr auto refine_ext = &p8est_refine_ext;
  static constexpr auto coarsen_ext = &p8est_coarsen_ext;
  static constexpr auto balance = &p8est_balance;
  static constexpr auto partition = &p8est_partition;
  static constexpr auto is_balanced = &p8est_is_balanced;
  static constexpr auto destroy = &p8est_destroy;
  static constexpr auto memory_used = &p8est_memory_used;
  static constexpr auto connectivity_destroy = &p8est_connectivity_destroy;
  static constexpr auto connectivity_memory_used = &p8est_connectivity_memory_used;
  static constexpr auto qcoord_to_vertex = &p8est_qcoord_to_vertex;
  /// p8est_connectivity_new_brick(W, H, D, 0, 0, 0).
  static connectivity_t* new_brick(const std::array<int, 3>& n) {
    return p8est_connectivity_new_brick(n[0], n[1], n[2], 0, 0, 0);
  }
  static tree_t* tree_at(sc_array_t* trees, p4est_topidx_t t) { return p8est_tree_array_index(trees, t); }
  static quadrant_t* quadrant_at(sc_array_t* quadrants, std::size_t k) {
    return p8est_quadrant_array_index(quadrants, k);
  }
  static QuadrantOf<3> quadrant(p4est_topidx_t tree, const quadrant_t& q) { return {tree, q.x, q.y, q.z, q.level}; }

  static std::array<std::int64_t, 3> axes(const Point& p) { return {p.x, p.y, p.z}; }
  static Point point(const std::array<std::int64_t, 3>& a) { return {a[0], a[1], a[2]}; }
  static std::array<std::int64_t, 3> cells(const LatticeSize& s) { return {s.W, s.H, s.D}; }

  static constexpr const char* kP4est = "p8est";
  static constexpr const char* kMaxName = "P8EST";
  static constexpr const char* kGrid = "W x H x D";
  static constexpr const char* kCell = "cube";
  static constexpr const char* kSquare = "cube";
  static constexpr const char* kQuadrant = "octant";
  static constexpr const char* kWhich = "3D ";
  static constexpr const char* kBalanced = "edge balanced (2:1 across faces and edges)";
  static constexpr const char* kNeighbor = "a face-or-edge neighbour";
};

/// The dimension of a lattice, graph or forest type; 0 for other types.
template <class T>
inline constexpr int dim_of = 0;
template <>
inline constexpr int dim_of<Graph> = 2;
template <>
inline constexpr int dim_of<LatticeSize> = 2;
template <>
inline constexpr int dim_of<p4est_t> = 2;
template <>
inline constexpr int dim_of<d3::Graph> = 3;
template <>
inline constexpr int dim_of<d3::LatticeSize> = 3;
template <>
inline constexpr int dim_of<p8est_t> = 3;

/// A leaf of a bccmis lattice: a cell (cube) center and its level.
template <int Dim>
struct LeafOf {
  typename P4<Dim>::Point center;
  int level = 0;
  friend auto operator<=>(const LeafOf&, const LeafOf&) = default;
  friend bool operator==(const LeafOf&, const LeafOf&) = default;
};

/// A forest or a leaf list that is not a valid bccmis lattice. what() names
/// the reason and the first offending leaf.
struct ImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Initializes MPI (singleton MPI_Init when not started by mpirun), libsc and
/// p4est (for p8est too) with log level SC_LP_ERROR, once per process;
/// finalizes at exit of the last Session. Safe to create when MPI is already
/// initialized.
class Session {
 public:
  Session(int* argc = nullptr, char*** argv = nullptr);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

struct ConnectivityDeleter {
  void operator()(p4est_connectivity_t* c) const noexcept { P4<2>::connectivity_destroy(c); }
  void operator()(p8est_connectivity_t* c) const noexcept { P4<3>::connectivity_destroy(c); }
};
struct ForestDeleter {
  void operator()(p4est_t* p) const noexcept { P4<2>::destroy(p); }
  void operator()(p8est_t* p) const noexcept { P4<3>::destroy(p); }
};
template <int Dim>
using ForestPtrOf = std::unique_ptr<typename P4<Dim>::forest_t, ForestDeleter>;

/// The brick connectivity of a lattice (W x H, 3D: W x H x D trees) and the
/// coordinate mapping.
template <int Dim>
class BrickOf {
 public:
  using Traits = P4<Dim>;
  using LatticeSize = typename Traits::LatticeSize;
  using Leaf = LeafOf<Dim>;
  using Quadrant = QuadrantOf<Dim>;
  using Cell = std::array<std::int64_t, Dim>;

  /// Throws LatticeError on an invalid size and std::invalid_argument when
  /// L > P4EST_QMAXLEVEL (P8EST_QMAXLEVEL) or the trees do not fit p4est's
  /// tree index.
  explicit BrickOf(const LatticeSize& size);

  const LatticeSize& size() const { return size_; }
  typename Traits::connectivity_t* connectivity() const { return conn_.get(); }

  /// The tree of level-0 cell (i, j), 0 <= i < W, 0 <= j < H (2D), or of
  /// level-0 cube (i, j, k), 0 <= k < D too (3D).
  template <class... I>
  requires(sizeof...(I) == Dim && (std::is_integral_v<I> && ...)) std::int32_t tree(I... index)
  const { return tree_at(Cell{static_cast<std::int64_t>(index)...}); }
  /// The tree of the level-0 cell with these indices along the axes.
  std::int32_t tree_at(const Cell& cell) const;

  /// The quadrant of a leaf. Precondition: a cell of this lattice.
  Quadrant to_quadrant(const Leaf& leaf) const;
  /// The leaf of a quadrant. Throws ImportError when the tree index is out of
  /// range, the level is negative or above L, or the coordinates are not
  /// those of a level-l quadrant inside the tree.
  Leaf to_leaf(const Quadrant& q) const;

 private:
  std::int64_t index(const Cell& cell) const;  // (k H + j) W + i

  LatticeSize size_;
  std::unique_ptr<typename Traits::connectivity_t, ConnectivityDeleter> conn_;
  std::vector<std::int32_t> tree_of_cell_;  // index -> tree
  std::vector<std::int64_t> cell_of_tree_;  // tree -> index
  int shift_ = 0;                           // Q - L
};

/// The leaves of g (its cells and their levels), sorted.
template <class G>
requires(dim_of<G> != 0) std::vector<LeafOf<dim_of<G>>> leaves(const G& g);

/// The forest on brick.connectivity() whose leaves are `leaves` (built by
/// recursive p4est_refine from the level-0 forest, partitioned over `comm`
/// as p4est_new does; every rank passes the same leaves). Throws
/// ImportError when the leaves do not tile the lattice.
template <int Dim>
ForestPtrOf<Dim> make_forest(const BrickOf<Dim>& brick, std::type_identity_t<std::span<const LeafOf<Dim>>> leaves,
                             sc_MPI_Comm comm);

/// make_forest(brick, leaves(g), comm).
template <int Dim>
ForestPtrOf<Dim> export_forest(const BrickOf<Dim>& brick, const typename P4<Dim>::Graph& g, sc_MPI_Comm comm);

/// This rank's leaf quadrants, in p4est's order (tree, then Morton order).
template <class Forest>
requires(dim_of<Forest> != 0) std::vector<QuadrantOf<dim_of<Forest>>> local_quadrants(const Forest* forest);

/// Every rank's leaf quadrants on rank `root` (empty on the other ranks), in
/// the global order. Collective over the forest's communicator.
template <class Forest>
requires(dim_of<Forest> != 0) std::vector<QuadrantOf<dim_of<Forest>>> gather_quadrants(const Forest* forest,
                                                                                       int root = 0);

/// Builds the graph whose leaves are the given quadrants and checks it:
/// throws ImportError when a quadrant is invalid (BrickOf::to_leaf), when two
/// leaves overlap, when a part of the domain is not covered, when the leaf
/// set is not face balanced (2:1 across every edge; 3D: edge balanced, 2:1
/// across faces and edges), or when the checker (invariants/, 3D:
/// invariants/d3/) finds a violation in the result.
template <int Dim>
typename P4<Dim>::Graph import_quadrants(const BrickOf<Dim>& brick,
                                         std::type_identity_t<std::span<const QuadrantOf<Dim>>> quadrants);

/// The same from leaves in bccmis coordinates (also refused: a center that
/// is not the center of a level-l cell of the lattice).
template <class Size>
requires(dim_of<Size> != 0) typename P4<dim_of<Size>>::Graph
    import_leaves(const Size& size, std::type_identity_t<std::span<const LeafOf<dim_of<Size>>>> leaves);

/// import_quadrants of a forest held entirely by this rank (one rank, or
/// after p4est_partition to one rank); throws ImportError otherwise.
template <int Dim>
typename P4<Dim>::Graph import_forest(const BrickOf<Dim>& brick, const typename P4<Dim>::forest_t* forest);

// ---- The 2D and 3D names ---------------------------------------------------------------------

using Leaf = LeafOf<2>;
using Quadrant = QuadrantOf<2>;
using Brick = BrickOf<2>;
using ForestPtr = ForestPtrOf<2>;

using Leaf3 = LeafOf<3>;
using Quadrant3 = QuadrantOf<3>;
using Brick3 = BrickOf<3>;
using Forest3Ptr = ForestPtrOf<3>;

}  // namespace bccmis::p4est_bridge
