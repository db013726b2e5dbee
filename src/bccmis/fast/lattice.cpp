// bccmis::fast: refine (§2.1) and coarsen (§2.2) as fixed slot updates.
//
// Directions. A quadrant (and a corner) q has bit 0 set when it points east
// (+x) and bit 1 set when it points north (+y): 0 = SW, 1 = SE, 2 = NW,
// 3 = NE; q ^ 3 is the opposite quadrant. A side s is 0 = S, 1 = E, 2 = N,
// 3 = W; s ^ 2 is the opposite side.
//
// The one rule that links the two pools: when node m is corner k of cell x,
// x lies in quadrant k ^ 3 of m, so m.cell[k ^ 3] == x; when m is the
// midpoint of side s of x, x fills the two quadrants of m that face x.
//
// Refinement of c (level l, half side h), with the names of refine.cpp:
//
//      K[2] ---- m[N] ---- K[3]          K[q]  the pure corners P (eq. 2c)
//       |  y[2]   |   y[3]  |            m[s]  the side midpoints: an old
//      m[W] ----- c ----- m[E]                 junction of J (eq. 2b) or a
//       |  y[0]   |   y[1]  |                  new one of J+ (eq. 5a, E1)
//      K[0] ---- m[S] ---- K[1]          y[q]  the children Y (eq. 4a)
//
// Child y[q] has corners K[q] (outer), c (inner, eq. 4c/4f), and the
// midpoints of the two sides of c it touches (eq. 6d/6e, 7b); it has no
// junction: across its outer sides lie cells of its own level (old junction)
// or of c's level (a new junction is made on that cell's side instead).
#include "bccmis/fast/lattice.h"
#include "bccmis/text_writer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bccmis::fast {

namespace {

using Index = Lattice::Index;
constexpr Index kNone = Lattice::kNone;

constexpr std::int64_t qx(int q) { return (q & 1) ? 1 : -1; }
constexpr std::int64_t qy(int q) { return (q & 2) ? 1 : -1; }
constexpr std::int64_t kSideDx[4] = {0, 1, 0, -1};
constexpr std::int64_t kSideDy[4] = {-1, 0, 1, 0};

// The side of c that child q touches horizontally (S or N) and vertically (W or E).
constexpr int hside(int q) { return (q & 2) ? 2 : 0; }
constexpr int vside(int q) { return (q & 1) ? 1 : 3; }

// For side s: a corner of c on that side, and the quadrant of that corner
// node that lies across side s, next to c. The same pair finds, in a refined
// cell, the midpoint of side s: corner kSideQuad[s] of child kSideCorner[s].
constexpr int kSideCorner[4] = {0, 1, 3, 2};
constexpr int kSideQuad[4] = {1, 3, 2, 0};
// The two quadrants of the midpoint of side s that face c, and the child of c
// in each; the two quadrants that face away from c.
constexpr int kInwardQuad[4][2] = {{2, 3}, {0, 2}, {0, 1}, {1, 3}};
constexpr int kInwardChild[4][2] = {{0, 1}, {1, 3}, {2, 3}, {0, 2}};
constexpr int kOutwardQuad[4][2] = {{0, 1}, {1, 3}, {2, 3}, {0, 2}};
// Sorted (x, y) orders: children (quadrants) and side midpoints.
constexpr int kQuadSorted[4] = {0, 2, 1, 3};
constexpr int kSideSorted[4] = {3, 0, 2, 1};

Point offset(const Point& p, std::int64_t dx, std::int64_t dy) { return {p.x + dx, p.y + dy}; }

bool point_less(const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

std::uint64_t mix(const Point& p) {
  std::uint64_t h = static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(p.y) * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return h;
}

constexpr std::size_t kMaxPool =
    (std::size_t{1} << 26) - 1;  // indices below 2^26 (the position table's reference field)

// The level of the cell centered at p, from p alone (spec/formats.md: a
// level-l center has both coordinates odd multiples of 2^(L-l)); empty if p
// is no cell center of the lattice's levels or lies outside the domain.
std::optional<int> center_level(const LatticeSize& size, const Point& p) {
  const std::int64_t S = std::int64_t{1} << (size.L + 1);
  if (p.x <= 0 || p.y <= 0 || p.x >= size.W * S || p.y >= size.H * S) return std::nullopt;
  const int tx = std::countr_zero(static_cast<std::uint64_t>(p.x));
  const int ty = std::countr_zero(static_cast<std::uint64_t>(p.y));
  if (tx != ty || tx > size.L) return std::nullopt;
  return size.L - tx;
}

// Where a position sits in the lattice (spec/formats.md, "Coordinates"):
// outside the closed domain; a corner of the level-0 grid (always a node); a
// position where a level-l cell would have its center (a center, a refined
// center = node, or nothing); or the midpoint of a side shared by two
// level-l cells (a node iff one of the two is refined).
struct Site {
  enum Kind { Outside, GridNode, CenterLike, SideMidpoint } kind = Outside;
  int level = 0;
  Point a, b;  ///< SideMidpoint: the centers of the two cells sharing the side
};

Site site_of(const LatticeSize& size, const Point& p) {
  Site site;
  const std::int64_t S = level0_side(size);
  if (p.x < 0 || p.y < 0 || p.x > size.W * S || p.y > size.H * S) return site;
  const int tx = std::countr_zero(static_cast<std::uint64_t>(p.x));  // 64 for 0
  const int ty = std::countr_zero(static_cast<std::uint64_t>(p.y));
  if (tx > size.L && ty > size.L) {
    site.kind = Site::GridNode;
  } else if (tx == ty) {
    site.kind = Site::CenterLike;
    site.level = size.L - tx;
  } else {
    site.kind = Site::SideMidpoint;
    const int t = std::min(tx, ty);
    site.level = size.L - t;
    const std::int64_t h = std::int64_t{1} << t;
    if (tx < ty) {  // on a horizontal side: the cells below and above
      site.a = {p.x, p.y - h};
      site.b = {p.x, p.y + h};
    } else {
      site.a = {p.x - h, p.y};
      site.b = {p.x + h, p.y};
    }
  }
  return site;
}

}  // namespace

// ---- Huge pages -------------------------------------------------------------

void detail::advise_huge_pages(void* p, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < 2 * kHuge) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice only: errors ignored
#else
  (void)p;
  (void)bytes;
#endif
}

// ---- SmallPoints / outcomes --------------------------------------------------

// ---- Records -----------------------------------------------------------------

Point Lattice::Center::position() const {
  std::uint64_t x = xy[0] | (std::uint64_t{xy[1]} << 32);
  std::uint64_t y = xy[2] | (std::uint64_t{xy[3]} << 32);
  return {static_cast<std::int64_t>(x), static_cast<std::int64_t>(y)};
}

void Lattice::Center::set_position(const Point& p) {
  const auto x = static_cast<std::uint64_t>(p.x);
  const auto y = static_cast<std::uint64_t>(p.y);
  xy[0] = static_cast<std::uint32_t>(x);
  xy[1] = static_cast<std::uint32_t>(x >> 32);
  xy[2] = static_cast<std::uint32_t>(y);
  xy[3] = static_cast<std::uint32_t>(y >> 32);
}

Point Lattice::node_position(Index n) const {
  const Node& nd = nodes_[n];
  int q = 0;
  while (nd.cell[q] == kNone) ++q;  // a live node has a cell in some quadrant
  const Index x = nd.cell[q];
  const Center& cx = centers_[x];
  const Point p = cx.position();
  const std::int64_t h = half_side(cx.level(size_.L));
  // x fills quadrant q; if it also fills the horizontally (vertically)
  // adjacent quadrant, the node is the midpoint of its south or north (west
  // or east) side, otherwise its corner q ^ 3.
  return {nd.cell[q ^ 1] == x ? p.x : p.x - qx(q) * h, nd.cell[q ^ 2] == x ? p.y : p.y - qy(q) * h};
}

// ---- Position table ----------------------------------------------------------------
//
// Robin Hood linear probing on 4-byte slots: bits 0-26 hold the vertex
// reference (bit 26 = node), bits 27-31 hold 1 + the entry's displacement
// from its home slot (saturated at 31, then recomputed from the key); 0 is an
// empty slot. Insertion lets the entry farther from home keep a slot;
// deletion shifts the following entries back by one. Neither needs a key,
// and a lookup compares a key only for entries with its own home, so the
// pools are touched about once per lookup, not once per probe.
//
// Only positions where a cell center can be are keys: the cells and the
// refined centers (nodes). A grid node or a side midpoint is found from the
// geometry (site_of): a side midpoint is a node iff one of the two cells
// sharing the side is refined. So refine inserts its four children and
// coarsen erases them, nothing else. The four children of a cell get homes
// 4 slots apart in one 16-slot (64-byte, aligned) line chosen by their
// parent's hash, so an operation touches one line of the table for them; the
// spacing keeps their runs apart (homes in consecutive slots make long Robin
// Hood runs). The load factor stays at most 0.6.

std::size_t Lattice::home(const Point& p) const {
  return home_at(p, std::countr_zero(static_cast<std::uint64_t>(p.x)));
}

std::size_t Lattice::home_at(const Point& p, int t) const {
  // p is a cell center position: both coordinates odd multiples of 2^t.
  if (t >= size_.L) return static_cast<std::size_t>(mix(p) >> table_shift_);  // level 0: no parent
  const std::int64_t s = std::int64_t{1} << (t + 2);                          // the parent's side
  const Point parent{(p.x & ~(s - 1)) | (s / 2), (p.y & ~(s - 1)) | (s / 2)};
  const std::size_t q = ((p.x & (s / 2)) ? 1u : 0u) | ((p.y & (s / 2)) ? 2u : 0u);
  return child_home(static_cast<std::size_t>(mix(parent) >> table_shift_), q);
}

Point Lattice::key_of(Index ref) const {
  return (ref & kNodeBit) ? node_position(ref & ~kNodeBit) : centers_[ref].position();
}

std::size_t Lattice::displacement(std::size_t i) const {
  const std::uint32_t d = table_[i] >> kDistShift;
  if (d != kDistSaturated) [[likely]]
    return d - 1u;
  return (i - home(key_of(table_[i] & kRefMask))) & (table_.size() - 1);
}

std::size_t Lattice::slot_of(Index ref, std::size_t at) const {
  const std::size_t mask = table_.size() - 1;
  std::size_t i = at;
  while (table_[i] == 0 || (table_[i] & kRefMask) != ref) i = (i + 1) & mask;
  return i;
}

void Lattice::replace_ref(std::size_t slot, Index ref) { table_[slot] = (table_[slot] & ~kRefMask) | ref; }

void Lattice::prefetch(std::size_t at) const { __builtin_prefetch(&table_[at]); }

template <class Match>
Index Lattice::probe(std::size_t i, Match match) const {
  const std::uint32_t* t = table_.data();
  const std::size_t mask = table_.size() - 1;
  for (std::size_t d = 0;; ++d, i = (i + 1) & mask) {
    const std::uint32_t s = t[i];
    if (s == 0) return kNone;
    const std::uint32_t f = s >> kDistShift;
    const std::size_t e = f != kDistSaturated ? f - 1u : displacement(i);
    if (e < d) return kNone;  // p would have displaced this entry: p is absent
    if (e == d && match(s & kRefMask)) return s & kRefMask;
  }
}

int Lattice::center_tz(const Point& p) const {
  if (p.x <= 0 || p.y <= 0 || p.x >= extent_x_ || p.y >= extent_y_) return -1;
  const int t = std::countr_zero(static_cast<std::uint64_t>(p.x));
  if (t != std::countr_zero(static_cast<std::uint64_t>(p.y)) || t > size_.L) return -1;
  return t;
}

Index Lattice::find_center(const Point& p) const {
  const int t = center_tz(p);
  if (t < 0) return kNone;
  return probe(home_at(p, t), [&](Index r) { return !(r & kNodeBit) && centers_[r].position() == p; });
}

Index Lattice::find_node(const Point& p) const {
  const int t = center_tz(p);
  if (t < 0) return kNone;
  const Index r = probe(home_at(p, t), [&](Index q) { return (q & kNodeBit) && node_position(q & ~kNodeBit) == p; });
  return r == kNone ? kNone : r & ~kNodeBit;
}

bool Lattice::node_exists(const Point& p) const {
  const Site site = site_of(size_, p);
  switch (site.kind) {
    case Site::Outside: return false;
    case Site::GridNode: return true;
    case Site::CenterLike: return find_node(p) != kNone;
    case Site::SideMidpoint: return find_node(site.a) != kNone || find_node(site.b) != kNone;
  }
  return false;
}

Index Lattice::locate(const Point& z) const {
  const std::int64_t S = level0_side(size_);
  if (z.x <= 0 || z.y <= 0 || z.x >= size_.W * S || z.y >= size_.H * S) return kNone;
  for (int l = 0; l <= size_.L; ++l) {
    const std::int64_t s = cell_side(size_, l);
    const Index c = find_center({(z.x / s) * s + s / 2, (z.y / s) * s + s / 2});
    if (c != kNone) return c;
  }
  return kNone;
}

void Lattice::table_insert_probe(Index ref, std::size_t at) {
  std::uint32_t* t = table_.data();
  const std::size_t mask = table_.size() - 1;
  ++table_used_;
  std::size_t i = at;
  for (std::size_t d = 0;; ++d, i = (i + 1) & mask) {
    const std::uint32_t s = t[i];
    if (s == 0) {
      t[i] = encode(ref, d);
      return;
    }
    const std::uint32_t f = s >> kDistShift;
    const std::size_t e = f != kDistSaturated ? f - 1u : displacement(i);
    if (e < d) {  // the resident is closer to home: it moves on instead
      t[i] = encode(ref, d);
      ref = s & kRefMask;
      d = e;
    }
  }
}

void Lattice::table_erase_probe(Index ref, std::size_t at) {
  std::uint32_t* t = table_.data();
  const std::size_t mask = table_.size() - 1;
  std::size_t i = at;
  while (t[i] == 0 || (t[i] & kRefMask) != ref) i = (i + 1) & mask;
  for (std::size_t j = (i + 1) & mask;; i = j, j = (j + 1) & mask) {
    const std::uint32_t s = t[j];
    const std::uint32_t f = s >> kDistShift;
    if (f <= 1) break;  // empty, or at its home
    t[i] = f != kDistSaturated ? s - (1u << kDistShift) : encode(s & kRefMask, displacement(j) - 1);
  }
  t[i] = 0;
  --table_used_;
}

void Lattice::rehash(std::size_t slots) {
  std::size_t bits = 4;
  while ((std::size_t{1} << bits) < slots) ++bits;
  detail::Array<std::uint32_t> fresh(std::size_t{1} << bits, 0);  // may throw: nothing changed yet
  table_.swap(fresh);
  table_shift_ = 64 - bits;
  table_used_ = 0;
  // The keys are visited in pool order, so their homes are random slots: a
  // cache miss each on a large table. Each home is computed and its line
  // prefetched kAhead keys before the insertion; the insertions keep the
  // pool order, so the table is the same as without the look-ahead.
  constexpr std::size_t kAhead = 16;
  std::array<std::pair<Index, std::size_t>, kAhead> queue{};
  std::size_t queued = 0;
  auto insert_later = [&](Index ref, std::size_t at) {
    __builtin_prefetch(&table_[at], 1);
    std::pair<Index, std::size_t>& entry = queue[queued % kAhead];
    if (queued >= kAhead) table_insert(entry.first, entry.second);
    entry = {ref, at};
    ++queued;
  };
  for (std::size_t c = 0; c < centers_.size(); ++c)
    if (centers_[c].live()) insert_later(static_cast<Index>(c), home(centers_[c].position()));
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (nodes_[n].live())
      if (const Point p = node_position(static_cast<Index>(n)); center_level(size_, p))
        insert_later(static_cast<Index>(n) | kNodeBit, home(p));
  for (std::size_t k = queued > kAhead ? queued - kAhead : 0; k < queued; ++k)
    table_insert(queue[k % kAhead].first, queue[k % kAhead].second);
}

// ---- Pools ------------------------------------------------------------------------

void Lattice::grow(std::size_t new_centers, std::size_t new_nodes, std::size_t new_keys) {
  auto grow = [](auto& pool, std::size_t free_count, std::size_t wanted) {
    if (free_count >= wanted) return;
    const std::size_t need = pool.size() + (wanted - free_count);
    if (need > kMaxPool) throw std::length_error("bccmis::fast::Lattice: more than 2^26 - 1 vertices of one kind");
    // Grow by half: amortized O(1), at most 1.5x the size in capacity.
    if (need > pool.capacity()) pool.reserve(std::min(kMaxPool, std::max(need, pool.capacity() + pool.capacity() / 2)));
  };
  grow(centers_, free_center_count_, new_centers);
  grow(nodes_, free_node_count_, new_nodes);
  // Load factor at most 0.6.
  std::size_t slots = table_.size();
  while ((table_used_ + new_keys) * 5 > slots * 3) slots *= 2;
  if (slots != table_.size()) rehash(slots);
}

// ---- Construction ------------------------------------------------------------------

Lattice::Lattice(const LatticeSize& size) : size_(size) {
  validate_lattice_size(size);
  extent_x_ = size.W * level0_side(size);
  extent_y_ = size.H * level0_side(size);
  const std::int64_t W = size.W, H = size.H;
  if (W > static_cast<std::int64_t>(kMaxPool) / H || (W + 1) > static_cast<std::int64_t>(kMaxPool) / (H + 1))
    throw std::length_error("bccmis::fast::Lattice: lattice " + std::to_string(W) + " x " + std::to_string(H) +
                            " needs 2^26 or more vertices of one kind");
  const std::int64_t S = level0_side(size);
  const auto node_at = [&](std::int64_t i, std::int64_t j) { return static_cast<Index>(j * (W + 1) + i); };
  const auto cell_at = [&](std::int64_t i, std::int64_t j) -> Index {
    if (i < 0 || j < 0 || i >= W || j >= H) return kNone;
    return static_cast<Index>(j * W + i);
  };
  centers_.resize(static_cast<std::size_t>(W * H));
  nodes_.resize(static_cast<std::size_t>((W + 1) * (H + 1)));
  for (std::int64_t j = 0; j < H; ++j)
    for (std::int64_t i = 0; i < W; ++i) {
      Center& c = centers_[cell_at(i, j)];
      c.set_position({i * S + S / 2, j * S + S / 2});
      for (int q = 0; q < 4; ++q) {
        c.corner[q] = node_at(i + (q & 1), j + (q >> 1));
        c.mid[q] = kNone;
      }
    }
  for (std::int64_t j = 0; j <= H; ++j)
    for (std::int64_t i = 0; i <= W; ++i)
      for (int q = 0; q < 4; ++q) nodes_[node_at(i, j)].cell[q] = cell_at(i - 1 + (q & 1), j - 1 + (q >> 1));
  cell_count_ = centers_.size();
  node_count_ = nodes_.size();
  rehash(cell_count_ * 5 / 3 + 1);  // the keys: the cells (grid nodes are found from the geometry)
}

Lattice Lattice::from_graph(const Graph& g) {
  validate_lattice_size(g.size);
  Lattice lat;
  lat.size_ = g.size;
  lat.extent_x_ = g.size.W * level0_side(g.size);
  lat.extent_y_ = g.size.H * level0_side(g.size);
  if (g.C.size() > kMaxPool || g.N.size() > kMaxPool)
    throw std::length_error("bccmis::fast::Lattice::from_graph: more than 2^26 - 1 vertices of one kind");
  std::vector<Point> node_points(g.N.begin(), g.N.end());  // sorted
  auto node_index = [&](const Point& p) -> Index {
    const auto it = std::lower_bound(node_points.begin(), node_points.end(), p);
    if (it == node_points.end() || *it != p)
      throw std::invalid_argument("from_graph: neighbor (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                                  ") of a center is not a node");
    return static_cast<Index>(it - node_points.begin());
  };
  lat.nodes_.assign(node_points.size(), Node{{kNone, kNone, kNone, kNone}});
  lat.centers_.reserve(g.C.size());
  for (const Point& c : g.C) {
    const auto lv = g.level.find(c);
    if (lv == g.level.end() || center_level(g.size, c) != lv->second)
      throw std::invalid_argument("from_graph: center (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                                  ") has no level in 0..L that matches its position");
    const auto ci = static_cast<Index>(lat.centers_.size());
    Center rec{};
    rec.set_position(c);
    for (int k = 0; k < 4; ++k) rec.corner[k] = rec.mid[k] = kNone;
    const std::int64_t h = lat.half_side(lv->second);
    for (const Point& b : g.nbr(c)) {
      const std::int64_t dx = b.x - c.x, dy = b.y - c.y;
      const Index n = node_index(b);
      if ((dx == h || dx == -h) && (dy == h || dy == -h)) {
        const int q = (dx > 0 ? 1 : 0) | (dy > 0 ? 2 : 0);
        rec.corner[q] = n;
        lat.nodes_[n].cell[q ^ 3] = ci;
      } else if ((dx == 0 && (dy == h || dy == -h)) || (dy == 0 && (dx == h || dx == -h))) {
        const int s = dy < 0 ? 0 : dx > 0 ? 1 : dy > 0 ? 2 : 3;
        rec.mid[s] = n;
        for (int k = 0; k < 2; ++k) lat.nodes_[n].cell[kInwardQuad[s][k]] = ci;
      } else {
        throw std::invalid_argument("from_graph: node (" + std::to_string(b.x) + ", " + std::to_string(b.y) +
                                    ") is neither a corner nor a side midpoint of cell (" + std::to_string(c.x) + ", " +
                                    std::to_string(c.y) + ")");
      }
    }
    for (int q = 0; q < 4; ++q)
      if (rec.corner[q] == kNone)
        throw std::invalid_argument("from_graph: cell (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                                    ") lacks a corner");
    lat.centers_.push_back(rec);
  }
  for (std::size_t n = 0; n < lat.nodes_.size(); ++n) {
    const Node& nd = lat.nodes_[n];
    if (nd.cell[0] == kNone && nd.cell[1] == kNone && nd.cell[2] == kNone && nd.cell[3] == kNone)
      throw std::invalid_argument("from_graph: node (" + std::to_string(node_points[n].x) + ", " +
                                  std::to_string(node_points[n].y) + ") touches no cell");
  }
  lat.cell_count_ = lat.centers_.size();
  lat.node_count_ = lat.nodes_.size();
  lat.rehash((lat.cell_count_ + lat.cell_count_ / 3) * 5 / 3 + 1);  // cells and refined centers
  if (const auto problem = lat.audit()) throw std::invalid_argument("from_graph: " + *problem);
  return lat;
}

// ---- Refinement: §2.1, eq. (2a)-(7b) with errata E1, E4, E5, E10 ------------------

std::optional<RefineRefusal> Lattice::can_refine(const Point& c) const {
  Index ci = kNone;
  return refine_refusal(c, ci);
}

std::optional<RefineRefusal> Lattice::refine_refusal(const Point& c, Index& ci) const {
  // pre-refine-cell: c in C
  ci = find_center(c);
  if (ci == kNone) return RefineRefusal::NoSuchCell;
  const Center& cc = centers_[ci];
  // pre-refine-max-level (E10): level(c) < L
  const int l = cc.level(size_.L);
  if (l >= size_.L) return RefineRefusal::MaxLevel;
  // pre-refine-level with X of eq. (3) (E4): the cells across the sides of c.
  // A side with a junction has two cells of level l+1 across it; a side
  // without one has one cell of level l or l-1 (or the domain boundary). The
  // cell across is coarser iff one of c's two corners on that side is its
  // side midpoint, i.e. the cell fills both of that corner's outer quadrants:
  // decided from c's corner nodes, without loading the cell across.
  for (int s = 0; s < 4; ++s) {
    if (cc.mid[s] != kNone) continue;
    const int o0 = kOutwardQuad[s][0], o1 = kOutwardQuad[s][1];  // also the corners of c on side s
    const Node& a = nodes_[cc.corner[o0]];
    const Node& b = nodes_[cc.corner[o1]];
    if ((a.cell[o0] == a.cell[o1] && a.cell[o0] != kNone) || (b.cell[o0] == b.cell[o1] && b.cell[o0] != kNone))
      return RefineRefusal::CoarserNeighbor;
  }
  return std::nullopt;
}

RefineResult Lattice::refine(const Point& c) {
  RefineResult out;
  Index ci = kNone;
  out.refused = refine_refusal(c, ci);
  if (out.refused) return out;

  // Everything that can allocate happens here; the update below cannot throw.
  // 3 centers (c's slot is reused by child 0), c as a node and up to 4 new
  // junctions; the 4 children in the table.
  ensure_room(3, 5, 4);  // keeps indices; may move the table slots
  const Center old = centers_[ci];
  const int l = old.level(size_.L);
  const std::int64_t h = half_side(l);
  const std::int64_t h2 = h / 2;

  // The table line of the children, fetched now so that the miss overlaps
  // with the updates below.
  const std::size_t y_base = static_cast<std::size_t>(mix(c) >> table_shift_);
  prefetch(child_home(y_base, 0));

  // 1. The neighborhood (eq. 2a-3): K = P, old.mid = J, across = X.
  Index across[4];
  for (int s = 0; s < 4; ++s)
    across[s] = old.mid[s] == kNone ? nodes_[old.corner[kSideCorner[s]]].cell[kSideQuad[s]] : kNone;

  // 2. Subdivide (eq. 4a-4h): Y, and c becomes a node.
  Index y[4];
  y[0] = ci;
  for (int q = 1; q < 4; ++q) y[q] = alloc_center();
  const Index nc = alloc_node();

  // 3. Side midpoints: old junctions (J) or new ones (J+, eq. 5a-5b, E1).
  Index m[4];
  bool fresh[4];
  for (int s = 0; s < 4; ++s) {
    fresh[s] = old.mid[s] == kNone;
    m[s] = fresh[s] ? alloc_node() : old.mid[s];
  }

  // Children: N(y_i) = {p_i, c} (4f) plus the two midpoints beside them (6d, 6e, 7b).
  for (int q = 0; q < 4; ++q) {
    Center& yc = centers_[y[q]];
    yc.set_position(offset(c, qx(q) * h2, qy(q) * h2));
    yc.corner[q] = old.corner[q];
    yc.corner[q ^ 3] = nc;
    yc.corner[q ^ 1] = m[hside(q)];
    yc.corner[q ^ 2] = m[vside(q)];
    for (int s = 0; s < 4; ++s) yc.mid[s] = kNone;
  }
  // N(c) = Y (4c).
  for (int q = 0; q < 4; ++q) nodes_[nc].cell[q] = y[q];
  // N(p_i) = N(p_i) ∪ {y_i} \ {c} (4e).
  for (int q = 0; q < 4; ++q) nodes_[old.corner[q]].cell[q ^ 3] = y[q];
  for (int s = 0; s < 4; ++s) {
    Node& mn = nodes_[m[s]];
    // Old junction: N(j) \ {c} (4d) ∪ {y_i} (7a). New junction: {x_k, y_i, y_j} (6c).
    for (int k = 0; k < 2; ++k) mn.cell[kInwardQuad[s][k]] = y[kInwardChild[s][k]];
    if (!fresh[s]) continue;
    mn.cell[kOutwardQuad[s][0]] = mn.cell[kOutwardQuad[s][1]] = across[s];
    // N(x_k) = N(x_k) ∪ {j+_k} (6b); x_k is empty on the domain boundary (E1).
    if (across[s] != kNone) centers_[across[s]].mid[s ^ 2] = m[s];
  }

  // Position table: c is now a node; the children and new junctions are added.
  replace_ref(slot_of(ci, home(c)), nc | kNodeBit);
  for (int q = 0; q < 4; ++q) table_insert(y[q], child_home(y_base, static_cast<std::size_t>(q)));

  cell_count_ += 3;
  node_count_ += 1;
  for (const int q : kQuadSorted) out.Y.push_back(offset(c, qx(q) * h2, qy(q) * h2));
  for (const int s : kSideSorted)
    if (fresh[s]) {
      out.J_plus.push_back(offset(c, kSideDx[s] * h, kSideDy[s] * h));
      ++node_count_;
    }
  return out;
}

// ---- Coarsening: §2.2, eq. (8a)-(12b) with errata E2, E3, E7 ----------------------

std::optional<CoarsenRefusal> Lattice::can_coarsen(const Point& n) const {
  Index ni = kNone;
  int coarse_level = 0;
  return coarsen_refusal(n, ni, coarse_level);
}

std::optional<CoarsenRefusal> Lattice::coarsen_refusal(const Point& n, Index& ni, int& coarse_level) const {
  // pre-coarsen-node: n in N
  ni = find_node(n);  // only refined centers are in the position table
  if (ni == kNone) return node_exists(n) ? CoarsenRefusal::NotARefinedCenter : CoarsenRefusal::NoSuchNode;
  // pre-coarsen-refined-center (E3, E7): the level from n's position. n is in
  // the table, so it sits where a cell center can be (bccmis::refined_center_level).
  const int l = size_.L - center_tz(n);  // n is in the table: center_tz(n) >= 0
  if (l >= size_.L) return CoarsenRefusal::NotARefinedCenter;
  coarse_level = l;
  // pre-coarsen-not-junction: |N(n)| = 4
  const Node& nd = nodes_[ni];
  for (int q = 0; q < 4; ++q) {
    if (nd.cell[q] == kNone) return CoarsenRefusal::NotARefinedCenter;
    for (int r = 0; r < q; ++r)
      if (nd.cell[r] == nd.cell[q]) return CoarsenRefusal::NotARefinedCenter;
  }
  // pre-coarsen-children-leaves (E3): every cell around n has level l+1.
  for (int q = 0; q < 4; ++q)
    if (level(nd.cell[q]) != l + 1) return CoarsenRefusal::ChildrenRefined;
  // pre-coarsen-balance (E3): no child has a junction (all four mid slots empty).
  for (int q = 0; q < 4; ++q) {
    const Center& y = centers_[nd.cell[q]];
    for (int s = 0; s < 4; ++s)
      if (y.mid[s] != kNone) return CoarsenRefusal::FinerNeighbor;
  }
  return std::nullopt;
}

CoarsenResult Lattice::coarsen(const Point& n) {
  CoarsenResult out;
  Index ni = kNone;
  int l = 0;
  out.refused = coarsen_refusal(n, ni, l);
  if (out.refused) return out;

  // Coarsening frees slots and table entries and never allocates.
  const std::int64_t h = half_side(l);
  const std::int64_t h2 = h / 2;
  const std::size_t y_base = static_cast<std::size_t>(mix(n) >> table_shift_);
  prefetch(child_home(y_base, 0));

  // 1. Y = N(n) (8a); B = the corners K and side midpoints m of the children (8b).
  Index y[4], K[4], m[4], outside[4];
  bool drop[4];
  for (int q = 0; q < 4; ++q) y[q] = nodes_[ni].cell[q];
  for (int q = 0; q < 4; ++q) K[q] = centers_[y[q]].corner[q];
  for (int s = 0; s < 4; ++s) {
    m[s] = centers_[y[kSideCorner[s]]].corner[kSideQuad[s]];
    // J- (10a, E2): a side midpoint left with at most one cell once Y is gone,
    // i.e. with one cell (or the domain boundary) in both outer quadrants.
    const Node& mn = nodes_[m[s]];
    outside[s] = mn.cell[kOutwardQuad[s][0]];
    drop[s] = outside[s] == mn.cell[kOutwardQuad[s][1]];
  }

  // Position table first, while every key can still be computed: the children
  // and J- leave; n becomes the center that reuses child 0's slot.
  for (int q = 0; q < 4; ++q) table_erase(y[q], child_home(y_base, static_cast<std::size_t>(q)));
  const Index nc = y[0];
  replace_ref(slot_of(ni | kNodeBit, home(n)), nc);

  // 2. The children go (9a-9f) and n becomes a center of level l (9d, 9e, E7).
  Center& cc = centers_[nc];
  cc.set_position(n);
  // 4. N(n) = B (12a) and N(b_i) ∪ {n} (12b), for the corners ...
  for (int q = 0; q < 4; ++q) {
    cc.corner[q] = K[q];
    nodes_[K[q]].cell[q ^ 3] = nc;
  }
  // ... and for the side midpoints that stay; 3. J- goes (10b-11d).
  for (int s = 0; s < 4; ++s) {
    if (drop[s]) {
      cc.mid[s] = kNone;
      // N(x_i) = N(x_i) \ {j-_i} (11b); x_i is empty on the domain boundary (E2).
      if (outside[s] != kNone) centers_[outside[s]].mid[s ^ 2] = kNone;
      free_node(m[s]);
    } else {
      cc.mid[s] = m[s];
      for (int k = 0; k < 2; ++k) nodes_[m[s]].cell[kInwardQuad[s][k]] = nc;
    }
  }
  for (int q = 1; q < 4; ++q) free_center(y[q]);
  free_node(ni);

  cell_count_ -= 3;
  node_count_ -= 1;
  for (const int q : kQuadSorted) out.Y.push_back(offset(n, qx(q) * h2, qy(q) * h2));
  for (const int s : kSideSorted)
    if (drop[s]) {
      out.J_minus.push_back(offset(n, kSideDx[s] * h, kSideDy[s] * h));
      --node_count_;
    }
  return out;
}

// ---- Batches: the same operations, with look-ahead prefetching --------------------

void Lattice::prefetch_slot(const Point& p) const {
  const int t = center_tz(p);
  if (t >= 0) prefetch(home_at(p, t));
}

void Lattice::prefetch_record(const Point& p, bool node) const {
  if (node) {
    if (const Index n = find_node(p); n != kNone) __builtin_prefetch(&nodes_[n]);
  } else if (const Index c = find_center(p); c != kNone) {
    __builtin_prefetch(&centers_[c]);
  }
}

namespace {
constexpr std::size_t kSlotAhead = 16;   // operations between the table prefetch and the operation
constexpr std::size_t kRecordAhead = 6;  // ... and between the record prefetch and the operation

// op(p) for each p in order, the table slot of the point kSlotAhead
// operations ahead and its record kRecordAhead ahead prefetched; the count
// of operations applied.
template <class PrefetchSlot, class PrefetchRecord, class Op>
std::size_t apply_each(std::span<const Point> points, PrefetchSlot prefetch_slot, PrefetchRecord prefetch_record,
                       Op op) {
  std::size_t applied = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i + kSlotAhead < points.size()) prefetch_slot(points[i + kSlotAhead]);
    if (i + kRecordAhead < points.size()) prefetch_record(points[i + kRecordAhead]);
    applied += op(points[i]).applied();
  }
  return applied;
}
}  // namespace

std::size_t Lattice::refine_each(std::span<const Point> cells) {
  return apply_each(
      cells, [&](const Point& p) { prefetch_slot(p); }, [&](const Point& p) { prefetch_record(p, false); },
      [&](const Point& c) { return refine(c); });
}

std::size_t Lattice::coarsen_each(std::span<const Point> nodes) {
  return apply_each(
      nodes, [&](const Point& p) { prefetch_slot(p); }, [&](const Point& p) { prefetch_record(p, true); },
      [&](const Point& n) { return coarsen(n); });
}

// ---- Queries -------------------------------------------------------------------------

bool Lattice::is_center(const Point& v) const { return find_center(v) != kNone; }

bool Lattice::is_node(const Point& v) const { return node_exists(v); }

int Lattice::level_of(const Point& c) const {
  const Index r = find_center(c);
  if (r == kNone) throw std::out_of_range("bccmis::fast::Lattice::level_of: not a center");
  return level(r);
}

namespace {

// 𝒩(c) of a center, in sorted (x, y) order: SW, W, NW, S, N, SE, E, NE.
template <class Out>
void center_neighbors(const Lattice::Center& cc, std::int64_t h, Out& out) {
  const Point c = cc.position();
  out.push_back(offset(c, -h, -h));
  if (cc.mid[3] != kNone) out.push_back(offset(c, -h, 0));
  out.push_back(offset(c, -h, h));
  if (cc.mid[0] != kNone) out.push_back(offset(c, 0, -h));
  if (cc.mid[2] != kNone) out.push_back(offset(c, 0, h));
  out.push_back(offset(c, h, -h));
  if (cc.mid[1] != kNone) out.push_back(offset(c, h, 0));
  out.push_back(offset(c, h, h));
}

// 𝒩(n) of a node, sorted.
SmallPoints<4> node_neighbors(const Lattice& g, Index n) {
  const Lattice::Node& nd = g.node_pool()[n];
  SmallPoints<4> out;
  for (int q = 0; q < 4; ++q) {
    const Index x = nd.cell[q];
    if (x == kNone) continue;
    bool seen = false;
    for (int r = 0; r < q; ++r) seen = seen || nd.cell[r] == x;
    if (!seen) out.push_back(g.center_pool()[x].position());
  }
  out.sort();
  return out;
}

}  // namespace

SmallPoints<8> Lattice::nbr(const Point& v) const {
  SmallPoints<8> out;
  if (const Index c = find_center(v); c != kNone) {
    center_neighbors(centers_[c], half_side(level(c)), out);
    return out;
  }
  if (const Index n = find_node(v); n != kNone) {
    for (const Point& p : node_neighbors(*this, n)) out.push_back(p);
    return out;
  }
  if (!node_exists(v)) return out;
  // A grid node or a junction is not in the position table: its neighbors
  // are the distinct leaves in the four quadrants around it.
  Index seen[4];
  std::size_t k = 0;
  for (int q = 0; q < 4; ++q) {
    const Index c = locate(offset(v, qx(q), qy(q)));
    if (c == kNone || std::find(seen, seen + k, c) != seen + k) continue;
    seen[k++] = c;
    out.push_back(centers_[c].position());
  }
  out.sort();
  return out;
}

std::vector<Point> Lattice::cells() const {
  std::vector<Point> out;
  out.reserve(cell_count_);
  for (const Center& c : centers_)
    if (c.live()) out.push_back(c.position());
  std::sort(out.begin(), out.end(), point_less);
  return out;
}

std::vector<Point> Lattice::nodes() const {
  std::vector<Point> out;
  out.reserve(node_count_);
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (nodes_[n].live()) out.push_back(node_position(static_cast<Index>(n)));
  std::sort(out.begin(), out.end(), point_less);
  return out;
}

// ---- Conversions and printing ----------------------------------------------------------

Graph Lattice::to_graph() const {
  Graph g;
  g.size = size_;
  std::vector<std::pair<Point, Index>> cs, ns;
  cs.reserve(cell_count_);
  ns.reserve(node_count_);
  for (std::size_t c = 0; c < centers_.size(); ++c)
    if (centers_[c].live()) cs.emplace_back(centers_[c].position(), static_cast<Index>(c));
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    if (nodes_[n].live()) ns.emplace_back(node_position(static_cast<Index>(n)), static_cast<Index>(n));
  const auto by_point = [](const auto& a, const auto& b) { return point_less(a.first, b.first); };
  std::sort(cs.begin(), cs.end(), by_point);
  std::sort(ns.begin(), ns.end(), by_point);
  for (const auto& [p, c] : cs) {
    g.C.insert(g.C.end(), p);
    g.level.emplace_hint(g.level.end(), p, level(c));
    SmallPoints<8> nb;
    center_neighbors(centers_[c], half_side(level(c)), nb);
    g.neighbors.emplace_hint(g.neighbors.end(), p, nb.to_set());
  }
  for (const auto& [p, n] : ns) {
    g.N.insert(g.N.end(), p);
    g.neighbors.emplace(p, node_neighbors(*this, n).to_set());
  }
  return g;
}

namespace {

// Sorts keys by their bits [low, low + bits), which are distinct between any
// two keys: a least-significant-digit radix sort, 11 bits a pass (the
// counts stay in L1), through one scratch array of the same size.
void sort_by_high_bits(std::vector<std::uint64_t>& keys, int low, int bits) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  std::vector<std::uint64_t> scratch(keys.size());
  std::vector<std::size_t> start(kBuckets);
  for (int shift = low; shift < low + bits; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), std::size_t{0});
    for (const std::uint64_t k : keys) ++start[(k >> shift) & (kBuckets - 1)];
    std::size_t sum = 0;
    for (std::size_t& c : start) sum += std::exchange(c, sum);
    for (const std::uint64_t k : keys) scratch[start[(k >> shift) & (kBuckets - 1)]++] = k;
    keys.swap(scratch);
  }
}

// Calls f(position, payload) for every live record i of a pool, in canonical
// (x, y) order (spec/formats.md), with payload(i) < 2^payload_bits.
// Positions lie in the closed domain, so both coordinates are below
// 2^coord_bits. When (x, y, payload) fit one 64-bit key, the sort moves 8
// bytes a record; otherwise (position, payload) pairs.
template <class Pool, class Position, class Payload, class F>
void for_each_sorted(const Pool& pool, std::size_t live, int coord_bits, int payload_bits, const Position& position,
                     const Payload& payload, const F& f) {
  if (2 * coord_bits + payload_bits <= 64) {
    const int x_shift = coord_bits + payload_bits;
    const std::uint64_t coord_mask = (std::uint64_t{1} << coord_bits) - 1;
    const std::uint64_t payload_mask = (std::uint64_t{1} << payload_bits) - 1;
    std::vector<std::uint64_t> keys;
    keys.reserve(live);
    for (std::size_t i = 0; i < pool.size(); ++i)
      if (pool[i].live()) {
        const Point p = position(static_cast<Index>(i));
        keys.push_back(static_cast<std::uint64_t>(p.x) << x_shift | static_cast<std::uint64_t>(p.y) << payload_bits |
                       payload(static_cast<Index>(i)));
      }
    sort_by_high_bits(keys, payload_bits, 2 * coord_bits);
    for (const std::uint64_t k : keys)
      f(Point{static_cast<std::int64_t>(k >> x_shift), static_cast<std::int64_t>((k >> payload_bits) & coord_mask)},
        static_cast<Index>(k & payload_mask));
    return;
  }
  std::vector<std::pair<Point, Index>> records;
  records.reserve(live);
  for (std::size_t i = 0; i < pool.size(); ++i)
    if (pool[i].live()) records.emplace_back(position(static_cast<Index>(i)), payload(static_cast<Index>(i)));
  std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) { return point_less(a.first, b.first); });
  for (const auto& [p, i] : records) f(p, i);
}

}  // namespace

namespace {

// bit_width of the largest coordinate of the closed domain.
int coordinate_bits(const LatticeSize& size) {
  const std::int64_t S = level0_side(size);
  return std::bit_width(static_cast<std::uint64_t>(std::max(size.W * S, size.H * S)));
}

template <class Records, class Position>
std::vector<Index> sorted_slots(const Records& pool, std::size_t live, const LatticeSize& size,
                                const Position& position) {
  std::vector<Index> out;
  out.reserve(live);
  for_each_sorted(
      pool, live, coordinate_bits(size), std::bit_width(pool.size()), position, [](Index i) { return i; },
      [&](const Point&, Index i) { out.push_back(i); });
  return out;
}

}  // namespace

std::vector<Lattice::Index> Lattice::sorted_center_slots() const {
  return sorted_slots(centers_, cell_count_, size_, [&](Index c) { return centers_[c].position(); });
}

std::vector<Lattice::Index> Lattice::sorted_node_slots() const {
  return sorted_slots(nodes_, node_count_, size_, [&](Index n) { return node_position(n); });
}

void write_canonical_state(std::ostream& out, const Lattice& g) {
  using Decimal = TextWriter::Decimal;
  const auto& centers = g.center_pool();
  const auto& nodes = g.node_pool();
  const LatticeSize& size = g.size();
  const int coord_bits = coordinate_bits(size);
  TextWriter w(out);
  w.put("bccmis-state 1\nlattice ");
  w.put_int(size.W);
  w.put(' ');
  w.put_int(size.H);
  w.put(' ');
  w.put_int(size.L);
  w.put('\n');
  // A C line holds at most 9 points and a level, an N line 5 points; every
  // number is copied as sizeof(Decimal::text) bytes.
  constexpr std::size_t kLine = 16 + 19 * sizeof(Decimal::text);
  // A cell's line follows from its position and which sides have a junction
  // (bit s for side s), so the sort carries those 4 bits and the lines are
  // written without going back to the pool. 𝒩(c) in sorted order: SW, W, NW,
  // S, N, SE, E, NE (W, S, N, E when there is a junction).
  for_each_sorted(
      centers, g.cell_count(), coord_bits, 4, [&](Index c) { return centers[c].position(); },
      [&](Index c) {
        Index mids = 0;
        for (int s = 0; s < 4; ++s) mids |= centers[c].mid[s] != Lattice::kNone ? Index{1} << s : 0;
        return mids;
      },
      [&](const Point& p, Index mids) {
        const int t = std::countr_zero(static_cast<std::uint64_t>(p.x));  // h = 2^t, level L - t
        const std::int64_t h = std::int64_t{1} << t;
        const Decimal x0(p.x - h), x1(p.x), x2(p.x + h), y0(p.y - h), y1(p.y), y2(p.y + h);
        char* q = w.room(kLine);
        auto point = [&](const Decimal& x, const Decimal& y) {
          *q++ = ' ';
          q = x.copy_to(q);
          *q++ = ' ';
          q = y.copy_to(q);
        };
        *q++ = 'C';
        point(x1, y1);
        *q++ = ' ';
        q = TextWriter::write_int(q, size.L - t);
        *q++ = ' ';
        *q++ = ':';
        point(x0, y0);
        if (mids & 8) point(x0, y1);
        point(x0, y2);
        if (mids & 1) point(x1, y0);
        if (mids & 4) point(x1, y2);
        point(x2, y0);
        if (mids & 2) point(x2, y1);
        point(x2, y2);
        *q++ = '\n';
        w.commit(q);
      });
  for_each_sorted(
      nodes, g.node_count(), coord_bits, std::bit_width(nodes.size()), [&](Index n) { return g.node_position(n); },
      [](Index n) { return n; },
      [&](const Point& p, Index n) {
        char* q = w.room(kLine);
        *q++ = 'N';
        q = TextWriter::write_point(q, p.x, p.y);
        *q++ = ' ';
        *q++ = ':';
        for (const Point& b : node_neighbors(g, n)) q = TextWriter::write_point(q, b.x, b.y);
        *q++ = '\n';
        w.commit(q);
      });
  w.put("end ");
  w.put_int(static_cast<std::int64_t>(g.cell_count()));
  w.put(' ');
  w.put_int(static_cast<std::int64_t>(g.node_count()));
  w.put('\n');
  w.flush();
}

std::string canonical_state(const Lattice& g) { return canonical_text(g); }

// ---- Memory and audit -------------------------------------------------------------------

void Lattice::reserve(std::size_t cells) {
  cells = std::min(kMaxPool, cells);
  const std::size_t nodes = cells + cells / 4 + 16;
  centers_.reserve(cells);
  nodes_.reserve(std::min(kMaxPool, nodes));
  std::size_t slots = table_.size();
  while ((cells + cells / 3) * 5 > slots * 3) slots *= 2;  // keys: cells and refined centers
  if (slots != table_.size()) rehash(slots);
}

void reserve(Lattice& g, std::size_t cells) {
  try {
    g.reserve(std::min(cells, kMaxReserveHint));
  } catch (const std::bad_alloc&) {
    // Lattice::reserve changes capacities only: the lattice is as it was,
    // and grows when it must.
  }
}

void Lattice::shrink_to_fit() {
  centers_.shrink_to_fit();
  nodes_.shrink_to_fit();
}

std::size_t Lattice::memory_bytes() const {
  return centers_.capacity() * sizeof(Center) + nodes_.capacity() * sizeof(Node) +
         table_.capacity() * sizeof(std::uint32_t);
}

std::optional<std::string> Lattice::audit() const {
  auto at = [](const Point& p) {
    std::string out = "(";  // appended, not `"(" + ...`: GCC 12 -O3 warns falsely (-Wrestrict, PR 105329)
    out += std::to_string(p.x);
    out += ", ";
    out += std::to_string(p.y);
    out += ")";
    return out;
  };
  auto live_node = [&](Index n) { return n < nodes_.size() && nodes_[n].live(); };
  auto live_center = [&](Index c) { return c < centers_.size() && centers_[c].live(); };
  std::size_t cells = 0, nodes = 0, keyed_nodes = 0;
  for (std::size_t ci = 0; ci < centers_.size(); ++ci) {
    const Center& c = centers_[ci];
    if (!c.live()) continue;
    ++cells;
    const Point p = c.position();
    if (center_level(size_, p) != level(static_cast<Index>(ci)))
      return "cell " + at(p) + " is not at a cell center of its level";
    for (int q = 0; q < 4; ++q) {
      if (!live_node(c.corner[q]) || nodes_[c.corner[q]].cell[q ^ 3] != ci)
        return "cell " + at(p) + ": corner " + std::to_string(q) + " does not list the cell back";
      if (c.mid[q] != kNone)
        for (int k = 0; k < 2; ++k)
          if (!live_node(c.mid[q]) || nodes_[c.mid[q]].cell[kInwardQuad[q][k]] != ci)
            return "cell " + at(p) + ": junction on side " + std::to_string(q) + " does not list the cell back";
    }
    if (find_center(p) != ci) return "cell " + at(p) + " is not in the position table";
  }
  for (std::size_t ni = 0; ni < nodes_.size(); ++ni) {
    const Node& n = nodes_[ni];
    if (!n.live()) continue;
    ++nodes;
    bool any = false;
    for (int q = 0; q < 4; ++q) {
      const Index x = n.cell[q];
      if (x == kNone) continue;
      any = true;
      if (!live_center(x)) return "node " + std::to_string(ni) + " lists a free cell slot";
      const Center& c = centers_[x];
      bool listed = false;
      for (int k = 0; k < 4; ++k) listed = listed || c.corner[k] == ni || c.mid[k] == ni;
      if (!listed) return "node " + std::to_string(ni) + ": cell " + at(c.position()) + " does not list it";
    }
    if (!any) return "node " + std::to_string(ni) + " touches no cell";
    const Point p = node_position(static_cast<Index>(ni));
    if (center_level(size_, p)) {
      ++keyed_nodes;
      if (find_node(p) != ni) return "refined center " + at(p) + " is not in the position table";
    } else if (!node_exists(p)) {
      return "node " + at(p) + " is not found from its position";
    }
  }
  if (cells != cell_count_ || nodes != node_count_) return std::string("vertex counts are off");
  if (table_used_ != cells + keyed_nodes) return std::string("the position table holds stale entries");
  if (free_center_count_ + cells != centers_.size() || free_node_count_ + nodes != nodes_.size())
    return std::string("free-list counts are off");
  return std::nullopt;
}

}  // namespace bccmis::fast
