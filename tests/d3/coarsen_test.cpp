// spec/lattice3d.md §5, equation by equation, on the hand example of §7
// (lattice 2 1 1 2, spec/examples/d3/face.trace). Expected sets by hand.
#include <gtest/gtest.h>

#include "util.h"

namespace bccmis::d3 {
namespace {

using test::vs;

constexpr const char* kRefinedLeft = "lattice 2 1 1 2\nrefine 4 4 4\n";
constexpr const char* kRefinedBoth = "lattice 2 1 1 2\nrefine 4 4 4\nrefine 12 4 4\n";
const Point n{4, 4, 4};
const PointSet kChildren = vs({{2, 2, 2}, {2, 2, 6}, {2, 6, 2}, {2, 6, 6}, {6, 2, 2}, {6, 2, 6}, {6, 6, 2}, {6, 6, 6}});
const PointSet kMidpoints = test::edge_midpoints_and_face_centers_of_cube_0_8();
const PointSet kShared = vs({{8, 0, 4}, {8, 4, 0}, {8, 4, 4}, {8, 4, 8}, {8, 8, 4}});

// Every vertex of `deleted` is gone from g: no center, no node, no
// neighbor set, no level.
void expect_deleted(const Graph& g, const PointSet& deleted) {
  for (const Point& p : deleted) {
    EXPECT_FALSE(g.is_center(p)) << to_string(p);
    EXPECT_FALSE(g.is_node(p)) << to_string(p);
    EXPECT_EQ(g.neighbors.count(p), 0u) << to_string(p);
    EXPECT_EQ(g.level.count(p), 0u) << to_string(p);
  }
}

TEST(D3Coarsen, K1_BoundaryIsTwentySixNodesClassifiedByChildren) {
  //= bccmis3d#eq-K1a type=test
  //= bccmis3d#eq-K1b type=test
  //= bccmis3d#eq-K1c type=test
  const Graph g = test::build(kRefinedLeft);
  // K1a: Y = N(n) is the 8 children.
  EXPECT_EQ(g.nbr(n), kChildren);
  // K1b/K1c: the children's boundary minus n is {0, 4, 8}^3 \ {n}; corners
  // are in 1 child, edge midpoints in 2, face centers in 4.
  PointSet B;
  for (const Point& y : kChildren)
    for (const Point& b : g.nbr(y)) B.insert(b);
  B.erase(n);
  EXPECT_EQ(B.size(), 26u);
  for (const Point& b : B) {
    std::size_t k = 0;
    for (const Point& y : g.nbr(b)) k += kChildren.count(y);
    const bool is_midpoint = kMidpoints.count(b) != 0;
    const bool is_face_center = (b.x == 4) + (b.y == 4) + (b.z == 4) == 2;
    EXPECT_EQ(k, is_midpoint ? (is_face_center ? 4u : 2u) : 1u) << to_string(b);
  }
}

TEST(D3Coarsen, K2_TheEightChildrenAreDeletedAndNBecomesACenter) {
  //= bccmis3d#eq-K2a type=test
  //= bccmis3d#eq-K2b type=test
  //= bccmis3d#eq-K2c type=test
  //= bccmis3d#eq-K2d type=test
  //= bccmis3d#eq-K2e type=test
  //= bccmis3d#eq-K2f type=test
  Graph g = test::build(kRefinedLeft);
  const CoarsenResult r = coarsen(g, n);
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.Y, kChildren);
  expect_deleted(g, kChildren);
  EXPECT_FALSE(g.is_node(n));
  EXPECT_TRUE(g.is_center(n));
  EXPECT_EQ(g.level_of(n), 0);
  // K2a then K4b: a corner of the coarse cube lost its child and has n again.
  EXPECT_EQ(g.nbr({0, 0, 0}), vs({n}));
  EXPECT_EQ(g.nbr({8, 8, 8}), vs({n, {12, 4, 4}}));
}

TEST(D3Coarsen, K3a_JMinusIsTheMidpointsNoRemainingCellHasAsCorner) {
  //= bccmis3d#eq-K3a type=test
  //= bccmis3d#eq-K3b type=test
  //= bccmis3d#eq-K3c type=test
  //= bccmis3d#eq-K3d type=test
  //= bccmis3d#eq-K3e type=test
  //= bccmis3d#eq-K4a type=test
  Graph g = test::build(kRefinedLeft);
  const CoarsenResult r = coarsen(g, n);
  ASSERT_TRUE(r.applied());
  // All 18: 13 on the domain boundary keep no cell; the 5 on x = 8 keep only
  // the level-0 cube (12,4,4), for which they are not corners.
  EXPECT_EQ(r.J_minus, kMidpoints);
  expect_deleted(g, kMidpoints);
  // K3d: the cube beyond lost them; K4a: n has its 8 corners.
  EXPECT_EQ(g.nbr({12, 4, 4}).size(), 8u);
  EXPECT_EQ(g.nbr(n), vs({{0, 0, 0}, {0, 0, 8}, {0, 8, 0}, {0, 8, 8}, {8, 0, 0}, {8, 0, 8}, {8, 8, 0}, {8, 8, 8}}));
}

TEST(D3Coarsen, K3a_KeepsMidpointsOfFinerNeighbours) {
  //= bccmis3d#eq-K3a type=test
  //= bccmis3d#eq-K3b type=test
  //= bccmis3d#eq-K4a type=test
  //= bccmis3d#eq-K4b type=test
  Graph g = test::build(kRefinedBoth);
  const CoarsenResult r = coarsen(g, n);
  ASSERT_TRUE(r.applied());
  // The 5 nodes on x = 8 are corners of the right cube's level-1 children: kept.
  PointSet expected_deleted;
  for (const Point& j : kMidpoints)
    if (!kShared.count(j)) expected_deleted.insert(j);
  EXPECT_EQ(r.J_minus, expected_deleted);
  // They are junctions of the coarse cell now: 5 for the face center, 3 for
  // the edge midpoints (domain boundary), and n lists 8 + 5 nodes.
  EXPECT_EQ(g.nbr({8, 4, 4}), vs({n, {10, 2, 2}, {10, 2, 6}, {10, 6, 2}, {10, 6, 6}}));
  EXPECT_EQ(g.nbr({8, 4, 0}), vs({n, {10, 2, 2}, {10, 6, 2}}));
  EXPECT_EQ(g.nbr(n).size(), 13u);
  for (const Point& j : kShared) EXPECT_TRUE(g.nbr(n).count(j));
  // And it is the state of refining the right cube alone.
  EXPECT_EQ(g, test::build("lattice 2 1 1 2\nrefine 12 4 4\n"));
}

TEST(D3Coarsen, K3a_DeletesInteriorMidpointsLeftWithThreeCoarseCells) {
  //= bccmis3d#eq-K3a type=test
  // lattice 2 2 2 1 (S = 4): refine and coarsen the cube (2,2,2). After K2a
  // the interior edge midpoint (4,4,2) keeps the 3 other level-0 cubes around
  // its edge and the interior face center (4,2,2) keeps 1: neither is a corner
  // of a remaining cell, so both are deleted, although a count of 3 means
  // "keep" for a corner on a domain face (spec/lattice3d.md §5).
  Graph g = test::build("lattice 2 2 2 1\nrefine 2 2 2\n");
  EXPECT_EQ(g.nbr({4, 4, 2}).size(), 5u);
  EXPECT_EQ(g.nbr({4, 2, 2}).size(), 5u);
  const CoarsenResult r = coarsen(g, {2, 2, 2});
  ASSERT_TRUE(r.applied());
  EXPECT_TRUE(r.J_minus.count({4, 4, 2}));
  EXPECT_TRUE(r.J_minus.count({4, 2, 2}));
  EXPECT_EQ(r.J_minus.size(), 18u);
  EXPECT_EQ(g, Graph(LatticeSize{2, 2, 2, 1}));
  // A corner of the coarse cube is never in M: (4,0,0), on a domain edge, kept
  // 1 cell after K2a (the count the 2D rule deletes at) and stays.
  EXPECT_EQ(g.nbr({4, 0, 0}), vs({{2, 2, 2}, {6, 2, 2}}));
}

TEST(D3Coarsen, Claim_InverseOfRefine) {
  //= bccmis3d#claim-inverse type=test
  Graph g = test::build("lattice 2 1 1 2\n");
  const Graph before = g;
  ASSERT_TRUE(refine(g, n).applied());
  ASSERT_TRUE(coarsen(g, n).applied());
  EXPECT_EQ(g, before);
}

}  // namespace
}  // namespace bccmis::d3
