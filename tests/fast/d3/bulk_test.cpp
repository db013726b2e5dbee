// d3::fast::Lattice's bulk construction against the 3D reference: from_graph of
// states the reference reached by random operations (the same canonical
// state, a consistent lattice, and the same decisions on the operations that
// follow), and refine_each / coarsen_each against one reference call per
// position (lists with repeats and positions that are refused).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <random>
#include <stdexcept>
#include <vector>

#include "bccmis/d3/ops.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/io/d3/format.h"

namespace {

using namespace bccmis;

template <class Set>
d3::Point pick(std::mt19937_64& rng, const Set& set) {
  auto it = set.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(std::uniform_int_distribution<std::size_t>(0, set.size() - 1)(rng)));
  return *it;
}

// A random refine (of a cell) or coarsen (at a refined center) on g.
std::pair<bool, d3::Point> random_operation(std::mt19937_64& rng, const d3::Graph& g) {
  if (std::uniform_int_distribution<int>(0, 2)(rng) < 2) return {true, pick(rng, g.C)};
  std::vector<d3::Point> refined;
  for (const d3::Point& n : g.N)
    if (d3::refined_center_level(g.size, n)) refined.push_back(n);
  if (refined.empty()) return {true, pick(rng, g.C)};
  return {false, pick(rng, refined)};
}

TEST(Fast3Bulk, FromGraphOfRandomStatesContinuesInLockStep) {
  std::size_t applied = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    std::mt19937_64 rng(1900 + seed);
    auto uniform = [&](std::int64_t lo, std::int64_t hi) {
      return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
    };
    const d3::LatticeSize size{uniform(1, 2), uniform(1, 2), uniform(1, 2), static_cast<int>(uniform(1, 3))};
    d3::Graph g(size);
    for (int i = 0; i < 30; ++i) {
      const auto [is_refine, p] = random_operation(rng, g);
      if (is_refine)
        d3::refine(g, p);
      else
        d3::coarsen(g, p);
    }
    d3::fast::Lattice f = d3::fast::Lattice::from_graph(g);
    ASSERT_EQ(d3::fast::canonical_state(f), d3::canonical_state(g)) << "seed " << seed;
    ASSERT_EQ(f.audit(), std::nullopt) << "seed " << seed;
    for (int i = 0; i < 30; ++i) {
      const auto [is_refine, p] = random_operation(rng, g);
      const bool ours = is_refine ? f.refine(p).applied() : f.coarsen(p).applied();
      const bool theirs = is_refine ? d3::refine(g, p).applied() : d3::coarsen(g, p).applied();
      ASSERT_EQ(ours, theirs) << "seed " << seed << ", step " << i << " at " << d3::to_string(p);
      ASSERT_EQ(d3::fast::canonical_state(f), d3::canonical_state(g)) << "seed " << seed << ", step " << i;
      applied += ours;
    }
    ASSERT_EQ(f.audit(), std::nullopt) << "seed " << seed;
  }
  EXPECT_GT(applied, 40u * 10u);  // the continuations mostly apply
}

// Lists longer than coarsen_each's look-ahead (spec/lattice3d.md §9.12: 16
// positions): the prefetches must change no result.
TEST(Fast3Bulk, RefineEachAndCoarsenEachAreOneCallPerPosition) {
  const d3::LatticeSize size{2, 1, 1, 3};
  d3::Graph g(size);
  d3::fast::Lattice f(size);
  std::mt19937_64 rng(19);
  std::vector<std::vector<d3::Point>> refined;
  for (int level = 0; level < size.L; ++level) {
    std::vector<d3::Point> cells(g.C.begin(), g.C.end());
    refined.push_back(cells);
    // Repeats (refused: no longer a cell) and a position that is no vertex.
    const std::vector<d3::Point> again(cells.begin(), cells.begin() + std::min<std::ptrdiff_t>(3, std::ssize(cells)));
    cells.insert(cells.end(), again.begin(), again.end());
    cells.push_back({1, 1, 1});
    std::shuffle(cells.begin(), cells.end(), rng);
    std::size_t expected = 0;
    for (const d3::Point& c : cells) expected += d3::refine(g, c).applied();
    EXPECT_EQ(f.refine_each(cells), expected);
    ASSERT_EQ(d3::fast::canonical_state(f), d3::canonical_state(g)) << "level " << level;
  }
  for (int level = size.L - 1; level >= 0; --level) {
    std::vector<d3::Point> nodes = refined[static_cast<std::size_t>(level)];
    // A coarser center first (refused: its children are refined), repeats.
    if (level > 0) nodes.insert(nodes.begin(), refined[static_cast<std::size_t>(level - 1)].front());
    const std::vector<d3::Point> again(nodes.begin(), nodes.begin() + 2);
    nodes.insert(nodes.end(), again.begin(), again.end());
    std::shuffle(nodes.begin() + 1, nodes.end(), rng);
    std::size_t expected = 0;
    for (const d3::Point& n : nodes) expected += d3::coarsen(g, n).applied();
    EXPECT_EQ(f.coarsen_each(nodes), expected);
    ASSERT_EQ(d3::fast::canonical_state(f), d3::canonical_state(g)) << "level " << level;
  }
  EXPECT_EQ(f.cell_count(), 2u);
  EXPECT_EQ(f.audit(), std::nullopt);
}

TEST(Fast3Bulk, FromGraphRefusesGraphsItCannotHold) {
  d3::Graph g({1, 1, 1, 2});
  d3::refine(g, *g.C.begin());
  {
    d3::Graph bad = g;
    bad.level.erase(*bad.C.begin());  // a center without a level
    EXPECT_THROW(d3::fast::Lattice::from_graph(bad), std::invalid_argument);
  }
  {
    d3::Graph bad = g;
    bad.level[*bad.C.begin()] = 0;  // a level its position does not give
    EXPECT_THROW(d3::fast::Lattice::from_graph(bad), std::invalid_argument);
  }
  {
    d3::Graph bad = g;
    const d3::Point c = *bad.C.begin();
    bad.neighbors[c].insert({c.x + 1, c.y, c.z});  // a neighbor that is not a node
    EXPECT_THROW(d3::fast::Lattice::from_graph(bad), std::invalid_argument);
  }
  EXPECT_EQ(d3::fast::canonical_state(d3::fast::Lattice::from_graph(g)), d3::canonical_state(g));
}

}  // namespace
