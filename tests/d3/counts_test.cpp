// The exact state counts of spec/lattice3d.md §6, two ways: breadth-first
// search over refine and coarsen from the initial lattice, and enumeration of
// the balanced octree leaf sets directly (tests/d3/leaf_model.h, no refine or
// coarsen). The two must give the same sets of leaf sets, not only the same
// numbers.
#include <gtest/gtest.h>

#include <deque>
#include <set>

#include "check.h"
#include "util.h"

namespace bccmis::d3 {
namespace {

std::set<model::Leaves> reachable(const LatticeSize& size) {
  std::set<std::string> seen;
  std::set<model::Leaves> out;
  std::deque<Graph> queue{Graph(size)};
  seen.insert(canonical_state(queue.front()));
  while (!queue.empty()) {
    const Graph g = std::move(queue.front());
    queue.pop_front();
    EXPECT_EQ(test::state_problem(g), "");
    out.insert(test::leaves_of(g));
    auto visit = [&](Graph&& h) {
      if (seen.insert(canonical_state(h)).second) queue.push_back(std::move(h));
    };
    for (const Point& c : g.C)
      if (!can_refine(g, c)) {
        Graph h = g;
        refine(h, c);
        visit(std::move(h));
      }
    for (const Point& n : g.N)
      if (!can_coarsen(g, n)) {
        Graph h = g;
        coarsen(h, n);
        visit(std::move(h));
      }
  }
  EXPECT_EQ(seen.size(), out.size());
  return out;
}

std::set<model::Leaves> enumerated(const LatticeSize& size) {
  std::set<model::Leaves> out;
  for (const model::Leaves& leaves : model::all_leaf_sets(size)) {
    EXPECT_EQ(model::tiling_problem(size, leaves), "");
    if (model::balance_problem(size, leaves, model::geometric_graph(size, leaves)).empty()) out.insert(leaves);
  }
  return out;
}

// BFS over refine/coarsen reaches `count` states, and the same leaf sets
// as the enumeration of balanced octree tilings.
void expect_states(const LatticeSize& size, std::size_t count) {
  const auto bfs = reachable(size);
  EXPECT_EQ(bfs.size(), count);
  EXPECT_EQ(bfs, enumerated(size));
}

TEST(D3Counts, Lattice1111HasTwoStates) {
  //= bccmis3d#fact-counts type=test
  expect_states(LatticeSize{1, 1, 1, 1}, 2u);
}

TEST(D3Counts, Lattice1112Has257States) {
  //= bccmis3d#fact-counts type=test
  // The root, or its 8 children with any subset of them refined: 1 + 2^8.
  expect_states(LatticeSize{1, 1, 1, 2}, 257u);
}

TEST(D3Counts, Lattice2211HasSixteenStates) {
  //= bccmis3d#fact-counts type=test
  // Four level-0 cubes, each refined or not: levels 0 and 1 are always balanced.
  expect_states(LatticeSize{2, 2, 1, 1}, 16u);
}

TEST(D3Counts, BalanceFiltersTheEnumeration) {
  // lattice 2 1 1 2: 257^2 octree leaf sets, of which the balanced ones are
  // those where no level-2 cube meets the other level-0 cube along the shared
  // face or its edges. Counted here only by enumeration against BFS on the
  // smaller 1 1 1 2 above; this checks that the enumeration's balance filter
  // rejects something (it must be able to fail).
  const LatticeSize size{2, 1, 1, 2};
  model::Leaves unbalanced{{{12, 4, 4}, 0}};
  for (const Point c :
       {Point{2, 2, 2}, Point{2, 2, 6}, Point{2, 6, 2}, Point{2, 6, 6}, Point{6, 2, 6}, Point{6, 6, 2}, Point{6, 6, 6}})
    unbalanced[c] = 1;
  for (const Point c : {Point{5, 1, 1}, Point{5, 1, 3}, Point{5, 3, 1}, Point{5, 3, 3}, Point{7, 1, 1}, Point{7, 1, 3},
                        Point{7, 3, 1}, Point{7, 3, 3}})
    unbalanced[c] = 2;
  EXPECT_EQ(model::tiling_problem(size, unbalanced), "");
  EXPECT_NE(model::balance_problem(size, unbalanced, model::geometric_graph(size, unbalanced)), "");
}

}  // namespace
}  // namespace bccmis::d3
