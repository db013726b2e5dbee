// One regression test per erratum of spec/errata.toml. Each uses the erratum's
// minimal repro and asserts a fact that the literal reading of the paper gets
// wrong (the comment says what the literal reading does instead).
#include <gtest/gtest.h>

#include "bccmis/geometry.h"
#include "test_util.h"

namespace bccmis {
namespace {

using test::vs;

// E3: n has |N(n)| = 4 in g, which the paper's only test for coarsening
// asks, and coarsen(g, n) is refused nevertheless, with `why`.
void expect_four_cells_but_refused(Graph g, const Point& n, CoarsenRefusal why) {
  ASSERT_EQ(g.nbr(n).size(), 4u);
  EXPECT_EQ(coarsen(g, n).refused, why);
}

TEST(Errata, E1_RefineGivesBoundarySidesAMidpointNode) {
  //= erleben2009#eq-5a type=test
  //= erleben2009#eq-6c type=test
  // Literal (6): no corner pair of the root has a common cell once c is
  // removed, so no junction is connected; J+ stays isolated and the children
  // have 2 neighbors each.
  Graph g = make_lattice({1, 1, 1});  // S = 4, root center (2,2)
  const RefineResult r = refine(g, {2, 2});
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.J_plus, vs({{0, 2}, {2, 0}, {2, 4}, {4, 2}}));
  EXPECT_EQ(g.nbr({2, 0}), vs({{1, 1}, {3, 1}}));
  EXPECT_EQ(g.nbr({0, 2}), vs({{1, 1}, {1, 3}}));
  EXPECT_EQ(g.nbr({4, 2}), vs({{3, 1}, {3, 3}}));
  EXPECT_EQ(g.nbr({2, 4}), vs({{1, 3}, {3, 3}}));
  EXPECT_EQ(g.nbr({1, 1}), vs({{0, 0}, {0, 2}, {2, 0}, {2, 2}}));
  EXPECT_EQ(g.nbr({3, 3}), vs({{2, 2}, {2, 4}, {4, 2}, {4, 4}}));
}

TEST(Errata, E2_CoarsenKeepsBoundaryCornersAndDropsBoundaryMidpoints) {
  //= erleben2009#eq-10a type=test
  // Literal (10a): (4,0) and (4,4) fall to one neighbor and are deleted; the
  // boundary midpoints (2,0), (0,2), (2,4) fall to zero and are kept.
  const Graph initial = make_lattice({2, 1, 1});  // S = 4
  Graph g = initial;
  ASSERT_TRUE(refine(g, {2, 2}).applied());
  const CoarsenResult r = coarsen(g, {2, 2});
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.J_minus, vs({{0, 2}, {2, 0}, {2, 4}, {4, 2}}));
  EXPECT_TRUE(g.is_node({4, 0}));
  EXPECT_TRUE(g.is_node({4, 4}));
  EXPECT_FALSE(g.is_node({2, 0}));
  EXPECT_EQ(canonical_state(g), canonical_state(initial));
}

TEST(Errata, E3_GridNodeWithFourCellsIsNotCoarsenable) {
  //= erleben2009#pre-coarsen-refined-center type=test
  // Literal: |N(4,4)| = 4, accepted, and the result is a "level -1" cell.
  expect_four_cells_but_refused(make_lattice({2, 2, 1}), {4, 4}, CoarsenRefusal::NotARefinedCenter);
}

TEST(Errata, E3_MidpointBetweenTwoRefinedCellsIsNotCoarsenable) {
  // Literal: the shared side midpoint (8,6) has 4 cells around it and is
  // accepted, giving a cell that straddles two level-0 cells.
  expect_four_cells_but_refused(test::build("lattice 4 3 1\nrefine 6 6\nrefine 10 6\n"), {8, 6},
                                CoarsenRefusal::NotARefinedCenter);
}

TEST(Errata, E3_CenterWithARefinedChildIsNotCoarsenable) {
  //= erleben2009#pre-coarsen-children-leaves type=test
  // Literal: |N(4,4)| = 4 (three children and a grandchild), accepted, and the
  // new cell overlaps the grandchildren.
  expect_four_cells_but_refused(test::build("lattice 1 1 2\nrefine 4 4\nrefine 2 2\n"), {4, 4},
                                CoarsenRefusal::ChildrenRefined);
}

TEST(Errata, E3_SiblingsWithAFinerNeighborAreNotCoarsenable) {
  //= erleben2009#pre-coarsen-balance type=test
  // Literal: accepted; the level-0 cell (4,4) would then touch the level-2
  // cells (9,1), (9,3) along its right side (a level difference of 2).
  expect_four_cells_but_refused(test::build("lattice 2 1 2\nrefine 4 4\nrefine 12 4\nrefine 10 2\n"), {4, 4},
                                CoarsenRefusal::FinerNeighbor);
}

TEST(Errata, E4_DiagonalCoarserCellDoesNotBlockRefinement) {
  //= erleben2009#eq-3 type=test
  // Lattice 2 2 2 (S = 8): three of the four level-0 cells refined. The child
  // (6,6) has only level-1 cells along its sides, but touches the level-0
  // cell (12,12) at the corner (8,8). The formula of (3) (edge neighbors)
  // accepts; the sentence reading (all cells at the pure corners) refuses.
  Graph g = test::build("lattice 2 2 2\nrefine 4 4\nrefine 12 4\nrefine 4 12\n");
  ASSERT_TRUE(g.nbr({8, 8}).count({12, 12}));  // the sentence reading's X
  EXPECT_TRUE(refine(g, {6, 6}).applied());
}

TEST(Errata, E7_CoarsenedCellTakesTheLevelOfItsPosition) {
  Graph g = test::build("lattice 1 1 2\nrefine 4 4\nrefine 2 2\n");
  ASSERT_TRUE(coarsen(g, {2, 2}).applied());
  EXPECT_EQ(g.level_of({2, 2}), 1);
  ASSERT_TRUE(coarsen(g, {4, 4}).applied());
  EXPECT_EQ(g.level_of({4, 4}), 0);
}

TEST(Errata, E7_RefinedCenterLevelFromPosition) {
  const LatticeSize s{3, 2, 2};  // S = 8
  EXPECT_EQ(refined_center_level(s, {4, 4}), 0);
  EXPECT_EQ(refined_center_level(s, {12, 4}), 0);
  EXPECT_EQ(refined_center_level(s, {2, 6}), 1);
  EXPECT_EQ(refined_center_level(s, {1, 1}), std::nullopt);   // level-L center
  EXPECT_EQ(refined_center_level(s, {8, 8}), std::nullopt);   // grid node
  EXPECT_EQ(refined_center_level(s, {4, 8}), std::nullopt);   // side midpoint
  EXPECT_EQ(refined_center_level(s, {4, 2}), std::nullopt);   // mixed
  EXPECT_EQ(refined_center_level(s, {28, 4}), std::nullopt);  // outside (W*S = 24)
  EXPECT_EQ(refined_center_level(s, {-4, 4}), std::nullopt);
}

TEST(Errata, E6_TheGraphStoresTwoThirdsOfTheEdges) {
  // Counted by hand for a uniform W x H lattice: every cell has 4 diagonal
  // (stored) edges; the hull edges of eq. (1) are the W(H+1) horizontal and
  // H(W+1) vertical grid edges. The paper says the stored edges are a third.
  for (const LatticeSize s : {LatticeSize{1, 1, 0}, LatticeSize{4, 3, 1}, LatticeSize{10, 10, 0}}) {
    const Graph g = make_lattice(s);
    std::size_t stored = 0;
    for (const Point& c : g.C) stored += g.nbr(c).size();
    const auto W = static_cast<std::size_t>(s.W), H = static_cast<std::size_t>(s.H);
    EXPECT_EQ(stored, 4 * W * H);
    const std::size_t hull = W * (H + 1) + H * (W + 1);
    EXPECT_EQ(3 * stored, 2 * (stored + hull - W - H));  // exactly 2/3 of the edges off the boundary
    EXPECT_GT(3 * stored, stored + hull);                // more than one third, always
  }
}

}  // namespace
}  // namespace bccmis
