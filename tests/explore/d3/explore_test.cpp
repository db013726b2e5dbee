// Exhaustive exploration of small 3D lattices (src/bccmis/explore, 3D): every
// state reachable by refine and coarsen, each checked by the independent 3D
// checker with the mesh layer, every operation tried on every vertex, every
// accepted one undone by its inverse.
//
// The counts are compared with an enumeration that uses no refine or coarsen
// at all (tests/d3/leaf_model.h): every octree leaf set of the lattice, kept
// when no two leaves two or more levels apart share an edge segment or a face
// patch. For every kept leaf set, the refine edges out of it are its leaves of
// level < L whose 8 children, put in its place, leave the set balanced. The
// state and edge counts of spec/lattice3d.md §6 are repeated in the table, so
// that a change of the enumeration cannot silently move both sides.
//
// The small lattices run with the properties (label `property`); 2 2 2 1
// (ExploreExhaustive3) under the label `exhaustive`, in the release build:
//   cmake --workflow --preset exhaustive
// and 2 1 1 2, 1 1 2 2 (ExploreLong3) only by hand.
#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

#include "bccmis/explore/d3/explore.h"
#include "d3/leaf_model.h"

namespace bccmis::d3 {
namespace {

struct Counts {
  std::int64_t states = 0;
  std::int64_t refine_edges = 0;
};

/// The balanced leaf sets and the refine edges out of them, by enumeration.
/// Leaves are compared pairwise; a leaf's children can only break the rule
/// with the leaves its own cube touches along an edge or a face.
Counts enumerate(const LatticeSize& size) {
  Counts out;
  std::vector<std::pair<Point, int>> leaves;
  std::vector<std::vector<std::size_t>> touching;
  model::for_each_leaf_set(size, [&](const model::Leaves& set) {
    leaves.assign(set.begin(), set.end());
    touching.assign(leaves.size(), {});
    for (std::size_t i = 0; i < leaves.size(); ++i)
      for (std::size_t j = i + 1; j < leaves.size(); ++j) {
        const auto& [a, la] = leaves[i];
        const auto& [b, lb] = leaves[j];
        if (model::unbalanced_pair(size, a, la, b, lb)) return;
        if (model::contact_dimension(model::cube(size, a, la), model::cube(size, b, lb)) >= 1) {
          touching[i].push_back(j);
          touching[j].push_back(i);
        }
      }
    ++out.states;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      const auto& [c, l] = leaves[i];
      if (l >= size.L) continue;
      bool balanced = true;
      for (const Point& child : model::children(size, c, l))
        for (const std::size_t j : touching[i])
          balanced = balanced && !model::unbalanced_pair(size, child, l + 1, leaves[j].first, leaves[j].second);
      out.refine_edges += balanced;
    }
  });
  return out;
}

struct Expected {
  LatticeSize size;
  std::int64_t states;
  std::int64_t refine_edges;
};

void PrintTo(const Expected& e, std::ostream* os) {
  *os << "lattice " << e.size.W << " " << e.size.H << " " << e.size.D << " " << e.size.L << ": " << e.states
      << " states, " << e.refine_edges << " refine edges";
}

std::string name_of(const testing::TestParamInfo<Expected>& info) {
  const LatticeSize& s = info.param.size;
  return "W" + std::to_string(s.W) + "_H" + std::to_string(s.H) + "_D" + std::to_string(s.D) + "_L" +
         std::to_string(s.L);
}

void expect_counts(const Expected& e) {
  const Counts independent = enumerate(e.size);
  EXPECT_EQ(independent.states, e.states) << "enumeration";
  EXPECT_EQ(independent.refine_edges, e.refine_edges) << "enumeration";

  const ExploreResult r = explore(e.size);
  testing::Test::RecordProperty("seconds", std::to_string(r.seconds));
  ASSERT_FALSE(r.first_failure.has_value()) << r.first_failure->message << "\nreproducer trace:\n"
                                            << r.first_failure->trace;
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(r.states, independent.states) << summary(r);
  EXPECT_EQ(r.refine_edges, independent.refine_edges) << summary(r);
  EXPECT_EQ(r.coarsen_edges, r.refine_edges) << summary(r);  // each coarsen edge is a refine edge reversed
  std::cout << summary(r) << "\n";
}

class ExploreSmall3 : public testing::TestWithParam<Expected> {};
TEST_P(ExploreSmall3, EveryReachableStateIsValidAndCountsMatchTheEnumeration) {
  //= bccmis3d#fact-counts type=test
  expect_counts(GetParam());
}
// 1 1 1 1: the root or its 8 children (1 edge). 1 1 1 2: the root, or the 8
// children with any subset refined; 1 edge from the root, and 8 * 2^7 from
// the subsets (each unrefined child of each). 2 2 1 1: each of 4 cubes refined
// or not (4 * 2^3 edges).
INSTANTIATE_TEST_SUITE_P(Lattices, ExploreSmall3,
                         testing::Values(Expected{{1, 1, 1, 1}, 2, 1}, Expected{{1, 1, 1, 2}, 257, 1025},
                                         Expected{{2, 2, 1, 1}, 16, 32}),
                         name_of);

class ExploreExhaustive3 : public testing::TestWithParam<Expected> {};
TEST_P(ExploreExhaustive3, EveryReachableStateIsValidAndCountsMatchTheEnumeration) {
  //= bccmis3d#fact-counts type=test
  expect_counts(GetParam());
}
// 2 2 2 1: each of 8 cubes refined or not (8 * 2^7 edges).
INSTANTIATE_TEST_SUITE_P(Lattices, ExploreExhaustive3, testing::Values(Expected{{2, 2, 2, 1}, 256, 1024}), name_of);

// Beyond the exhaustive workflow's budget (tens of CPU minutes each in the
// release build): not registered with ctest, run by hand with
//   build/release/tests/d3_explore_tests --gtest_filter='*ExploreLong3*'
// Two cubes of 257 leaf sets each: both refined (2^16 states, 2 * 2^8 * 8 * 2^7
// edges), one unrefined and the other's 4 children away from it free (2 * 16
// states, 2 * (16 + 4 * 2^3) edges), both unrefined (1 state, 2 edges).
class ExploreLong3 : public testing::TestWithParam<Expected> {};
TEST_P(ExploreLong3, EveryReachableStateIsValidAndCountsMatchTheEnumeration) {
  //= bccmis3d#fact-counts type=test
  expect_counts(GetParam());
}
INSTANTIATE_TEST_SUITE_P(Lattices, ExploreLong3,
                         testing::Values(Expected{{2, 1, 1, 2}, 65569, 524386}, Expected{{1, 1, 2, 2}, 65569, 524386}),
                         name_of);

// The enumeration alone for ExploreLong3's lattices (seconds in the release
// build), against the counts by hand: runs with the exhaustive workflow.
class EnumerationExhaustive3 : public testing::TestWithParam<Expected> {};
TEST_P(EnumerationExhaustive3, CountsMatchTheCountsByHand) {
  const Counts independent = enumerate(GetParam().size);
  EXPECT_EQ(independent.states, GetParam().states);
  EXPECT_EQ(independent.refine_edges, GetParam().refine_edges);
}
INSTANTIATE_TEST_SUITE_P(Lattices, EnumerationExhaustive3,
                         testing::Values(Expected{{2, 1, 1, 2}, 65569, 524386}, Expected{{1, 1, 2, 2}, 65569, 524386}),
                         name_of);

// ---- The 3D explorer itself ---------------------------------------------------

TEST(ExploreKey3, RoundTripsValidAndBrokenGraphs) {
  Graph g(LatticeSize{2, 1, 1, 2});
  ASSERT_TRUE(refine(g, Point{4, 4, 4}).applied());
  ASSERT_TRUE(refine(g, Point{2, 2, 2}).applied());
  EXPECT_EQ(decode_state_key(encode_state_key(g), g.size), g);
  EXPECT_EQ(encode_state_key(g)[0], '\0');  // the compact encoding

  Graph outside = g;
  outside.N.insert(Point{-3, 100, 2});
  Graph no_level = g;
  no_level.level.erase(Point{12, 4, 4});
  for (const Graph* h : {&outside, &no_level}) {
    const std::string key = encode_state_key(*h);
    EXPECT_EQ(key[0], '\1');
    EXPECT_EQ(decode_state_key(key, h->size), *h);
    EXPECT_NE(key, encode_state_key(g));
  }
  Graph fewer = g;
  fewer.neighbors[Point{4, 4, 4}].erase(*g.nbr(Point{4, 4, 4}).begin());  // one neighbour less, still compact
  EXPECT_NE(encode_state_key(fewer), encode_state_key(g));
  EXPECT_EQ(decode_state_key(encode_state_key(fewer), g.size), fewer);
}

TEST(Explore3, SummaryAndJsonNameTheFourNumbers) {
  const ExploreResult r = explore(LatticeSize{1, 1, 1, 1});
  EXPECT_EQ(summary(r).rfind("explore 1 1 1 1: 2 states, 1 refine edges, 1 coarsen edges, ", 0), 0u) << summary(r);
  EXPECT_NE(to_json(r).find("{\"W\": 1, \"H\": 1, \"D\": 1, \"L\": 1, \"states\": 2, "), std::string::npos);
  EXPECT_TRUE(r.ok());
}

TEST(Explore3, ResultDoesNotDependOnTheNumberOfThreads) {
  ExploreOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const ExploreResult a = explore(LatticeSize{2, 2, 1, 1}, one);
  const ExploreResult b = explore(LatticeSize{2, 2, 1, 1}, two);
  EXPECT_EQ(a.states, b.states);
  EXPECT_EQ(a.refine_edges, b.refine_edges);
  EXPECT_EQ(a.ops_tried, b.ops_tried);
  EXPECT_EQ(a.key_bytes, b.key_bytes);
}

// The explorer's checks can fail: a coarsen that refuses everything breaks
// the inverse; a refine that changes the graph when it refuses is caught with
// the refused call named; a state the checker rejects stops the search.
TEST(Explore3, ReportsABrokenInverse) {
  ExploreOptions options;
  options.coarsen = [](Graph& g, const Point& n) {
    CoarsenResult r;
    r.refused = g.is_node(n) ? CoarsenRefusal::FinerNeighbor : CoarsenRefusal::NoSuchNode;
    return r;
  };
  const ExploreResult r = explore(LatticeSize{1, 1, 1, 1}, options);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_NE(r.first_failure->message.find("refine (2, 2, 2) then coarsen (2, 2, 2): the coarsen was refused"),
            std::string::npos)
      << r.first_failure->message;
  EXPECT_EQ(r.first_failure->trace, "lattice 1 1 1 1\nrefine 2 2 2\ncoarsen 2 2 2\n");
  EXPECT_FALSE(r.ok());
}

TEST(Explore3, ReportsARefusalThatChangesTheState) {
  ExploreOptions options;
  options.refine = [](Graph& g, const Point& c) {
    RefineResult r = refine(g, c);
    if (r.refused && g.is_node(c)) g.neighbors[c].insert(Point{0, 0, 0});
    return r;
  };
  const ExploreResult r = explore(LatticeSize{1, 1, 1, 1}, options);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_NE(r.first_failure->message.find("was refused (no-such-cell) but changed the state"), std::string::npos)
      << r.first_failure->message;
}

TEST(Explore3, ReportsAnInvalidState) {
  ExploreOptions options;
  options.refine = [](Graph& g, const Point& c) {
    RefineResult r = refine(g, c);
    if (r.applied()) g.level[*r.Y.begin()] = 0;  // a child that claims level 0
    return r;
  };
  options.coarsen = [](Graph& g, const Point& n) {
    if (!g.is_node(n) || g.nbr(n).size() != 8) return coarsen(g, n);
    for (const Point& y : g.nbr(n)) g.level[y] = 1;  // undo the planted level before coarsening
    return coarsen(g, n);
  };
  const ExploreResult r = explore(LatticeSize{1, 1, 1, 1}, options);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_EQ(r.first_failure->message.rfind("invalid state: ", 0), 0u) << r.first_failure->message;
}

}  // namespace
}  // namespace bccmis::d3
