// spec/lattice3d.md §4, equation by equation, on the hand examples of §7:
// lattice 1 1 1 1 with the root refined (spec/examples/d3/root.trace) and
// lattice 2 1 1 2 with one cube refined (d3/face.trace). Every expected set
// below is derived by hand from the geometry (spec/lattice3d.md §7), not
// printed by the code.
#include <gtest/gtest.h>

#include "util.h"

namespace bccmis::d3 {
namespace {

using test::vs;

constexpr const char* kRoot = "lattice 1 1 1 1\n";
constexpr const char* kTwo = "lattice 2 1 1 2\n";
const Point root{2, 2, 2};

// The 8 points {a, b}^3.
PointSet corners(std::int64_t a, std::int64_t b) {
  PointSet s;
  for (std::int64_t x : {a, b})
    for (std::int64_t y : {a, b})
      for (std::int64_t z : {a, b}) s.insert({x, y, z});
  return s;
}

TEST(D3Refine, R1_BoundaryCellHasOnlyItsCorners) {
  //= bccmis3d#eq-R1a type=test
  //= bccmis3d#eq-R1b type=test
  //= bccmis3d#eq-R1c type=test
  //= bccmis3d#claim-P-has-8 type=test
  const Graph g = test::build(kRoot);
  // R1a: B = N(c) is the 8 corners {0, 4}^3; each has N = {c}, so J = ∅ and P = B.
  EXPECT_EQ(g.nbr(root), corners(0, 4));
  for (const Point& b : g.nbr(root)) EXPECT_EQ(g.nbr(b), vs({root}));
  // Every pair of corners shares only c: X = ∅, and the sets cannot tell an
  // edge from a diagonal (choice Q2).
  EXPECT_EQ(can_refine(g, root), std::nullopt);
}

TEST(D3Refine, R1_FaceNeighbourJunctions) {
  //= bccmis3d#eq-R1b type=test
  //= bccmis3d#eq-R1d type=test
  const Graph g = test::build(std::string(kTwo) + "refine 4 4 4\n");
  const Point right{12, 4, 4};
  // B = N(right): its 8 corners and the 5 nodes the refinement put on the face x = 8.
  const PointSet face_nodes = vs({{8, 0, 4}, {8, 4, 0}, {8, 4, 4}, {8, 4, 8}, {8, 8, 4}});
  PointSet B = face_nodes;
  for (const Point& p :
       vs({{8, 0, 0}, {8, 0, 8}, {8, 8, 0}, {8, 8, 8}, {16, 0, 0}, {16, 0, 8}, {16, 8, 0}, {16, 8, 8}}))
    B.insert(p);
  EXPECT_EQ(g.nbr(right), B);
  // R1b: J by cardinality: the face center has 5 cells, the four edge
  // midpoints (on the domain boundary) 3; the corners have 1 or 2 (pure).
  EXPECT_EQ(g.nbr({8, 4, 4}).size(), 5u);
  for (const Point& j : vs({{8, 0, 4}, {8, 4, 0}, {8, 4, 8}, {8, 8, 4}}))
    EXPECT_EQ(g.nbr(j).size(), 3u) << to_string(j);
  for (const Point& p : vs({{8, 0, 0}, {8, 0, 8}, {8, 8, 0}, {8, 8, 8}})) EXPECT_EQ(g.nbr(p).size(), 2u);
  for (const Point& p : vs({{16, 0, 0}, {16, 0, 8}, {16, 8, 0}, {16, 8, 8}})) EXPECT_EQ(g.nbr(p).size(), 1u);
  // R1d: for the child (6,2,2) beside the face, X holds the level-0 cube: refused.
  EXPECT_EQ(can_refine(g, {6, 2, 2}), RefineRefusal::CoarserNeighbor);
  // The cube itself has no coarser neighbour.
  EXPECT_EQ(can_refine(g, right), std::nullopt);
}

TEST(D3Refine, R2_ChildrenAreHalfwayBetweenCenterAndCorners) {
  //= bccmis3d#eq-R2a type=test
  //= bccmis3d#eq-R2b type=test
  //= bccmis3d#eq-R2c type=test
  //= bccmis3d#eq-R2g type=test
  //= bccmis3d#eq-R2h type=test
  Graph g = test::build(kRoot);
  const RefineResult r = refine(g, root);
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.Y, corners(1, 3));  // R2a: y_i = midpoint(c, p_i) (Q1)
  for (const Point& y : r.Y) {
    EXPECT_TRUE(g.is_center(y));
    EXPECT_EQ(g.level_of(y), 1);  // R2b, with level l + 1
  }
  EXPECT_FALSE(g.is_center(root));  // R2g
  EXPECT_TRUE(g.is_node(root));     // R2h
  EXPECT_EQ(g.level.count(root), 0u);
  EXPECT_EQ(g.nbr(root), corners(1, 3));  // R2c: N(c) = Y; c has 8 cells (pure, interior)
}

TEST(D3Refine, R2_CornersSwapCForTheirChild) {
  //= bccmis3d#eq-R2e type=test
  //= bccmis3d#eq-R2f type=test
  Graph g = test::build(kRoot);
  ASSERT_TRUE(refine(g, root).applied());
  // R2e: each corner p_i now has only its child y_i (|N| = 1, a domain corner).
  EXPECT_EQ(g.nbr({0, 0, 0}), vs({{1, 1, 1}}));
  EXPECT_EQ(g.nbr({4, 0, 4}), vs({{3, 1, 3}}));
  EXPECT_EQ(g.nbr({4, 4, 4}), vs({{3, 3, 3}}));
  // R2f then step 3: the child (1,1,1) holds p_1 = (0,0,0), c, the three edge
  // midpoints and three face centers at p_1: its 8 corners {0, 2}^3.
  EXPECT_EQ(g.nbr({1, 1, 1}), corners(0, 2));
}

TEST(D3Refine, R3a_JPlusIsTheMissingMidpointsAndFaceCenters) {
  //= bccmis3d#eq-R3a type=test
  //= bccmis3d#eq-R3b type=test
  Graph g = test::build(kTwo);
  const RefineResult first = refine(g, {4, 4, 4});
  ASSERT_TRUE(first.applied());
  // J = ∅: all 12 edge midpoints and 6 face centers of [0,8]^3 are new.
  const PointSet left_new = test::edge_midpoints_and_face_centers_of_cube_0_8();
  EXPECT_EQ(first.J_plus, left_new);
  for (const Point& j : first.J_plus) EXPECT_TRUE(g.is_node(j));
  // Refining the right cube: the 5 nodes on x = 8 are old junctions (J), so
  // J+ is the other 13 midpoints and face centers of [8,16] x [0,8] x [0,8].
  const RefineResult second = refine(g, {12, 4, 4});
  ASSERT_TRUE(second.applied());
  EXPECT_EQ(second.J_plus, vs({{12, 0, 0},
                               {12, 0, 8},
                               {12, 8, 0},
                               {12, 8, 8},
                               {16, 4, 0},
                               {16, 4, 8},
                               {16, 0, 4},
                               {16, 8, 4},
                               {16, 4, 4},
                               {12, 0, 4},
                               {12, 8, 4},
                               {12, 4, 0},
                               {12, 4, 8}}));
}

TEST(D3Refine, R3_NewNodesOnTheDomainBoundaryJoinOnlyChildren) {
  //= bccmis3d#eq-R1e type=test
  //= bccmis3d#eq-R1f type=test
  //= bccmis3d#eq-R3d type=test
  //= bccmis3d#eq-R3e type=test
  //= bccmis3d#eq-R3g type=test
  //= bccmis3d#eq-R3h type=test
  Graph g = test::build(kRoot);
  ASSERT_TRUE(refine(g, root).applied());
  // An edge on a domain edge: X_e = ∅, N(j+) = {y_i, y_j} (2: pure).
  EXPECT_EQ(g.nbr({2, 0, 0}), vs({{1, 1, 1}, {3, 1, 1}}));
  EXPECT_EQ(g.nbr({0, 4, 2}), vs({{1, 3, 1}, {1, 3, 3}}));
  // A face on the domain boundary: X_f = ∅, N(j+) = the 4 children of the face.
  EXPECT_EQ(g.nbr({2, 2, 0}), vs({{1, 1, 1}, {1, 3, 1}, {3, 1, 1}, {3, 3, 1}}));
  EXPECT_EQ(g.nbr({4, 2, 2}), vs({{3, 1, 1}, {3, 1, 3}, {3, 3, 1}, {3, 3, 3}}));
  // R3e/R3h: a child holds the three edge midpoints and three face centers at its corner.
  for (const Point& j : vs({{2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {2, 2, 0}, {2, 0, 2}, {0, 2, 2}}))
    EXPECT_TRUE(g.nbr({1, 1, 1}).count(j)) << to_string(j);
}

TEST(D3Refine, R3_NewNodesOnASharedFaceJoinTheCellBeyond) {
  //= bccmis3d#eq-R3c type=test
  //= bccmis3d#eq-R3d type=test
  //= bccmis3d#eq-R3f type=test
  //= bccmis3d#eq-R3g type=test
  Graph g = test::build(std::string(kTwo) + "refine 4 4 4\n");
  const Point right{12, 4, 4};
  // X_f = {right} for the shared face: N = 4 children + right (5).
  EXPECT_EQ(g.nbr({8, 4, 4}), vs({{6, 2, 2}, {6, 2, 6}, {6, 6, 2}, {6, 6, 6}, right}));
  // X_e = {right} for the edges of the shared face (domain boundary): 2 children + right (3).
  EXPECT_EQ(g.nbr({8, 4, 0}), vs({{6, 2, 2}, {6, 6, 2}, right}));
  EXPECT_EQ(g.nbr({8, 8, 4}), vs({{6, 6, 2}, {6, 6, 6}, right}));
  // R3c/R3f: the cell beyond gained the 5 nodes: 8 + 5 = 13.
  EXPECT_EQ(g.nbr(right).size(), 13u);
  // Edges of the left cube away from the face keep X_e = ∅ (domain edges).
  EXPECT_EQ(g.nbr({4, 0, 0}), vs({{2, 2, 2}, {6, 2, 2}}));
}

TEST(D3Refine, R4_OldJunctionsJoinTheChildrenBesideThem) {
  //= bccmis3d#eq-R2d type=test
  //= bccmis3d#eq-R4a type=test
  //= bccmis3d#eq-R4b type=test
  //= bccmis3d#claim-children-have-8 type=test
  Graph g = test::build(std::string(kTwo) + "refine 4 4 4\n");
  ASSERT_TRUE(refine(g, {12, 4, 4}).applied());
  // The old face center loses c (R2d) and gains the 4 children of its face
  // (R4a): 8 cells, now a pure interior node.
  EXPECT_EQ(g.nbr({8, 4, 4}),
            vs({{6, 2, 2}, {6, 2, 6}, {6, 6, 2}, {6, 6, 6}, {10, 2, 2}, {10, 2, 6}, {10, 6, 2}, {10, 6, 6}}));
  // An old edge midpoint gains the 2 children at the ends of its edge: 4 (pure, domain face).
  EXPECT_EQ(g.nbr({8, 4, 0}), vs({{6, 2, 2}, {6, 6, 2}, {10, 2, 2}, {10, 6, 2}}));
  EXPECT_EQ(g.nbr({8, 0, 4}), vs({{6, 2, 2}, {6, 2, 6}, {10, 2, 2}, {10, 2, 6}}));
  // R4b and the claim: each child of the right cube has exactly its 8 corners.
  EXPECT_EQ(g.nbr({10, 2, 2}),
            vs({{8, 0, 0}, {8, 0, 4}, {8, 4, 0}, {8, 4, 4}, {12, 0, 0}, {12, 0, 4}, {12, 4, 0}, {12, 4, 4}}));
  EXPECT_EQ(g.nbr({14, 6, 6}),
            vs({{12, 4, 4}, {12, 4, 8}, {12, 8, 4}, {12, 8, 8}, {16, 4, 4}, {16, 4, 8}, {16, 8, 4}, {16, 8, 8}}));
}

TEST(D3Refine, R4_InteriorEdgeMidpointCountsFiveSixSevenEight) {
  //= bccmis3d#eq-R3d type=test
  //= bccmis3d#eq-R4a type=test
  // lattice 2 2 2 1 (S = 4): the four cubes around the interior edge x = y = 4,
  // z in [0, 4], refined one after the other. Its midpoint (4,4,2) is created
  // with X_e = the 3 other cubes (5), then each refinement replaces one cube
  // by its 2 children at the midpoint: 6, 7, and 8 when it is pure.
  Graph g = test::build("lattice 2 2 2 1\n");
  const Point m{4, 4, 2};
  ASSERT_TRUE(refine(g, {2, 2, 2}).applied());
  EXPECT_EQ(g.nbr(m), vs({{3, 3, 1}, {3, 3, 3}, {6, 2, 2}, {2, 6, 2}, {6, 6, 2}}));
  ASSERT_TRUE(refine(g, {6, 2, 2}).applied());
  EXPECT_EQ(g.nbr(m), vs({{3, 3, 1}, {3, 3, 3}, {5, 3, 1}, {5, 3, 3}, {2, 6, 2}, {6, 6, 2}}));
  ASSERT_TRUE(refine(g, {2, 6, 2}).applied());
  EXPECT_EQ(g.nbr(m).size(), 7u);
  ASSERT_TRUE(refine(g, {6, 6, 2}).applied());
  EXPECT_EQ(g.nbr(m), vs({{3, 3, 1}, {3, 3, 3}, {5, 3, 1}, {5, 3, 3}, {3, 5, 1}, {3, 5, 3}, {5, 5, 1}, {5, 5, 3}}));
}

}  // namespace
}  // namespace bccmis::d3
