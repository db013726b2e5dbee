// Negative and positive tests of the checker (invariants/, issue 4).
//
// For every invariant code: a minimal valid state, written as canonical-state
// text, broken in exactly one place; the test asserts the code, the layer, the
// positions in `where`, and that the message names them. Then valid states:
// initial lattices, and states reached by the core's refine/coarsen.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "bccmis/invariants/checked.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "invariants/two_level_jump.h"

namespace bccmis {
namespace {

// lattice 1 1 1: one level-0 cell [0, 4]^2.
constexpr const char* kOneCell =
    "bccmis-state 1\n"
    "lattice 1 1 1\n"
    "C 2 2 0 : 0 0 0 4 4 0 4 4\n"
    "N 0 0 : 2 2\n"
    "N 0 4 : 2 2\n"
    "N 4 0 : 2 2\n"
    "N 4 4 : 2 2\n"
    "end 1 4\n";

// lattice 2 1 1 after refine (6, 2): a level-0 cell beside four level-1
// cells, with the junction (4, 2) on the shared side.
constexpr const char* kJunction =
    "bccmis-state 1\n"
    "lattice 2 1 1\n"
    "C 2 2 0 : 0 0 0 4 4 0 4 2 4 4\n"
    "C 5 1 1 : 4 0 4 2 6 0 6 2\n"
    "C 5 3 1 : 4 2 4 4 6 2 6 4\n"
    "C 7 1 1 : 6 0 6 2 8 0 8 2\n"
    "C 7 3 1 : 6 2 6 4 8 2 8 4\n"
    "N 0 0 : 2 2\n"
    "N 0 4 : 2 2\n"
    "N 4 0 : 2 2 5 1\n"
    "N 4 2 : 2 2 5 1 5 3\n"
    "N 4 4 : 2 2 5 3\n"
    "N 6 0 : 5 1 7 1\n"
    "N 6 2 : 5 1 5 3 7 1 7 3\n"
    "N 6 4 : 5 3 7 3\n"
    "N 8 0 : 7 1\n"
    "N 8 2 : 7 1 7 3\n"
    "N 8 4 : 7 3\n"
    "end 5 11\n";

// lattice 2 1 1: two level-0 cells.
constexpr const char* kTwoCells =
    "bccmis-state 1\n"
    "lattice 2 1 1\n"
    "C 2 2 0 : 0 0 0 4 4 0 4 4\n"
    "C 6 2 0 : 4 0 4 4 8 0 8 4\n"
    "N 0 0 : 2 2\n"
    "N 0 4 : 2 2\n"
    "N 4 0 : 2 2 6 2\n"
    "N 4 4 : 2 2 6 2\n"
    "N 8 0 : 6 2\n"
    "N 8 4 : 6 2\n"
    "end 2 6\n";

Graph state(const char* text) { return parse_state(text, "<test>"); }

// Adds the edge a-b in both directions (the vertices must exist).
void link(Graph& g, Point a, Point b) {
  g.neighbors[a].insert(b);
  g.neighbors[b].insert(a);
}

void add_node(Graph& g, Point n) { g.N.insert(n); }

std::string pos(Point p) { return to_string(p); }

// Asserts that g's first violation has this code, layer and where, that the
// message starts with the code and names every position in where.
void expect_violation(const Graph& g, const std::string& code, int layer, const std::vector<Point>& where) {
  const std::optional<Violation> v = find_violation(g);
  ASSERT_TRUE(v.has_value()) << "expected " << code << ", but the state is valid:\n" << canonical_state(g);
  EXPECT_EQ(v->code, code) << to_string(*v);
  EXPECT_EQ(v->layer, layer) << to_string(*v);
  EXPECT_EQ(v->where, where) << to_string(*v);
  EXPECT_EQ(v->message.rfind(code + ": ", 0), 0U) << v->message;
  for (const Point& p : where)
    EXPECT_NE(v->message.find(pos(p)), std::string::npos) << v->message << " misses " << pos(p);
  EXPECT_FALSE(v->section.empty());
  EXPECT_EQ(v->section.rfind("§", 0), 0U) << v->section;
  EXPECT_EQ(v->message.find('\n'), std::string::npos);
  EXPECT_EQ(to_string(*v), v->message + " [paper " + v->section + "]");
  EXPECT_FALSE(is_valid(g));
  // Every lower depth passes: the layers are ordered.
  EXPECT_TRUE(is_valid(g, layer - 1)) << to_string(*find_violation(g, layer - 1));
}

// ---- The base states are valid ---------------------------------------------

TEST(Invariants, BaseStatesAreValid) {
  for (const char* text : {kOneCell, kJunction, kTwoCells}) {
    const Graph g = state(text);
    const auto v = find_violation(g);
    EXPECT_FALSE(v.has_value()) << to_string(*v) << "\n" << text;
    EXPECT_TRUE(is_valid(g));
  }
}

TEST(Invariants, BaseStatesMatchTheCore) {
  EXPECT_EQ(state(kOneCell), make_lattice({1, 1, 1}));
  EXPECT_EQ(state(kTwoCells), make_lattice({2, 1, 1}));
  Graph g = make_lattice({2, 1, 1});
  ASSERT_TRUE(refine(g, {6, 2}).applied());
  EXPECT_EQ(canonical_state(g), kJunction);
}

// ---- Layer 1: combinatorial ------------------------------------------------

TEST(Layer1, LatticeSize) {
  Graph g = state(kOneCell);
  g.size.L = -1;
  expect_violation(g, "lattice-size", 1, {});
  EXPECT_NE(find_violation(g)->message.find("lattice 1 1 -1"), std::string::npos);
  g.size = {0, 1, 1};
  expect_violation(g, "lattice-size", 1, {});
  g.size = {std::int64_t{1} << 61, 1, 1};  // W*S = 2^63
  expect_violation(g, "lattice-size", 1, {});
}

TEST(Layer1, Partition) {
  Graph g = state(kOneCell);
  g.C.insert({0, 0});
  g.level[{0, 0}] = 0;
  expect_violation(g, "partition", 1, {{0, 0}});
}

TEST(Layer1, NeighborEntry) {
  Graph g = state(kOneCell);
  g.neighbors.erase({4, 0});
  expect_violation(g, "neighbor-entry", 1, {{4, 0}});
}

TEST(Layer1, StaleEntry) {
  Graph g = state(kOneCell);
  g.neighbors[{2, 0}] = {};  // e.g. a deleted junction whose entry was left behind
  expect_violation(g, "stale-entry", 1, {{2, 0}});
}

TEST(Layer1, DanglingNeighbor) {
  Graph g = state(kOneCell);
  g.neighbors[{2, 2}].insert({2, 0});  // a deleted junction still listed
  expect_violation(g, "dangling-neighbor", 1, {{2, 2}, {2, 0}});
}

TEST(Layer1, BipartiteNodeNode) {
  Graph g = state(kOneCell);
  link(g, {0, 0}, {4, 0});
  expect_violation(g, "bipartite", 1, {{0, 0}, {4, 0}});
}

TEST(Layer1, BipartiteCenterCenter) {
  Graph g = state(kTwoCells);
  link(g, {2, 2}, {6, 2});
  expect_violation(g, "bipartite", 1, {{2, 2}, {6, 2}});
}

TEST(Layer1, Symmetry) {
  Graph g = state(kJunction);
  g.neighbors[{4, 2}].erase({2, 2});  // skip (6b)/(7a)-like: one direction only
  expect_violation(g, "symmetry", 1, {{2, 2}, {4, 2}});
  EXPECT_EQ(find_violation(g)->message, "symmetry: center (2, 2) lists node (4, 2), which does not list it");
}

TEST(Layer1, ChecksAreReportedInPriorityOrder) {
  // An asymmetric edge (2, 2)-(0, 0) and an empty set at (0, 0) sort before
  // the node-node edge (4, 0)-(4, 4), but bipartite comes first.
  Graph g = state(kOneCell);
  g.neighbors[{0, 0}].erase({2, 2});  // also leaves (0, 0) with an empty set
  link(g, {4, 0}, {4, 4});
  expect_violation(g, "bipartite", 1, {{4, 0}, {4, 4}});
  // And a dangling neighbor anywhere beats both.
  g.neighbors[{4, 4}].insert({9, 9});
  expect_violation(g, "dangling-neighbor", 1, {{4, 4}, {9, 9}});
}

TEST(Layer1, EmptyNeighbors) {
  Graph g = state(kOneCell);
  add_node(g, {2, 0});
  g.neighbors[{2, 0}] = {};  // a J- vertex emptied (11c) but not deleted (10c)
  expect_violation(g, "empty-neighbors", 1, {{2, 0}});
}

TEST(Layer1, MissingLevel) {
  Graph g = state(kOneCell);
  g.level.erase({2, 2});
  expect_violation(g, "missing-level", 1, {{2, 2}});
}

TEST(Layer1, StrayLevel) {
  Graph g = state(kOneCell);
  g.level[{4, 4}] = 0;  // a coarsened child's level left behind on a node
  expect_violation(g, "stray-level", 1, {{4, 4}});
}

// ---- Layer 2: structural ---------------------------------------------------

TEST(Layer2, CenterDegree) {
  // kOneCell without the node (0, 0): the cell has 3 neighbors.
  const Graph g = state(
      "bccmis-state 1\nlattice 1 1 1\n"
      "C 2 2 0 : 0 4 4 0 4 4\n"
      "N 0 4 : 2 2\nN 4 0 : 2 2\nN 4 4 : 2 2\n"
      "end 1 3\n");
  expect_violation(g, "center-degree", 2, {{2, 2}});
  EXPECT_NE(find_violation(g)->message.find("3 neighbors"), std::string::npos);
}

TEST(Layer2, CenterCorner) {
  // kJunction without the domain corner (0, 0): (2, 2) still has 4 neighbors.
  Graph g = state(kJunction);
  g.neighbors[{2, 2}].erase({0, 0});
  g.neighbors.erase({0, 0});
  g.N.erase({0, 0});
  expect_violation(g, "center-corner", 2, {{2, 2}, {0, 0}});
  EXPECT_NE(find_violation(g)->message.find("[0, 4] x [0, 4]"), std::string::npos);
}

TEST(Layer2, CenterNeighbor) {
  Graph g = state(kTwoCells);
  link(g, {2, 2}, {8, 0});  // a corner of the other cell
  expect_violation(g, "center-neighbor", 2, {{2, 2}, {8, 0}});
}

TEST(Layer2, NodeDegreeInteriorMissingItsJunctionLink) {
  // The coarse cell forgets its junction (skipping 6b): (4, 2) is then an
  // interior node with only the two finer cells.
  Graph g = state(kJunction);
  g.neighbors[{2, 2}].erase({4, 2});
  g.neighbors[{4, 2}].erase({2, 2});
  expect_violation(g, "node-degree", 2, {{4, 2}});
  EXPECT_NE(find_violation(g)->message.find("interior node (4, 2) has 2 neighbors"), std::string::npos);
}

TEST(Layer2, NodeDegreeBoundary) {
  // A level-2 cell (3, 1) stacked on the middle of the bottom side of the
  // level-0 cell (lattice 1 1 2): the boundary node (2, 0) has one cell.
  const Graph g = state(
      "bccmis-state 1\nlattice 1 1 2\n"
      "C 3 1 2 : 2 0 2 2 4 0 4 2\n"
      "C 4 4 0 : 0 0 0 8 8 0 8 8\n"
      "N 0 0 : 4 4\nN 0 8 : 4 4\nN 2 0 : 3 1\nN 2 2 : 3 1\nN 4 0 : 3 1\nN 4 2 : 3 1\nN 8 0 : 4 4\nN 8 8 : 4 4\n"
      "end 2 8\n");
  expect_violation(g, "node-degree", 2, {{2, 0}});
  EXPECT_NE(find_violation(g)->message.find("boundary node (2, 0) has 1 neighbor, a boundary node has 2"),
            std::string::npos);
}

TEST(Layer2, NodeDegreeDomainCorner) {
  // Two stacked cells share the domain corner (0, 0): the level-0 cell and a
  // level-2 cell inside it (lattice 1 1 2).
  const Graph g = state(
      "bccmis-state 1\nlattice 1 1 2\n"
      "C 1 1 2 : 0 0 0 2 2 0 2 2\n"
      "C 4 4 0 : 0 0 0 8 8 0 8 8\n"
      "N 0 0 : 1 1 4 4\nN 0 2 : 1 1\nN 0 8 : 4 4\nN 2 0 : 1 1\nN 2 2 : 1 1\nN 8 0 : 4 4\nN 8 8 : 4 4\n"
      "end 2 7\n");
  expect_violation(g, "node-degree", 2, {{0, 0}});
  EXPECT_NE(find_violation(g)->message.find("domain corner (0, 0) has 2 neighbors"), std::string::npos);
}

TEST(Layer2, NodeDegreeAboveFour) {
  // lattice 2 2 2 and one more level-2 cell (9, 9) in the corner of (8, 8):
  // (8, 8) has 5 neighbors, each of which has it as a corner.
  Graph g = make_lattice({2, 2, 2});
  g.C.insert({9, 9});
  g.level[{9, 9}] = 2;
  for (const Point p : {Point{8, 8}, Point{8, 10}, Point{10, 8}, Point{10, 10}}) {
    add_node(g, p);
    link(g, {9, 9}, p);
  }
  expect_violation(g, "node-degree", 2, {{8, 8}});
  EXPECT_NE(find_violation(g)->message.find("5 neighbors"), std::string::npos);
}

TEST(Layer2, BoundaryJunction) {
  // The literal paper on the boundary: a junction at the midpoint (2, 4) of a
  // side on the domain boundary.
  Graph g = state(kOneCell);
  add_node(g, {2, 4});
  link(g, {2, 2}, {2, 4});
  expect_violation(g, "boundary-junction", 2, {{2, 2}, {2, 4}});
}

TEST(Layer2, JunctionDegreeLeftover) {
  // A junction left behind after coarsening (a wrong J- test): (4, 2) is
  // listed by the coarse cell but no finer cell lies beyond it.
  Graph g = state(kTwoCells);
  add_node(g, {4, 2});
  link(g, {2, 2}, {4, 2});
  expect_violation(g, "junction-degree", 2, {{4, 2}, {2, 2}});
  EXPECT_NE(find_violation(g)->message.find("has 1 neighbor;"), std::string::npos);
}

TEST(Layer2, JunctionDegreeTwoCoarseCells) {
  Graph g = state(kTwoCells);
  add_node(g, {4, 2});
  link(g, {2, 2}, {4, 2});
  link(g, {6, 2}, {4, 2});
  expect_violation(g, "junction-degree", 2, {{4, 2}, {2, 2}, {6, 2}});
}

// ---- Layer 3: grading ------------------------------------------------------

TEST(Layer3, Grading) {
  // lattice 2 1 2 with the level of (4, 4) stored as 2: the squares (derived
  // from positions) are fine, but the stored levels of two cells that share
  // the side (8, 0)-(8, 8) differ by 2.
  Graph g = make_lattice({2, 1, 2});
  g.level[{4, 4}] = 2;
  expect_violation(g, "grading", 3, {{4, 4}, {12, 4}});
  EXPECT_NE(find_violation(g)->message.find("differ by 2 levels"), std::string::npos);
}

TEST(Layer3, DiagonalNeighborsMayDifferByTwo) {
  // lattice 2 2 2: refine (12, 12), then its child (10, 10); the level-2 cell
  // (9, 9) touches the level-0 cell (4, 4) only at the corner (8, 8).
  Graph g = make_lattice({2, 2, 2});
  ASSERT_TRUE(refine(g, {12, 4}).applied());
  ASSERT_TRUE(refine(g, {4, 12}).applied());
  ASSERT_TRUE(refine(g, {12, 12}).applied());
  ASSERT_TRUE(refine(g, {10, 10}).applied());
  ASSERT_TRUE(g.is_center({9, 9}));
  EXPECT_EQ(g.level_of({9, 9}) - g.level_of({4, 4}), 2);
  EXPECT_TRUE(g.nbr({8, 8}).count({4, 4}) && g.nbr({8, 8}).count({9, 9}));
  const auto v = find_violation(g);
  EXPECT_FALSE(v.has_value()) << to_string(*v);
}

TEST(Layer3, TwoLevelJumpIsCaughtByLayer2) {
  // The state an unguarded refine of (10, 2) would make next to the level-0
  // cell (4, 4) (lattice 2 1 2): eq. (6b) hands (4, 4) the new junction
  // (8, 2), a quarter point of its side. Exact node degrees already reject it.
  const Graph jump = test::two_level_jump(true);
  const auto v = find_violation(jump);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->code, "center-neighbor") << to_string(*v);
  EXPECT_EQ(v->where, (std::vector<Point>{{4, 4}, {8, 2}}));
}

// ---- Layer 4: geometry -----------------------------------------------------

TEST(Layer4, LevelRange) {
  Graph g = state(kOneCell);
  g.level[{2, 2}] = 2;  // L = 1
  expect_violation(g, "level-range", 4, {{2, 2}});
}

TEST(Layer4, OutsideDomain) {
  // A second cell [-4, 0] x [0, 4] to the left of the domain.
  const Graph g = state(
      "bccmis-state 1\nlattice 1 1 1\n"
      "C -2 2 0 : -4 0 -4 4 0 0 0 4\n"
      "C 2 2 0 : 0 0 0 4 4 0 4 4\n"
      "N -4 0 : -2 2\nN -4 4 : -2 2\n"
      "N 0 0 : -2 2 2 2\nN 0 4 : -2 2 2 2\nN 4 0 : 2 2\nN 4 4 : 2 2\n"
      "end 2 6\n");
  expect_violation(g, "outside-domain", 4, {{-4, 0}});
}

TEST(Layer4, CenterPositionWrongLevel) {
  Graph g = state(kOneCell);
  g.level[{2, 2}] = 1;
  expect_violation(g, "center-position", 4, {{2, 2}});
  EXPECT_NE(find_violation(g)->message.find("the center of a level-0 cell"), std::string::npos);
}

TEST(Layer4, CenterPositionNotACenter) {
  const Graph g = state(
      "bccmis-state 1\nlattice 1 1 1\n"
      "C 2 1 0 : 0 0 0 4 4 0 4 4\n"
      "N 0 0 : 2 1\nN 0 4 : 2 1\nN 4 0 : 2 1\nN 4 4 : 2 1\n"
      "end 1 4\n");
  expect_violation(g, "center-position", 4, {{2, 1}});
  EXPECT_NE(find_violation(g)->message.find("odd multiples of 2"), std::string::npos);
}

// Overlap and coverage are the tiling's safety net: no state that passes
// layers 1-3 is known to break them (an exhaustive search over all 2^21 sets
// of cells of lattice 1 1 2 found none; spec/invariants.md). They are tested
// on layer 4 alone.
TEST(Layer4, Overlap) {
  // A level-0 cell and a level-2 cell (1, 1) inside it (lattice 1 1 2).
  const Graph g = state(
      "bccmis-state 1\nlattice 1 1 2\n"
      "C 1 1 2 : 0 0 0 2 2 0 2 2\n"
      "C 4 4 0 : 0 0 0 8 8 0 8 8\n"
      "N 0 0 : 1 1 4 4\nN 0 2 : 1 1\nN 0 8 : 4 4\nN 2 0 : 1 1\nN 2 2 : 1 1\nN 8 0 : 4 4\nN 8 8 : 4 4\n"
      "end 2 7\n");
  EXPECT_EQ(find_violation(g)->code, "node-degree");  // (0, 0) has 2 cells
  const auto v = check_layer(g, 4);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->code, "overlap");
  EXPECT_EQ(v->layer, 4);
  EXPECT_EQ(v->where, (std::vector<Point>{{4, 4}, {1, 1}}));
  EXPECT_NE(v->message.find("center (1, 1)"), std::string::npos) << v->message;
  EXPECT_NE(v->message.find("center (4, 4)"), std::string::npos) << v->message;
}

TEST(Layer4, CoverageMissingChild) {
  // lattice 1 1 1 refined, without the child (3, 3).
  Graph g = make_lattice({1, 1, 1});
  ASSERT_TRUE(refine(g, {2, 2}).applied());
  for (const Point p : g.nbr({3, 3})) g.neighbors[p].erase({3, 3});
  g.neighbors.erase({3, 3});
  g.C.erase({3, 3});
  g.level.erase({3, 3});
  const auto v = check_layer(g, 4);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->code, "coverage");
  EXPECT_EQ(v->where, (std::vector<Point>{{3, 3}}));
  EXPECT_NE(v->message.find("centered at (3, 3)"), std::string::npos);
}

TEST(Layer4, CoverageMissingLevel0Cell) {
  Graph g = make_lattice({3, 2, 1});
  const Point c{6, 6};  // the middle top cell
  for (const Point p : g.nbr(c)) g.neighbors[p].erase(c);
  g.neighbors.erase(c);
  g.C.erase(c);
  g.level.erase(c);
  const auto v = check_layer(g, 4);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->code, "coverage");
  EXPECT_EQ(v->where, (std::vector<Point>{c}));
}

// ---- Valid states ----------------------------------------------------------

TEST(Valid, InitialLattices) {
  for (const LatticeSize size : {LatticeSize{1, 1, 0}, LatticeSize{1, 1, 3}, LatticeSize{2, 1, 2}, LatticeSize{3, 5, 1},
                                 LatticeSize{6, 6, 4}, LatticeSize{1, 1, 61}, LatticeSize{2, 2, 60}})
    EXPECT_TRUE(is_valid(make_lattice(size)))
        << size.W << " " << size.H << " " << size.L << ": " << to_string(*find_violation(make_lattice(size)));
}

TEST(Valid, UniformRefinement) {
  Graph g = make_lattice({2, 3, 3});
  for (int level = 0; level < 3; ++level) {
    const PointSet cells = g.C;
    for (const Point& c : cells) checked_refine(g, c);
    EXPECT_TRUE(is_valid(g));
  }
  EXPECT_EQ(g.C.size(), 2u * 3u * 64u);
}

TEST(Valid, RandomRefineCoarsenSequences) {
  // Random operations through the checked wrappers: every state reached is
  // valid, and refused operations change nothing (checked_* would throw).
  for (const LatticeSize size : {LatticeSize{1, 1, 3}, LatticeSize{2, 1, 2}, LatticeSize{3, 2, 3}}) {
    std::mt19937 rng(12345);
    Graph g = make_lattice(size);
    int applied = 0;
    for (int step = 0; step < 400; ++step) {
      if (rng() % 3 != 0) {
        std::vector<Point> cells(g.C.begin(), g.C.end());
        applied += checked_refine(g, cells[rng() % cells.size()]).applied();
      } else {
        std::vector<Point> nodes(g.N.begin(), g.N.end());
        applied += checked_coarsen(g, nodes[rng() % nodes.size()]).applied();
      }
    }
    EXPECT_GT(applied, 20) << size.W << " " << size.H << " " << size.L;
  }
}

TEST(Valid, DepthZeroChecksNothing) {
  Graph g = state(kOneCell);
  g.C.insert({0, 0});
  EXPECT_TRUE(is_valid(g, 0));
  EXPECT_FALSE(is_valid(g, 1));
}

// ---- Checked wrappers ------------------------------------------------------

TEST(Checked, RefusedOperationsReturnTheRefusal) {
  Graph g = make_lattice({1, 1, 1});
  const Graph before = g;
  EXPECT_FALSE(checked_refine(g, {0, 0}).applied());   // a node: no-such-cell
  EXPECT_FALSE(checked_coarsen(g, {2, 2}).applied());  // a center: no-such-node
  EXPECT_EQ(g, before);
  ASSERT_TRUE(checked_refine(g, {2, 2}).applied());
  EXPECT_FALSE(checked_refine(g, {1, 1}).applied());  // level L: max-level
}

TEST(Checked, RefineThenCoarsenRestores) {
  Graph g = make_lattice({2, 2, 2});
  const Graph before = g;
  const RefineResult r = checked_refine(g, {4, 4});
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.Y.size(), 4u);
  const CoarsenResult c = checked_coarsen(g, {4, 4});
  ASSERT_TRUE(c.applied());
  EXPECT_EQ(c.Y, r.Y);
  EXPECT_EQ(c.J_minus, r.J_plus);
  EXPECT_EQ(g, before);
}

TEST(Checked, InvalidStateIsRejectedBefore) {
  Graph g = state(kJunction);
  g.neighbors[{4, 2}].erase({2, 2});
  try {
    checked_refine(g, {5, 1});
    FAIL() << "no ViolationError";
  } catch (const ViolationError& e) {
    EXPECT_EQ(e.violation.code, "symmetry");
    EXPECT_EQ(e.context, "before refine (5, 1)");
    EXPECT_EQ(std::string(e.what()), "before refine (5, 1): " + to_string(e.violation));
  }
  EXPECT_THROW(checked_coarsen(g, {6, 2}), ViolationError);
}

}  // namespace
}  // namespace bccmis
