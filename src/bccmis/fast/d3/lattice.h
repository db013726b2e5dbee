// bccmis::fast: the 3D lattice of spec/lattice3d.md with fixed neighbor slots.
//
// The reference (src/bccmis/d3) writes refine and coarsen as the set
// equations of spec/equations3d.toml on std::set and is the oracle. This is
// the same graph, the same operations and the same decisions, laid out for
// the machine (spec/lattice3d.md §9):
//
//   - every neighbor has a fixed slot by direction. A center keeps 26 node
//     slots, one per direction d in {-1, 0, 1}^3 \ {0} (its 8 corners, 12
//     edge midpoints and 6 face centers; kNone where its boundary has no
//     node there): 128 bytes with its position. A node keeps, per octant
//     around it, the leaf cell that covers that octant (8 slots, 32 bytes); a
//     cell covering several octants fills each. The set equations become
//     fixed slot reads and writes, with no search.
//   - only centers store a position; a cell's level follows from it, and a
//     node's position from any cell around it and the octants that cell fills.
//   - the position table holds the cells and the refined centers (nodes at a
//     center's position) only; the other nodes are found from a cell and a
//     direction. The 8 children of a cell take their homes from one hash
//     of the cell.
//   - the records live in two pools (fast/pool.h, §9.8) grown by one byte
//     copy, or by mremap from 1 MiB up; refine and coarsen make room first
//     (pools, table) and then only write, so in steady state they allocate
//     nothing and a failed growth leaves the lattice as it was.
//
// The preconditions and refusal codes are those of the reference (bccmis/ops.h),
// Y and J+ / J- are returned sorted by position, and the canonical state is
// byte-identical to d3::canonical_state: tests/fast/d3/differential_test.cpp and
// fuzz/fuzz_differential_3d.cpp run both on the same operations.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/d3/ops.h"  // d3::RefineResult, d3::CoarsenResult (to_sets)
#include "bccmis/d3/point.h"
#include "bccmis/fast/d3/position_table.h"
#include "bccmis/fast/lattice.h"  // kMaxReserveHint
#include "bccmis/fast/pool.h"
#include "bccmis/fast/small_points.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis::d3::fast {

/// Up to N 3D points, sorted by (x, y, z) like the reference's std::set; no heap.
template <std::size_t N>
using SmallPoints = bccmis::fast::BasicSmallPoints<d3::Point, N>;

/// What Lattice::refine and Lattice::coarsen did: the reference's result
/// types on fixed-size sets (Y: 8 points, J+ / J-: at most 18), sorted.
using RefineResult = BasicRefineResult<SmallPoints<18>>;
using CoarsenResult = BasicCoarsenResult<SmallPoints<18>>;

/// The same results with std::set members (allocates; for comparisons).
inline d3::RefineResult to_sets(const RefineResult& r) { return {r.refused, r.Y.to_set(), r.J_plus.to_set()}; }
inline d3::CoarsenResult to_sets(const CoarsenResult& r) { return {r.refused, r.Y.to_set(), r.J_minus.to_set()}; }

/// The adaptive 3D lattice on flat records. Copyable and movable.
class Lattice {
 public:
  using point_type = d3::Point;
  using size_type = d3::LatticeSize;
  static constexpr int dimension = 3;

  /// The initial lattice of d3::make_lattice(size): W x H x D level-0 cubes.
  /// Throws LatticeError on an invalid size, std::length_error when the
  /// lattice would need 2^26 or more vertices of one kind (the position table names records by 26 bits).
  explicit Lattice(const d3::LatticeSize& size);

  const d3::LatticeSize& size() const { return size_; }

  // ---- The operations (same preconditions and codes as d3::refine/coarsen)

  std::optional<RefineRefusal> can_refine(const d3::Point& c) const;
  std::optional<CoarsenRefusal> can_coarsen(const d3::Point& n) const;
  /// spec/lattice3d.md §4: split cell c into its 8 children. A refused call
  /// changes nothing.
  RefineResult refine(const d3::Point& c);
  /// spec/lattice3d.md §5: merge the 8 cells around node n. A refused call
  /// changes nothing.
  CoarsenResult coarsen(const d3::Point& n);

  /// refine / coarsen of every position in order, each exactly as a single
  /// call would; returns how many were applied. Prefetches the position
  /// table slot of an operation a few ahead, so long lists on large lattices
  /// wait less for memory; coarsen_each also the node's record and its
  /// cells' records, nearer ahead (spec/lattice3d.md §9.12).
  std::size_t refine_each(std::span<const d3::Point> cells);
  std::size_t coarsen_each(std::span<const d3::Point> nodes);

  // ---- Queries (the reference's Graph accessors, by position) -------------

  std::size_t cell_count() const { return cell_count_; }  ///< |C|
  std::size_t node_count() const { return node_count_; }  ///< |N|
  bool is_center(const d3::Point& v) const;
  bool is_node(const d3::Point& v) const;
  /// Level of center c; throws std::out_of_range if c is not a center.
  int level_of(const d3::Point& c) const;
  /// N(v), sorted; empty for a position that is not a vertex.
  SmallPoints<26> nbr(const d3::Point& v) const;
  /// C and N, sorted by (x, y, z) (allocates).
  std::vector<d3::Point> cells() const;
  std::vector<d3::Point> nodes() const;

  /// The same state as a reference Graph (allocates; O(size log size)).
  d3::Graph to_graph() const;

  /// Builds the lattice of a valid reference graph (one the checker accepts,
  /// e.g. parsed from a canonical state): every operation and the canonical
  /// state are then those of the graph. Throws std::invalid_argument when a
  /// center has no level, or one its position does not give, or a neighbor
  /// of a center is not a node at its corner, edge midpoint or face center,
  /// or a center lacks a corner, or two cells cover one octant of a node, or
  /// a node has no cell or is not where its cells put it.
  static Lattice from_graph(const d3::Graph& g);

  // ---- Memory -----------------------------------------------------------------

  /// Room for `cells` cells and about as many nodes without reallocating.
  void reserve(std::size_t cells);
  /// Bytes held by the pools and the position table (capacity, not size).
  std::size_t memory_bytes() const;
  /// The position table's slots and keys (spec/lattice3d.md §9.4, §9.9).
  std::size_t table_slots() const { return table_.slots(); }
  std::size_t table_keys() const { return table_.used(); }

  /// Internal consistency: every link is mirrored, every live record is in
  /// the position table under its position, the counts add up. Empty when
  /// consistent, otherwise the first problem. For tests; O(size).
  std::optional<std::string> audit() const;

  /// The canonical text of spec/formats.md ("3D extension"), written from
  /// the pools.
  void write_canonical_state(std::ostream& out) const;

  using Index = std::uint32_t;
  static constexpr Index kNone = 0xFFFFFFFFu;

  /// The nodes on the closed boundary of a cell, read from its slots: what
  /// the mesh rule asks of a leaf (d3/detail/tetrahedra.h), with no sorting
  /// and no table lookup per question.
  class Boundary {
   public:
    /// Whether node p is on the cell's boundary (p ∈ N(u)).
    bool contains(const d3::Point& p) const;
    /// The cell's level, from its record (spec/mesh3d.md M25.1).
    int level() const { return level_; }
    /// spec/mesh3d.md M25.2: whether w, the cell's position moved by its
    /// side along `axis` (toward + when `high`), is a leaf, for a face that
    /// is not on the hull and whose center is not in N(u) (M4.3): the leaf
    /// in the slot across the face of the face's first corner.
    bool equal_across(int axis, bool high, const d3::Point& w) const;

   private:
    friend class Lattice;
    const Lattice* g_ = nullptr;
    Index c_ = kNone;  ///< the cell's record
    d3::Point u_{};
    std::int64_t h_ = 0;       ///< half the cell's side
    std::uint32_t slots_ = 0;  ///< bit k: slot k holds a node
    int level_ = 0;
  };
  /// The boundary of cell u; throws std::out_of_range if u is not a center.
  Boundary boundary(const d3::Point& u) const;

 private:
  Lattice() = default;

  static constexpr Index kNodeBit = Index{1} << 26;  ///< a table reference naming a node
  static constexpr Index kFreeMark = 0xFFFFFFFEu;
  static constexpr std::size_t kMaxPool = kNodeBit - 1;

  /// A cell center: its position and its 26 node slots, slot slot_of(d) for
  /// direction d (spec/lattice3d.md §9.1). 128 bytes. A free record has
  /// nbr[25] == kFreeMark and nbr[0] linking the free list.
  struct Center {
    d3::Point p;
    Index nbr[26];
    bool live() const { return nbr[25] != kFreeMark; }
  };
  /// A node: the leaf cell covering each octant around it, octant o with
  /// bit a set when it lies on the + side of axis a (kNone outside the
  /// domain). 32 bytes. A free record has cell[7] == kFreeMark and cell[0]
  /// linking the free list.
  struct Node {
    Index cell[8];
    bool live() const { return cell[7] != kFreeMark; }
  };

  // The helpers below are inline (defined in lattice.cpp, used only there),
  // so that the operations inline them.
  int level(Index c) const {  ///< of a live center
    return size_.L - std::countr_zero(static_cast<std::uint64_t>(centers_[c].p.x));
  }
  std::int64_t half_side(int level) const { return std::int64_t{1} << (size_.L - level); }
  inline d3::Point node_position(Index n) const;  ///< of a live node (§9.2)
  /// The trailing zeros t of a position where a cell center can be (level
  /// L - t), or -1 for any other position.
  inline int center_tz(const d3::Point& p) const;
  /// The table hash of center position p (§9.4); t: the trailing zeros of
  /// its coordinates (its level is L - t).
  inline std::uint64_t key_hash(const d3::Point& p) const;
  inline std::uint64_t key_hash_at(const d3::Point& p, int t) const;
  Index find_ref(const d3::Point& p, bool node) const;
  Index find_ref(const d3::Point& p, bool node, std::uint64_t& hash) const;  ///< and p's hash
  Index find_center(const d3::Point& p) const { return find_ref(p, false); }
  Index find_refined(const d3::Point& p) const;  ///< the node at a refined center, or kNone
  /// The node at p, any kind, from the table and the geometry (§9.3), or kNone.
  Index find_node(const d3::Point& p) const;
  /// The leaf cell covering the finest cube at node position p toward
  /// octant o, or kNone when that leaf is coarser than any cube with p on
  /// its slots (§9.3).
  Index locate(const d3::Point& p, int o) const;
  void prefetch_home(const d3::Point& p) const;  ///< the table line of p's home, if p can be a center
  /// A live node whose table entry has p's hash bits, or kNone: p's node when
  /// p is a refined center, read without confirming the position (§9.12).
  Index peek_node(const d3::Point& p) const;

  /// The refusal, or none with the record and its table hash.
  std::optional<RefineRefusal> refine_refusal(const d3::Point& c, Index& ci, std::uint64_t& hash) const;
  std::optional<CoarsenRefusal> coarsen_refusal(const d3::Point& n, Index& ni, int& l, std::uint64_t& hash) const;

  /// Room for that many more centers, nodes and table entries, so that the
  /// update that follows cannot allocate. Load factor at most 0.6.
  void ensure_room(std::size_t new_centers, std::size_t new_nodes, std::size_t new_keys);
  inline Index alloc_center(const d3::Point& p);
  inline Index alloc_node();         ///< every cell slot kNone
  inline Index alloc_node_record();  ///< its cell slots unwritten (refine writes all 8, §9.5)
  inline void free_center(Index c);
  inline void free_node(Index n);

  /// The live center (node) records sorted by position.
  std::vector<Index> sorted_centers() const;
  std::vector<std::pair<d3::Point, Index>> sorted_nodes() const;
  /// The distinct cells of node n, sorted by position.
  SmallPoints<8> node_cells(Index n) const;

  d3::LatticeSize size_;
  std::int64_t extent_[3] = {0, 0, 0};  ///< the domain: W*S, H*S, D*S
  bccmis::fast::Pool<Center> centers_;  ///< spec/lattice3d.md §9.8
  bccmis::fast::Pool<Node> nodes_;
  Index free_centers_ = kNone;
  Index free_nodes_ = kNone;
  std::size_t free_center_count_ = 0;
  std::size_t free_node_count_ = 0;
  std::size_t cell_count_ = 0;
  std::size_t node_count_ = 0;
  PositionTable table_;
};

/// The mesh rule's view of leaf u (d3/detail/tetrahedra.h): its slots.
inline Lattice::Boundary leaf_boundary(const Lattice& g, const d3::Point& u) { return g.boundary(u); }
/// spec/mesh3d.md M25: the mesh rule's level of leaf u and its equal-face
/// test, read from the boundary's record instead of the position table.
inline int leaf_level(const Lattice&, const d3::Point&, const Lattice::Boundary& b) { return b.level(); }
inline bool equal_across(const Lattice&, const Lattice::Boundary& b, int axis, bool high, const d3::Point& w) {
  return b.equal_across(axis, high, w);
}

// ---- The lattice vocabulary (bccmis/lattice.h): Lattice models AdaptiveLattice

inline const d3::LatticeSize& size_of(const Lattice& g) { return g.size(); }
inline std::optional<RefineRefusal> can_refine(const Lattice& g, const d3::Point& c) { return g.can_refine(c); }
inline std::optional<CoarsenRefusal> can_coarsen(const Lattice& g, const d3::Point& n) { return g.can_coarsen(n); }
inline RefineResult refine(Lattice& g, const d3::Point& c) { return g.refine(c); }
inline CoarsenResult coarsen(Lattice& g, const d3::Point& n) { return g.coarsen(n); }
inline bool is_center(const Lattice& g, const d3::Point& v) { return g.is_center(v); }
inline bool is_node(const Lattice& g, const d3::Point& v) { return g.is_node(v); }
inline int level_of(const Lattice& g, const d3::Point& c) { return g.level_of(c); }
inline SmallPoints<26> neighbors(const Lattice& g, const d3::Point& v) { return g.nbr(v); }
inline std::vector<d3::Point> cells(const Lattice& g) { return g.cells(); }
inline std::vector<d3::Point> nodes(const Lattice& g) { return g.nodes(); }
inline std::size_t cell_count(const Lattice& g) { return g.cell_count(); }
inline std::size_t node_count(const Lattice& g) { return g.node_count(); }
/// Optional in the vocabulary (replay calls it): room for `cells` cells, a
/// hint, capped at kMaxReserveHint. A reservation the allocator refuses is
/// dropped; beyond the hint the lattice grows as it goes.
void reserve(Lattice& g, std::size_t cells);
/// The canonical text of spec/formats.md, byte-identical to
/// d3::canonical_state(g.to_graph()), printed from the pools directly.
inline void write_canonical_state(std::ostream& out, const Lattice& g) { g.write_canonical_state(out); }
std::string canonical_state(const Lattice& g);

}  // namespace bccmis::d3::fast

static_assert(bccmis::AdaptiveLattice<bccmis::d3::fast::Lattice>);
static_assert(bccmis::d3::fast::Lattice::dimension == 3);
