// Independent reference model of the lattice states of Erleben 2009,
// "Maximal independent set graph partitions for representations of BCC
// lattices".  This model deliberately does NOT use the graph code: a state
// is just a set of quadtree leaves over a W x H forest of level-0 cells, and
// every rule is written from the geometry of those leaves.
//
// Definitions
//   * Lattice W x H level-0 cells, maximum level L.
//   * A leaf / cell is (level, i, j) with 0 <= i < W*2^level,
//     0 <= j < H*2^level.
//   * Integer coordinates: a level-l cell has side s_l = 2^(L+1-l), so a
//     level-0 cell has side 2^(L+1) and a level-L cell has side 2.  Cell
//     (l,i,j) covers [i*s_l,(i+1)*s_l] x [j*s_l,(j+1)*s_l]; its center is
//     (i*s_l + s_l/2, j*s_l + s_l/2).  All centers and corners are integers.
//   * Balance (2:1 EDGE balance): two leaves sharing a boundary segment of
//     positive length differ in level by at most 1.  Corner-only contact is
//     not constrained.
//   * The canonical key of a state is its sorted vector of leaves.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <functional>
#include <optional>
#include <ostream>
#include <set>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace bccmis::model {

struct Leaf {
  int level = 0;
  std::int64_t i = 0;
  std::int64_t j = 0;
  auto operator<=>(const Leaf&) const = default;
};

struct Pos {
  std::int64_t x = 0;
  std::int64_t y = 0;
  auto operator<=>(const Pos&) const = default;
};

inline std::ostream& operator<<(std::ostream& os, const Leaf& c) {
  return os << "(" << c.level << "," << c.i << "," << c.j << ")";
}
inline std::ostream& operator<<(std::ostream& os, const Pos& p) { return os << "(" << p.x << "," << p.y << ")"; }

struct Lattice {
  int W = 1;
  int H = 1;
  int L = 0;

  // Side of a level-l cell: 2^(L+1-l).
  std::int64_t side(int level) const { return std::int64_t{1} << (L + 1 - level); }
  // Number of cells of level l along x / y.
  std::int64_t nx(int level) const { return std::int64_t{W} << level; }
  std::int64_t ny(int level) const { return std::int64_t{H} << level; }

  bool valid_cell(const Leaf& c) const {
    return c.level >= 0 && c.level <= L && c.i >= 0 && c.i < nx(c.level) && c.j >= 0 && c.j < ny(c.level);
  }
};

// ---------------------------------------------------------------------------
// Geometry
// ---------------------------------------------------------------------------

struct Rect {
  std::int64_t x0, y0, x1, y1;
};

inline Rect rect_of(const Lattice& lat, const Leaf& c) {
  const std::int64_t s = lat.side(c.level);
  return Rect{c.i * s, c.j * s, (c.i + 1) * s, (c.j + 1) * s};
}

// Center of cell c: (i*s + s/2, j*s + s/2).
inline Pos center_of(const Lattice& lat, const Leaf& c) {
  const std::int64_t s = lat.side(c.level);
  return Pos{c.i * s + s / 2, c.j * s + s / 2};
}

// Inverse of center_of: the (valid) cell whose center is p, if any.  The
// cell need not be a leaf of any particular state.
inline std::optional<Leaf> cell_at_center(const Lattice& lat, const Pos& p) {
  if (p.x < 0 || p.y < 0) return std::nullopt;
  for (int l = 0; l <= lat.L; ++l) {
    const std::int64_t s = lat.side(l);
    const std::int64_t h = s / 2;
    if (p.x % s == h && p.y % s == h) {
      Leaf c{l, p.x / s, p.y / s};
      if (lat.valid_cell(c)) return c;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

inline bool is_corner_of(const Lattice& lat, const Leaf& c, const Pos& p) {
  const Rect r = rect_of(lat, c);
  return (p.x == r.x0 || p.x == r.x1) && (p.y == r.y0 || p.y == r.y1);
}

// True iff the two (interior-disjoint) cells share a boundary segment of
// positive length.  Corner-only contact returns false.
inline bool share_edge(const Lattice& lat, const Leaf& a, const Leaf& b) {
  const Rect A = rect_of(lat, a);
  const Rect B = rect_of(lat, b);
  const bool touch_x = (A.x1 == B.x0 || B.x1 == A.x0);
  const bool touch_y = (A.y1 == B.y0 || B.y1 == A.y0);
  const bool overlap_y = std::min(A.y1, B.y1) > std::max(A.y0, B.y0);
  const bool overlap_x = std::min(A.x1, B.x1) > std::max(A.x0, B.x0);
  return (touch_x && overlap_y) || (touch_y && overlap_x);
}

inline Leaf parent_of(const Leaf& c) { return Leaf{c.level - 1, c.i / 2, c.j / 2}; }

inline std::array<Leaf, 4> children_of(const Leaf& c) {
  const int l = c.level + 1;
  return {Leaf{l, 2 * c.i, 2 * c.j}, Leaf{l, 2 * c.i + 1, 2 * c.j}, Leaf{l, 2 * c.i, 2 * c.j + 1},
          Leaf{l, 2 * c.i + 1, 2 * c.j + 1}};
}

// ---------------------------------------------------------------------------
// State
// ---------------------------------------------------------------------------

// A state: the lattice plus its leaf set, kept as a sorted vector without
// duplicates, which is also the canonical key of the state.
struct State {
  Lattice lat;
  std::vector<Leaf> leaves;  // sorted, unique

  const std::vector<Leaf>& key() const { return leaves; }
  bool has(const Leaf& c) const { return std::binary_search(leaves.begin(), leaves.end(), c); }
  void erase(const Leaf& c) {
    auto it = std::lower_bound(leaves.begin(), leaves.end(), c);
    if (it != leaves.end() && *it == c) leaves.erase(it);
  }
  void insert(const Leaf& c) {
    auto it = std::lower_bound(leaves.begin(), leaves.end(), c);
    if (it == leaves.end() || *it != c) leaves.insert(it, c);
  }
};

inline State initial_state(int W, int H, int L) {
  State s{Lattice{W, H, L}, {}};
  for (int i = 0; i < W; ++i)
    for (int j = 0; j < H; ++j) s.insert(Leaf{0, i, j});
  return s;
}

// Builds a state from an arbitrary list of leaves (sorted, deduplicated).
inline State make_state(const Lattice& lat, std::vector<Leaf> leaves) {
  std::sort(leaves.begin(), leaves.end());
  leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
  return State{lat, std::move(leaves)};
}

// Full O(n^2) pairwise check of the 2:1 edge-balance rule.
inline bool is_balanced(const State& s) {
  for (const Leaf& a : s.leaves)
    for (const Leaf& b : s.leaves)
      if (a < b && std::abs(a.level - b.level) > 1 && share_edge(s.lat, a, b)) return false;
  return true;
}

// Check that the leaves tile the domain: total area equals W*H*S^2 and every
// leaf is a valid cell with no leaf strictly inside another leaf's region.
inline bool is_tiling(const State& s) {
  std::int64_t area = 0;
  for (const Leaf& c : s.leaves) {
    if (!s.lat.valid_cell(c)) return false;
    const std::int64_t sd = s.lat.side(c.level);
    area += sd * sd;
    for (Leaf a = c; a.level > 0;) {  // no ancestor may also be a leaf
      a = parent_of(a);
      if (s.has(a)) return false;
    }
  }
  const std::int64_t S = s.lat.side(0);
  return area == std::int64_t{s.lat.W} * s.lat.H * S * S;
}

// ---------------------------------------------------------------------------
// Refine
// ---------------------------------------------------------------------------

enum class RefineResult { ok, no_such_cell, max_level, coarser_neighbor };

inline std::string_view to_string(RefineResult r) {
  switch (r) {
    case RefineResult::ok: return "ok";
    case RefineResult::no_such_cell: return "no-such-cell";
    case RefineResult::max_level: return "max-level";
    case RefineResult::coarser_neighbor: return "coarser-neighbor";
  }
  return "?";
}
inline std::ostream& operator<<(std::ostream& os, RefineResult r) { return os << to_string(r); }

// Legality of refining `c`, assuming `s` is balanced.  Refining replaces c by
// its 4 children; the only new leaf pairs are (child, other leaf), so the
// result is balanced iff no child is edge-adjacent to a leaf more than one
// level coarser than the child, i.e. no edge neighbor of c is coarser
// than c.  We check the children literally.
inline RefineResult check_refine(const State& s, const Leaf& c) {
  if (!s.has(c)) return RefineResult::no_such_cell;
  if (c.level >= s.lat.L) return RefineResult::max_level;
  for (const Leaf& ch : children_of(c))
    for (const Leaf& o : s.leaves)
      if (o != c && std::abs(o.level - ch.level) > 1 && share_edge(s.lat, ch, o)) return RefineResult::coarser_neighbor;
  return RefineResult::ok;
}

// Refine the cell whose center is p.
inline RefineResult check_refine_at(const State& s, const Pos& p) {
  const std::optional<Leaf> c = cell_at_center(s.lat, p);
  if (!c) return RefineResult::no_such_cell;
  return check_refine(s, *c);
}

// Replaces leaf c by its 4 children (no legality check).
inline void apply_refine(State& s, const Leaf& c) {
  s.erase(c);
  for (const Leaf& ch : children_of(c)) s.insert(ch);
}

// Applies the refine if legal; returns the reason.
inline RefineResult refine(State& s, const Leaf& c) {
  const RefineResult r = check_refine(s, c);
  if (r == RefineResult::ok) apply_refine(s, c);
  return r;
}

// ---------------------------------------------------------------------------
// Coarsen
// ---------------------------------------------------------------------------

enum class CoarsenResult { ok, no_such_node, not_a_refined_center, children_refined, finer_neighbor };

inline std::string_view to_string(CoarsenResult r) {
  switch (r) {
    case CoarsenResult::ok: return "ok";
    case CoarsenResult::no_such_node: return "no-such-node";
    case CoarsenResult::not_a_refined_center: return "not-a-refined-center";
    case CoarsenResult::children_refined: return "children-refined";
    case CoarsenResult::finer_neighbor: return "finer-neighbor";
  }
  return "?";
}
inline std::ostream& operator<<(std::ostream& os, CoarsenResult r) { return os << to_string(r); }

// True iff p is a corner of some current leaf (a mesh node; includes side
// midpoints of coarse leaves that are corners of finer leaves).
inline bool is_node(const State& s, const Pos& p) {
  for (const Leaf& c : s.leaves)
    if (is_corner_of(s.lat, c, p)) return true;
  return false;
}

// Coarsen named by a position (the parent's center).  Reasons in order:
//   no-such-node          p is not a corner of any current leaf;
//   not-a-refined-center  p is a node but not the center of a cell of level
//                         0..L-1 (level-0 grid corners, side midpoints, ...);
//   children-refined      p is the center of a subdivided cell P but not all
//                         4 children of P are leaves;
//   finer-neighbor        all 4 children are leaves, but some leaf that is
//                         edge-adjacent to P is finer than level(P)+1.
// Note: if p is a node and the center of a valid cell P, then P is
// necessarily subdivided (a center of P lies in P's interior, and the
// interior of a leaf contains no leaf corner).
inline CoarsenResult check_coarsen_at(const State& s, const Pos& p) {
  if (!is_node(s, p)) return CoarsenResult::no_such_node;
  const std::optional<Leaf> P = cell_at_center(s.lat, p);
  if (!P || P->level >= s.lat.L) return CoarsenResult::not_a_refined_center;
  for (const Leaf& k : children_of(*P))
    if (!s.has(k)) return CoarsenResult::children_refined;
  // After coarsening, the only new leaf pairs are (P, other leaf).  The 4
  // children (level(P)+1) are removed, but they could never fail the test
  // below anyway, and no other leaf overlaps P.
  for (const Leaf& o : s.leaves)
    if (o.level - P->level > 1 && share_edge(s.lat, *P, o)) return CoarsenResult::finer_neighbor;
  return CoarsenResult::ok;
}

// Coarsen named by the parent cell.  A parent that is not a valid cell of
// level 0..L-1 has no refinable center -> not-a-refined-center; otherwise
// this is check_coarsen_at(center).
inline CoarsenResult check_coarsen(const State& s, const Leaf& parent) {
  if (!s.lat.valid_cell(parent) || parent.level >= s.lat.L) return CoarsenResult::not_a_refined_center;
  return check_coarsen_at(s, center_of(s.lat, parent));
}

// Replaces the 4 children of `parent` by `parent` (no legality check).
inline void apply_coarsen(State& s, const Leaf& parent) {
  for (const Leaf& k : children_of(parent)) s.erase(k);
  s.insert(parent);
}

// Applies the coarsen if legal; returns the reason.
inline CoarsenResult coarsen(State& s, const Leaf& parent) {
  const CoarsenResult r = check_coarsen(s, parent);
  if (r == CoarsenResult::ok) apply_coarsen(s, parent);
  return r;
}

// ---------------------------------------------------------------------------
// Method 1: BFS over legal operations from the initial lattice.
// ---------------------------------------------------------------------------

struct ReachableCount {
  std::int64_t states = 0;
  std::int64_t refine_edges = 0;   // (state, legal refine) pairs
  std::int64_t coarsen_edges = 0;  // (state, legal coarsen) pairs
};

// Hash of a canonical key (for the visited set of the BFS).
struct KeyHash {
  std::size_t operator()(const std::vector<Leaf>& k) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the leaf fields
    for (const Leaf& c : k)
      for (std::uint64_t v :
           {static_cast<std::uint64_t>(c.level), static_cast<std::uint64_t>(c.i), static_cast<std::uint64_t>(c.j)})
        h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// `visit` (optional) is called once per reachable state.
inline ReachableCount count_reachable_states(int W, int H, int L, const std::function<void(const State&)>& visit = {}) {
  ReachableCount rc;
  const State init = initial_state(W, H, L);
  std::unordered_set<std::vector<Leaf>, KeyHash> seen{init.key()};
  std::deque<State> queue{init};
  auto push = [&](const State& t) {
    if (seen.insert(t.key()).second) queue.push_back(t);
  };
  while (!queue.empty()) {
    const State s = std::move(queue.front());
    queue.pop_front();
    ++rc.states;
    if (visit) visit(s);
    std::set<Leaf> parents;
    for (const Leaf& c : s.leaves) {
      if (c.level > 0) parents.insert(parent_of(c));
      if (check_refine(s, c) == RefineResult::ok) {
        ++rc.refine_edges;
        State t = s;
        apply_refine(t, c);
        push(t);
      }
    }
    for (const Leaf& P : parents) {
      if (check_coarsen(s, P) == CoarsenResult::ok) {
        ++rc.coarsen_edges;
        State t = s;
        apply_coarsen(t, P);
        push(t);
      }
    }
  }
  return rc;
}

// ---------------------------------------------------------------------------
// Method 2: direct enumeration of balanced leaf sets, no operations at all.
//
// Every complete quadtree leaf set of one level-0 cell is generated by the
// recursion  trees(c) = { {c} } U (level(c) < L ? product of trees(child) : {}).
// A leaf set is painted onto the finest grid (level-L cells, 2^L x 2^L per
// root): each finest cell gets the level of the leaf containing it.  Two
// leaves share a boundary segment of positive length iff some pair of
// edge-adjacent finest cells lies one in each, so the set is 2:1 edge
// balanced iff every pair of edge-adjacent finest cells has levels differing
// by at most 1.  Roots are placed in row-major order and each placement
// checks the adjacent pairs whose both cells are already painted (pruning).
// ---------------------------------------------------------------------------

// All complete quadtree leaf sets of a single root cell, as patches: the
// n x n finest cells (n = 2^L) of the root, each holding the level of the
// leaf that contains it, index [y*n + x].  Depth-first over a stack of
// undecided cells: each cell is either kept as a leaf (painted with its
// level) or, if its level is < L, split into 4 undecided children.  Every
// tree corresponds to exactly one sequence of decisions.  (Paint left over
// from an abandoned branch is always overwritten, since every finest cell
// is painted again by the leaf that finally covers it.)
inline std::vector<std::vector<int>> root_patches(int L) {
  const int n = 1 << L;
  struct Sq {
    int level;
    int x, y;  // lower-left finest cell
  };
  std::vector<std::vector<int>> patches;
  std::vector<int> patch(static_cast<std::size_t>(n) * n, -1);
  std::vector<Sq> undecided{Sq{0, 0, 0}};
  std::function<void()> rec = [&]() {
    if (undecided.empty()) {
      patches.push_back(patch);
      return;
    }
    const Sq c = undecided.back();
    undecided.pop_back();
    const int w = n >> c.level;
    // Option 1: c is a leaf.
    for (int y = c.y; y < c.y + w; ++y)
      for (int x = c.x; x < c.x + w; ++x) patch[static_cast<std::size_t>(y) * n + x] = c.level;
    rec();
    // Option 2: c is split.
    if (c.level < L) {
      const int h = w / 2;
      for (int k = 0; k < 4; ++k) undecided.push_back(Sq{c.level + 1, c.x + (k % 2) * h, c.y + (k / 2) * h});
      rec();
      undecided.resize(undecided.size() - 4);
    }
    undecided.push_back(c);
  };
  rec();
  return patches;
}

inline std::int64_t count_balanced_leaf_sets(int W, int H, int L) {
  const int n = 1 << L;
  const int GX = W * n, GY = H * n;
  const std::vector<std::vector<int>> patches = root_patches(L);
  std::vector<int> grid(static_cast<std::size_t>(GX) * GY, -1);  // -1 = unpainted
  auto at = [&](int x, int y) -> int& { return grid[static_cast<std::size_t>(y) * GX + x]; };
  auto ok_pair = [](int a, int b) { return a < 0 || b < 0 || std::abs(a - b) <= 1; };

  std::function<std::int64_t(int)> place = [&](int r) -> std::int64_t {
    if (r == W * H) return 1;
    const int rx = (r % W) * n, ry = (r / W) * n;
    std::int64_t total = 0;
    for (const auto& p : patches) {
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) at(rx + x, ry + y) = p[static_cast<std::size_t>(y) * n + x];
      bool ok = true;
      for (int y = ry; y < ry + n && ok; ++y)
        for (int x = rx; x < rx + n && ok; ++x) {
          if (x + 1 < GX && !ok_pair(at(x, y), at(x + 1, y))) ok = false;
          if (x > 0 && !ok_pair(at(x, y), at(x - 1, y))) ok = false;
          if (y + 1 < GY && !ok_pair(at(x, y), at(x, y + 1))) ok = false;
          if (y > 0 && !ok_pair(at(x, y), at(x, y - 1))) ok = false;
        }
      if (ok) total += place(r + 1);
    }
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) at(rx + x, ry + y) = -1;
    return total;
  };
  return place(0);
}

}  // namespace bccmis::model
