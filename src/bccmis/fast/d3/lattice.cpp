// bccmis::fast: refine (spec/lattice3d.md §4) and coarsen (§5) in 3D as fixed
// slot reads and writes (the layout of §9).
//
// Directions (spec/lattice3d.md §9.1). An octant o has bit a set when it lies on the + side of
// axis a (a = 0, 1, 2 for x, y, z); s_o is its sign vector. A direction d is
// in {-1, 0, 1}^3 \ {0}; its nonzero axes form the mask nz(d). A center u of
// half side h keeps in slot slot_of(d) the node at u + d h, if any.
//
// The one rule that links the two pools (§9.1): the node b = u + d h of cell
// u has u in every octant t with t_a = -d_a on the axes of nz(d) (any sign on
// the others): 1 octant for a corner, 2 for an edge midpoint, 4 for a face
// center.
//
// Refinement of c (level l, half side h) in the 3 x 3 x 3 grid of points
// c + g h, g in {-1, 0, 1}^3: G[g] is the node there (c itself once refined,
// the corners P, the old junctions J and the new nodes J+). Child y_o is
// centred at c + s_o h / 2; its corner in direction e is the grid point g with
// g_a = s_o,a where e_a = s_o,a and 0 elsewhere; the node at grid point g
// has, in each of its octants t inside c, the child y_(t XOR nz(g)).
#include "bccmis/fast/d3/lattice.h"

#include <algorithm>
#include <array>
#include <bit>
#include <map>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "bccmis/d3/detail/position_order.h"
#include "bccmis/text_writer.h"

namespace bccmis::d3::fast {

namespace {

using Index = Lattice::Index;

// The position's hash: the three coordinates combined, then the splitmix64
// finalizer, so that the top bits (the home slot) depend on every bit of
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

// A direction d in {-1, 0, 1}^3 \ {0} and its slot (§9.1): the 27 points of
// the 3 x 3 x 3 grid are numbered (dx+1) + 3(dy+1) + 9(dz+1); the slot skips
// the middle one (13).
constexpr int grid_index(int dx, int dy, int dz) { return (dx + 1) + 3 * (dy + 1) + 9 * (dz + 1); }
constexpr int slot_of_grid(int g) { return g < 13 ? g : g - 1; }
constexpr int slot_of(int dx, int dy, int dz) { return slot_of_grid(grid_index(dx, dy, dz)); }
constexpr int sign(int o, int a) { return ((o >> a) & 1) ? 1 : -1; }
// The slot of corner o (direction s_o).
constexpr int corner_slot(int o) { return slot_of(sign(o, 0), sign(o, 1), sign(o, 2)); }

// Everything refine and coarsen read or write for the node in slot k of a
// cell c, worked out once from the direction d of slot k (§9.5, §9.6).
struct SlotRule {
  int d[3] = {0, 0, 0};
  int nz = 0;      // the axes where d is nonzero (7: a corner)
  int inside = 0;  // the bits on nz of the octants facing c: t_a = -d_a
  // The corner of c with d's signs on nz and - elsewhere, and at it the
  // octant across the face or edge next to c (d's signs on nz, + elsewhere).
  int corner = 0;
  int across = 0;
  // The octants of the node inside c, and the child of c in each (t ^ nz).
  int inside_count = 0;
  int inside_octant[4] = {};
  int inside_child[4] = {};
  // The octants of the node outside c (edges and faces only): the octant of
  // the same cell at `corner`, the slot toward the node of a cell there, and
  // the octant beside it with + on the axes off nz (the same cell iff the
  // node is inside that cell's edge or face).
  int outside_count = 0;
  int outside_octant[6] = {};
  int outside_at_corner[6] = {};
  int outside_toward[6] = {};
  int outside_beside[6] = {};
  // Coarsen: the node at n + d h is corner `child_corner` of child `child`.
  int child = 0;
  int child_corner = 0;
};

constexpr std::array<SlotRule, 26> make_rules() {
  std::array<SlotRule, 26> rules{};
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        SlotRule& r = rules[static_cast<std::size_t>(slot_of(dx, dy, dz))];
        const int d[3] = {dx, dy, dz};
        for (int a = 0; a < 3; ++a) {
          r.d[a] = d[a];
          if (d[a] != 0) r.nz |= 1 << a;
          if (d[a] < 0) r.inside |= 1 << a;
        }
        const int outward = r.nz & ~r.inside, off = 7 & ~r.nz;
        r.corner = corner_slot(outward);
        r.across = outward | off;
        r.child = outward;
        r.child_corner = corner_slot(outward | off);
        for (int t = 0; t < 8; ++t) {
          if ((t & r.nz) == r.inside) {
            r.inside_octant[r.inside_count] = t;
            r.inside_child[r.inside_count++] = t ^ r.nz;
          } else if (r.nz != 7) {
            int toward[3] = {0, 0, 0};
            for (int a = 0; a < 3; ++a) toward[a] = ((r.nz >> a) & 1) ? -sign(t, a) : 0;
            r.outside_octant[r.outside_count] = t;
            r.outside_at_corner[r.outside_count] = (t & r.nz) | off;
            r.outside_toward[r.outside_count] = slot_of(toward[0], toward[1], toward[2]);
            r.outside_beside[r.outside_count++] = t | off;
          }
        }
      }
  return rules;
}
constexpr std::array<SlotRule, 26> kRule = make_rules();
const SlotRule& rule(int k) { return kRule[static_cast<std::size_t>(k)]; }

// The slots in sorted order of the positions they name (x, then y, then z).
constexpr std::array<int, 26> make_sorted_slots() {
  std::array<int, 26> out{};
  std::size_t k = 0;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz)
        if (dx != 0 || dy != 0 || dz != 0) out[k++] = slot_of(dx, dy, dz);
  return out;
}
constexpr std::array<int, 26> kSortedSlots = make_sorted_slots();
// The 18 edge and face slots in slot order (the order of a record's slots).
constexpr std::array<int, 18> make_midpoint_slots() {
  std::array<int, 18> out{};
  std::size_t k = 0;
  for (int s = 0; s < 26; ++s)
    if (kRule[static_cast<std::size_t>(s)].nz != 7) out[k++] = s;
  return out;
}
constexpr std::array<int, 18> kMidpointSlots = make_midpoint_slots();
// The octants in sorted order of the children's positions.
constexpr int kSortedOctants[8] = {0, 4, 2, 6, 1, 5, 3, 7};
// Refine: corner e of child o is the node at grid point g of its parent
// (g_a = s_o,a where e agrees with s_o, 0 elsewhere): its slot, or -1 for
// the parent's center (g = 0).
constexpr std::array<std::array<int, 8>, 8> make_child_corners() {
  std::array<std::array<int, 8>, 8> out{};
  for (int o = 0; o < 8; ++o)
    for (int e = 0; e < 8; ++e) {
      const int agree = ~(o ^ e) & 7;
      int g[3] = {0, 0, 0};
      for (int a = 0; a < 3; ++a) g[a] = ((agree >> a) & 1) ? sign(o, a) : 0;
      out[static_cast<std::size_t>(o)][static_cast<std::size_t>(e)] = agree == 0 ? -1 : slot_of(g[0], g[1], g[2]);
    }
  return out;
}
// The pass of refine writes each child's corners from the nodes around it:
// the node in slot k lists, in its octant t inside the parent, the child
// y_(t XOR nz), whose corner toward the node is t XOR 7. The same as
// child o's corner e read from the grid (above), for every child and corner.
constexpr bool corners_from_nodes_agree() {
  constexpr auto child_corner = make_child_corners();
  int written = 0;
  for (int k = 0; k < 26; ++k)
    for (int j = 0; j < kRule[static_cast<std::size_t>(k)].inside_count; ++j) {
      const SlotRule& r = kRule[static_cast<std::size_t>(k)];
      const int t = r.inside_octant[j];
      if (child_corner[static_cast<std::size_t>(t ^ r.nz)][static_cast<std::size_t>(t ^ 7)] != k) return false;
      ++written;
    }
  for (int o = 0; o < 8; ++o)  // the parent's own node: corner o ^ 7 of child o
    if (child_corner[static_cast<std::size_t>(o)][static_cast<std::size_t>(o ^ 7)] != -1) return false;
  return written + 8 == 64;  // each of the 8 x 8 corners once
}
static_assert(corners_from_nodes_agree());
// §9.5: refine writes every slot of a new node on an edge or face of c, its
// octants inside c and outside it, each once, so its record needs no filling.
constexpr bool new_nodes_written_whole() {
  for (const SlotRule& r : kRule) {
    if (r.nz == 7) continue;
    int written = 0;
    for (int j = 0; j < r.inside_count; ++j) written |= 1 << r.inside_octant[j];
    for (int j = 0; j < r.outside_count; ++j) written |= 1 << r.outside_octant[j];
    if (written != 0xFF || r.inside_count + r.outside_count != 8) return false;
  }
  return true;
}
static_assert(new_nodes_written_whole());

// f(std::integral_constant<int, I>{}) for I = 0 .. N-1, unrolled: a pass over
// the slots whose rule fields and indices are constants in every step.
template <class F, int... I>
void unroll(F&& f, std::integer_sequence<int, I...>) {
  (f(std::integral_constant<int, I>{}), ...);
}
template <int N, class F>
void unroll(F&& f) {
  unroll(f, std::make_integer_sequence<int, N>{});
}
// Every slot of a record kNone, as N stores (std::fill of 0xFF bytes
// becomes a call to memset).
template <int N>
void fill_none(Index (&slots)[N]) {
  unroll<N>([&](auto i) { slots[i] = Lattice::kNone; });
}

std::int64_t coord(const Point& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
Point offset(const Point& p, const int d[3], std::int64_t h) {
  return {p.x + d[0] * h, p.y + d[1] * h, p.z + d[2] * h};
}
bool is_corner(int slot) { return rule(slot).nz == 7; }

}  // namespace

// ---- Records and geometry (§9.2) --------------------------------------------------

inline Point Lattice::node_position(Index n) const {
  const Node& r = nodes_[n];
  int t = 0;
  while (r.cell[t] == kNone) ++t;  // a live node has a cell in some octant
  const Index x = r.cell[t];
  const Point& p = centers_[x].p;
  const std::int64_t h = half_side(level(x));
  // x covers octant t; where it also covers the octant across axis a, the
  // node lies on x's middle plane of that axis, otherwise on its side -t_a.
  std::int64_t q[3];
  for (int a = 0; a < 3; ++a) q[a] = r.cell[t ^ (1 << a)] == x ? coord(p, a) : coord(p, a) - sign(t, a) * h;
  return {q[0], q[1], q[2]};
}

inline int Lattice::center_tz(const Point& p) const {
  if (p.x <= 0 || p.y <= 0 || p.z <= 0 || p.x >= extent_[0] || p.y >= extent_[1] || p.z >= extent_[2]) return -1;
  const int t = std::countr_zero(static_cast<std::uint64_t>(p.x));
  if (t != std::countr_zero(static_cast<std::uint64_t>(p.y)) ||
      t != std::countr_zero(static_cast<std::uint64_t>(p.z)) || t > size_.L)
    return -1;
  return t;
}

// ---- Position table (§9.4) -------------------------------------------------------------

inline std::uint64_t Lattice::key_hash(const Point& p) const {
  return key_hash_at(p, std::countr_zero(static_cast<std::uint64_t>(p.x)));
}

inline std::uint64_t Lattice::key_hash_at(const Point& p, int t) const {
  // p: a center position, every coordinate an odd multiple of 2^t.
  if (t >= size_.L) return mix(p);                    // level 0: no parent
  const std::int64_t s = std::int64_t{1} << (t + 2);  // the parent's side
  const Point parent{(p.x & ~(s - 1)) | (s / 2), (p.y & ~(s - 1)) | (s / 2), (p.z & ~(s - 1)) | (s / 2)};
  const std::size_t o = ((p.x & (s / 2)) ? 1u : 0u) | ((p.y & (s / 2)) ? 2u : 0u) | ((p.z & (s / 2)) ? 4u : 0u);
  return PositionTable::family_hash(mix(parent), o);
}

Index Lattice::find_ref(const Point& p, bool node) const {
  std::uint64_t hash;
  return find_ref(p, node, hash);
}

Index Lattice::find_ref(const Point& p, bool node, std::uint64_t& hash) const {
  const int t = center_tz(p);
  if (t < 0) return kNone;
  hash = key_hash_at(p, t);
  if (node) {
    const Index r = table_.find(hash, [&](Index q) { return (q & kNodeBit) && node_position(q & ~kNodeBit) == p; });
    return r == kNone ? kNone : r & ~kNodeBit;
  }
  return table_.find(hash, [&](Index q) { return !(q & kNodeBit) && centers_[q].p == p; });
}

Index Lattice::find_refined(const Point& p) const { return find_ref(p, true); }

// ---- Finding nodes from the geometry (§9.3) -----------------------------------------------

Index Lattice::locate(const Point& p, int o) const {
  const Point z{p.x + sign(o, 0), p.y + sign(o, 1), p.z + sign(o, 2)};
  if (center_tz(z) < 0) return kNone;  // outside the domain
  // p's coordinates are multiples of 2^m: p is a corner, edge midpoint or
  // face center of a cube of level L - m or finer only, so a coarser leaf
  // holds p inside (§9.3) and the search starts at level L - m.
  const int m =
      std::min({std::countr_zero(static_cast<std::uint64_t>(p.x)), std::countr_zero(static_cast<std::uint64_t>(p.y)),
                std::countr_zero(static_cast<std::uint64_t>(p.z))});
  for (int l = std::max(0, size_.L - m); l <= size_.L; ++l) {
    const std::int64_t s = cell_side(size_, l);
    const Point q{(z.x / s) * s + s / 2, (z.y / s) * s + s / 2, (z.z / s) * s + s / 2};
    const Index r = table_.find(key_hash_at(q, size_.L - l), [&](Index x) {
      return (x & kNodeBit) ? node_position(x & ~kNodeBit) == q : centers_[x].p == q;
    });
    if (r == kNone) return kNone;   // inside a coarser leaf
    if (!(r & kNodeBit)) return r;  // the leaf
  }
  return kNone;
}

Index Lattice::find_node(const Point& p) const {
  if (p.x < 0 || p.y < 0 || p.z < 0 || p.x > extent_[0] || p.y > extent_[1] || p.z > extent_[2]) return kNone;
  if ((p.x | p.y | p.z) & 1) return kNone;  // a node is a corner of a cube of level <= L
  if (center_tz(p) >= 0) return find_refined(p);
  int o = 0;  // an octant at p inside the domain
  for (int a = 0; a < 3; ++a)
    if (coord(p, a) < extent_[a]) o |= 1 << a;
  const Index x = locate(p, o);
  if (x == kNone) return kNone;
  const Point& q = centers_[x].p;
  const std::int64_t h = half_side(level(x));
  int d[3];
  for (int a = 0; a < 3; ++a) {
    const std::int64_t diff = coord(p, a) - coord(q, a);
    if (diff != 0 && diff != h && diff != -h) return kNone;
    d[a] = diff == 0 ? 0 : diff > 0 ? 1 : -1;
  }
  if (d[0] == 0 && d[1] == 0 && d[2] == 0) return kNone;
  return centers_[x].nbr[slot_of(d[0], d[1], d[2])];
}

// ---- Pools ------------------------------------------------------------------------------

inline Index Lattice::alloc_center(const Point& p) {
  Index c;
  if (free_centers_ == kNone) {
    c = static_cast<Index>(centers_.append_reserved());  // room made first (§9.8); every field written below
  } else {
    c = free_centers_;
    free_centers_ = centers_[c].nbr[0];
    --free_center_count_;
  }
  Center& r = centers_[c];
  r.p = p;
  fill_none(r.nbr);
  ++cell_count_;
  return c;
}

inline Index Lattice::alloc_node() {
  const Index n = alloc_node_record();
  fill_none(nodes_[n].cell);
  return n;
}

inline Index Lattice::alloc_node_record() {
  Index n;
  if (free_nodes_ == kNone) {
    n = static_cast<Index>(nodes_.append_reserved());  // room made first (§9.8); the caller writes its 8 slots (§9.5)
  } else {
    n = free_nodes_;
    free_nodes_ = nodes_[n].cell[0];
    --free_node_count_;
  }
  ++node_count_;
  return n;
}

inline void Lattice::free_center(Index c) {
  Center& r = centers_[c];
  r.nbr[25] = kFreeMark;
  r.nbr[0] = free_centers_;
  free_centers_ = c;
  ++free_center_count_;
  --cell_count_;
}

inline void Lattice::free_node(Index n) {
  Node& r = nodes_[n];
  fill_none(r.cell);
  r.cell[7] = kFreeMark;
  r.cell[0] = free_nodes_;
  free_nodes_ = n;
  ++free_node_count_;
  --node_count_;
}

void Lattice::ensure_room(std::size_t new_centers, std::size_t new_nodes, std::size_t new_keys) {
  auto grow = [](auto& pool, std::size_t free_count, std::size_t wanted) {
    if (free_count + (pool.capacity() - pool.size()) >= wanted) return;
    const std::size_t need = pool.size() + (wanted - free_count);
    if (need > kMaxPool) throw std::length_error("d3::fast::Lattice: 2^26 or more vertices of one kind");
    // §9.9: by 4 on the heap, by 1/8 once mapped; amortized O(1).
    pool.reserve(std::min(kMaxPool, pool.grown_capacity(need)));
  };
  grow(centers_, free_center_count_, new_centers);
  grow(nodes_, free_node_count_, new_nodes);
  // §9.9: load at most 0.6; 4x below 1 MiB of slots, 2x from there.
  if (const std::size_t slots = PositionTable::grown(table_.slots(), table_.used() + new_keys); slots != table_.slots())
    table_.rehash(slots);
}

void Lattice::reserve(std::size_t cells) {
  cells = std::min(cells, kMaxPool);
  centers_.reserve(cells);
  nodes_.reserve(std::min(kMaxPool, cells + cells / 4 + 64));
  // The keys: the cells and the refined centers (about a seventh of them).
  const std::size_t keys = cells + cells / 7 + 16;
  std::size_t slots = std::max<std::size_t>(table_.slots(), 32);
  while (keys * 5 > slots * 3) slots *= 2;
  if (slots != table_.slots()) table_.rehash(slots);
}

void reserve(Lattice& g, std::size_t cells) {
  try {
    g.reserve(std::min(cells, bccmis::fast::kMaxReserveHint));
  } catch (const std::bad_alloc&) {
    // A hint: the lattice grows as it goes.
  }
}

std::size_t Lattice::memory_bytes() const {
  return centers_.capacity() * sizeof(Center) + nodes_.capacity() * sizeof(Node) + table_.memory_bytes();
}

// ---- Construction ----------------------------------------------------------------------

Lattice::Lattice(const d3::LatticeSize& size) : size_(size) {
  d3::validate_lattice_size(size);
  const std::int64_t S = d3::level0_side(size);
  extent_[0] = size.W * S;
  extent_[1] = size.H * S;
  extent_[2] = size.D * S;
  const auto limit = static_cast<std::int64_t>(kMaxPool);
  auto product_below_limit = [&](std::int64_t a, std::int64_t b, std::int64_t c) {
    return a <= limit && b <= limit && c <= limit && a * b <= limit && a * b * c <= limit;
  };
  if (!product_below_limit(size.W, size.H, size.D) || !product_below_limit(size.W + 1, size.H + 1, size.D + 1))
    throw std::length_error("d3::fast::Lattice: the initial lattice needs 2^26 or more vertices of one kind");
  const std::int64_t W = size.W, H = size.H, D = size.D;
  const auto cell_at = [&](std::int64_t i, std::int64_t j, std::int64_t k) -> Index {
    if (i < 0 || j < 0 || k < 0 || i >= W || j >= H || k >= D) return kNone;
    return static_cast<Index>((k * H + j) * W + i);
  };
  const auto node_at = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<Index>((k * (H + 1) + j) * (W + 1) + i);
  };
  centers_.resize(static_cast<std::size_t>(W * H * D));
  nodes_.resize(static_cast<std::size_t>((W + 1) * (H + 1) * (D + 1)));
  for (std::int64_t k = 0; k < D; ++k)
    for (std::int64_t j = 0; j < H; ++j)
      for (std::int64_t i = 0; i < W; ++i) {
        Center& c = centers_[cell_at(i, j, k)];
        c.p = {i * S + S / 2, j * S + S / 2, k * S + S / 2};
        std::fill(std::begin(c.nbr), std::end(c.nbr), kNone);
        for (int o = 0; o < 8; ++o) c.nbr[corner_slot(o)] = node_at(i + (o & 1), j + ((o >> 1) & 1), k + (o >> 2));
      }
  for (std::int64_t k = 0; k <= D; ++k)
    for (std::int64_t j = 0; j <= H; ++j)
      for (std::int64_t i = 0; i <= W; ++i)
        for (int t = 0; t < 8; ++t)
          nodes_[node_at(i, j, k)].cell[t] = cell_at(i - 1 + (t & 1), j - 1 + ((t >> 1) & 1), k - 1 + (t >> 2));
  cell_count_ = centers_.size();
  node_count_ = nodes_.size();
  table_.reset(32);
  ensure_room(0, 0, cell_count_);
  for (Index c = 0; c < centers_.size(); ++c) table_.insert(c, key_hash(centers_[c].p));
}

Lattice Lattice::from_graph(const d3::Graph& g) {
  d3::validate_lattice_size(g.size);
  Lattice lat;
  lat.size_ = g.size;
  const std::int64_t S = d3::level0_side(g.size);
  lat.extent_[0] = g.size.W * S;
  lat.extent_[1] = g.size.H * S;
  lat.extent_[2] = g.size.D * S;
  if (g.C.size() > kMaxPool || g.N.size() > kMaxPool)
    throw std::invalid_argument("d3::fast::Lattice::from_graph: 2^26 or more vertices of one kind");
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("d3::fast::Lattice::from_graph: " + what);
  };
  std::map<Point, Index> node_id;
  lat.nodes_.reserve(g.N.size());
  for (const Point& n : g.N) node_id.emplace(n, lat.alloc_node());
  lat.centers_.reserve(g.C.size());
  for (const Point& c : g.C) {
    const auto lv = g.level.find(c);
    const int t = lat.center_tz(c);
    if (lv == g.level.end() || t < 0 || g.size.L - t != lv->second)
      fail("center " + d3::to_string(c) + " has no level in 0..L that matches its position");
    const Index ci = lat.alloc_center(c);
    const std::int64_t h = lat.half_side(lv->second);
    for (const Point& b : g.nbr(c)) {
      const auto id = node_id.find(b);
      int d[3];
      bool on_boundary = id != node_id.end();
      for (int a = 0; a < 3 && on_boundary; ++a) {
        const std::int64_t diff = coord(b, a) - coord(c, a);
        on_boundary = diff == 0 || diff == h || diff == -h;
        d[a] = diff == 0 ? 0 : diff > 0 ? 1 : -1;
      }
      if (!on_boundary || (d[0] == 0 && d[1] == 0 && d[2] == 0))
        fail("neighbor " + d3::to_string(b) + " of center " + d3::to_string(c) +
             " is not a node at a corner, edge midpoint or face center of it");
      const int k = slot_of(d[0], d[1], d[2]);
      lat.centers_[ci].nbr[k] = id->second;
      Node& rn = lat.nodes_[id->second];
      for (int i = 0; i < rule(k).inside_count; ++i) {
        const int octant = rule(k).inside_octant[i];
        if (rn.cell[octant] != kNone) fail("two cells cover one octant of node " + d3::to_string(b));
        rn.cell[octant] = ci;
      }
    }
    for (int o = 0; o < 8; ++o)
      if (lat.centers_[ci].nbr[corner_slot(o)] == kNone) fail("center " + d3::to_string(c) + " lacks a corner");
  }
  for (const auto& [n, id] : node_id) {
    const Node& rn = lat.nodes_[id];
    if (std::all_of(std::begin(rn.cell), std::end(rn.cell), [](Index x) { return x == kNone; }))
      fail("node " + d3::to_string(n) + " has no cell");
    if (lat.node_position(id) != n) fail("node " + d3::to_string(n) + " is not where its cells put it");
  }
  lat.table_.reset(32);
  std::size_t keys = g.C.size();
  for (const auto& entry : node_id) keys += lat.center_tz(entry.first) >= 0;
  lat.ensure_room(0, 0, keys);
  for (Index c = 0; c < lat.centers_.size(); ++c) lat.table_.insert(c, lat.key_hash(lat.centers_[c].p));
  for (const auto& [n, id] : node_id)
    if (lat.center_tz(n) >= 0) lat.table_.insert(id | kNodeBit, lat.key_hash(n));
  return lat;
}

// ---- Queries ------------------------------------------------------------------------------

bool Lattice::is_center(const Point& v) const { return find_center(v) != kNone; }
bool Lattice::is_node(const Point& v) const { return find_node(v) != kNone; }

int Lattice::level_of(const Point& c) const {
  const Index ci = find_center(c);
  if (ci == kNone) throw std::out_of_range("d3::fast::Lattice::level_of: " + d3::to_string(c) + " is not a center");
  return level(ci);
}

SmallPoints<8> Lattice::node_cells(Index n) const {
  SmallPoints<8> out;
  const Node& r = nodes_[n];
  for (int t = 0; t < 8; ++t) {
    const Index x = r.cell[t];
    if (x == kNone) continue;
    bool seen = false;
    for (int s = 0; s < t; ++s) seen = seen || r.cell[s] == x;
    if (!seen) out.push_back(centers_[x].p);
  }
  out.sort();
  return out;
}

SmallPoints<26> Lattice::nbr(const Point& v) const {
  SmallPoints<26> out;
  if (const Index c = find_center(v); c != kNone) {
    const Center& r = centers_[c];
    const std::int64_t h = half_side(level(c));
    for (const int k : kSortedSlots)
      if (r.nbr[k] != kNone) out.push_back(offset(r.p, rule(k).d, h));
    return out;
  }
  if (const Index n = find_node(v); n != kNone)
    for (const Point& p : node_cells(n)) out.push_back(p);
  return out;
}

Lattice::Boundary Lattice::boundary(const Point& u) const {
  const Index c = find_center(u);
  if (c == kNone) throw std::out_of_range("d3::fast::Lattice::boundary: " + d3::to_string(u) + " is not a center");
  Boundary b;
  b.g_ = this;
  b.c_ = c;
  b.u_ = u;
  b.level_ = level(c);
  b.h_ = half_side(b.level_);
  for (int k = 0; k < 26; ++k)
    if (centers_[c].nbr[k] != kNone) b.slots_ |= 1u << k;
  return b;
}

bool Lattice::Boundary::contains(const Point& p) const {
  const std::int64_t diff[3] = {p.x - u_.x, p.y - u_.y, p.z - u_.z};
  int g = 0, scale = 1;
  for (const std::int64_t v : diff) {
    if (v != 0 && v != h_ && v != -h_) return false;
    g += (v == 0 ? 1 : v > 0 ? 2 : 0) * scale;
    scale *= 3;
  }
  return g != 13 && ((slots_ >> slot_of_grid(g)) & 1u);
}

bool Lattice::Boundary::equal_across(int axis, bool high, const Point& w) const {
  // spec/mesh3d.md M25.2: b, the corner of the face at -h on its tangential
  // axes i and j; t, the octant at b across the face and toward its center.
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  int d[3];
  d[axis] = high ? 1 : -1;
  d[i] = -1;
  d[j] = -1;
  const Index b = g_->centers_[c_].nbr[slot_of(d[0], d[1], d[2])];
  const int t = (high ? 1 << axis : 0) | 1 << i | 1 << j;
  const Index x = g_->nodes_[b].cell[t];
  return x != kNone && g_->centers_[x].p == w;
}

std::vector<Index> Lattice::sorted_centers() const {
  // §9.7: the order of S8a's radix sort of the live centers' positions.
  std::vector<Index> ids;
  std::vector<Point> positions;
  ids.reserve(cell_count_);
  positions.reserve(cell_count_);
  for (Index i = 0; i < centers_.size(); ++i)
    if (centers_[i].live()) ids.push_back(i), positions.push_back(centers_[i].p);
  const std::vector<std::uint32_t> order = d3::detail::position_order(positions);
  positions = {};
  std::vector<Index> sorted(ids.size());
  for (std::size_t r = 0; r < order.size(); ++r) sorted[r] = ids[order[r]];
  return sorted;
}

std::vector<std::pair<Point, Index>> Lattice::sorted_nodes() const {
  std::vector<std::pair<Point, Index>> out;
  out.reserve(node_count_);
  for (Index i = 0; i < nodes_.size(); ++i)
    if (nodes_[i].live()) out.emplace_back(node_position(i), i);
  std::sort(out.begin(), out.end());
  return out;
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
  for (const auto& entry : sorted_nodes()) out.push_back(entry.first);
  return out;
}

d3::Graph Lattice::to_graph() const {
  d3::Graph g;
  g.size = size_;
  for (Index c = 0; c < centers_.size(); ++c) {
    if (!centers_[c].live()) continue;
    const Point& p = centers_[c].p;
    g.C.insert(p);
    g.level[p] = level(c);
    d3::PointSet& s = g.neighbors[p];
    for (const Point& b : nbr(p)) s.insert(b);
  }
  for (const auto& [p, n] : sorted_nodes()) {
    g.N.insert(p);
    d3::PointSet& s = g.neighbors[p];
    for (const Point& x : node_cells(n)) s.insert(x);
  }
  return g;
}

std::optional<std::string> Lattice::audit() const {
  std::size_t live_cells = 0, live_nodes = 0, refined = 0;
  for (Index i = 0; i < centers_.size(); ++i) {
    const Center& c = centers_[i];
    if (!c.live()) continue;
    ++live_cells;
    const std::string name = "center " + d3::to_string(c.p);
    if (center_tz(c.p) < 0) return name + " is not at a center position";
    if (find_center(c.p) != i) return name + " is not in the position table";
    for (int k = 0; k < 26; ++k) {
      const Index n = c.nbr[k];
      if (n == kNone) {
        if (is_corner(k)) return name + " lacks a corner";
        continue;
      }
      if (n >= nodes_.size() || !nodes_[n].live()) return name + " names a free node record";
      bool mirrored = true;
      for (int j = 0; j < rule(k).inside_count; ++j)
        mirrored = mirrored && nodes_[n].cell[rule(k).inside_octant[j]] == i;
      if (!mirrored) return name + ": its node in slot " + std::to_string(k) + " does not list it in every octant";
    }
  }
  for (Index i = 0; i < nodes_.size(); ++i) {
    const Node& n = nodes_[i];
    if (!n.live()) continue;
    ++live_nodes;
    const Point p = node_position(i);
    for (int t = 0; t < 8; ++t) {
      const Index x = n.cell[t];
      if (x == kNone) continue;
      if (x >= centers_.size() || !centers_[x].live()) return "node " + d3::to_string(p) + " names a free center";
      const std::int64_t h = half_side(level(x));
      int d[3];
      for (int a = 0; a < 3; ++a) {
        const std::int64_t diff = coord(p, a) - coord(centers_[x].p, a);
        if (diff != 0 && diff != h && diff != -h) return "node " + d3::to_string(p) + " is not on a cell it lists";
        d[a] = diff == 0 ? 0 : diff > 0 ? 1 : -1;
      }
      if (centers_[x].nbr[slot_of(d[0], d[1], d[2])] != i)
        return "node " + d3::to_string(p) + " lists center " + d3::to_string(centers_[x].p) +
               ", which does not list it";
    }
    if (center_tz(p) >= 0) {
      ++refined;
      if (find_refined(p) != i) return "refined center " + d3::to_string(p) + " is not in the position table";
    }
  }
  if (live_cells != cell_count_ || live_nodes != node_count_) return std::string("the vertex counts do not add up");
  if (table_.used() != live_cells + refined) return std::string("the position table holds other entries");
  std::size_t free_centers = 0, free_nodes = 0;
  for (Index i = free_centers_; i != kNone; i = centers_[i].nbr[0]) ++free_centers;
  for (Index i = free_nodes_; i != kNone; i = nodes_[i].cell[0]) ++free_nodes;
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
  for (const Index i : sorted_centers()) {
    const Center& c = centers_[i];
    const int l = level(i);
    const std::int64_t h = half_side(l);
    w.put('C');
    w.put_point(c.p.x, c.p.y, c.p.z);
    w.put(' ');
    w.put_int(l);
    w.put(" :");
    for (const int k : kSortedSlots)
      if (c.nbr[k] != kNone) {
        const Point b = offset(c.p, rule(k).d, h);
        w.put_point(b.x, b.y, b.z);
      }
    w.put('\n');
  }
  for (const auto& [p, n] : sorted_nodes()) {
    w.put('N');
    w.put_point(p.x, p.y, p.z);
    w.put(" :");
    for (const Point& x : node_cells(n)) w.put_point(x.x, x.y, x.z);
    w.put('\n');
  }
  w.put("end ");
  w.put_int(static_cast<std::int64_t>(cell_count_));
  w.put(' ');
  w.put_int(static_cast<std::int64_t>(node_count_));
  w.put('\n');
  w.flush();
}

std::string canonical_state(const Lattice& g) { return canonical_text(g); }

// ---- Preconditions (§9.5, §9.6) -------------------------------------------------------------

std::optional<RefineRefusal> Lattice::refine_refusal(const Point& c, Index& ci, std::uint64_t& hash) const {
  // spec/lattice3d.md §4 preconditions, in the reference's order.
  ci = find_ref(c, false, hash);
  if (ci == kNone) return RefineRefusal::NoSuchCell;
  const int l = level(ci);
  if (l >= size_.L) return RefineRefusal::MaxLevel;
  // R1d, §9.5: a coarser cell of X shares a face or an edge of c, so it
  // covers, at a corner of that face or edge, the octant across it: the
  // octant t = (d's outward bits on nz(d)) | (+ on the other axes) of the
  // corner with d's signs on nz(d) and - elsewhere. 6 faces + 12 edges.
  const Center& rc = centers_[ci];
  const std::int64_t coarse_mask = 2 * half_side(l) - 1;  // a coarser center's coordinates are multiples of 2h
  bool coarser = false;
  unroll<18>([&](auto i) {
    constexpr const SlotRule& r = kRule[kMidpointSlots[decltype(i)::value]];
    const Index x = nodes_[rc.nbr[r.corner]].cell[r.across];
    coarser = coarser || (x != kNone && (centers_[x].p.x & coarse_mask) == 0);
  });
  if (coarser) return RefineRefusal::CoarserNeighbor;
  return std::nullopt;
}

std::optional<CoarsenRefusal> Lattice::coarsen_refusal(const Point& n, Index& ni, int& l, std::uint64_t& hash) const {
  // spec/lattice3d.md §5 preconditions, in the reference's order.
  const int t = center_tz(n);
  ni = t >= 0 ? find_ref(n, true, hash) : kNone;
  if (ni == kNone) return find_node(n) != kNone ? CoarsenRefusal::NotARefinedCenter : CoarsenRefusal::NoSuchNode;
  l = size_.L - t;
  if (l >= size_.L) return CoarsenRefusal::NotARefinedCenter;
  const Node& rn = nodes_[ni];
  // |N(n)| = 8: eight distinct cells. Eight cells of level l + 1 around n
  // are distinct (n is a corner of each), so the pairs are compared only
  // when a level differs.
  for (int o = 0; o < 8; ++o)
    if (rn.cell[o] == kNone) return CoarsenRefusal::NotARefinedCenter;
  for (int o = 0; o < 8; ++o)
    if (level(rn.cell[o]) != l + 1) {
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < a; ++b)
          if (rn.cell[a] == rn.cell[b]) return CoarsenRefusal::NotARefinedCenter;
      return CoarsenRefusal::ChildrenRefined;
    }
  // |N(y)| = 8: no node but the corners. kNone has every bit set, so the 8
  // children's 144 edge and face slots hold no node iff their AND is kNone:
  // one pass of loads and ANDs, no branch per slot.
  Index none = kNone;
  for (int o = 0; o < 8; ++o) {
    const Center& y = centers_[rn.cell[o]];
    for (const int k : kMidpointSlots) none &= y.nbr[k];
  }
  if (none != kNone) return CoarsenRefusal::FinerNeighbor;
  return std::nullopt;
}

std::optional<RefineRefusal> Lattice::can_refine(const Point& c) const {
  Index ci;
  std::uint64_t hash;
  return refine_refusal(c, ci, hash);
}

std::optional<CoarsenRefusal> Lattice::can_coarsen(const Point& n) const {
  Index ni;
  int l;
  std::uint64_t hash;
  return coarsen_refusal(n, ni, l, hash);
}

// ---- Refine (§4 as §9.5) -------------------------------------------------------------------

RefineResult Lattice::refine(const Point& c) {
  RefineResult result;
  Index ci;
  std::uint64_t hash = 0;  // c's table hash
  result.refused = refine_refusal(c, ci, hash);
  if (result.refused) return result;
  std::size_t new_nodes = 1;  // c, and a node on each edge and face that has none
  unroll<18>([&](auto i) { new_nodes += centers_[ci].nbr[kMidpointSlots[decltype(i)::value]] == kNone; });
  ensure_room(8, new_nodes, 8);  // c's table entry is renamed, the 8 children added

  const int l = level(ci);
  const std::int64_t h = half_side(l);
  const std::uint64_t family = mix(c);  // the children's hashes (§9.4)

  // R1a-R1c: B = N(c) by slot: the corners P, the old junctions J (the
  // edge and face slots that hold a node).
  Index G[26];
  std::copy(std::begin(centers_[ci].nbr), std::end(centers_[ci].nbr), G);
  // R2g, R2h: c leaves C and joins N, under the same table entry.
  const Index cn = alloc_node_record();  // its 8 slots written below (§9.5)
  table_.replace(ci, hash, cn | kNodeBit);
  free_center(ci);
  // R2a, R2b: Y = {y_o}, y_o centred at c + s_o h/2 (choice Q1).
  Index y[8];
  for (int o = 0; o < 8; ++o)
    y[o] = alloc_center({c.x + sign(o, 0) * h / 2, c.y + sign(o, 1) * h / 2, c.z + sign(o, 2) * h / 2});
  for (const int o : kSortedOctants) result.Y.push_back(centers_[y[o]].p);

  // One pass over the 26 slots in sorted order (§9.5). R3a-R3h: a new node
  // j+ on each edge and face of c without one; the cells around it outside c
  // (X_e, X_f) are read at the corner with d's signs on nz(d) and -
  // elsewhere (octants outside c, which this pass does not write), and each
  // gets j+ in its slot toward it. R2c-R2f, R3d-R3h, R4a, R4b: the node b in
  // the slot lists, in each of its octants t inside c, the child y_(t XOR
  // nz(d)), which has b as its corner t XOR 7 (the corner toward b).
  unroll<8>([&](auto t) {
    constexpr int e = corner_slot(decltype(t)::value ^ 7);
    nodes_[cn].cell[t] = y[t];
    centers_[y[t]].nbr[e] = cn;
  });
  unroll<26>([&](auto i) {
    constexpr int k = kSortedSlots[decltype(i)::value];
    constexpr const SlotRule& r = kRule[k];
    if constexpr (r.nz != 7) {
      if (G[k] == kNone) {
        const Index jp = alloc_node_record();  // its 8 slots written in this step (§9.5)
        G[k] = jp;
        result.J_plus.push_back(offset(c, r.d, h));
        const Node& corner = nodes_[G[r.corner]];
        Node& rj = nodes_[jp];
        for (int j = 0; j < r.outside_count; ++j) {
          const Index x = corner.cell[r.outside_at_corner[j]];
          rj.cell[r.outside_octant[j]] = x;                           // R3d, R3g: X ⊆ N(j+)
          if (x != kNone) centers_[x].nbr[r.outside_toward[j]] = jp;  // R3c, R3f
        }
      }
    }
    const Index b = G[k];
    Node& rb = nodes_[b];
    unroll<r.inside_count>([&](auto j) {
      constexpr int t = kRule[k].inside_octant[decltype(j)::value];
      constexpr int e = corner_slot(t ^ 7);
      const Index yc = y[t ^ kRule[k].nz];
      rb.cell[t] = yc;
      centers_[yc].nbr[e] = b;
    });
  });
  for (int o = 0; o < 8; ++o) table_.insert(y[o], PositionTable::family_hash(family, static_cast<std::size_t>(o)));
  return result;
}

// ---- Coarsen (§5 as §9.6) --------------------------------------------------------------------

CoarsenResult Lattice::coarsen(const Point& n) {
  CoarsenResult result;
  Index ni;
  int l = 0;
  std::uint64_t hash = 0;  // n's table hash
  result.refused = coarsen_refusal(n, ni, l, hash);
  if (result.refused) return result;
  // Coarsening frees 8 centers, takes 1 and adds no table entry: no room to make.
  const std::int64_t h = half_side(l);
  const std::uint64_t family = mix(n);

  // K1a: Y = N(n), y_o in octant o. K1b: B, the 26 nodes of the merged
  // cube's boundary: grid point d is corner (d on nz(d), + elsewhere) of the
  // child with d's signs on nz(d) and - elsewhere.
  Index y[8];
  std::copy(std::begin(nodes_[ni].cell), std::end(nodes_[ni].cell), y);
  for (const int o : kSortedOctants) result.Y.push_back(centers_[y[o]].p);
  Index B[26];
  unroll<26>([&](auto k) { B[k] = centers_[y[kRule[k].child]].nbr[kRule[k].child_corner]; });
  // K2b, K2f: the children are deleted. K2c-K2e: n leaves N and joins C
  // (choice Q4), under the same table entry.
  for (int o = 0; o < 8; ++o) table_.erase(y[o], PositionTable::family_hash(family, static_cast<std::size_t>(o)));
  for (int o = 0; o < 8; ++o) free_center(y[o]);
  const Index cc = alloc_center(n);
  table_.replace(ni | kNodeBit, hash, cc);
  free_node(ni);

  // K2a, K4b: every node of B lists the merged cell in its octants inside it.
  // K3a (§9.6): an edge midpoint or face center b stays iff a cell outside
  // has it as a corner, that is iff the octants outside on one side of the
  // merged cube's boundary hold different cells.
  Center& rc = centers_[cc];
  unroll<26>([&](auto i) {
    constexpr int k = kSortedSlots[decltype(i)::value];
    constexpr const SlotRule& r = kRule[k];
    Node& b = nodes_[B[k]];
    for (int j = 0; j < r.inside_count; ++j) b.cell[r.inside_octant[j]] = cc;
    rc.nbr[k] = B[k];  // K4a
    if constexpr (r.nz != 7) {
      bool corner_of_a_cell = false;
      for (int j = 0; j < r.outside_count; ++j)
        corner_of_a_cell = corner_of_a_cell || b.cell[r.outside_octant[j]] != b.cell[r.outside_beside[j]];
      if (!corner_of_a_cell) {
        // K3b-K3e: j in J-: its cells outside drop it, it is deleted.
        for (int j = 0; j < r.outside_count; ++j)
          if (const Index x = b.cell[r.outside_octant[j]]; x != kNone) centers_[x].nbr[r.outside_toward[j]] = kNone;
        result.J_minus.push_back(offset(n, r.d, h));
        rc.nbr[k] = kNone;
        free_node(B[k]);
      }
    }
  });
  return result;
}

// ---- Batches ------------------------------------------------------------------------------

void Lattice::prefetch_home(const Point& p) const {
  if (const int t = center_tz(p); t >= 0) table_.prefetch(key_hash_at(p, t));
}

Lattice::Index Lattice::peek_node(const Point& p) const {
  const int t = center_tz(p);
  if (t < 0) return kNone;
  const Index r = table_.find(key_hash_at(p, t), [](Index q) { return (q & kNodeBit) != 0; });
  return r == kNone ? kNone : r & ~kNodeBit;
}

namespace {
// op(p) for each p in order, the table line of the position kAhead later
// prefetched first; how many op applied.
template <class Prefetch, class Op>
std::size_t apply_each(std::span<const Point> points, Prefetch prefetch, Op op) {
  constexpr std::size_t kAhead = 8;
  std::size_t applied = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i + kAhead < points.size()) prefetch(points[i + kAhead]);
    applied += op(points[i]);
  }
  return applied;
}
}  // namespace

std::size_t Lattice::refine_each(std::span<const Point> cells) {
  return apply_each(
      cells, [this](const Point& p) { prefetch_home(p); }, [this](const Point& p) { return refine(p).applied(); });
}

std::size_t Lattice::coarsen_each(std::span<const Point> nodes) {
  // spec/lattice3d.md §9.12: three stages of look-ahead, each reading only
  // what the stage before brought in.
  constexpr std::size_t kTable = 16, kNode = 8, kCells = 4;
  std::size_t applied = 0;
  const std::size_t k = nodes.size();
  for (std::size_t i = 0; i < k; ++i) {
    if (i + kTable < k) prefetch_home(nodes[i + kTable]);
    if (i + kNode < k)
      if (const Index n = peek_node(nodes[i + kNode]); n != kNone) __builtin_prefetch(&nodes_[n]);
    if (i + kCells < k)
      if (const Index n = peek_node(nodes[i + kCells]); n != kNone)
        for (const Index c : nodes_[n].cell)
          if (c < centers_.size()) {  // kNone, and the free mark, are not
            __builtin_prefetch(&centers_[c]);
            __builtin_prefetch(reinterpret_cast<const char*>(&centers_[c]) + 64);
          }
    applied += coarsen(nodes[i]).applied();
  }
  return applied;
}

}  // namespace bccmis::d3::fast
