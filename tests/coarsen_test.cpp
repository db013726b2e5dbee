// §2.2 equation by equation on the paper's Fig. 3 configuration: the result of
// Fig. 2 (see refine_test.cpp) coarsened back. Expected sets derived by hand
// (spec/examples/fig2.md).
#include <gtest/gtest.h>

#include "test_util.h"

namespace bccmis {
namespace {

using test::vs;

constexpr const char* kFig2Before = "lattice 3 1 1\nrefine 10 2\n";
constexpr const char* kFig3Before = "lattice 3 1 1\nrefine 10 2\nrefine 6 2\n";
const Point n{6, 2};

TEST(Coarsen, Eq8a_Eq9f_TheFourChildrenAreDeleted) {
  //= erleben2009#eq-8a type=test
  //= erleben2009#eq-9b type=test
  //= erleben2009#eq-9f type=test
  Graph g = test::build(kFig3Before);
  const CoarsenResult r = coarsen(g, n);
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.Y, vs({{5, 1}, {5, 3}, {7, 1}, {7, 3}}));
  for (const Point& y : r.Y) {
    EXPECT_FALSE(g.is_center(y));
    EXPECT_FALSE(g.is_node(y));
    EXPECT_EQ(g.neighbors.count(y), 0u);
    EXPECT_EQ(g.level.count(y), 0u);
  }
}

TEST(Coarsen, Eq9d_Eq9e_Eq12a_NodeBecomesCenterOfTheRemainingBoundary) {
  //= erleben2009#eq-8b type=test
  //= erleben2009#eq-9c type=test
  //= erleben2009#eq-9d type=test
  //= erleben2009#eq-9e type=test
  //= erleben2009#eq-10b type=test
  //= erleben2009#eq-12a type=test
  Graph g = test::build(kFig3Before);
  ASSERT_TRUE(coarsen(g, n).applied());
  EXPECT_TRUE(g.is_center(n));
  EXPECT_FALSE(g.is_node(n));
  EXPECT_EQ(g.level_of(n), 0);
  // B (8b) is the 8 boundary nodes; minus J- (10b) leaves 4 corners and the
  // junction (8,2) that still has two finer cells beyond it.
  EXPECT_EQ(g.nbr(n), vs({{4, 0}, {4, 4}, {8, 0}, {8, 2}, {8, 4}}));
}

TEST(Coarsen, Eq10a_JMinusIsTheSideMidpointsLeftWithAtMostOneCell) {
  //= erleben2009#eq-10a type=test
  //= erleben2009#eq-10c type=test
  //= erleben2009#eq-11d type=test
  Graph g = test::build(kFig3Before);
  const CoarsenResult r = coarsen(g, n);
  ASSERT_TRUE(r.applied());
  // (4,2): one cell (2,2) beyond; (6,0), (6,4): the domain boundary (E2).
  EXPECT_EQ(r.J_minus, vs({{4, 2}, {6, 0}, {6, 4}}));
  for (const Point& j : r.J_minus) {
    EXPECT_FALSE(g.is_node(j));
    EXPECT_EQ(g.neighbors.count(j), 0u);
  }
  // The literal (10a) would also have taken the corners, which keep 1 cell.
  for (const Point b : {Point{4, 0}, Point{4, 4}, Point{8, 0}, Point{8, 4}}) EXPECT_TRUE(g.is_node(b));
}

TEST(Coarsen, Eq11b_NeighborAcrossADeletedJunctionForgetsIt) {
  //= erleben2009#eq-11a type=test
  //= erleben2009#eq-11b type=test
  //= erleben2009#eq-11c type=test
  Graph g = test::build(kFig3Before);
  ASSERT_TRUE(coarsen(g, n).applied());
  EXPECT_EQ(g.nbr({2, 2}), vs({{0, 0}, {0, 4}, {4, 0}, {4, 4}}));
}

TEST(Coarsen, Eq9a_Eq12b_BoundaryNodesSwapTheChildrenForN) {
  //= erleben2009#eq-9a type=test
  //= erleben2009#eq-12b type=test
  Graph g = test::build(kFig3Before);
  ASSERT_TRUE(coarsen(g, n).applied());
  EXPECT_EQ(g.nbr({4, 0}), vs({{2, 2}, {6, 2}}));
  EXPECT_EQ(g.nbr({8, 0}), vs({{6, 2}, {9, 1}}));
  EXPECT_EQ(g.nbr({8, 2}), vs({{6, 2}, {9, 1}, {9, 3}}));
  EXPECT_EQ(g.nbr({8, 4}), vs({{6, 2}, {9, 3}}));
}

TEST(Coarsen, Fig3_UndoesFig2Exactly) {
  //= erleben2009#claim-inverse type=test
  Graph g = test::build(kFig3Before);
  ASSERT_TRUE(coarsen(g, n).applied());
  EXPECT_EQ(canonical_state(g), canonical_state(test::build(kFig2Before)));
}

// ---- Refusals: each code, in order, and nothing changes --------------------

void expect_refused(const std::string& setup, const Point& at, CoarsenRefusal expected) {
  Graph g = test::build(setup);
  const std::string before = canonical_state(g);
  const CoarsenResult r = coarsen(g, at);
  ASSERT_TRUE(r.refused.has_value()) << "coarsen (" << at.x << ", " << at.y << ") was applied";
  EXPECT_EQ(code(*r.refused), code(expected));
  EXPECT_EQ(canonical_state(g), before);
  EXPECT_TRUE(r.Y.empty());
  EXPECT_TRUE(r.J_minus.empty());
}

TEST(CoarsenRefusal, NoSuchNode_ForACenterAGapAndAPointOutside) {
  //= erleben2009#pre-coarsen-node type=test
  expect_refused("lattice 2 2 1\n", {2, 2}, CoarsenRefusal::NoSuchNode);    // a center
  expect_refused("lattice 2 2 1\n", {1, 1}, CoarsenRefusal::NoSuchNode);    // nothing
  expect_refused("lattice 2 2 1\n", {99, -7}, CoarsenRefusal::NoSuchNode);  // outside
}

TEST(CoarsenRefusal, NotARefinedCenter_GridNodesAndSideMidpoints) {
  //= erleben2009#pre-coarsen-refined-center type=test
  //= erleben2009#pre-coarsen-not-junction type=test
  // An interior grid node has four cells around it (E3).
  expect_refused("lattice 2 2 1\n", {4, 4}, CoarsenRefusal::NotARefinedCenter);
  // A boundary grid node and a junction.
  expect_refused("lattice 2 2 1\n", {0, 0}, CoarsenRefusal::NotARefinedCenter);
  expect_refused("lattice 2 1 1\nrefine 6 2\n", {4, 2}, CoarsenRefusal::NotARefinedCenter);
  // A boundary side midpoint of a refined cell.
  expect_refused("lattice 1 1 1\nrefine 2 2\n", {2, 0}, CoarsenRefusal::NotARefinedCenter);
}

TEST(CoarsenRefusal, ChildrenRefined_WhenAChildIsItselfRefined) {
  //= erleben2009#pre-coarsen-children-leaves type=test
  expect_refused("lattice 1 1 2\nrefine 4 4\nrefine 2 2\n", {4, 4}, CoarsenRefusal::ChildrenRefined);
}

TEST(CoarsenRefusal, FinerNeighbor_WhenAChildHasAJunction) {
  //= erleben2009#pre-coarsen-balance type=test
  // Lattice 2 1 2 (S = 8): both cells refined, then the right cell's child
  // (10,2) beside the left cell's child (6,2) refined: coarsening (4,4) would
  // put a level-0 cell beside level-2 cells.
  expect_refused("lattice 2 1 2\nrefine 4 4\nrefine 12 4\nrefine 10 2\n", {4, 4}, CoarsenRefusal::FinerNeighbor);
}

}  // namespace
}  // namespace bccmis
