// bccmis::fast: the 3D lattice of spec/lattice3d.md on flat records.
//
// The reference (src/bccmis/d3) writes refine and coarsen as the set
// equations of spec/equations3d.toml on std::set and is the oracle. This is
// the same graph, the same operations and the same decisions, stored for
// speed:
//
//   - a center is one record: its position, its level and up to 26 node ids
//     (8 corners, 12 edge midpoints, 6 face centers); a node is one record:
//     its position and up to 8 center ids (spec/lattice3d.md §3, F2: at most
//     8 cells meet at a node). Neighbor ids are kept unsorted; they are
//     sorted by position only where a sorted set is asked for (nbr(), the
//     canonical state).
//   - centers and nodes live in two flat pools with free lists; a vertex that
//     changes kind (c in refine, n in coarsen) moves to the other pool. Its
//     old neighbors never refer to it afterwards (R2c-R2e, K2a-K2c), so no
//     id has to be rewritten.
//   - a position -> record table (open addressing, linear probing, deletion
//     by backward shift) over every vertex serves the trace interface.
//   - refine and coarsen first make room (pools and table) for every vertex
//     they can create and compute every set they need; then they only write.
//     In steady state (free slots for the vertices an operation creates) they
//     allocate nothing, and a throwing allocation leaves the lattice as it was.
//
// The preconditions and refusal codes are those of the reference (bccmis/ops.h),
// Y and J+ / J- are returned sorted by position, and the canonical state is
// byte-identical to d3::canonical_state: tests/fast/d3/differential_test.cpp and
// fuzz/fuzz_differential_3d.cpp run both on the same operations.
#pragma once

#include <array>
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
#include "bccmis/fast/lattice.h"  // kMaxReserveHint
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
  /// lattice would need 2^31 or more vertices of one kind.
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
  /// wait less for memory.
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
  /// of a center is not a node, or a vertex has more neighbors than a
  /// lattice allows (26 for a center, 8 for a node).
  static Lattice from_graph(const d3::Graph& g);

  // ---- Memory -----------------------------------------------------------------

  /// Room for `cells` cells and about as many nodes without reallocating.
  void reserve(std::size_t cells);
  /// Bytes held by the pools and the position table (capacity, not size).
  std::size_t memory_bytes() const;

  /// Internal consistency: every link is mirrored, every live record is in
  /// the position table under its position, the counts add up. Empty when
  /// consistent, otherwise the first problem. For tests; O(size).
  std::optional<std::string> audit() const;

  /// The canonical text of spec/formats.md ("3D extension"), written from
  /// the pools.
  void write_canonical_state(std::ostream& out) const;

  using Index = std::uint32_t;
  static constexpr Index kNone = 0xFFFFFFFFu;

 private:
  static constexpr Index kNodeBit = 0x80000000u;  ///< a table entry naming a node
  static constexpr std::uint32_t kFree = 0xFFFFFFFFu;

  /// A cell center: position, level and its node ids. A free record has
  /// level -1 and nbr[0] linking the free list.
  struct Center {
    d3::Point p;
    std::int32_t level = -1;
    std::uint32_t count = 0;
    Index nbr[26];
    bool live() const { return level >= 0; }
  };
  /// A node: position and its center ids. A free record has count == kFree
  /// and nbr[0] linking the free list.
  struct Node {
    d3::Point p;
    std::uint32_t count = 0;
    Index nbr[8];
    bool live() const { return count != kFree; }
  };

  // Position table: a slot holds kNone or a reference (a center index, or
  // kNodeBit | a node index); the key is read from the record.
  const d3::Point& key_of(Index ref) const { return (ref & kNodeBit) ? nodes_[ref & ~kNodeBit].p : centers_[ref].p; }
  std::size_t home(const d3::Point& p) const;
  /// The slot holding p, or the empty slot where p would go.
  std::size_t slot_of(const d3::Point& p) const;
  /// The reference at p, or kNone.
  Index find(const d3::Point& p) const { return table_[slot_of(p)]; }
  Index find_center(const d3::Point& p) const {
    const Index r = find(p);
    return r != kNone && !(r & kNodeBit) ? r : kNone;
  }
  Index find_node(const d3::Point& p) const {
    const Index r = find(p);
    return r != kNone && (r & kNodeBit) ? r & ~kNodeBit : kNone;
  }
  void table_insert(Index ref);  ///< its key must be absent, with room
  void table_erase(const d3::Point& p);
  void table_replace(const d3::Point& p, Index ref);
  void rehash(std::size_t slots);

  /// Makes room for the vertices an operation may create, so that the update
  /// that follows cannot allocate. Table load factor at most 0.7.
  void ensure_room(std::size_t new_centers, std::size_t new_nodes);
  Index alloc_center(const d3::Point& p, int level);
  Index alloc_node(const d3::Point& p);
  void free_center(Index c);
  void free_node(Index n);

  // Neighbor-list edits (unsorted lists; a removal moves the last id in).
  static void add_id(Index* ids, std::uint32_t& count, std::uint32_t capacity, Index id);
  static void remove_id(Index* ids, std::uint32_t& count, Index id);
  void link(Index center, Index node);  ///< N(center) ∪= {node}, N(node) ∪= {center}

  /// The level of the refined cell centered at p, from its position alone
  /// (choice Q4 of spec/choices3d.toml), as d3::refined_center_level.
  std::optional<int> refined_center_level(const d3::Point& p) const;
  std::optional<RefineRefusal> refine_refusal(const d3::Point& c, Index& ci) const;
  std::optional<CoarsenRefusal> coarsen_refusal(const d3::Point& n, Index& ni, int& l) const;

  std::vector<Index> sorted_centers() const;
  std::vector<Index> sorted_nodes() const;

  d3::LatticeSize size_;
  std::vector<Center> centers_;
  std::vector<Node> nodes_;
  Index free_centers_ = kNone;
  Index free_nodes_ = kNone;
  std::size_t free_center_count_ = 0;
  std::size_t free_node_count_ = 0;
  std::size_t cell_count_ = 0;
  std::size_t node_count_ = 0;
  std::vector<Index> table_;  ///< size a power of two
  std::size_t table_used_ = 0;
};

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
