// Every decision code of spec/lattice3d.md §4-§5, each in a state where the
// reason is plain, with the state byte-identical after the refusal.
#include <gtest/gtest.h>

#include "util.h"

namespace bccmis::d3 {
namespace {

// The sets an operation created or deleted besides Y.
const PointSet& junctions(const RefineResult& r) { return r.J_plus; }
const PointSet& junctions(const CoarsenResult& r) { return r.J_minus; }

// In the state `trace` builds, can(g, p) and op(g, p) refuse with `why`,
// op returns empty sets, and the state is byte-identical after it.
template <class Refusal, class Can, class Op>
void expect_refused(const std::string& trace, const Point& p, Refusal why, const char* op_name, Can can, Op op) {
  Graph g = test::build(trace);
  const std::string before = canonical_state(g);
  EXPECT_EQ(can(g, p), why) << to_string(p);
  const auto r = op(g, p);
  EXPECT_EQ(r.refused, why) << to_string(p);
  EXPECT_TRUE(r.Y.empty());
  EXPECT_TRUE(junctions(r).empty());
  EXPECT_EQ(canonical_state(g), before) << op_name << " " << to_string(p) << " changed the state";
}

void expect_refine_refused(const std::string& trace, const Point& c, RefineRefusal why) {
  expect_refused(
      trace, c, why, "refine", [](const Graph& g, const Point& p) { return can_refine(g, p); },
      [](Graph& g, const Point& p) { return refine(g, p); });
}

void expect_coarsen_refused(const std::string& trace, const Point& n, CoarsenRefusal why) {
  expect_refused(
      trace, n, why, "coarsen", [](const Graph& g, const Point& p) { return can_coarsen(g, p); },
      [](Graph& g, const Point& p) { return coarsen(g, p); });
}

constexpr const char* kTwo = "lattice 2 1 1 2\n";

TEST(D3Refusals, NoSuchCell) {
  //= bccmis3d#pre-refine-cell type=test
  expect_refine_refused(kTwo, {5, 5, 5}, RefineRefusal::NoSuchCell);                                  // nothing there
  expect_refine_refused(kTwo, {8, 0, 0}, RefineRefusal::NoSuchCell);                                  // a node
  expect_refine_refused(std::string(kTwo) + "refine 4 4 4\n", {4, 4, 4}, RefineRefusal::NoSuchCell);  // refined
}

TEST(D3Refusals, MaxLevel) {
  //= bccmis3d#pre-refine-max-level type=test
  expect_refine_refused("lattice 1 1 1 1\nrefine 2 2 2\n", {1, 1, 1}, RefineRefusal::MaxLevel);
  expect_refine_refused("lattice 1 1 1 0\n", {1, 1, 1}, RefineRefusal::MaxLevel);
}

TEST(D3Refusals, CoarserNeighborAcrossAFace) {
  //= bccmis3d#pre-refine-level type=test
  expect_refine_refused(std::string(kTwo) + "refine 4 4 4\n", {6, 2, 2}, RefineRefusal::CoarserNeighbor);
  expect_refine_refused(std::string(kTwo) + "refine 4 4 4\n", {6, 6, 6}, RefineRefusal::CoarserNeighbor);
}

TEST(D3Refusals, CoarserNeighborAcrossAnEdgeOnly) {
  //= bccmis3d#pre-refine-level type=test
  //= bccmis3d#eq-R1d type=test
  // spec/lattice3d.md §2: in lattice 2 2 1 2 (S = 8) the three cubes around
  // (0,0,0)'s edge x = y = 8 are refined; the level-1 cube (10,10,2) has only
  // level-1 face neighbours, but shares the segment x = y = 8, z in [0, 4]
  // with the level-0 cube (4,4,4). Face balance alone would accept it.
  expect_refine_refused("lattice 2 2 1 2\nrefine 12 4 4\nrefine 4 12 4\nrefine 12 12 4\n", {10, 10, 2},
                        RefineRefusal::CoarserNeighbor);
}

TEST(D3Refusals, CornerOnlyCoarserCellDoesNotBlock) {
  //= bccmis3d#pre-refine-level type=test
  // lattice 2 2 2 2: all cubes but (4,4,4) refined; the level-1 cube
  // (10,10,10) meets (4,4,4) only at the corner (8,8,8): accepted.
  Graph g = test::build(
      "lattice 2 2 2 2\nrefine 12 4 4\nrefine 4 12 4\nrefine 4 4 12\nrefine 12 12 4\nrefine 12 4 12\n"
      "refine 4 12 12\nrefine 12 12 12\n");
  EXPECT_EQ(can_refine(g, {10, 10, 10}), std::nullopt);
  EXPECT_TRUE(refine(g, {10, 10, 10}).applied());
  EXPECT_EQ(g.level_of({4, 4, 4}), 0);
  EXPECT_EQ(g.level_of({9, 9, 9}), 2);
}

TEST(D3Refusals, NoSuchNode) {
  //= bccmis3d#pre-coarsen-node type=test
  expect_coarsen_refused(kTwo, {4, 4, 4}, CoarsenRefusal::NoSuchNode);  // a center
  expect_coarsen_refused(kTwo, {8, 4, 4}, CoarsenRefusal::NoSuchNode);  // nothing there yet
}

TEST(D3Refusals, NotARefinedCenter) {
  //= bccmis3d#pre-coarsen-refined-center type=test
  //= bccmis3d#pre-coarsen-eight-cells type=test
  const std::string refined = std::string(kTwo) + "refine 4 4 4\n";
  expect_coarsen_refused(refined, {8, 0, 0}, CoarsenRefusal::NotARefinedCenter);  // a domain-boundary grid node
  expect_coarsen_refused(refined, {8, 4, 4}, CoarsenRefusal::NotARefinedCenter);  // a face-center junction
  expect_coarsen_refused(refined, {8, 4, 0}, CoarsenRefusal::NotARefinedCenter);  // an edge-midpoint junction
  expect_coarsen_refused(refined, {4, 0, 4}, CoarsenRefusal::NotARefinedCenter);  // a domain-face center
  // An interior grid node of lattice 2 2 2 1 with 8 cells around it.
  expect_coarsen_refused("lattice 2 2 2 1\n", {4, 4, 4}, CoarsenRefusal::NotARefinedCenter);
}

TEST(D3Refusals, ChildrenRefined) {
  //= bccmis3d#pre-coarsen-children-leaves type=test
  expect_coarsen_refused("lattice 1 1 1 2\nrefine 4 4 4\nrefine 2 2 2\n", {4, 4, 4}, CoarsenRefusal::ChildrenRefined);
  expect_coarsen_refused(std::string(kTwo) + "refine 4 4 4\nrefine 12 4 4\nrefine 10 2 2\n", {12, 4, 4},
                         CoarsenRefusal::ChildrenRefined);
}

TEST(D3Refusals, FinerNeighbor) {
  //= bccmis3d#pre-coarsen-balance type=test
  // Across a face: the child (6,2,2) has 13 nodes once (10,2,2) is refined.
  expect_coarsen_refused(std::string(kTwo) + "refine 4 4 4\nrefine 12 4 4\nrefine 10 2 2\n", {4, 4, 4},
                         CoarsenRefusal::FinerNeighbor);
  // Across an edge only: in lattice 2 2 1 2, the level-2 cubes of (10,10,2)
  // meet the child (6,6,2) of (4,4,4) along x = y = 8 only.
  expect_coarsen_refused(
      "lattice 2 2 1 2\nrefine 4 4 4\nrefine 12 4 4\nrefine 4 12 4\nrefine 12 12 4\nrefine 10 10 2\n", {4, 4, 4},
      CoarsenRefusal::FinerNeighbor);
}

}  // namespace
}  // namespace bccmis::d3
