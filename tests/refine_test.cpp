// §2.1 equation by equation on the paper's Fig. 2 configuration.
//
// Configuration (lattice 3 1 1, S = 4, spec/examples/fig2.trace): three level-0
// cells side by side, centers (2,2), (6,2), (10,2). The right cell (10,2) is
// refined first, so the middle cell c = (6,2) has a same-level neighbor on the
// left, two finer neighbors and an old junction (8,2) on the right, and the
// domain boundary above and below: every case of eq. (2)-(7) at once.
// Every expected set below was derived by hand from the equations (the
// derivation is in spec/examples/fig2.md), not printed by the code.
#include <gtest/gtest.h>

#include "test_util.h"

namespace bccmis {
namespace {

using test::vs;

constexpr const char* kFig2Before = "lattice 3 1 1\nrefine 10 2\n";
const Point c{6, 2};

TEST(Refine, Fig2Before_EdgeNeighborhoodIsAsDrawn) {
  //= erleben2009#eq-2a type=test
  //= erleben2009#eq-2b type=test
  const Graph g = test::build(kFig2Before);
  // (2a) B = N(c): 4 corners and the old junction on the right side.
  EXPECT_EQ(g.nbr(c), vs({{4, 0}, {4, 4}, {8, 0}, {8, 2}, {8, 4}}));
  // (2b) the junction has exactly three neighbors: c and the two finer cells.
  EXPECT_EQ(g.nbr({8, 2}), vs({{6, 2}, {9, 1}, {9, 3}}));
  // (6c) on the boundary (erratum E1): the right cell's new boundary junctions
  // join only its two children.
  EXPECT_EQ(g.nbr({10, 0}), vs({{9, 1}, {11, 1}}));
  EXPECT_EQ(g.nbr({12, 2}), vs({{11, 1}, {11, 3}}));
}

TEST(Refine, Eq4And5_CreatesFourChildrenAndOnlyTheMissingJunctions) {
  //= erleben2009#eq-4a type=test
  //= erleben2009#eq-5a type=test
  //= erleben2009#eq-5b type=test
  Graph g = test::build(kFig2Before);
  const RefineResult r = refine(g, c);
  ASSERT_TRUE(r.applied());
  // (4a) y_i is the child with corner p_i, halfway between c and p_i.
  EXPECT_EQ(r.Y, vs({{5, 1}, {5, 3}, {7, 1}, {7, 3}}));
  // (5a) ||J+|| = 4 - ||J|| = 3: left (same-level neighbor), bottom and top
  // (domain boundary); the right side keeps its old junction (8,2).
  EXPECT_EQ(r.J_plus, vs({{4, 2}, {6, 0}, {6, 4}}));
  for (const Point& j : r.J_plus) EXPECT_TRUE(g.is_node(j));
}

TEST(Refine, Eq4c_RefinedCellBecomesNodeOfItsFourChildren) {
  //= erleben2009#eq-4b type=test
  //= erleben2009#eq-4c type=test
  //= erleben2009#eq-4g type=test
  //= erleben2009#eq-4h type=test
  Graph g = test::build(kFig2Before);
  ASSERT_TRUE(refine(g, c).applied());
  EXPECT_TRUE(g.is_node(c));
  EXPECT_FALSE(g.is_center(c));
  EXPECT_EQ(g.nbr(c), vs({{5, 1}, {5, 3}, {7, 1}, {7, 3}}));
  EXPECT_EQ(g.level.count(c), 0u);
  for (const Point y : {Point{5, 1}, Point{5, 3}, Point{7, 1}, Point{7, 3}}) {
    EXPECT_TRUE(g.is_center(y));
    EXPECT_EQ(g.level_of(y), 1);  // (4b) with level(c) + 1
  }
}

TEST(Refine, Eq4e_PureCornersSwapCForTheirChild) {
  //= erleben2009#eq-2c type=test
  //= erleben2009#eq-4e type=test
  Graph g = test::build(kFig2Before);
  ASSERT_TRUE(refine(g, c).applied());
  EXPECT_EQ(g.nbr({4, 0}), vs({{2, 2}, {5, 1}}));
  EXPECT_EQ(g.nbr({4, 4}), vs({{2, 2}, {5, 3}}));
  EXPECT_EQ(g.nbr({8, 0}), vs({{7, 1}, {9, 1}}));
  EXPECT_EQ(g.nbr({8, 4}), vs({{7, 3}, {9, 3}}));
}

TEST(Refine, Eq6_NewJunctionJoinsNeighborAcrossTheSideAndTwoChildren) {
  //= erleben2009#eq-6a type=test
  //= erleben2009#eq-6b type=test
  //= erleben2009#eq-6c type=test
  Graph g = test::build(kFig2Before);
  ASSERT_TRUE(refine(g, c).applied());
  // Left side: x_k = N(p_i) ∩ N(p_j) = {(2,2)}, the same-level neighbor.
  EXPECT_EQ(g.nbr({4, 2}), vs({{2, 2}, {5, 1}, {5, 3}}));
  EXPECT_EQ(g.nbr({2, 2}), vs({{0, 0}, {0, 4}, {4, 0}, {4, 2}, {4, 4}}));
  // Boundary sides (erratum E1): x_k = ∅.
  EXPECT_EQ(g.nbr({6, 0}), vs({{5, 1}, {7, 1}}));
  EXPECT_EQ(g.nbr({6, 4}), vs({{5, 3}, {7, 3}}));
}

TEST(Refine, Eq4d_Eq7_OldJunctionMovesFromCToTheTwoChildrenBesideIt) {
  //= erleben2009#eq-4d type=test
  //= erleben2009#eq-7-condition type=test
  //= erleben2009#eq-7a type=test
  //= erleben2009#eq-7b type=test
  Graph g = test::build(kFig2Before);
  ASSERT_TRUE(refine(g, c).applied());
  // (4d) removes c; (7a) adds the children y_i with |N(j) ∩ N(p_i)| = 1.
  EXPECT_EQ(g.nbr({8, 2}), vs({{7, 1}, {7, 3}, {9, 1}, {9, 3}}));
}

TEST(Refine, Eq4f_Eq6d_Eq7b_ChildrenEndWithTheirFourCorners) {
  //= erleben2009#eq-4f type=test
  //= erleben2009#eq-6d type=test
  //= erleben2009#eq-6e type=test
  Graph g = test::build(kFig2Before);
  ASSERT_TRUE(refine(g, c).applied());
  EXPECT_EQ(g.nbr({5, 1}), vs({{4, 0}, {4, 2}, {6, 0}, {6, 2}}));
  EXPECT_EQ(g.nbr({5, 3}), vs({{4, 2}, {4, 4}, {6, 2}, {6, 4}}));
  EXPECT_EQ(g.nbr({7, 1}), vs({{6, 0}, {6, 2}, {8, 0}, {8, 2}}));
  EXPECT_EQ(g.nbr({7, 3}), vs({{6, 2}, {6, 4}, {8, 2}, {8, 4}}));
}

TEST(Refine, RootOfLattice111GivesFourCellsAndNineNodes) {
  //= erleben2009#claim-P-has-4 type=test
  Graph g = make_lattice({1, 1, 1});
  ASSERT_TRUE(refine(g, {2, 2}).applied());
  EXPECT_EQ(g.C.size(), 4u);
  EXPECT_EQ(g.N.size(), 9u);  // 4 corners + 4 side midpoints + the old center
}

TEST(Refine, Eq4_CountsChangeByOneNodePlusNewJunctions) {
  Graph g = test::build(kFig2Before);
  const auto C0 = g.C.size(), N0 = g.N.size();
  const RefineResult r = refine(g, c);
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(g.C.size(), C0 - 1 + 4);
  EXPECT_EQ(g.N.size(), N0 + 1 + r.J_plus.size());
}

// ---- Refusals: each code, in order, and nothing changes --------------------

void expect_refused(const std::string& setup, const Point& at, RefineRefusal expected) {
  Graph g = test::build(setup);
  const std::string before = canonical_state(g);
  const RefineResult r = refine(g, at);
  ASSERT_TRUE(r.refused.has_value()) << "refine (" << at.x << ", " << at.y << ") was applied";
  EXPECT_EQ(code(*r.refused), code(expected));
  EXPECT_EQ(canonical_state(g), before);
  EXPECT_TRUE(r.Y.empty());
  EXPECT_TRUE(r.J_plus.empty());
}

TEST(RefineRefusal, NoSuchCell_ForANodeAGapAndAPointOutside) {
  //= erleben2009#pre-refine-cell type=test
  expect_refused("lattice 2 2 1\n", {0, 0}, RefineRefusal::NoSuchCell);              // a node
  expect_refused("lattice 2 2 1\n", {1, 1}, RefineRefusal::NoSuchCell);              // nothing there
  expect_refused("lattice 2 2 1\n", {-2, 2}, RefineRefusal::NoSuchCell);             // outside
  expect_refused("lattice 1 1 1\nrefine 2 2\n", {2, 2}, RefineRefusal::NoSuchCell);  // now a node
}

TEST(RefineRefusal, MaxLevel_AtLevelL) {
  //= erleben2009#pre-refine-max-level type=test
  expect_refused("lattice 1 1 0\n", {1, 1}, RefineRefusal::MaxLevel);
  expect_refused("lattice 1 1 1\nrefine 2 2\n", {1, 1}, RefineRefusal::MaxLevel);
}

TEST(RefineRefusal, CoarserNeighbor_AcrossASide) {
  //= erleben2009#pre-refine-level type=test
  // Lattice 2 1 2 (S = 8): refine the left cell; its child (6,2) touches the
  // level-0 right cell along a side.
  expect_refused("lattice 2 1 2\nrefine 4 4\n", {6, 2}, RefineRefusal::CoarserNeighbor);
  // The order of the tests: max-level is reported before coarser-neighbor.
  expect_refused("lattice 2 1 1\nrefine 2 2\n", {3, 1}, RefineRefusal::MaxLevel);
}

TEST(RefineRefusal, NoSuchCellWinsOverEverythingElse) {
  expect_refused("lattice 1 1 0\n", {0, 0}, RefineRefusal::NoSuchCell);
}

}  // namespace
}  // namespace bccmis
