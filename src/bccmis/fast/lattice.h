// bccmis::fast: the graph of Erleben 2009 §2 on flat arrays, for embedding.
//
// The reference core (src/bccmis) transcribes the paper's set equations onto
// std::set and is the oracle. This is the same graph, the same operations and
// the same decisions, stored for speed:
//
//   - every neighbor set has a fixed place per direction. A center keeps its
//     4 corners and its 4 side midpoints (junctions, empty when absent): at
//     most 8 neighbors. A node keeps, per quadrant around it, the leaf cell
//     that occupies that quadrant: at most 4 neighbors (a junction is the side
//     midpoint of one cell, which then occupies two quadrants). The paper's
//     set operations become a fixed number of slot writes: O(1).
//   - centers (48 bytes) and nodes (16 bytes) live in two flat pools with
//     free lists (fast/pool.h, the 3D lattice's: grown by one byte copy, or
//     by mremap from 1 MiB up, spec/lattice3d.md §9.8). Only centers store a position (integer, spec/formats.md);
//     a cell's level follows from its position, and a node's position from
//     any cell around it.
//   - a position -> vertex table (Robin Hood open addressing, 4 bytes a
//     slot) over the cells and refined centers serves the trace interface:
//     refine(Point) and coarsen(Point). Grid nodes and side midpoints are
//     found from the geometry, so refine and coarsen only add or remove the
//     four children, which share one 64-byte line of the table.
//   - in steady state (a free slot for every vertex an operation creates)
//     refine and coarsen allocate nothing; they reserve first and then only
//     write, so a throwing allocation leaves the lattice unchanged (strong
//     guarantee, as the reference).
//
// The preconditions and refusal codes are those of the reference
// (spec/errata.toml E3, E4, E7, E10; spec/formats.md), and the canonical state is
// byte-identical: tests/fast/*_test.cpp replay every trace and random
// operation sequences through both and compare every decision and state.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/fast/pool.h"
#include "bccmis/fast/small_points.h"
#include "bccmis/graph.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis::fast {

namespace detail {
/// The allocator of the position table: 64-byte aligned (a
/// table line of 16 slots is one cache line), and arrays of 4 MiB and up ask
/// the kernel for transparent huge pages (madvise, Linux): they are accessed
/// at random once they outgrow the caches, and 2 MiB pages cut the TLB
/// misses that otherwise cost as much as the cache misses.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;
template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlign{64};
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    T* p = static_cast<T*>(::operator new(n * sizeof(T), kAlign));
    advise_huge_pages(p, n * sizeof(T));
    return p;
  }
  void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, kAlign); }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
};
template <class T>
using Array = std::vector<T, HugePageAllocator<T>>;
}  // namespace detail

/// Up to N 2D points, sorted by (x, y) like the reference's std::set; no heap.
template <std::size_t N>
using SmallPoints = BasicSmallPoints<Point, N>;

/// What Lattice::refine and Lattice::coarsen did: the reference's result
/// types on fixed-size sets (no heap), sorted by (x, y) as the reference's.
using RefineResult = BasicRefineResult<SmallPoints<4>>;
using CoarsenResult = BasicCoarsenResult<SmallPoints<4>>;

/// The same results with std::set members (allocates; for comparisons).
inline bccmis::RefineResult to_sets(const RefineResult& r) { return {r.refused, r.Y.to_set(), r.J_plus.to_set()}; }
inline bccmis::CoarsenResult to_sets(const CoarsenResult& r) { return {r.refused, r.Y.to_set(), r.J_minus.to_set()}; }

/// The adaptive lattice on flat arrays. Copyable and movable.
class Lattice {
 public:
  using point_type = Point;
  using size_type = LatticeSize;
  static constexpr int dimension = 2;

  /// The initial lattice of make_lattice(size): W x H level-0 cells. Throws
  /// LatticeError on an invalid size, std::length_error when the lattice
  /// would need 2^26 or more vertices of one kind (about 6.7e7 cells).
  explicit Lattice(const LatticeSize& size);

  const LatticeSize& size() const { return size_; }

  // ---- The operations (same preconditions and codes as bccmis::refine/coarsen)

  std::optional<RefineRefusal> can_refine(const Point& c) const;
  std::optional<CoarsenRefusal> can_coarsen(const Point& n) const;
  /// §2.1: split cell c into its four children. A refused call changes nothing.
  RefineResult refine(const Point& c);
  /// §2.2: merge the four cells around node n. A refused call changes nothing.
  CoarsenResult coarsen(const Point& n);

  /// refine (coarsen) each position in order, exactly as that many calls
  /// would; returns how many were applied. Looks ahead in the list and
  /// prefetches the position table and the records of the coming
  /// operations, so long lists on large lattices wait less for memory.
  std::size_t refine_each(std::span<const Point> cells);
  std::size_t coarsen_each(std::span<const Point> nodes);

  // ---- Queries (the reference's Graph accessors, by position) ---------------

  std::size_t cell_count() const { return cell_count_; }  ///< |C|
  std::size_t node_count() const { return node_count_; }  ///< |N|
  bool is_center(const Point& v) const;
  bool is_node(const Point& v) const;
  /// Level of center c; throws std::out_of_range if c is not a center.
  int level_of(const Point& c) const;
  /// 𝒩(v), sorted; empty for a position that is not a vertex.
  SmallPoints<8> nbr(const Point& v) const;
  /// C and N, sorted by (x, y) (allocates).
  std::vector<Point> cells() const;
  std::vector<Point> nodes() const;

  /// Calls f(Point center, int level) for every cell, in storage order.
  template <class F>
  void for_each_cell(F&& f) const {
    for (const Center& c : centers_)
      if (c.live()) f(c.position(), c.level(size_.L));
  }

  // ---- Conversions ------------------------------------------------------------

  /// The same state as a reference Graph (allocates; O(size log size)).
  Graph to_graph() const;
  /// Builds the lattice of a valid reference graph (one the checker accepts,
  /// e.g. parsed from a canonical state). Throws std::invalid_argument when a
  /// neighbor is not at a corner or side midpoint of its cell.
  static Lattice from_graph(const Graph& g);

  // ---- Memory -----------------------------------------------------------------

  /// Room for `cells` cells (at most 2^26 - 1) and about as many nodes
  /// without reallocating.
  void reserve(std::size_t cells);
  /// Gives back unused pool capacity (the free lists stay).
  void shrink_to_fit();
  /// Bytes held by the pools and the position table (capacity, not size).
  std::size_t memory_bytes() const;

  /// Internal consistency: every slot link is mirrored, every vertex is in
  /// the position table under its position, the counts add up. Empty when
  /// consistent, otherwise the first problem. For tests; O(size).
  std::optional<std::string> audit() const;

  /// Implementation details used by the printers (canonical_state) and the
  /// benchmarks; not part of the stable interface.
  using Index = std::uint32_t;
  static constexpr Index kNone = 0xFFFFFFFFu;
  static constexpr Index kFreeMark = 0xFFFFFFFEu;

  /// A cell center: position, 4 corners (by quadrant q: bit 0 = east,
  /// bit 1 = north) and 4 side midpoints (s: 0 south, 1 east, 2 north,
  /// 3 west; kNone when the side has no junction). 48 bytes. The level is
  /// not stored: a level-l center has both coordinates odd multiples of
  /// 2^(L-l) (spec/formats.md), so l = L - (trailing zeros of x). A free slot
  /// has corner[3] == kFreeMark and corner[0] linking the free list.
  struct Center {
    std::uint32_t xy[4];  ///< x and y as two 32-bit halves each (keeps the record 4-aligned)
    Index corner[4];
    Index mid[4];
    Point position() const;
    void set_position(const Point& p);
    bool live() const { return corner[3] != kFreeMark; }
    /// The level of this center in a lattice of maximum level L.
    int level(int L) const { return L - std::countr_zero(std::uint64_t{xy[0]} | (std::uint64_t{xy[1]} << 32)); }
  };
  /// A node: the leaf cell in each quadrant around it (kNone outside the
  /// domain). 16 bytes. A free slot has cell[3] == kFreeMark and cell[0]
  /// linking the free list.
  struct Node {
    Index cell[4];
    bool live() const { return cell[3] != kFreeMark; }
  };

  /// The live center (node) slots in canonical order: sorted by position.
  std::vector<Index> sorted_center_slots() const;
  std::vector<Index> sorted_node_slots() const;
  /// Calls f(node slot, position) for the boundary nodes of the live center
  /// slot c in the order of bccmis::boundary_in_angular_order (counter-
  /// clockwise from the south-west corner): SW, S, SE, E, NE, N, NW, W, the
  /// side midpoints only where the cell has a junction.
  template <class F>
  void for_each_boundary_node(Index c, F&& f) const {
    static constexpr int kCorner[4] = {0, 1, 3, 2};  // SW, SE, NE, NW
    static constexpr std::int64_t kCornerDx[4] = {-1, 1, 1, -1}, kCornerDy[4] = {-1, -1, 1, 1};
    static constexpr std::int64_t kSideDx[4] = {0, 1, 0, -1}, kSideDy[4] = {-1, 0, 1, 0};  // S, E, N, W
    const Center& r = centers_[c];
    const Point p = r.position();
    const std::int64_t h = half_side(r.level(size_.L));
    for (int k = 0; k < 4; ++k) {
      f(r.corner[kCorner[k]], Point{p.x + kCornerDx[k] * h, p.y + kCornerDy[k] * h});
      if (r.mid[k] != kNone) f(r.mid[k], Point{p.x + kSideDx[k] * h, p.y + kSideDy[k] * h});
    }
  }

  const Pool<Center>& center_pool() const { return centers_; }
  const Pool<Node>& node_pool() const { return nodes_; }
  /// Position of a live node.
  Point node_position(Index n) const;
  /// The level of a live center slot.
  int level(Index c) const { return centers_[c].level(size_.L); }
  /// Half the side of a level-l cell: 2^(L-l).
  std::int64_t half_side(int level) const { return std::int64_t{1} << (size_.L - level); }

 private:
  Lattice() = default;

  // Position table: Robin Hood open addressing over the cells and refined
  // centers; a slot holds a vertex reference (kNodeBit | index for nodes,
  // index for centers) and its displacement from home (see lattice.cpp).
  // Keys are recomputed from the pools, so every vertex in the table must be
  // live and consistent.
  static constexpr Index kNodeBit = 1u << 26;
  static constexpr std::uint32_t kRefMask = (1u << 27) - 1;  ///< a slot's reference bits
  static constexpr int kDistShift = 27;                      ///< a slot's 1 + displacement bits
  static constexpr std::uint32_t kDistSaturated = 31;
  /// A slot holding ref at `displacement` from its home.
  static constexpr std::uint32_t encode(Index ref, std::size_t displacement) {
    return ref | (static_cast<std::uint32_t>(displacement < kDistSaturated - 1 ? displacement + 1 : kDistSaturated)
                  << kDistShift);
  }
  std::size_t home(const Point& p) const;
  /// home(p) for a cell center position whose coordinates have t trailing zeros.
  std::size_t home_at(const Point& p, int t) const;
  /// The trailing zeros t of a position where a cell center can be (then
  /// its level is L - t), or -1 for any other position.
  int center_tz(const Point& p) const;
  /// Home of child q of the cell whose hash is `base`: slots base+1, +5, +9,
  /// +13 within base's 16-slot line (never base itself, the home of a
  /// level-0 parent).
  std::size_t child_home(std::size_t base, std::size_t q) const {
    return ((base & ~std::size_t{15}) | ((base + 1 + 4 * q) & 15)) & (table_.size() - 1);
  }
  Point key_of(Index ref) const;
  std::size_t displacement(std::size_t slot) const;
  /// Probes from slot `at` for the entry whose home is `at` and that `match`es.
  template <class Match>
  Index probe(std::size_t at, Match match) const;
  /// The slot holding `ref`, whose key has home slot `at`.
  std::size_t slot_of(Index ref, std::size_t at) const;
  /// Stores another reference in a slot, keeping its displacement.
  void replace_ref(std::size_t slot, Index ref);
  void prefetch(std::size_t at) const;
  /// Look-ahead for refine_each / coarsen_each: the table line of p (far
  /// ahead), then the record it names (near ahead).
  void prefetch_slot(const Point& p) const;
  void prefetch_record(const Point& p, bool node) const;
  /// The center at p, or kNone.
  Index find_center(const Point& p) const;
  /// The refined center (a node) at p, or kNone. Other nodes (grid nodes,
  /// side midpoints) are not in the table: see node_exists.
  Index find_node(const Point& p) const;
  /// Whether p is a node (any kind), from the table and the geometry.
  bool node_exists(const Point& p) const;
  /// The leaf cell strictly containing point z, or kNone outside the domain.
  Index locate(const Point& z) const;
  /// can_refine / can_coarsen that also return the index they found.
  std::optional<RefineRefusal> refine_refusal(const Point& c, Index& ci) const;
  std::optional<CoarsenRefusal> coarsen_refusal(const Point& n, Index& ni, int& coarse_level) const;
  /// Inserts ref whose key has home slot `at` (the key must be absent and
  /// there must be room); erases ref whose key has home slot `at`. The
  /// common cases (an empty home; ref at home with nothing displaced behind
  /// it) are inline, the Robin Hood probing out of line.
  void table_insert(Index ref, std::size_t at) {
    if (table_[at] == 0) {
      table_[at] = ref | (1u << kDistShift);  // displacement 0
      ++table_used_;
      return;
    }
    table_insert_probe(ref, at);
  }
  void table_erase(Index ref, std::size_t at) {
    const std::size_t next = (at + 1) & (table_.size() - 1);
    if (table_[at] == (ref | (1u << kDistShift)) && (table_[next] >> kDistShift) <= 1) {
      table_[at] = 0;
      --table_used_;
      return;
    }
    table_erase_probe(ref, at);
  }
  void table_insert_probe(Index ref, std::size_t at);
  void table_erase_probe(Index ref, std::size_t at);
  void rehash(std::size_t slots);

  /// Makes room for `new_centers` more centers, `new_nodes` more nodes and
  /// `new_keys` more table entries, so that the update that follows cannot
  /// allocate (and so cannot throw). Load factor at most 0.6.
  void ensure_room(std::size_t new_centers, std::size_t new_nodes, std::size_t new_keys) {
    if (free_center_count_ + (centers_.capacity() - centers_.size()) >= new_centers &&
        free_node_count_ + (nodes_.capacity() - nodes_.size()) >= new_nodes &&
        (table_used_ + new_keys) * 5 <= table_.size() * 3)
      return;
    grow(new_centers, new_nodes, new_keys);
  }
  void grow(std::size_t new_centers, std::size_t new_nodes, std::size_t new_keys);
  // Pop a free slot or append (capacity reserved by ensure_room); push a slot.
  Index alloc_center() { return pop_or_append(centers_, &Center::corner, free_centers_, free_center_count_); }
  Index alloc_node() { return pop_or_append(nodes_, &Node::cell, free_nodes_, free_node_count_); }
  // The head of a pool's free list, linked through the first entry of each
  // free record's `link` array, or a new record at the pool's end.
  template <class Records, class Record>
  static Index pop_or_append(Records& pool, Index (Record::*link)[4], Index& free_head, std::size_t& free_count) {
    if (free_head == kNone) {
      pool.emplace_back();
      return static_cast<Index>(pool.size() - 1);
    }
    const Index slot = free_head;
    free_head = (pool[slot].*link)[0];
    --free_count;
    return slot;
  }
  void free_center(Index c) {
    Center& r = centers_[c];
    r.corner[3] = kFreeMark;
    r.corner[0] = free_centers_;
    free_centers_ = c;
    ++free_center_count_;
  }
  void free_node(Index n) {
    Node& r = nodes_[n];
    r.cell[0] = free_nodes_;
    r.cell[1] = r.cell[2] = kNone;
    r.cell[3] = kFreeMark;
    free_nodes_ = n;
    ++free_node_count_;
  }

  LatticeSize size_;
  std::int64_t extent_x_ = 0, extent_y_ = 0;  ///< the domain: W*S by H*S
  Pool<Center> centers_;                      ///< spec/lattice3d.md §9.8, §9.9: the 3D lattice's pools
  Pool<Node> nodes_;
  Index free_centers_ = kNone;
  Index free_nodes_ = kNone;
  std::size_t free_center_count_ = 0;
  std::size_t free_node_count_ = 0;
  std::size_t cell_count_ = 0;
  std::size_t node_count_ = 0;
  detail::Array<std::uint32_t> table_;
  std::size_t table_shift_ = 64;  ///< home = hash >> table_shift_
  std::size_t table_used_ = 0;
};

// ---- The lattice vocabulary (bccmis/lattice.h): Lattice models AdaptiveLattice

inline const LatticeSize& size_of(const Lattice& g) { return g.size(); }
inline std::optional<RefineRefusal> can_refine(const Lattice& g, const Point& c) { return g.can_refine(c); }
inline std::optional<CoarsenRefusal> can_coarsen(const Lattice& g, const Point& n) { return g.can_coarsen(n); }
inline RefineResult refine(Lattice& g, const Point& c) { return g.refine(c); }
inline CoarsenResult coarsen(Lattice& g, const Point& n) { return g.coarsen(n); }
inline bool is_center(const Lattice& g, const Point& v) { return g.is_center(v); }
inline bool is_node(const Lattice& g, const Point& v) { return g.is_node(v); }
inline int level_of(const Lattice& g, const Point& c) { return g.level_of(c); }
inline SmallPoints<8> neighbors(const Lattice& g, const Point& v) { return g.nbr(v); }
inline std::vector<Point> cells(const Lattice& g) { return g.cells(); }
inline std::vector<Point> nodes(const Lattice& g) { return g.nodes(); }
inline std::size_t cell_count(const Lattice& g) { return g.cell_count(); }
inline std::size_t node_count(const Lattice& g) { return g.node_count(); }
/// Optional in the vocabulary (replay calls it when a lattice has it):
/// room for `cells` cells, a hint, of at most kMaxReserveHint cells. The
/// pools' capacity is address space until it is used; the position table is
/// sized for that many cells (about 9-18 bytes a cell, so at most 32 MiB for
/// a hint however many refines a trace lists). A reservation the allocator
/// refuses is dropped. Beyond the hint the lattice grows as it goes.
inline constexpr std::size_t kMaxReserveHint = std::size_t{1} << 22;
void reserve(Lattice& g, std::size_t cells);
/// The canonical text of spec/formats.md, written from the pools.
void write_canonical_state(std::ostream& out, const Lattice& g);

/// The canonical text of spec/formats.md, byte-identical to
/// bccmis::canonical_state(g.to_graph()), printed from the pools directly.
std::string canonical_state(const Lattice& g);

}  // namespace bccmis::fast

static_assert(bccmis::AdaptiveLattice<bccmis::fast::Lattice>);
