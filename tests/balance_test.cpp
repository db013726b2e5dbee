// The core's cascade refine_balanced, edge_neighbors and find_corner_imbalance
// (src/bccmis/balance.h), and coarsen_where and
// boundary_after_coarsen (src/bccmis/apps/balance.h), checked against an
// independent geometric closure on quadtree cells (level, i, j) that never
// looks at the graph's sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/geometry.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/ops.h"

namespace bccmis {
namespace {

// ---- The independent model: a set of split quadtree cells --------------------

/// A quadtree cell: level l, index (i, j) among the level-l cells.
using QCell = std::tuple<int, std::int64_t, std::int64_t>;

struct Closure {
  LatticeSize size;
  std::set<QCell> split;
  bool corner = false;  ///< the diagonal neighbors count too (corner balance)

  bool inside(const QCell& q) const {
    const auto [l, i, j] = q;
    const std::int64_t k = std::int64_t{1} << l;
    return l >= 0 && i >= 0 && j >= 0 && i < size.W * k && j < size.H * k;
  }

  /// Splits q and everything a balanced quadtree with q split must split:
  /// q's ancestors, and the parents of q's four same-level side neighbors
  /// (otherwise a child of q would touch a leaf two levels coarser); in
  /// corner mode the parents of the four diagonal neighbors too.
  void require(const QCell& q) {
    std::vector<QCell> work{q};
    while (!work.empty()) {
      const QCell c = work.back();
      work.pop_back();
      if (!inside(c) || !split.insert(c).second) continue;
      const auto [l, i, j] = c;
      if (l == 0) continue;
      work.push_back({l - 1, i / 2, j / 2});
      for (const auto& [di, dj] :
           std::array<std::pair<int, int>, 8>{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}}) {
        if (!corner && di != 0 && dj != 0) continue;
        const QCell n{l, i + di, j + dj};
        if (inside(n)) work.push_back({l - 1, (i + di) / 2, (j + dj) / 2});
      }
    }
  }

  /// The leaves as (level, center) pairs: unsplit cells whose parent is split.
  std::set<std::pair<int, Point>> leaves() const {
    std::set<std::pair<int, Point>> out;
    auto visit = [&](auto&& self, const QCell& q) -> void {
      const auto [l, i, j] = q;
      if (split.count(q) == 0) {
        const std::int64_t s = cell_side(size, l);
        out.insert({l, Point{i * s + s / 2, j * s + s / 2}});
        return;
      }
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) self(self, QCell{l + 1, 2 * i + a, 2 * j + b});
    };
    for (std::int64_t i = 0; i < size.W; ++i)
      for (std::int64_t j = 0; j < size.H; ++j) visit(visit, QCell{0, i, j});
    return out;
  }
};

QCell qcell_of(const Graph& g, const Point& c) {
  const int l = g.level_of(c);
  const std::int64_t s = cell_side(g.size, l);
  return {l, (c.x - s / 2) / s, (c.y - s / 2) / s};
}

std::set<std::pair<int, Point>> leaves_of(const Graph& g) {
  std::set<std::pair<int, Point>> out;
  for (const auto& [c, l] : g.level) out.insert({l, c});
  return out;
}

Point pick(const PointSet& s, std::mt19937_64& rng) {
  auto it = s.begin();
  std::advance(it, static_cast<long>(rng() % s.size()));
  return *it;
}

// ---- refine_balanced -------------------------------------------------------------

TEST(RefineBalanced, RefusesOnlyMissingCellsAndMaxLevel) {
  Graph g = make_lattice({2, 2, 1});
  const Graph before = g;
  EXPECT_EQ(refine_balanced(g, {3, 3}).refused, RefineRefusal::NoSuchCell);
  EXPECT_EQ(refine_balanced(g, {0, 0}).refused, RefineRefusal::NoSuchCell);
  EXPECT_EQ(g, before);
  ASSERT_TRUE(refine_balanced(g, {2, 2}).applied());
  const Graph once = g;
  EXPECT_EQ(refine_balanced(g, {1, 1}).refused, RefineRefusal::MaxLevel);
  EXPECT_EQ(g, once);
}

TEST(RefineBalanced, CascadesThroughCoarserNeighbors) {
  // 2x1 lattice, L = 3 (S = 16): the left cell A = (8, 8) is refined, then
  // its upper-left child (4, 12). Refining the level-2 cell (6, 14) needs its
  // right neighbor (12, 12) (level 1) refined first, which needs the right
  // cell B = (24, 8) (level 0) refined first: a chain of two.
  Graph g = make_lattice({2, 1, 3});
  ASSERT_TRUE(refine(g, {8, 8}).applied());
  ASSERT_TRUE(refine(g, {4, 12}).applied());
  EXPECT_EQ(can_refine(g, {6, 14}), RefineRefusal::CoarserNeighbor);
  const BalancedRefineResult r = refine_balanced(g, {6, 14});
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.refined, (std::vector<Point>{{24, 8}, {12, 12}, {6, 14}}));
  EXPECT_TRUE(is_valid(g)) << to_string(*find_violation(g));
  Closure m{g.size, {}};
  m.require({0, 0, 0});
  m.require({1, 0, 1});
  m.require({2, 1, 3});
  EXPECT_EQ(leaves_of(g), m.leaves());
}

void closure_in_any_order(Balance mode) {
  std::mt19937_64 rng(mode == Balance::Edge ? 20090303 : 20090304);
  const std::array<LatticeSize, 4> sizes{{{1, 1, 4}, {3, 2, 4}, {2, 3, 5}, {4, 4, 3}}};
  int states = 0;
  for (const LatticeSize& size : sizes) {
    for (int round = 0; round < 6; ++round) {
      // Phase 1: a random balanced start state, requests drawn from the live cells.
      Graph start = make_lattice(size);
      Closure model{size, {}, mode == Balance::Corner};
      const int requests = 2 + static_cast<int>(rng() % 8);
      for (int k = 0; k < requests; ++k) {
        const Point c = pick(start.C, rng);
        if (start.level_of(c) == size.L) continue;
        model.require(qcell_of(start, c));
        ASSERT_TRUE(refine_balanced(start, c, mode).applied());
        ASSERT_TRUE(is_valid(start)) << to_string(*find_violation(start));
        if (mode == Balance::Corner) {
          ASSERT_FALSE(find_corner_imbalance(start));
        }
      }
      ASSERT_EQ(leaves_of(start), model.leaves());

      // Phase 2: a batch of requests on cells of the start state, replayed in
      // several random orders: one leaf set, equal to the closure.
      std::vector<Point> batch;
      for (const Point& c : start.C)
        if (start.level_of(c) < size.L && rng() % 3 == 0) batch.push_back(c);
      Closure expected = model;
      for (const Point& c : batch) expected.require(qcell_of(start, c));
      std::string first;
      for (int order = 0; order < 5; ++order) {
        std::shuffle(batch.begin(), batch.end(), rng);
        Graph g = start;
        for (const Point& c : batch) {
          // A cascade may already have refined c: then it is no cell any more.
          const BalancedRefineResult r = refine_balanced(g, c, mode);
          if (!r.applied()) {
            ASSERT_EQ(r.refused, RefineRefusal::NoSuchCell);
          }
        }
        ASSERT_TRUE(is_valid(g)) << to_string(*find_violation(g));
        ASSERT_EQ(leaves_of(g), expected.leaves()) << "order " << order;
        ASSERT_EQ(find_corner_imbalance(g).has_value() && mode == Balance::Corner, false);
        const std::string text = canonical_state(g);
        if (order == 0) first = text;
        EXPECT_EQ(text, first) << "the order of the requests changed the state";
      }
      ++states;
    }
  }
  EXPECT_EQ(states, 24);
}

TEST(RefineBalanced, MatchesGeometricClosureInAnyOrder) { closure_in_any_order(Balance::Edge); }

TEST(RefineBalanced, CornerModeMatchesTheCornerClosureInAnyOrder) { closure_in_any_order(Balance::Corner); }

TEST(RefineBalanced, CornerModeAlsoRefinesDiagonalCoarserCells) {
  // 2x2 lattice, L = 2: refine the lower-left cell and its upper-right child
  // (edge mode cascades into the right and upper cells only). Corner mode
  // also refines the diagonal cell (24, 24), which touches that child's
  // children at the lattice's center point.
  for (const Balance mode : {Balance::Edge, Balance::Corner}) {
    Graph g = make_lattice({2, 2, 2});
    ASSERT_TRUE(refine_balanced(g, {4, 4}, mode).applied());
    const BalancedRefineResult r = refine_balanced(g, {6, 6}, mode);
    ASSERT_TRUE(r.applied());
    EXPECT_TRUE(is_valid(g));
    EXPECT_EQ(g.is_center({12, 12}), mode == Balance::Edge) << name(mode);
    EXPECT_EQ(find_corner_imbalance(g).has_value(), mode == Balance::Edge) << name(mode);
    EXPECT_EQ(r.refined.size(), mode == Balance::Edge ? 3u : 4u);
  }
}

// ---- edge_neighbors --------------------------------------------------------------

// Cells whose squares share a piece of side of positive length with c's.
PointSet touching_sides(const Graph& g, const Point& c) {
  auto box = [&](const Point& p) {
    const std::int64_t h = cell_side(g.size, g.level_of(p)) / 2;
    return std::array<std::int64_t, 4>{p.x - h, p.x + h, p.y - h, p.y + h};
  };
  const auto a = box(c);
  PointSet out;
  for (const Point& d : g.C) {
    if (d == c) continue;
    const auto b = box(d);
    const bool x_touch = a[1] == b[0] || b[1] == a[0];
    const bool y_touch = a[3] == b[2] || b[3] == a[2];
    const bool x_overlap = std::min(a[1], b[1]) > std::max(a[0], b[0]);
    const bool y_overlap = std::min(a[3], b[3]) > std::max(a[2], b[2]);
    if ((x_touch && y_overlap) || (y_touch && x_overlap)) out.insert(d);
  }
  return out;
}

TEST(EdgeNeighbors, AreTheCellsSharingASide) {
  std::mt19937_64 rng(7);
  Graph g = make_lattice({3, 3, 3});
  for (int k = 0; k < 40; ++k) refine_balanced(g, pick(g.C, rng));
  ASSERT_TRUE(is_valid(g));
  for (const Point& c : g.C) EXPECT_EQ(edge_neighbors(g, c), touching_sides(g, c)) << c.x << " " << c.y;
  EXPECT_TRUE(edge_neighbors(g, {0, 0}).empty());
}

// ---- coarsen_where and boundary_after_coarsen ------------------------------------

Graph random_state(const LatticeSize& size, int refinements, std::mt19937_64& rng) {
  Graph g = make_lattice(size);
  for (int k = 0; k < refinements; ++k) refine_balanced(g, pick(g.C, rng));
  return g;
}

TEST(CoarsenWhere, AlwaysTrueReturnsToTheInitialLattice) {
  std::mt19937_64 rng(11);
  for (int round = 0; round < 10; ++round) {
    const LatticeSize size{1 + static_cast<std::int64_t>(rng() % 3), 1 + static_cast<std::int64_t>(rng() % 3), 4};
    Graph g = random_state(size, 30, rng);
    const std::size_t refined = (g.C.size() - static_cast<std::size_t>(size.W * size.H)) / 3;
    const std::size_t done = coarsen_where(g, [](const Graph&, const Point&) { return true; });
    EXPECT_EQ(done, refined);  // every coarsening removes 3 cells
    EXPECT_EQ(g, make_lattice(size));
  }
}

TEST(CoarsenWhere, NeverTrueChangesNothingAndTheFixpointRespectsThePredicate) {
  std::mt19937_64 rng(12);
  Graph g = random_state({3, 3, 4}, 60, rng);
  const Graph before = g;
  EXPECT_EQ(coarsen_where(g, [](const Graph&, const Point&) { return false; }), 0u);
  EXPECT_EQ(g, before);
  // Only the left half may merge; every node left coarsenable is on the right.
  const std::int64_t mid = 3 * level0_side(g.size) / 2;
  auto left = [&](const Graph&, const Point& n) { return n.x < mid; };
  const std::size_t done = coarsen_where(g, left);
  EXPECT_GT(done, 0u);
  EXPECT_TRUE(is_valid(g)) << to_string(*find_violation(g));
  for (const Point& n : g.N) {
    if (!can_coarsen(g, n)) {
      EXPECT_GE(n.x, mid) << n.x << " " << n.y;
    }
  }
  for (const auto& [c, l] : before.level) {
    if (c.x - cell_side(g.size, l) / 2 >= mid) {
      EXPECT_TRUE(g.is_center(c)) << "right-half cell changed";
    }
  }
}

TEST(CoarsenWhere, BoundaryAfterCoarsenPredictsCoarsen) {
  std::mt19937_64 rng(13);
  int checked = 0;
  for (int round = 0; round < 8; ++round) {
    const Graph g = random_state({2, 2, 4}, 40, rng);
    for (const Point& n : g.N) {
      if (can_coarsen(g, n)) continue;
      const PointSet predicted = boundary_after_coarsen(g, n);
      Graph h = g;
      ASSERT_TRUE(coarsen(h, n).applied());
      EXPECT_EQ(predicted, h.nbr(n)) << n.x << " " << n.y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

// ---- Corner balance: the check and state counts -----------------------------------

/// The levels of the finest-level cells (an (W*2^L) x (H*2^L) grid) under
/// the leaves of g, and the 2:1 test on it: edge-adjacent fine cells, and in
/// corner mode diagonal ones too, lie in leaves at most one level apart. Two
/// leaves share a side piece iff two of their fine cells are edge-adjacent,
/// and touch at all iff two are edge- or diagonally adjacent.
struct FineGrid {
  std::int64_t w, h;
  std::vector<int> level;
  explicit FineGrid(const LatticeSize& s) : w(s.W << s.L), h(s.H << s.L), level(static_cast<std::size_t>(w * h), -1) {}
  void fill(const LatticeSize& s, int l, std::int64_t i, std::int64_t j) {
    const std::int64_t k = std::int64_t{1} << (s.L - l);
    for (std::int64_t a = i * k; a < (i + 1) * k; ++a)
      for (std::int64_t b = j * k; b < (j + 1) * k; ++b) level[static_cast<std::size_t>(b * w + a)] = l;
  }
  bool balanced(bool corner) const {
    for (std::int64_t b = 0; b < h; ++b)
      for (std::int64_t a = 0; a < w; ++a) {
        const int l = level[static_cast<std::size_t>(b * w + a)];
        for (const auto& [da, db] : std::array<std::pair<int, int>, 4>{{{1, 0}, {0, 1}, {1, 1}, {1, -1}}}) {
          if (!corner && da != 0 && db != 0) continue;
          const std::int64_t a2 = a + da, b2 = b + db;
          if (a2 < 0 || b2 < 0 || a2 >= w || b2 >= h) continue;
          if (std::abs(level[static_cast<std::size_t>(b2 * w + a2)] - l) > 1) return false;
        }
      }
    return true;
  }
};

FineGrid fine_grid(const Graph& g) {
  FineGrid f(g.size);
  for (const auto& [c, l] : g.level) {
    const auto [lq, i, j] = qcell_of(g, c);
    f.fill(g.size, lq, i, j);
  }
  return f;
}

TEST(CornerBalance, FindCornerImbalanceAgreesWithTheGeometry) {
  std::mt19937_64 rng(21);
  int unbalanced = 0;
  for (int round = 0; round < 30; ++round) {
    Graph g = random_state({3, 2, 4}, 1 + round % 8, rng);
    ASSERT_TRUE(is_valid(g));
    const bool geometric = !fine_grid(g).balanced(true);
    EXPECT_EQ(find_corner_imbalance(g).has_value(), geometric);
    unbalanced += geometric ? 1 : 0;
  }
  EXPECT_GT(unbalanced, 5);
  EXPECT_LT(unbalanced, 30);
}

// Every quadtree on the lattice, counted by the fine-grid test.
std::pair<std::size_t, std::size_t> count_balanced_quadtrees(const LatticeSize& s) {
  std::size_t edge = 0, corner = 0;
  FineGrid grid(s);
  std::vector<QCell> open;
  for (std::int64_t i = 0; i < s.W; ++i)
    for (std::int64_t j = 0; j < s.H; ++j) open.push_back({0, i, j});
  auto recurse = [&](auto&& self) -> void {
    if (open.empty()) {
      edge += grid.balanced(false) ? 1 : 0;
      corner += grid.balanced(true) ? 1 : 0;
      return;
    }
    const QCell q = open.back();
    open.pop_back();
    const auto [l, i, j] = q;
    grid.fill(s, l, i, j);  // q is a leaf
    self(self);
    if (l < s.L) {  // q is split
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) open.push_back({l + 1, 2 * i + a, 2 * j + b});
      self(self);
      open.resize(open.size() - 4);
    }
    open.push_back(q);
  };
  recurse(recurse);
  return {edge, corner};
}

// States reachable from the initial lattice by refine and coarsen under the
// mode's preconditions (can_refine_under, can_coarsen_under). A state is
// keyed by its set of split cells (one bit per cell that can be split); it is
// rebuilt from the initial lattice by refining the split cells coarsest first
// (legal in a balanced lattice), and its moves are read off the guards.
std::size_t count_reachable_states(const LatticeSize& s, Balance mode) {
  std::vector<std::pair<int, Point>> splittable;  // (level, center), sorted coarsest first
  for (int l = 0; l < s.L; ++l) {
    const std::int64_t side = cell_side(s, l);
    for (std::int64_t i = 0; i < (s.W << l); ++i)
      for (std::int64_t j = 0; j < (s.H << l); ++j)
        splittable.push_back({l, {i * side + side / 2, j * side + side / 2}});
  }
  EXPECT_LE(splittable.size(), 64u);
  std::map<Point, int> bit;
  for (std::size_t k = 0; k < splittable.size(); ++k) bit[splittable[k].second] = static_cast<int>(k);
  std::set<std::uint64_t> seen{0};
  std::vector<std::uint64_t> work{0};
  while (!work.empty()) {
    const std::uint64_t key = work.back();
    work.pop_back();
    Graph g = make_lattice(s);
    for (std::size_t k = 0; k < splittable.size(); ++k)
      if ((key >> k) & 1u) {
        EXPECT_TRUE(refine(g, splittable[k].second).applied());
      }
    auto visit = [&](std::uint64_t next) {
      if (seen.insert(next).second) work.push_back(next);
    };
    for (const Point& c : g.C)
      if (!can_refine_under(g, c, mode)) visit(key | (std::uint64_t{1} << bit.at(c)));
    for (const Point& n : g.N)
      if (refined_center_level(s, n) && !can_coarsen_under(g, n, mode)) visit(key & ~(std::uint64_t{1} << bit.at(n)));
  }
  return seen.size();
}

void expect_counts(const LatticeSize& s, std::size_t edge, std::size_t corner) {
  const auto [edge_trees, corner_trees] = count_balanced_quadtrees(s);
  EXPECT_EQ(edge_trees, edge);
  EXPECT_EQ(corner_trees, corner);
  EXPECT_EQ(count_reachable_states(s, Balance::Edge), edge_trees);
  EXPECT_EQ(count_reachable_states(s, Balance::Corner), corner_trees);
}

// The counts (edge, corner): every quadtree enumerated and tested on the fine
// grid, against the states the operations reach under each mode's guards.
// On 1x1 L=2 and 2x1 L=2 no cell can meet a cell two levels coarser at a
// corner only, so the counts agree; the smallest lattices where corner
// balance forbids states are 2x2 L=2 and 1x1 L=3 (CornerBalanceExhaustive).
TEST(CornerBalance, StateCountsMatchAnIndependentQuadtreeCount) {
  expect_counts({1, 1, 1}, 2, 2);
  expect_counts({1, 1, 2}, 17, 17);
  expect_counts({2, 1, 2}, 265, 265);
  expect_counts({3, 1, 1}, 8, 8);
}

// The 66k-state lattices, for the release build (label `exhaustive`).
TEST(CornerBalanceExhaustive, StateCountsMatchAnIndependentQuadtreeCount) {
  expect_counts({2, 2, 2}, 66641, 66129);
  expect_counts({1, 1, 3}, 66642, 66130);
}

TEST(CornerBalance, CoarsenWhereKeepsCornerBalance) {
  std::mt19937_64 rng(31);
  for (int round = 0; round < 10; ++round) {
    Graph g = make_lattice({3, 3, 4});
    for (int k = 0; k < 25; ++k) refine_balanced(g, pick(g.C, rng), Balance::Corner);
    ASSERT_FALSE(find_corner_imbalance(g));
    // Merge the left half: corner balance holds after every merge.
    const std::int64_t mid = 3 * level0_side(g.size) / 2;
    coarsen_where(
        g,
        [&](const Graph& now, const Point& n) {
          EXPECT_FALSE(find_corner_imbalance(now));
          return n.x < mid;
        },
        Balance::Corner);
    EXPECT_TRUE(is_valid(g));
    EXPECT_FALSE(find_corner_imbalance(g));
    coarsen_where(
        g, [](const Graph&, const Point&) { return true; }, Balance::Corner);
    EXPECT_EQ(g, make_lattice({3, 3, 4}));
  }
}

}  // namespace
}  // namespace bccmis
