// §3's claim: refine and coarsen are exact inverses. Checked on every cell of
// several lattices, on full refinement and back, and on every reachable state
// of small lattices (whose number is known independently: tests/model/).
#include <gtest/gtest.h>

#include <deque>
#include <set>
#include <string>
#include <vector>

#include "test_util.h"

namespace bccmis {
namespace {

// Applies `op` at each of `points` (in sorted order) to a copy of g and
// checks that `inverse` at the same position restores the canonical state
// byte for byte.
template <class Op, class Inverse>
void expect_every_undone(const Graph& g, const PointSet& points, Op op, Inverse inverse, const std::string& op_name,
                         const std::string& inverse_name) {
  const std::string before = canonical_state(g);
  for (const Point& p : points) {
    Graph h = g;
    if (!op(h, p).applied()) continue;
    ASSERT_TRUE(inverse(h, p).applied()) << inverse_name << " after " << op_name << " of (" << p.x << ", " << p.y
                                         << ")";
    EXPECT_EQ(canonical_state(h), before) << op_name << "+" << inverse_name << " of (" << p.x << ", " << p.y << ")";
  }
}

// Refines every cell of g and checks that coarsening the same position
// restores the canonical state.
void expect_every_refine_undone(const Graph& g) {
  expect_every_undone(
      g, g.C, [](Graph& h, const Point& c) { return refine(h, c); },
      [](Graph& h, const Point& c) { return coarsen(h, c); }, "refine", "coarsen");
}

void expect_every_coarsen_undone(const Graph& g) {
  expect_every_undone(
      g, g.N, [](Graph& h, const Point& n) { return coarsen(h, n); },
      [](Graph& h, const Point& n) { return refine(h, n); }, "coarsen", "refine");
}

TEST(RoundTrip, RefineThenCoarsenOnInteriorBoundaryAndCornerCells) {
  //= erleben2009#claim-inverse type=test
  for (const LatticeSize s : {LatticeSize{1, 1, 1}, LatticeSize{2, 1, 2}, LatticeSize{3, 3, 2}, LatticeSize{4, 2, 3}}) {
    SCOPED_TRACE(testing::Message() << "lattice " << s.W << " " << s.H << " " << s.L);
    expect_every_refine_undone(make_lattice(s));
  }
  // Mixed levels: a 3x3 lattice with junctions on several sides.
  expect_every_refine_undone(
      test::build("lattice 3 3 2\nrefine 12 12\nrefine 4 12\nrefine 12 4\nrefine 10 10\nrefine 20 4\n"));
}

TEST(RoundTrip, CoarsenThenRefineOnMixedLevels) {
  //= erleben2009#claim-inverse type=test
  expect_every_coarsen_undone(
      test::build("lattice 3 3 2\nrefine 12 12\nrefine 4 12\nrefine 12 4\nrefine 10 10\nrefine 20 4\n"));
  expect_every_coarsen_undone(
      test::build("lattice 2 2 3\nrefine 8 8\nrefine 24 8\nrefine 8 24\nrefine 24 24\nrefine 12 12\nrefine 20 "
                  "12\nrefine 12 20\nrefine 14 14\n"));
}

TEST(RoundTrip, RefineEverythingToLevel2AndCoarsenEverythingBack) {
  //= erleben2009#claim-inverse type=test
  const Graph initial = make_lattice({3, 2, 2});
  Graph g = initial;
  for (int level = 0; level < 2; ++level) {
    const PointSet cells = g.C;
    for (const Point& c : cells) ASSERT_TRUE(refine(g, c).applied());
  }
  EXPECT_EQ(g.C.size(), 3u * 2u * 16u);
  // A uniform level-2 grid of 12 x 8 cells has 13 x 9 nodes.
  EXPECT_EQ(g.N.size(), 13u * 9u);
  for (bool changed = true; changed;) {
    changed = false;
    const PointSet nodes = g.N;
    for (const Point& n : nodes) changed |= coarsen(g, n).applied();
  }
  EXPECT_EQ(canonical_state(g), canonical_state(initial));
}

// Breadth-first search over every state reachable by refine and coarsen.
std::size_t count_reachable(const LatticeSize& s) {
  std::set<std::string> seen;
  std::deque<Graph> queue;
  queue.push_back(make_lattice(s));
  seen.insert(canonical_state(queue.front()));
  while (!queue.empty()) {
    const Graph g = queue.front();
    queue.pop_front();
    auto visit = [&](const Graph& h) {
      if (seen.insert(canonical_state(h)).second) queue.push_back(h);
    };
    for (const Point& c : g.C) {
      Graph h = g;
      if (refine(h, c).applied()) visit(h);
    }
    for (const Point& n : g.N) {
      Graph h = g;
      if (coarsen(h, n).applied()) visit(h);
    }
  }
  return seen.size();
}

TEST(ReachableStates, Lattice112Has17) { EXPECT_EQ(count_reachable({1, 1, 2}), 17u); }
TEST(ReachableStates, Lattice221Has16) { EXPECT_EQ(count_reachable({2, 2, 1}), 16u); }

}  // namespace
}  // namespace bccmis
