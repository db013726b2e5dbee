// bccmis::fast: refine (spec/lattice3d.md §4) and coarsen (§5) in 3D on flat
// records.
//
// Both follow the set equations of spec/equations3d.toml step by step, as the
// reference does (src/bccmis/d3/refine.cpp, coarsen.cpp); each step names
// the equation it implements (R1a-R4b, K1a-K4b). A set is a small array of
// record ids; a union that cannot meet an element twice is an append, a
// difference a removal. Every set is computed before the first write, so
// that a lattice that is not valid (a logic_error) is left unchanged.
#include "bccmis/fast/d3/lattice.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <initializer_list>
#include <new>
#include <stdexcept>

#include "bccmis/d3/geometry.h"
#include "bccmis/text_writer.h"

namespace bccmis::d3::fast {

namespace {

using Index = Lattice::Index;

// The position's hash: the three coordinates combined, then the splitmix64
// finalizer, so that the low bits (the home slot) depend on every bit of
// every coordinate (lattice coordinates are multiples of powers of two).
std::uint64_t mix(const Point& p) {
  std::uint64_t h = static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ull;
  h += std::rotl(static_cast<std::uint64_t>(p.y) * 0xC2B2AE3D27D4EB4Full, 21);
  h += std::rotl(static_cast<std::uint64_t>(p.z) * 0x165667B19E3779F9ull, 42);
  h ^= h >> 30;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 27;
  h *= 0x94D049BB133111EBull;
  h ^= h >> 31;
  return h;
}

// A junction's cardinality (spec/lattice3d.md §3, F2; choice V2): 3, 5, 6 or 7.
bool is_junction_cardinality(std::uint32_t k) { return k == 3 || k == 5 || k == 6 || k == 7; }

// A small set of ids (no heap).
template <std::size_t N>
struct Ids {
  std::array<Index, N> v{};
  std::size_t n = 0;
  void push(Index i) { v[n++] = i; }
  bool has(Index i) const { return std::find(v.begin(), v.begin() + n, i) != v.begin() + n; }
  const Index* begin() const { return v.data(); }
  const Index* end() const { return v.data() + n; }
};

}  // namespace

// ---- Construction and memory --------------------------------------------------

Lattice::Lattice(const d3::LatticeSize& size) : size_(size) {
  d3::validate_lattice_size(size);
  const std::int64_t S = d3::level0_side(size);
  // The number of cubes and of grid nodes, each below 2^31 (records are named by 31-bit ids).
  constexpr std::int64_t kLimit = std::int64_t{1} << 31;
  auto product_below_limit = [](std::int64_t a, std::int64_t b, std::int64_t c) {
    return a < kLimit && b < kLimit && c < kLimit && a * b < kLimit && a * b * c < kLimit;
  };
  if (!product_below_limit(size.W, size.H, size.D) || !product_below_limit(size.W + 1, size.H + 1, size.D + 1))
    throw std::length_error("d3::fast::Lattice: the initial lattice needs 2^31 or more vertices of one kind");
  const std::int64_t cubes = size.W * size.H * size.D;
  reserve(static_cast<std::size_t>(cubes));
  for (std::int64_t i = 0; i <= size.W; ++i)
    for (std::int64_t j = 0; j <= size.H; ++j)
      for (std::int64_t k = 0; k <= size.D; ++k) table_insert(alloc_node({i * S, j * S, k * S}) | kNodeBit);
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t k = 0; k < size.D; ++k) {
        const Index c = alloc_center({i * S + S / 2, j * S + S / 2, k * S + S / 2}, 0);
        table_insert(c);
        for (std::int64_t di = 0; di <= 1; ++di)
          for (std::int64_t dj = 0; dj <= 1; ++dj)
            for (std::int64_t dk = 0; dk <= 1; ++dk) link(c, find_node({(i + di) * S, (j + dj) * S, (k + dk) * S}));
      }
}

void Lattice::reserve(std::size_t cells) {
  centers_.reserve(cells);
  nodes_.reserve(cells + cells / 2 + 64);
  const std::size_t keys = centers_.capacity() + nodes_.capacity();
  std::size_t slots = std::max<std::size_t>(table_.size(), 64);
  while (slots * 7 < keys * 10) slots *= 2;
  if (slots != table_.size()) rehash(slots);
}

Lattice Lattice::from_graph(const d3::Graph& g) {
  Lattice lat(g.size);  // validates the size
  lat.centers_.clear();
  lat.nodes_.clear();
  lat.free_centers_ = lat.free_nodes_ = kNone;
  lat.free_center_count_ = lat.free_node_count_ = 0;
  lat.cell_count_ = lat.node_count_ = 0;
  std::fill(lat.table_.begin(), lat.table_.end(), kNone);
  lat.table_used_ = 0;
  if (g.C.size() >= kNodeBit || g.N.size() >= kNodeBit)
    throw std::invalid_argument("d3::fast::Lattice::from_graph: 2^31 or more vertices of one kind");
  lat.centers_.reserve(g.C.size());
  lat.nodes_.reserve(g.N.size());
  lat.ensure_room(g.C.size(), g.N.size());
  for (const Point& n : g.N) {
    if (g.nbr(n).size() > 8)
      throw std::invalid_argument("d3::fast::Lattice::from_graph: node " + d3::to_string(n) +
                                  " has more than 8 neighbors");
    lat.table_insert(lat.alloc_node(n) | kNodeBit);
  }
  const std::int64_t S = d3::level0_side(g.size);
  for (const Point& c : g.C) {
    const auto lv = g.level.find(c);
    // A level-l center has odd multiples of 2^(L-l) as coordinates, inside the domain.
    const auto zeros = [](std::int64_t v) { return v > 0 ? std::countr_zero(static_cast<std::uint64_t>(v)) : -1; };
    const int tz = zeros(c.x);
    const bool inside = c.x < g.size.W * S && c.y < g.size.H * S && c.z < g.size.D * S;
    if (lv == g.level.end() || !inside || tz < 0 || zeros(c.y) != tz || zeros(c.z) != tz ||
        g.size.L - tz != lv->second || lv->second < 0)
      throw std::invalid_argument("d3::fast::Lattice::from_graph: center " + d3::to_string(c) +
                                  " has no level in 0..L that matches its position");
    const d3::PointSet& B = g.nbr(c);
    if (B.size() > 26)
      throw std::invalid_argument("d3::fast::Lattice::from_graph: center " + d3::to_string(c) +
                                  " has more than 26 neighbors");
    const Index ci = lat.alloc_center(c, lv->second);
    lat.table_insert(ci);
    for (const Point& b : B) {
      const Index ni = lat.find_node(b);
      if (ni == kNone)
        throw std::invalid_argument("d3::fast::Lattice::from_graph: neighbor " + d3::to_string(b) + " of center " +
                                    d3::to_string(c) + " is not a node");
      lat.link(ci, ni);
    }
  }
  return lat;
}

std::size_t Lattice::refine_each(std::span<const Point> cells) {
  constexpr std::size_t kAhead = 8;
  std::size_t applied = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i + kAhead < cells.size()) __builtin_prefetch(&table_[home(cells[i + kAhead])]);
    applied += refine(cells[i]).applied();
  }
  return applied;
}

std::size_t Lattice::coarsen_each(std::span<const Point> nodes) {
  constexpr std::size_t kAhead = 8;
  std::size_t applied = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (i + kAhead < nodes.size()) __builtin_prefetch(&table_[home(nodes[i + kAhead])]);
    applied += coarsen(nodes[i]).applied();
  }
  return applied;
}

void reserve(Lattice& g, std::size_t cells) {
  try {
    g.reserve(std::min(cells, bccmis::fast::kMaxReserveHint));
  } catch (const std::bad_alloc&) {
    // A hint: the lattice grows as it goes.
  }
}

std::size_t Lattice::memory_bytes() const {
  return centers_.capacity() * sizeof(Center) + nodes_.capacity() * sizeof(Node) + table_.capacity() * sizeof(Index);
}

void Lattice::ensure_room(std::size_t new_centers, std::size_t new_nodes) {
  auto grow = [](auto& pool, std::size_t free_count, std::size_t needed) {
    if (free_count + (pool.capacity() - pool.size()) < needed)
      pool.reserve(std::max(2 * pool.capacity(), pool.size() + needed));
  };
  grow(centers_, free_center_count_, new_centers);
  grow(nodes_, free_node_count_, new_nodes);
  std::size_t slots = table_.size();
  while ((table_used_ + new_centers + new_nodes) * 10 > slots * 7) slots *= 2;
  if (slots != table_.size()) rehash(slots);
}

Index Lattice::alloc_center(const Point& p, int level) {
  Index c;
  if (free_centers_ == kNone) {
    if (centers_.size() >= kNodeBit) throw std::length_error("d3::fast::Lattice: 2^31 centers");
    centers_.emplace_back();
    c = static_cast<Index>(centers_.size() - 1);
  } else {
    c = free_centers_;
    free_centers_ = centers_[c].nbr[0];
    --free_center_count_;
  }
  Center& r = centers_[c];
  r.p = p;
  r.level = level;
  r.count = 0;
  ++cell_count_;
  return c;
}

Index Lattice::alloc_node(const Point& p) {
  Index n;
  if (free_nodes_ == kNone) {
    if (nodes_.size() >= kNodeBit) throw std::length_error("d3::fast::Lattice: 2^31 nodes");
    nodes_.emplace_back();
    n = static_cast<Index>(nodes_.size() - 1);
  } else {
    n = free_nodes_;
    free_nodes_ = nodes_[n].nbr[0];
    --free_node_count_;
  }
  Node& r = nodes_[n];
  r.p = p;
  r.count = 0;
  ++node_count_;
  return n;
}

void Lattice::free_center(Index c) {
  Center& r = centers_[c];
  r.level = -1;
  r.count = 0;
  r.nbr[0] = free_centers_;
  free_centers_ = c;
  ++free_center_count_;
  --cell_count_;
}

void Lattice::free_node(Index n) {
  Node& r = nodes_[n];
  r.count = kFree;
  r.nbr[0] = free_nodes_;
  free_nodes_ = n;
  ++free_node_count_;
  --node_count_;
}

void Lattice::add_id(Index* ids, std::uint32_t& count, std::uint32_t capacity, Index id) {
  if (count >= capacity)
    throw std::logic_error("d3::fast::Lattice: a neighbor list overflows; the lattice is not valid");
  ids[count++] = id;
}

void Lattice::remove_id(Index* ids, std::uint32_t& count, Index id) {
  for (std::uint32_t i = 0; i < count; ++i)
    if (ids[i] == id) {
      ids[i] = ids[--count];
      return;
    }
}

void Lattice::link(Index center, Index node) {
  Center& c = centers_[center];
  Node& n = nodes_[node];
  add_id(c.nbr, c.count, 26, node);
  add_id(n.nbr, n.count, 8, center);
}

// ---- Position table -------------------------------------------------------------

std::size_t Lattice::home(const Point& p) const { return static_cast<std::size_t>(mix(p)) & (table_.size() - 1); }

std::size_t Lattice::slot_of(const Point& p) const {
  const std::size_t mask = table_.size() - 1;
  for (std::size_t s = home(p);; s = (s + 1) & mask)
    if (table_[s] == kNone || key_of(table_[s]) == p) return s;
}

void Lattice::table_insert(Index ref) {
  const std::size_t mask = table_.size() - 1;
  std::size_t s = home(key_of(ref));
  while (table_[s] != kNone) s = (s + 1) & mask;
  table_[s] = ref;
  ++table_used_;
}

void Lattice::table_replace(const Point& p, Index ref) { table_[slot_of(p)] = ref; }

void Lattice::table_erase(const Point& p) {
  // Linear probing's deletion by backward shift: an entry after the hole
  // moves into it unless its home lies cyclically in (hole, entry].
  const std::size_t mask = table_.size() - 1;
  std::size_t hole = slot_of(p);
  if (table_[hole] == kNone) return;
  for (std::size_t s = (hole + 1) & mask; table_[s] != kNone; s = (s + 1) & mask) {
    const std::size_t h = home(key_of(table_[s]));
    const bool stays = hole <= s ? (hole < h && h <= s) : (hole < h || h <= s);
    if (!stays) {
      table_[hole] = table_[s];
      hole = s;
    }
  }
  table_[hole] = kNone;
  --table_used_;
}

void Lattice::rehash(std::size_t slots) {
  std::vector<Index> old(slots, kNone);
  old.swap(table_);
  table_used_ = 0;
  for (const Index ref : old)
    if (ref != kNone) table_insert(ref);
}

// ---- Queries -----------------------------------------------------------------------

bool Lattice::is_center(const Point& v) const { return find_center(v) != kNone; }
bool Lattice::is_node(const Point& v) const { return find_node(v) != kNone; }

int Lattice::level_of(const Point& c) const {
  const Index ci = find_center(c);
  if (ci == kNone) throw std::out_of_range("d3::fast::Lattice::level_of: " + d3::to_string(c) + " is not a center");
  return centers_[ci].level;
}

SmallPoints<26> Lattice::nbr(const Point& v) const {
  SmallPoints<26> out;
  const Index r = find(v);
  if (r == kNone) return out;
  if (r & kNodeBit) {
    const Node& n = nodes_[r & ~kNodeBit];
    for (std::uint32_t i = 0; i < n.count; ++i) out.push_back(centers_[n.nbr[i]].p);
  } else {
    const Center& c = centers_[r];
    for (std::uint32_t i = 0; i < c.count; ++i) out.push_back(nodes_[c.nbr[i]].p);
  }
  out.sort();
  return out;
}

std::vector<Index> Lattice::sorted_centers() const {
  std::vector<Index> ids;
  ids.reserve(cell_count_);
  for (Index i = 0; i < centers_.size(); ++i)
    if (centers_[i].live()) ids.push_back(i);
  std::sort(ids.begin(), ids.end(), [&](Index a, Index b) { return centers_[a].p < centers_[b].p; });
  return ids;
}

std::vector<Index> Lattice::sorted_nodes() const {
  std::vector<Index> ids;
  ids.reserve(node_count_);
  for (Index i = 0; i < nodes_.size(); ++i)
    if (nodes_[i].live()) ids.push_back(i);
  std::sort(ids.begin(), ids.end(), [&](Index a, Index b) { return nodes_[a].p < nodes_[b].p; });
  return ids;
}

std::vector<Point> Lattice::cells() const {
  std::vector<Point> out;
  out.reserve(cell_count_);
  for (const Index i : sorted_centers()) out.push_back(centers_[i].p);
  return out;
}

std::vector<Point> Lattice::nodes() const {
  std::vector<Point> out;
  out.reserve(node_count_);
  for (const Index i : sorted_nodes()) out.push_back(nodes_[i].p);
  return out;
}

d3::Graph Lattice::to_graph() const {
  d3::Graph g;
  g.size = size_;
  for (const Center& c : centers_) {
    if (!c.live()) continue;
    g.C.insert(c.p);
    g.level[c.p] = c.level;
    d3::PointSet& s = g.neighbors[c.p];
    for (std::uint32_t i = 0; i < c.count; ++i) s.insert(nodes_[c.nbr[i]].p);
  }
  for (const Node& n : nodes_) {
    if (!n.live()) continue;
    g.N.insert(n.p);
    d3::PointSet& s = g.neighbors[n.p];
    for (std::uint32_t i = 0; i < n.count; ++i) s.insert(centers_[n.nbr[i]].p);
  }
  return g;
}

std::optional<std::string> Lattice::audit() const {
  std::size_t live_cells = 0, live_nodes = 0;
  for (Index i = 0; i < centers_.size(); ++i) {
    const Center& c = centers_[i];
    if (!c.live()) continue;
    ++live_cells;
    if (find(c.p) != i) return "center " + d3::to_string(c.p) + " is not in the position table";
    for (std::uint32_t k = 0; k < c.count; ++k) {
      const Node& n = nodes_[c.nbr[k]];
      if (!n.live()) return "center " + d3::to_string(c.p) + " lists a free node record";
      if (std::find(n.nbr, n.nbr + n.count, i) == n.nbr + n.count)
        return "center " + d3::to_string(c.p) + " lists node " + d3::to_string(n.p) + ", which does not list it";
      if (std::find(c.nbr, c.nbr + k, c.nbr[k]) != c.nbr + k) return "center " + d3::to_string(c.p) + ": a repeat";
    }
  }
  for (Index i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    if (!n.live()) continue;
    ++live_nodes;
    if (find(n.p) != (i | kNodeBit)) return "node " + d3::to_string(n.p) + " is not in the position table";
    for (std::uint32_t k = 0; k < n.count; ++k) {
      const Center& c = centers_[n.nbr[k]];
      if (!c.live()) return "node " + d3::to_string(n.p) + " lists a free center record";
      if (std::find(c.nbr, c.nbr + c.count, i) == c.nbr + c.count)
        return "node " + d3::to_string(n.p) + " lists center " + d3::to_string(c.p) + ", which does not list it";
      if (std::find(n.nbr, n.nbr + k, n.nbr[k]) != n.nbr + k) return "node " + d3::to_string(n.p) + ": a repeat";
    }
  }
  if (live_cells != cell_count_ || live_nodes != node_count_) return std::string("the vertex counts do not add up");
  if (table_used_ != live_cells + live_nodes) return std::string("the position table holds other entries");
  std::size_t free_centers = 0, free_nodes = 0;
  for (Index i = free_centers_; i != kNone; i = centers_[i].nbr[0]) ++free_centers;
  for (Index i = free_nodes_; i != kNone; i = nodes_[i].nbr[0]) ++free_nodes;
  if (free_centers != free_center_count_ || live_cells + free_centers != centers_.size() ||
      free_nodes != free_node_count_ || live_nodes + free_nodes != nodes_.size())
    return std::string("the free lists do not add up");
  return std::nullopt;
}

// ---- Canonical state ---------------------------------------------------------------

void Lattice::write_canonical_state(std::ostream& out) const {
  TextWriter w(out);
  w.put("bccmis-state 1\nlattice ");
  w.put_int(size_.W);
  w.put(' ');
  w.put_int(size_.H);
  w.put(' ');
  w.put_int(size_.D);
  w.put(' ');
  w.put_int(size_.L);
  w.put('\n');
  std::array<Point, 26> around{};
  auto neighbors = [&](std::size_t count) {
    std::sort(around.begin(), around.begin() + static_cast<std::ptrdiff_t>(count));
    w.put(" :");
    for (std::size_t i = 0; i < count; ++i) w.put_point(around[i].x, around[i].y, around[i].z);
    w.put('\n');
  };
  for (const Index i : sorted_centers()) {
    const Center& c = centers_[i];
    w.put('C');
    w.put_point(c.p.x, c.p.y, c.p.z);
    w.put(' ');
    w.put_int(c.level);
    for (std::uint32_t k = 0; k < c.count; ++k) around[k] = nodes_[c.nbr[k]].p;
    neighbors(c.count);
  }
  for (const Index i : sorted_nodes()) {
    const Node& n = nodes_[i];
    w.put('N');
    w.put_point(n.p.x, n.p.y, n.p.z);
    for (std::uint32_t k = 0; k < n.count; ++k) around[k] = centers_[n.nbr[k]].p;
    neighbors(n.count);
  }
  w.put("end ");
  w.put_int(static_cast<std::int64_t>(cell_count_));
  w.put(' ');
  w.put_int(static_cast<std::int64_t>(node_count_));
  w.put('\n');
  w.flush();
}

std::string canonical_state(const Lattice& g) { return canonical_text(g); }

// ---- Preconditions -------------------------------------------------------------------

std::optional<int> Lattice::refined_center_level(const Point& p) const {
  const std::int64_t S = d3::level0_side(size_);
  if (p.x <= 0 || p.y <= 0 || p.z <= 0 || p.x >= size_.W * S || p.y >= size_.H * S || p.z >= size_.D * S)
    return std::nullopt;
  const int tx = std::countr_zero(static_cast<std::uint64_t>(p.x));
  const int ty = std::countr_zero(static_cast<std::uint64_t>(p.y));
  const int tz = std::countr_zero(static_cast<std::uint64_t>(p.z));
  if (tx != ty || tx != tz) return std::nullopt;
  const int l = size_.L - tx;
  if (l < 0 || l >= size_.L) return std::nullopt;
  return l;
}

std::optional<RefineRefusal> Lattice::refine_refusal(const Point& c, Index& ci) const {
  // spec/lattice3d.md §4 preconditions, in the reference's order.
  ci = find_center(c);
  if (ci == kNone) return RefineRefusal::NoSuchCell;
  const Center& rc = centers_[ci];
  if (rc.level >= size_.L) return RefineRefusal::MaxLevel;
  // R1d: X = (union over b_i != b_j in B of N(b_i) ∩ N(b_j)) \ {c}, that is
  // the cells other than c that have at least two of c's nodes. Every x in X
  // must be at least as fine as c, so only the coarser cells around c are
  // counted: c is refused when one of them has two of c's nodes.
  std::array<Index, 26 * 8> coarser{};
  std::size_t n = 0;
  for (std::uint32_t i = 0; i < rc.count; ++i) {
    const Node& b = nodes_[rc.nbr[i]];
    for (std::uint32_t k = 0; k < b.count; ++k) {
      const Index x = b.nbr[k];
      if (x == ci || centers_[x].level >= rc.level) continue;
      const auto end = coarser.begin() + static_cast<std::ptrdiff_t>(n);
      if (std::find(coarser.begin(), end, x) != end) return RefineRefusal::CoarserNeighbor;  // x in X
      coarser[n++] = x;
    }
  }
  return std::nullopt;
}

std::optional<CoarsenRefusal> Lattice::coarsen_refusal(const Point& n, Index& ni, int& l) const {
  // spec/lattice3d.md §5 preconditions, in the reference's order.
  ni = find_node(n);
  if (ni == kNone) return CoarsenRefusal::NoSuchNode;
  const std::optional<int> level = refined_center_level(n);
  if (!level) return CoarsenRefusal::NotARefinedCenter;
  l = *level;
  const Node& rn = nodes_[ni];
  if (rn.count != 8) return CoarsenRefusal::NotARefinedCenter;
  for (std::uint32_t i = 0; i < 8; ++i)
    if (centers_[rn.nbr[i]].level != l + 1) return CoarsenRefusal::ChildrenRefined;
  for (std::uint32_t i = 0; i < 8; ++i)
    if (centers_[rn.nbr[i]].count != 8) return CoarsenRefusal::FinerNeighbor;
  return std::nullopt;
}

std::optional<RefineRefusal> Lattice::can_refine(const Point& c) const {
  Index ci;
  return refine_refusal(c, ci);
}

std::optional<CoarsenRefusal> Lattice::can_coarsen(const Point& n) const {
  Index ni;
  int l;
  return coarsen_refusal(n, ni, l);
}

// ---- Refine ----------------------------------------------------------------------------

RefineResult Lattice::refine(const Point& c) {
  RefineResult result;
  Index ci;
  result.refused = refine_refusal(c, ci);
  if (result.refused) return result;
  // Room for the 8 children, c as a node and at most 18 new nodes.
  ensure_room(8, 19);

  const int l = centers_[ci].level;
  const std::int64_t half = d3::cell_side(size_, l) / 2;

  // 1. The neighborhood of c (R1a-R1c): B = N(c), J the junctions of B, P = B \ J.
  Ids<26> J;
  std::array<Point, 8> p{};  // p_1..p_8, the corners, sorted by position
  std::array<Index, 8> pid{};
  {
    std::size_t i = 0;
    for (std::int64_t dx : {-half, half})
      for (std::int64_t dy : {-half, half})
        for (std::int64_t dz : {-half, half}) p[i++] = {c.x + dx, c.y + dy, c.z + dz};
  }
  std::size_t corners = 0;
  const Center& rc = centers_[ci];
  for (std::uint32_t k = 0; k < rc.count; ++k) {
    const Index b = rc.nbr[k];
    if (is_junction_cardinality(nodes_[b].count)) {
      J.push(b);
      continue;
    }
    const auto at = std::find(p.begin(), p.end(), nodes_[b].p);
    if (at == p.end()) {
      corners = 9;  // a pure node that is not a corner
      break;
    }
    pid[static_cast<std::size_t>(at - p.begin())] = b;
    ++corners;
  }
  // claim-P-has-8: P is exactly the 8 corners of c.
  if (corners != 8)
    throw std::logic_error(
        "refine: P is not the 8 corners of c although no face or edge neighbour is "
        "coarser; the graph is not a valid lattice");

  // The edges and faces of c (choice Q2) with their midpoints m; an old
  // junction at m (step 4), or the cells around m other than c (R1e, R1f)
  // that the new node at m (step 3) joins.
  struct Mid {
    Point m;
    Index old = kNone;  // the junction at m, if any
    Ids<8> X;           // X_e or X_f
  };
  const std::array<d3::CubeEdge, 12> cube_edges = d3::cube_edges(p);
  const std::array<d3::CubeFace, 6> cube_faces = d3::cube_faces(p);
  std::array<Mid, 12> edges{};
  std::array<Mid, 6> faces{};
  std::size_t old_junctions = 0;
  auto junction_at = [&](const Point& m) {
    for (const Index j : J)
      if (nodes_[j].p == m) return j;
    return kNone;
  };
  // The cells other than c around every corner in `ids` (the intersection of
  // their N(p_i), minus c).
  auto common_cells = [&](Mid& mid, std::initializer_list<std::size_t> ids) {
    const Node& first = nodes_[pid[*ids.begin()]];
    for (std::uint32_t k = 0; k < first.count; ++k) {
      const Index x = first.nbr[k];
      if (x == ci) continue;
      bool everywhere = true;
      for (const std::size_t i : ids) {
        const Node& other = nodes_[pid[i]];
        everywhere = everywhere && std::find(other.nbr, other.nbr + other.count, x) != other.nbr + other.count;
      }
      if (everywhere) mid.X.push(x);
    }
  };
  for (std::size_t e = 0; e < 12; ++e) {
    Mid& mid = edges[e];
    mid.m = d3::midpoint(p[cube_edges[e].i], p[cube_edges[e].j]);
    mid.old = junction_at(mid.m);
    if (mid.old != kNone) {
      ++old_junctions;
      continue;
    }
    // R1e: X_e = (N(p_i) ∩ N(p_j)) \ {c}.
    common_cells(mid, {cube_edges[e].i, cube_edges[e].j});
  }
  for (std::size_t f = 0; f < 6; ++f) {
    Mid& mid = faces[f];
    const auto& q = cube_faces[f].corners;
    mid.m = d3::midpoint(p[q[0]], p[q[3]]);  // opposite corners of the face
    mid.old = junction_at(mid.m);
    if (mid.old != kNone) {
      ++old_junctions;
      continue;
    }
    // R1f: X_f = (N(p_i) ∩ N(p_j) ∩ N(p_k) ∩ N(p_m)) \ {c}.
    common_cells(mid, {q[0], q[1], q[2], q[3]});
  }
  // claim-J-on-edges-and-faces: every junction is an edge midpoint or a face center of c.
  if (old_junctions != J.n)
    throw std::logic_error(
        "refine: a junction of c is not an edge midpoint or face center of c; "
        "the graph is not a valid lattice");

  // 2. Subdivide c (R2a-R2h). y_i, centred halfway between c and p_i
  //    (choice Q1), is the child that holds corner p_i; Y is sorted as p.
  std::array<Index, 8> y{};
  for (std::size_t i = 0; i < 8; ++i) {
    // R2a, R2b: Y = {y_1, ..., y_8}, C = C ∪ Y.
    y[i] = alloc_center(d3::midpoint(c, p[i]), l + 1);
    result.Y.push_back(centers_[y[i]].p);
  }
  // R2h: N = N ∪ {c}; R2c: N(c) = Y.
  const Index cn = alloc_node(c);
  // R2d: N(j) = N(j) \ {c} for all j in J.
  for (const Index j : J) remove_id(nodes_[j].nbr, nodes_[j].count, ci);
  for (std::size_t i = 0; i < 8; ++i) {
    // R2e: N(p_i) = (N(p_i) ∪ {y_i}) \ {c}.
    remove_id(nodes_[pid[i]].nbr, nodes_[pid[i]].count, ci);
    // R2f: N(y_i) = {p_i, c}.
    link(y[i], pid[i]);
    link(y[i], cn);
  }
  // R2g: C = C \ {c}; c is named by its node record from now on.
  table_replace(c, cn | kNodeBit);
  free_center(ci);
  for (const Index yi : y) table_insert(yi);

  // 3. New nodes on the edges and faces of c that had none (R3a-R3h), and
  // 4. old junctions join the children beside them (R4a, R4b; choice Q3).
  Ids<18> J_plus;
  auto join = [&](const Mid& mid, std::initializer_list<std::size_t> ids) {
    if (mid.old != kNone) {
      // R4a: N(j) ∪= {y_i : p_i in e}; R4b: N(y_i) ∪= {j}.
      for (const std::size_t i : ids) link(y[i], mid.old);
      return;
    }
    // R3a, R3b: J+ gets m, N = N ∪ J+.
    const Index jp = alloc_node(mid.m);
    table_insert(jp | kNodeBit);
    J_plus.push(jp);
    // R3c / R3f: N(x) ∪= {j+} for x in X_e (X_f); R3d / R3g: N(j+) = X ∪ {y_i ...}.
    for (const Index x : mid.X) link(x, jp);
    // R3e / R3h: N(y) ∪= {j+} for the children of the edge (face).
    for (const std::size_t i : ids) link(y[i], jp);
  };
  for (std::size_t e = 0; e < 12; ++e) join(edges[e], {cube_edges[e].i, cube_edges[e].j});
  for (std::size_t f = 0; f < 6; ++f) {
    const auto& q = cube_faces[f].corners;
    join(faces[f], {q[0], q[1], q[2], q[3]});
  }
  for (const Index j : J_plus) result.J_plus.push_back(nodes_[j].p);
  result.J_plus.sort();
  return result;
}

// ---- Coarsen ---------------------------------------------------------------------------

CoarsenResult Lattice::coarsen(const Point& n) {
  CoarsenResult result;
  Index ni;
  int l = 0;
  result.refused = coarsen_refusal(n, ni, l);
  if (result.refused) return result;
  ensure_room(1, 0);

  // 1. K1a: Y = N(n). K1b: B = (union of N(y_i)) \ {n}. K1c: M = the b in
  //    two or four children (edge midpoints and face centers; choice V4).
  Ids<8> Y;
  for (std::uint32_t k = 0; k < 8; ++k) Y.push(nodes_[ni].nbr[k]);
  Ids<26 * 8> B;
  for (const Index yi : Y) {
    const Center& ry = centers_[yi];
    for (std::uint32_t k = 0; k < ry.count; ++k)
      if (ry.nbr[k] != ni && !B.has(ry.nbr[k])) B.push(ry.nbr[k]);
  }
  Ids<26 * 8> M;
  for (const Index b : B) {
    const Node& rb = nodes_[b];
    std::size_t k = 0;
    for (std::uint32_t i = 0; i < rb.count; ++i) k += Y.has(rb.nbr[i]);
    if (k == 2 || k == 4) M.push(b);
  }
  if (B.n != 26 || M.n != 18)
    throw std::logic_error(
        "coarsen: the children's boundary is not 8 corners, 12 edge midpoints and "
        "6 face centers; the graph is not a valid lattice");

  for (const Index yi : Y) result.Y.push_back(centers_[yi].p);
  result.Y.sort();

  // 2. K2a: N(b) = N(b) \ Y for all b in B.
  for (const Index b : B)
    for (const Index yi : Y) remove_id(nodes_[b].nbr, nodes_[b].count, yi);
  // K2b, K2f: the children are deleted (C = C \ Y).
  for (const Index yi : Y) {
    table_erase(centers_[yi].p);
    free_center(yi);
  }
  // K2c, K2d, K2e: n leaves N and joins C as a level-l cell (choice Q4).
  const Index cc = alloc_center(n, l);
  table_replace(n, cc);
  free_node(ni);

  // 3. K3a: J- = {b in M : level(x) <= l for all x in N(b)} (choice V3).
  Ids<18> J_minus;
  for (const Index b : M) {
    const Node& rb = nodes_[b];
    bool corner_of_a_cell = false;
    for (std::uint32_t i = 0; i < rb.count; ++i) corner_of_a_cell = corner_of_a_cell || centers_[rb.nbr[i]].level > l;
    if (!corner_of_a_cell) J_minus.push(b);
  }
  for (const Index j : J_minus) result.J_minus.push_back(nodes_[j].p);
  result.J_minus.sort();
  // K3b-K3e: N = N \ J-; N(x) = N(x) \ {j} for x in N(j); the j are deleted.
  for (const Index j : J_minus) {
    Node& rj = nodes_[j];
    for (std::uint32_t i = 0; i < rj.count; ++i) remove_id(centers_[rj.nbr[i]].nbr, centers_[rj.nbr[i]].count, j);
    table_erase(rj.p);
    free_node(j);
  }

  // 4. K4a: N(n) = B \ J-; K4b: N(b) = N(b) ∪ {n}.
  for (const Index b : B)
    if (!J_minus.has(b)) link(cc, b);
  return result;
}

}  // namespace bccmis::d3::fast
