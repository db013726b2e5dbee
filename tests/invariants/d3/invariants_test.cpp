// The independent 3D checker (src/bccmis/invariants/d3/, spec/invariants.md
// section "3D"): every code triggered by a planted violation in a state built
// with refine/coarsen, every state of random operation sequences valid, random
// single mutations always caught, the mesh layer on hand-built tetrahedra
// of one and two cubes, and on the meshes bccmis::d3::tetrahedra extracts.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bccmis/d3/graph.h"
#include "bccmis/d3/mesh.h"
#include "bccmis/d3/ops.h"
#include "bccmis/invariants/d3/invariants.h"
#include "d3/check.h"
#include "d3/util.h"  // PrintTo(Point)

namespace bccmis::d3 {
namespace {

// A state reached by applying every refine in order (each must be applied).
Graph refined(const LatticeSize& size, const std::vector<Point>& cells) {
  Graph g(size);
  for (const Point& c : cells) {
    const RefineResult r = refine(g, c);
    EXPECT_TRUE(r.applied()) << "refine " << to_string(c);
  }
  return g;
}

void link(Graph& g, const Point& a, const Point& b) {
  g.neighbors[a].insert(b);
  g.neighbors[b].insert(a);
}

// Adds the nodes `points`, each linked to every cell of `cells`.
void add_linked_nodes(Graph& g, std::initializer_list<Point> cells, std::initializer_list<Point> points) {
  for (const Point& p : points) {
    g.N.insert(p);
    for (const Point& c : cells) link(g, c, p);
  }
}

// Adds the cell c of `level` and its 8 corners c +- h (as nodes), linked.
void add_cube(Graph& g, const Point& c, int level, std::int64_t h) {
  g.C.insert(c);
  g.level[c] = level;
  for (const std::int64_t x : {c.x - h, c.x + h})
    for (const std::int64_t y : {c.y - h, c.y + h})
      for (const std::int64_t z : {c.z - h, c.z + h}) {
        g.N.insert({x, y, z});
        link(g, c, {x, y, z});
      }
}

void unlink(Graph& g, const Point& a, const Point& b) {
  g.neighbors[a].erase(b);
  g.neighbors[b].erase(a);
}

// Deletes node n and every edge to it.
void remove_node(Graph& g, const Point& n) {
  for (const Point& c : g.nbr(n)) g.neighbors[c].erase(n);
  g.neighbors.erase(n);
  g.N.erase(n);
}

// Deletes center c, its level and every edge to it, and the nodes left with
// no cell.
void remove_cell(Graph& g, const Point& c) {
  const PointSet nodes = g.nbr(c);
  for (const Point& n : nodes) {
    g.neighbors[n].erase(c);
    if (g.neighbors[n].empty()) {
      g.neighbors.erase(n);
      g.N.erase(n);
    }
  }
  g.neighbors.erase(c);
  g.C.erase(c);
  g.level.erase(c);
}

// The violation has the code and layer, and its message has the documented form.
void expect_violation(const std::optional<Violation>& v, const std::string& code, int layer) {
  ASSERT_TRUE(v.has_value()) << "expected " << code;
  EXPECT_EQ(v->code, code) << to_string(*v);
  EXPECT_EQ(v->layer, layer) << to_string(*v);
  EXPECT_EQ(v->message.rfind(code + ": ", 0), 0u) << v->message;
  EXPECT_EQ(v->message.find('\n'), std::string::npos) << v->message;
  for (const Point& p : v->where) EXPECT_NE(v->message.find(to_string(p)), std::string::npos) << v->message;
  EXPECT_EQ(to_string(*v), v->message + " [" + v->section + "]");
  EXPECT_EQ(v->section.rfind("spec/", 0), 0u) << v->section;
}

// spec/lattice3d.md §7: lattice 2 1 1 2 with (4, 4, 4) refined
// (spec/examples/d3/face_refined.state).
Graph face_state() { return refined({2, 1, 1, 2}, {{4, 4, 4}}); }

// ---------------------------------------------------------------- valid states

TEST(D3Invariants, InitialAndExampleStatesAreValid) {
  for (const LatticeSize& s : {LatticeSize{1, 1, 1, 0}, LatticeSize{2, 3, 1, 2}, LatticeSize{1, 1, 1, 61}})
    EXPECT_EQ(find_violation(Graph(s)), std::nullopt);
  EXPECT_EQ(find_violation(refined({1, 1, 1, 1}, {{2, 2, 2}})), std::nullopt);
  EXPECT_EQ(find_violation(face_state()), std::nullopt);
  // The 26-node cell of spec/lattice3d.md §3 F3: the middle cube of 3 3 3 1
  // with all 26 others refined.
  std::vector<Point> others;
  for (std::int64_t i = 0; i < 3; ++i)
    for (std::int64_t j = 0; j < 3; ++j)
      for (std::int64_t k = 0; k < 3; ++k)
        if (i != 1 || j != 1 || k != 1) others.push_back({4 * i + 2, 4 * j + 2, 4 * k + 2});
  const Graph g = refined({3, 3, 3, 1}, others);
  EXPECT_EQ(g.nbr({6, 6, 6}).size(), 26u);
  EXPECT_EQ(find_violation(g), std::nullopt);
  // The largest coordinates: the extent 2^62.
  const std::int64_t h = std::int64_t{1} << 61;
  EXPECT_TRUE(is_valid(refined({1, 1, 1, 61}, {{h, h, h}, {h / 2, h / 2, h / 2}})));
}

// spec/lattice3d.md §2: cells meeting only at a corner may differ by two.
TEST(D3Invariants, CornerNeighboursMayDifferByTwo) {
  // lattice 2 2 2 2 (S = 8): refine the 7 level-0 cubes other than (4, 4, 4),
  // then the child (10, 10, 10): the level-2 cube [8, 10]^3 meets the level-0
  // cube [0, 8]^3 at the point (8, 8, 8) only.
  const Graph g =
      refined({2, 2, 2, 2},
              {{12, 4, 4}, {4, 12, 4}, {12, 12, 4}, {4, 4, 12}, {12, 4, 12}, {4, 12, 12}, {12, 12, 12}, {10, 10, 10}});
  EXPECT_EQ(g.level.at({9, 9, 9}) - g.level.at({4, 4, 4}), 2);
  EXPECT_TRUE(g.nbr({8, 8, 8}).count({4, 4, 4}) && g.nbr({8, 8, 8}).count({9, 9, 9}));
  EXPECT_EQ(find_violation(g), std::nullopt);
}

template <class Set>
Point pick(const Set& s, std::mt19937_64& rng) {
  auto it = s.begin();
  std::advance(it, static_cast<long>(std::uniform_int_distribution<std::size_t>(0, s.size() - 1)(rng)));
  return *it;
}

// One random operation: refine a random cell, or coarsen a random node (half
// of the time one at a refined-center position). Appends it to `trace`.
void random_step(Graph& g, std::mt19937_64& rng, std::string& trace) {
  if (std::uniform_int_distribution<int>(0, 99)(rng) < 55) {
    const Point c = pick(g.C, rng);
    trace += "refine " + to_string(c) + "\n";
    refine(g, c);
    return;
  }
  std::vector<Point> centers;
  for (const Point& v : g.N)
    if (refined_center_level(g.size, v)) centers.push_back(v);
  const bool any = centers.empty() || std::uniform_int_distribution<int>(0, 1)(rng) == 0;
  const Point n = any ? pick(g.N, rng) : pick(centers, rng);
  trace += "coarsen " + to_string(n) + "\n";
  coarsen(g, n);
}

struct Case {
  LatticeSize size;
  int steps;
};
const Case kCases[] = {{{1, 1, 1, 3}, 80}, {{2, 1, 1, 2}, 80}, {{2, 2, 1, 2}, 60}, {{2, 2, 2, 1}, 40}};
constexpr std::uint64_t kSeeds[] = {20090303, 7};

TEST(D3Invariants, EveryStateOfRandomSequencesIsValid) {
  int states = 0;
  for (const Case& k : kCases)
    for (const std::uint64_t seed : kSeeds) {
      std::mt19937_64 rng(seed);
      Graph g(k.size);
      std::string trace;
      for (int step = 0; step < k.steps; ++step) {
        random_step(g, rng, trace);
        const std::optional<Violation> v = find_violation(g);
        ASSERT_EQ(v, std::nullopt) << "seed " << seed << ", lattice " << k.size.W << ' ' << k.size.H << ' ' << k.size.D
                                   << ' ' << k.size.L << ":\n"
                                   << trace << to_string(*v);
        ++states;
      }
    }
  EXPECT_GT(states, 400);
}

// Every single mutation of a valid state is caught: one side of one edge
// deleted, one level changed, one node removed.
TEST(D3Invariants, RandomMutationsAreCaught) {
  int mutations = 0;
  for (const Case& k : kCases)
    for (const std::uint64_t seed : kSeeds) {
      std::mt19937_64 rng(seed + 1000);
      Graph g(k.size);
      std::string trace;
      for (int step = 0; step < k.steps; ++step) {
        random_step(g, rng, trace);
        if (step % 4 != 3) continue;
        const std::string where = "seed " + std::to_string(seed) + " after:\n" + trace;
        {
          Graph m = g;
          const Point v = pick(std::uniform_int_distribution<int>(0, 1)(rng) ? m.C : m.N, rng);
          const Point w = pick(m.nbr(v), rng);
          m.neighbors[v].erase(w);
          const std::optional<Violation> found = find_violation(m);
          ASSERT_TRUE(found.has_value()) << where << "edge " << to_string(v) << " -> " << to_string(w) << " deleted";
          EXPECT_EQ(found->code, "symmetry") << to_string(*found);
        }
        {
          Graph m = g;
          const Point c = pick(m.C, rng);
          const int delta = std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1;
          m.level[c] += delta * std::uniform_int_distribution<int>(1, 2)(rng);
          EXPECT_FALSE(is_valid(m)) << where << "level of " << to_string(c) << " changed to " << m.level[c];
        }
        {
          Graph m = g;
          const Point n = pick(m.N, rng);
          remove_node(m, n);
          EXPECT_FALSE(is_valid(m)) << where << "node " << to_string(n) << " removed";
        }
        mutations += 3;
      }
    }
  EXPECT_GT(mutations, 100);
}

// The graph spec/lattice3d.md §1 derives from a leaf set, built by the test
// model (tests/d3/leaf_model.h), whatever the balance of the leaves.
Graph graph_of(const LatticeSize& size, const model::Leaves& leaves) {
  const model::GeometricGraph geo = model::geometric_graph(size, leaves);
  Graph g;
  g.size = size;
  g.N = geo.N;
  for (const auto& [c, l] : leaves) {
    g.C.insert(c);
    g.level[c] = l;
  }
  for (const auto& [v, nbrs] : geo.nbr) g.neighbors[v] = nbrs;
  return g;
}

// A random octree leaf set: each cube below level L is refined with
// probability `p`; balance is not enforced.
model::Leaves random_leaves(const LatticeSize& size, double p, std::mt19937_64& rng) {
  model::Leaves leaves;
  std::bernoulli_distribution split(p);
  const auto grow = [&](const auto& self, const Point& c, int l) -> void {
    if (l == size.L || !split(rng)) {
      leaves[c] = l;
      return;
    }
    const std::int64_t q = model::side(size, l) / 4;
    for (int i = 0; i < 8; ++i)
      self(self, {c.x + ((i & 4) ? q : -q), c.y + ((i & 2) ? q : -q), c.z + ((i & 1) ? q : -q)}, l + 1);
  };
  const std::int64_t S = model::side(size, 0);
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t k = 0; k < size.D; ++k) grow(grow, {i * S + S / 2, j * S + S / 2, k * S + S / 2}, 0);
  return leaves;
}

// The checker accepts the graph of a random leaf set exactly when the test
// model finds it balanced (and the cardinality facts hold): an unbalanced
// leaf set is always rejected, a balanced one always accepted.
TEST(D3Invariants, AgreesWithTheModelOnRandomLeafSets) {
  const LatticeSize sizes[] = {{2, 2, 1, 2}, {2, 1, 1, 3}, {1, 1, 1, 3}, {2, 2, 2, 2}};
  constexpr std::uint64_t seed = 20090303;
  std::mt19937_64 rng(seed);
  int balanced = 0, unbalanced = 0;
  for (int round = 0; round < 60; ++round)
    for (const LatticeSize& size : sizes) {
      const model::Leaves leaves = random_leaves(size, 0.35, rng);
      const Graph g = graph_of(size, leaves);
      const std::string problem = test::state_problem(g);
      const std::optional<Violation> v = find_violation(g);
      ASSERT_EQ(problem.empty(), !v.has_value())
          << "seed " << seed << ", round " << round << ": model says \"" << problem << "\", checker says \""
          << (v ? to_string(*v) : std::string("valid")) << "\"";
      ++(problem.empty() ? balanced : unbalanced);
    }
  EXPECT_GT(balanced, 20);
  EXPECT_GT(unbalanced, 20);
}

// Random mutations of random reachable states: the checker and the test
// model agree on every one (and both reject it).
TEST(D3Invariants, MutationsAgreeWithTheModel) {
  constexpr std::uint64_t seed = 99;
  std::mt19937_64 rng(seed);
  int checked = 0;
  for (const Case& k : kCases) {
    Graph g(k.size);
    std::string trace;
    for (int step = 0; step < k.steps; ++step) {
      random_step(g, rng, trace);
      Graph m = g;
      std::string what;
      switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
        case 0: {  // one edge deleted from both sides
          const Point c = pick(m.C, rng), n = pick(m.nbr(c), rng);
          unlink(m, c, n);
          what = "edge " + to_string(c) + " - " + to_string(n) + " deleted";
          break;
        }
        case 1: {  // an edge to a node not on the cell's cube
          const Point c = pick(m.C, rng), n = pick(m.N, rng);
          if (m.nbr(c).count(n)) continue;
          link(m, c, n);
          what = "edge " + to_string(c) + " - " + to_string(n) + " added";
          break;
        }
        case 2: {
          const Point c = pick(m.C, rng);
          remove_cell(m, c);
          what = "cell " + to_string(c) + " removed";
          break;
        }
        default: {
          const Point n = pick(m.N, rng);
          remove_node(m, n);
          what = "node " + to_string(n) + " removed";
          break;
        }
      }
      const std::string problem = test::state_problem(m);
      const std::optional<Violation> v = find_violation(m);
      ASSERT_EQ(problem.empty(), !v.has_value())
          << "seed " << seed << " after:\n"
          << trace << what << ": model says \"" << problem << "\", checker says \""
          << (v ? to_string(*v) : std::string("valid")) << "\"";
      EXPECT_TRUE(v.has_value()) << trace << what;
      ++checked;
    }
  }
  EXPECT_GT(checked, 150);
}

// ---------------------------------------------------------------- layer 1

TEST(D3Layer1, LatticeSize) {
  Graph g({1, 1, 1, 1});
  g.size.D = 0;
  expect_violation(find_violation(g), "lattice-size", 1);
  g.size = {1, 1, 1, 62};
  expect_violation(find_violation(g), "lattice-size", 1);
  g.size = {3, 1, 1, 61};  // 3 * 2^62 > 2^62
  expect_violation(find_violation(g), "lattice-size", 1);
  // Each extent and each lower bound on its own.
  const LatticeSize bad[] = {{0, 1, 1, 1}, {1, 0, 1, 1}, {1, 1, 1, -1}, {1, 3, 1, 61}, {1, 1, 3, 61}};
  for (const LatticeSize& size : bad) {
    g.size = size;
    expect_violation(find_violation(g), "lattice-size", 1);
  }
}

TEST(D3Layer1, Partition) {
  Graph g({1, 1, 1, 1});
  g.N.insert({2, 2, 2});
  expect_violation(find_violation(g), "partition", 1);
}

TEST(D3Layer1, NeighborEntry) {
  Graph g({1, 1, 1, 1});
  g.neighbors.erase({0, 0, 0});
  expect_violation(find_violation(g), "neighbor-entry", 1);
}

TEST(D3Layer1, StaleEntry) {
  Graph g = refined({1, 1, 1, 1}, {{2, 2, 2}});
  coarsen(g, {2, 2, 2});
  g.neighbors[{1, 1, 1}] = {{0, 0, 0}};  // a deleted child left behind
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "stale-entry", 1);
  EXPECT_EQ(v->where, std::vector<Point>({{1, 1, 1}}));
}

TEST(D3Layer1, DanglingNeighbor) {
  Graph g({1, 1, 1, 1});
  g.neighbors[{2, 2, 2}].insert({7, 7, 7});
  expect_violation(find_violation(g), "dangling-neighbor", 1);
}

TEST(D3Layer1, Bipartite) {
  Graph g({1, 1, 1, 1});
  link(g, {0, 0, 0}, {4, 0, 0});
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "bipartite", 1);
  EXPECT_EQ(v->where, std::vector<Point>({{0, 0, 0}, {4, 0, 0}}));
}

TEST(D3Layer1, Symmetry) {
  Graph g = face_state();
  g.neighbors[{12, 4, 4}].erase({8, 4, 4});
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "symmetry", 1);
  EXPECT_EQ(v->message, "symmetry: node (8, 4, 4) lists center (12, 4, 4), which does not list it");
  EXPECT_EQ(v->section, "spec/lattice3d.md §1");
}

TEST(D3Layer1, EmptyNeighbors) {
  Graph g({1, 1, 1, 1});
  for (const Point& n : g.N) unlink(g, {2, 2, 2}, n);
  expect_violation(find_violation(g), "empty-neighbors", 1);
}

TEST(D3Layer1, MissingLevel) {
  Graph g = face_state();
  g.level.erase({6, 6, 6});
  expect_violation(find_violation(g), "missing-level", 1);
}

TEST(D3Layer1, StrayLevel) {
  Graph g = face_state();
  g.level[{4, 4, 4}] = 0;  // the refined cell's center, now a node
  expect_violation(find_violation(g), "stray-level", 1);
}

// ---------------------------------------------------------------- layer 2

TEST(D3Layer2, CenterDegree) {
  Graph g({1, 1, 1, 1});
  remove_node(g, {0, 0, 0});  // the cell keeps 7 corners
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "center-degree", 2);
  EXPECT_EQ(v->section, "spec/lattice3d.md §3 F3");
}

TEST(D3Layer2, CenterCorner) {
  Graph g = face_state();
  remove_node(g, {16, 0, 0});  // (12, 4, 4) keeps 12 nodes, not its corner (16, 0, 0)
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "center-corner", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{12, 4, 4}, {16, 0, 0}}));
}

TEST(D3Layer2, CenterNeighbor) {
  Graph g({1, 1, 1, 1});
  g.N.insert({1, 0, 0});  // a quarter point of an edge
  link(g, {2, 2, 2}, {1, 0, 0});
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "center-neighbor", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{2, 2, 2}, {1, 0, 0}}));
}

TEST(D3Layer2, FaceCenterEdges) {
  Graph g = face_state();
  unlink(g, {12, 4, 4}, {8, 4, 0});  // (8, 4, 0) keeps its two children
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "face-center-edges", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{12, 4, 4}, {8, 4, 4}, {8, 4, 0}}));
}

TEST(D3Layer2, NodeDegreeOfAPureNode) {
  Graph g({2, 1, 1, 1});
  remove_cell(g, {6, 2, 2});  // a hole: (4, 0, 0) is a corner of one cell only
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "node-degree", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{4, 0, 0}}));
}

TEST(D3Layer2, NodeDegreeAboveEight) {
  // lattice 2 2 2 2 (S = 8): a level-2 cell [8, 10]^3 inside the level-0
  // cube (12, 12, 12) gives the interior node (8, 8, 8) a ninth cell.
  Graph g({2, 2, 2, 2});
  add_cube(g, {9, 9, 9}, 2, 1);
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "node-degree", 2);
  EXPECT_EQ(v->message, "node-degree: node (8, 8, 8) has 9 cells; a node has at most 8");
}

TEST(D3Layer2, BoundaryJunctionOnADomainEdge) {
  Graph g({1, 1, 1, 1});
  add_linked_nodes(g, {{2, 2, 2}}, {{2, 0, 0}});  // the midpoint of an edge on a domain edge
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "boundary-junction", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{2, 2, 2}, {2, 0, 0}}));
}

TEST(D3Layer2, BoundaryJunctionOnADomainFace) {
  // lattice 3 3 1 1: the middle cell lists the center of its bottom face,
  // which is in the domain boundary, with the face's four edge midpoints.
  Graph g({3, 3, 1, 1});
  add_linked_nodes(g, {{6, 6, 2}}, {{6, 6, 0}, {4, 6, 0}, {8, 6, 0}, {6, 4, 0}, {6, 8, 0}});
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "boundary-junction", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{6, 6, 2}, {6, 6, 0}}));
}

TEST(D3Layer2, JunctionDegree) {
  // lattice 2 1 1 1: both cells list the center of their shared face and its
  // edge midpoints, but no finer cell has them as corners.
  Graph g({2, 1, 1, 1});
  add_linked_nodes(g, {{2, 2, 2}, {6, 2, 2}}, {{4, 2, 2}, {4, 0, 2}, {4, 4, 2}, {4, 2, 0}, {4, 2, 4}});
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "junction-degree", 2);
  EXPECT_EQ(v->where, std::vector<Point>({{2, 2, 2}, {4, 0, 2}}));
}

// ---------------------------------------------------------------- layer 3

TEST(D3Layer3, Grading) {
  Graph g = face_state();
  g.level[{6, 2, 2}] = 2;  // stored two levels finer than its face neighbour (12, 4, 4)
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "grading", 3);
  EXPECT_EQ(v->where, std::vector<Point>({{6, 2, 2}, {12, 4, 4}}));
  EXPECT_EQ(v->section, "spec/lattice3d.md §2");
}

TEST(D3Layer3, ACorruptionByOneIsACenterPosition) {
  Graph g = face_state();
  g.level[{2, 2, 2}] = 2;  // away from the coarse cell: only siblings around
  expect_violation(find_violation(g), "center-position", 4);
}

// ---------------------------------------------------------------- layer 4

TEST(D3Layer4, LevelRange) {
  Graph g({1, 1, 1, 1});
  g.level[{2, 2, 2}] = 7;
  expect_violation(find_violation(g), "level-range", 4);
  g.level[{2, 2, 2}] = -1;
  expect_violation(find_violation(g), "level-range", 4);
}

TEST(D3Layer4, OutsideDomain) {
  // A second level-0 cube stacked on top of lattice 1 1 1 1 (S = 4).
  Graph g({1, 1, 1, 1});
  add_cube(g, {2, 2, 6}, 0, 2);
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "outside-domain", 4);
  EXPECT_EQ(v->where, std::vector<Point>({{0, 0, 8}}));
}

TEST(D3Layer4, CenterPosition) {
  Graph g = refined({1, 1, 1, 2}, {{4, 4, 4}});
  g.level[{2, 2, 2}] = 0;
  const std::optional<Violation> v = find_violation(g);
  expect_violation(v, "center-position", 4);
  EXPECT_EQ(v->where, std::vector<Point>({{2, 2, 2}}));
}

TEST(D3Layer4, Overlap) {
  Graph g = refined({1, 1, 1, 1}, {{2, 2, 2}});
  g.N.erase({2, 2, 2});  // the parent is a leaf again, and so are its children
  g.C.insert({2, 2, 2});
  g.level[{2, 2, 2}] = 0;
  const std::optional<Violation> v = check_layer(g, 4);
  expect_violation(v, "overlap", 4);
  EXPECT_EQ(v->where, std::vector<Point>({{2, 2, 2}, {1, 1, 1}}));
}

TEST(D3Layer4, Coverage) {
  Graph g = refined({1, 1, 1, 1}, {{2, 2, 2}});
  g.C.erase({3, 3, 3});
  g.level.erase({3, 3, 3});
  const std::optional<Violation> v = check_layer(g, 4);
  expect_violation(v, "coverage", 4);
  EXPECT_EQ(v->where, std::vector<Point>({{3, 3, 3}}));
  // A missing level-0 cube is found too.
  Graph h({2, 1, 1, 1});
  h.C.erase({6, 2, 2});
  h.level.erase({6, 2, 2});
  const std::optional<Violation> w = check_layer(h, 4);
  expect_violation(w, "coverage", 4);
  EXPECT_EQ(w->where, std::vector<Point>({{6, 2, 2}}));
}

TEST(D3Layer4, NodeCells) {
  Graph g = face_state();
  unlink(g, {12, 4, 4}, {8, 4, 0});
  const std::optional<Violation> v = check_layer(g, 4);
  expect_violation(v, "node-cells", 4);
  EXPECT_EQ(v->where, std::vector<Point>({{8, 4, 0}, {12, 4, 4}}));
  // A listed cell whose cube does not contain the node.
  Graph h({2, 1, 1, 1});
  link(h, {2, 2, 2}, {8, 0, 0});
  const std::optional<Violation> w = check_layer(h, 4);
  expect_violation(w, "node-cells", 4);
  EXPECT_EQ(w->where, std::vector<Point>({{8, 0, 0}, {2, 2, 2}}));
}

// The geometry layer's position tests, axis by axis: a vertex outside the box
// on each axis (a node, and a center), and centers whose coordinates fail the
// odd-multiple rule on x, on y or on z, on the box's boundary, or at a
// position no level of the lattice can have (spec/lattice3d.md §1).
TEST(D3Layer4, OutsideDomainOnEveryAxis) {
  const Point outside[] = {{-4, 0, 0}, {0, 8, 0}, {0, 0, 8}};
  for (const Point& p : outside) {
    Graph g({1, 1, 1, 1});  // the box [0, 4]^3
    g.N.insert(p);
    g.neighbors[p].insert({2, 2, 2});
    const std::optional<Violation> v = check_layer(g, 4);
    expect_violation(v, "outside-domain", 4);
    EXPECT_EQ(v->where, std::vector<Point>({p}));
    EXPECT_NE(v->message.find("node " + to_string(p)), std::string::npos) << v->message;
  }
  Graph g({1, 1, 1, 1});
  const Point c{2, 2, 6};
  g.C.insert(c);
  g.level[c] = 0;
  g.neighbors[c].insert({0, 0, 4});
  const std::optional<Violation> v = check_layer(g, 4);
  expect_violation(v, "outside-domain", 4);
  EXPECT_NE(v->message.find("center (2, 2, 6)"), std::string::npos) << v->message;
}

TEST(D3Layer4, CenterPositionOnEveryAxis) {
  // lattice 1 1 1 1 (S = 4): a level-0 center has coordinates that are odd
  // multiples of 2, i.e. (2, 2, 2). Each of these fails on one axis; none is
  // the center of any cube (mixed trailing zeros, or on the boundary).
  const Point wrong[] = {{1, 2, 2}, {2, 1, 2}, {2, 2, 1}, {0, 2, 2}, {2, 0, 2}, {2, 2, 4}};
  for (const Point& c : wrong) {
    Graph g({1, 1, 1, 1});
    g.C.insert(c);
    g.level[c] = 0;
    g.neighbors[c].insert({0, 0, 0});
    const std::optional<Violation> v = check_layer(g, 4);
    expect_violation(v, "center-position", 4);
    EXPECT_EQ(v->where, std::vector<Point>({c}));
    EXPECT_NE(v->message.find("is not the center of any cube"), std::string::npos) << v->message;
  }
  // lattice 2 2 2 1 (S = 4, box [0, 8]^3): (4, 4, 4) has three coordinates
  // with two trailing zero bits, a level -1 center: no level of this lattice.
  Graph g({2, 2, 2, 1});
  g.C.insert({4, 4, 4});
  g.level[{4, 4, 4}] = 1;
  g.neighbors[{4, 4, 4}].insert({0, 0, 0});
  const std::optional<Violation> v = check_layer(g, 4);
  expect_violation(v, "center-position", 4);
  EXPECT_NE(v->message.find("is not the center of any cube"), std::string::npos) << v->message;
  // (1, 1, 1) stored with level 0 is where a level-1 center is.
  Graph h = refined({1, 1, 1, 1}, {{2, 2, 2}});
  h.level[{1, 1, 1}] = 0;
  const std::optional<Violation> w = check_layer(h, 4);
  expect_violation(w, "center-position", 4);
  EXPECT_NE(w->message.find("the center of a level-1 cube"), std::string::npos) << w->message;
}

TEST(D3Layer4, CoverageBelowARefinedChildAndOnAHugeLattice) {
  // lattice 1 1 1 2 (S = 8): the root and its child (2, 2, 2) refined, one
  // grandchild removed: the walk passes the refined child and finds the gap.
  Graph g = refined({1, 1, 1, 2}, {{4, 4, 4}, {2, 2, 2}});
  g.C.erase({3, 3, 3});
  g.level.erase({3, 3, 3});
  const std::optional<Violation> v = check_layer(g, 4);
  expect_violation(v, "coverage", 4);
  EXPECT_EQ(v->where, std::vector<Point>({{3, 3, 3}}));
  // W*H*D overflows int64 (2^60 x 2^60 x 1 cubes, L = 0): the count cannot
  // match, and the walk over level-0 cubes stops at the first gap, (1, 1, 3)
  // beside the one leaf (1, 1, 1).
  Graph h;
  h.size = {std::int64_t{1} << 60, std::int64_t{1} << 60, 2, 0};
  h.C.insert({1, 1, 1});
  h.level[{1, 1, 1}] = 0;
  h.neighbors[{1, 1, 1}].insert({0, 0, 0});
  const std::optional<Violation> w = check_layer(h, 4);
  expect_violation(w, "coverage", 4);
  EXPECT_EQ(w->where, std::vector<Point>({{1, 1, 3}}));
}

TEST(D3Layers, CheckLayerRejectsOtherNumbers) {
  const Graph g({1, 1, 1, 0});
  EXPECT_THROW(check_layer(g, 0), std::invalid_argument);
  EXPECT_THROW(check_layer(g, 5), std::invalid_argument);
  EXPECT_EQ(find_violation(g, 0), std::nullopt);
}

TEST(D3Layers, LayersTwoToFourReportAnInvalidLatticeSize) {
  Graph g({1, 1, 1, 1});
  g.size.L = 70;
  for (int layer = 1; layer <= 4; ++layer) expect_violation(check_layer(g, layer), "lattice-size", 1);
}

// The checker is independent of the operations: of src/bccmis/ it includes
// only the data types (bccmis/d3/graph.h, which brings bccmis/graph.h), its
// own files, the violation type it shares with the 2D checker
// (bccmis/invariants/violation.h) and the layer it shares with it
// (bccmis/invariants/detail/combinatorial.h); those two include nothing of src/.
TEST(D3Layers, CheckerIncludesNothingOfTheOperations) {
  const std::filesystem::path dir = std::filesystem::path(BCCMIS_SOURCE_DIR) / "src/bccmis/invariants/d3";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path());
    ASSERT_TRUE(in) << entry.path();
    ++files;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("#include \"", 0) != 0) continue;
      const std::string header = line.substr(10, line.find('"', 10) - 10);
      EXPECT_TRUE(header == "bccmis/d3/graph.h" || header == "bccmis/invariants/detail/combinatorial.h" ||
                  header == "bccmis/invariants/violation.h" || header.rfind("bccmis/invariants/d3/", 0) == 0)
          << entry.path().filename() << " includes " << header;
    }
  }
  EXPECT_GE(files, 7);
}

// ---------------------------------------------------------------- layer 5: the mesh
namespace mesh {

std::int64_t orient(const Tet& t) {
  const auto d = [&](int i, int k) {
    const Point& p = t[static_cast<std::size_t>(i)];
    const Point& a = t[0];
    return k == 0 ? p.x - a.x : k == 1 ? p.y - a.y : p.z - a.z;
  };
  return d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1)) - d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0)) +
         d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0));
}

// A point of the cube [o, o + 2s]^3 from unit coordinates in {0, 1, 2}.
Point at(const Point& o, std::int64_t s, std::array<std::int64_t, 3> u) {
  return {o.x + s * u[0], o.y + s * u[1], o.z + s * u[2]};
}

// How one face of a cube is split.
enum class Split { Center, Diagonal02, Diagonal13 };

// The tets of the cube [o, o + 2s]^3: for each face the 4 tets
// (u, m_F, a, b) over consecutive corners a, b, with u the cube's center and
// m_F the face's center (24 in all), except that face `split_face` (2 * axis
// + side) is cut along a diagonal into 2 tets (u, p, q, r) instead.
// Orientation is decided on the unit cube, so s may be huge.
std::vector<Tet> cube_tets(const Point& o, std::int64_t s, int split_face = -1, Split split = Split::Center) {
  std::vector<Tet> tets;
  for (int face = 0; face < 6; ++face) {
    const int axis = face / 2;
    const std::int64_t side = (face % 2) * 2;
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    std::array<std::array<std::int64_t, 3>, 4> corners{};
    const std::int64_t cyc[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    for (std::size_t i = 0; i < 4; ++i) {
      corners[i][static_cast<std::size_t>(axis)] = side;
      corners[i][static_cast<std::size_t>(b)] = cyc[i][0];
      corners[i][static_cast<std::size_t>(c)] = cyc[i][1];
    }
    std::array<std::int64_t, 3> m{1, 1, 1};
    m[static_cast<std::size_t>(axis)] = side;
    std::vector<std::array<std::array<std::int64_t, 3>, 4>> unit;
    const Split how = face == split_face ? split : Split::Center;
    if (how == Split::Center) {
      for (std::size_t i = 0; i < 4; ++i) unit.push_back({{{1, 1, 1}, m, corners[i], corners[(i + 1) % 4]}});
    } else {
      const std::size_t k = how == Split::Diagonal02 ? 0 : 1;
      unit.push_back({{{1, 1, 1}, corners[k], corners[k + 1], corners[k + 2]}});
      unit.push_back({{{1, 1, 1}, corners[k], corners[k + 2], corners[(k + 3) % 4]}});
    }
    for (auto& t : unit) {
      Tet small{at({0, 0, 0}, 1, t[0]), at({0, 0, 0}, 1, t[1]), at({0, 0, 0}, 1, t[2]), at({0, 0, 0}, 1, t[3])};
      if (orient(small) < 0) std::swap(t[2], t[3]);
      tets.push_back({at(o, s, t[0]), at(o, s, t[1]), at(o, s, t[2]), at(o, s, t[3])});
    }
  }
  return tets;
}

// lattice 2 1 1 0: two cubes [0, 2] and [2, 4] along x, the shared face x = 2
// cut along a diagonal from both sides (the same one when `conforming`).
std::vector<Tet> two_cubes(bool conforming) {
  std::vector<Tet> tets = cube_tets({0, 0, 0}, 1, 1, Split::Diagonal02);
  const std::vector<Tet> right = cube_tets({2, 0, 0}, 1, 0, conforming ? Split::Diagonal02 : Split::Diagonal13);
  tets.insert(tets.end(), right.begin(), right.end());
  return tets;
}

TEST(D3Mesh, OneCubeIsValid) {
  const Graph g({1, 1, 1, 0});
  const std::vector<Tet> tets = cube_tets({0, 0, 0}, 1);
  ASSERT_EQ(tets.size(), 24u);
  for (const Tet& t : tets) EXPECT_GT(orient(t), 0);
  EXPECT_EQ(check_mesh(g, tets), std::nullopt);
}

TEST(D3Mesh, AnglesOfExactly45And120Pass) {
  // A face cut along a diagonal gives tets with dihedral angles of exactly
  // 45 and 120 degrees.
  const Graph g({1, 1, 1, 0});
  EXPECT_EQ(check_mesh(g, cube_tets({0, 0, 0}, 1, 4, Split::Diagonal13)), std::nullopt);
  EXPECT_EQ(check_mesh(Graph({2, 1, 1, 0}), two_cubes(true)), std::nullopt);
}

TEST(D3Mesh, ExactAtTheLargestExtent) {
  // lattice 1 1 1 61: the cube [0, 2^62]^3; six-fold volumes of 2^184 each.
  const Graph g({1, 1, 1, 61});
  std::vector<Tet> tets = cube_tets({0, 0, 0}, std::int64_t{1} << 61);
  EXPECT_EQ(check_mesh(g, tets), std::nullopt);
  tets.pop_back();
  expect_violation(check_mesh(g, tets), "mesh-volume", 5);
}

TEST(D3Mesh, LatticeSize) {
  Graph g({1, 1, 1, 0});
  g.size.W = 0;
  expect_violation(check_mesh(g, cube_tets({0, 0, 0}, 1)), "lattice-size", 1);
}

TEST(D3Mesh, MeshVertex) {
  const Graph g({1, 1, 1, 0});
  std::vector<Tet> tets = cube_tets({0, 0, 0}, 1);
  tets[3][1] = {1, 0, 0};  // an edge midpoint: no vertex
  const std::optional<Violation> v = check_mesh(g, tets);
  expect_violation(v, "mesh-vertex", 5);
  EXPECT_EQ(v->where, std::vector<Point>({{1, 0, 0}}));
}

TEST(D3Mesh, TetOrientation) {
  const Graph g({1, 1, 1, 0});
  std::vector<Tet> tets = cube_tets({0, 0, 0}, 1);
  std::swap(tets[5][2], tets[5][3]);
  const std::optional<Violation> v = check_mesh(g, tets);
  expect_violation(v, "tet-orientation", 5);
  EXPECT_EQ(v->where, std::vector<Point>(tets[5].begin(), tets[5].end()));
  EXPECT_NE(v->message.find("tet #5"), std::string::npos) << v->message;
}

TEST(D3Mesh, DihedralAngle) {
  const Graph g({1, 1, 1, 0});
  std::vector<Tet> tets = cube_tets({0, 0, 0}, 1);
  tets[0] = {{{0, 0, 0}, {0, 0, 2}, {2, 0, 0}, {2, 2, 2}}};  // positive, angles 35.26 to 125.26 degrees
  ASSERT_GT(orient(tets[0]), 0);
  const std::optional<Violation> v = check_mesh(g, tets);
  expect_violation(v, "dihedral-angle", 5);
  EXPECT_EQ(v->where, std::vector<Point>({{0, 0, 2}, {2, 0, 0}}));
}

TEST(D3Mesh, MeshVolumeOfARemovedOrDuplicatedTet) {
  const Graph g({1, 1, 1, 0});
  std::vector<Tet> removed = cube_tets({0, 0, 0}, 1);
  removed.erase(removed.begin() + 7);
  expect_violation(check_mesh(g, removed), "mesh-volume", 5);
  std::vector<Tet> duplicated = cube_tets({0, 0, 0}, 1);
  duplicated.push_back(duplicated[7]);
  expect_violation(check_mesh(g, duplicated), "mesh-volume", 5);
}

TEST(D3Mesh, FaceSides) {
  // A tet replaced by a copy of another of the same volume: the volume is
  // right, but the copy overlaps the original.
  const Graph g({1, 1, 1, 0});
  std::vector<Tet> tets = cube_tets({0, 0, 0}, 1);
  tets[1] = tets[0];
  expect_violation(check_mesh(g, tets), "face-sides", 5);
}

TEST(D3Mesh, FaceCount) {
  // The two cubes cut their shared face along different diagonals.
  const std::optional<Violation> v = check_mesh(Graph({2, 1, 1, 0}), two_cubes(false));
  expect_violation(v, "face-count", 5);
  ASSERT_EQ(v->where.size(), 3u);
  for (const Point& p : v->where) EXPECT_EQ(p.x, 2);
}

TEST(D3Mesh, MeshExtraEdge) {
  Graph g({1, 1, 1, 0});
  unlink(g, {1, 1, 1}, {0, 0, 0});
  const std::optional<Violation> v = check_mesh(g, cube_tets({0, 0, 0}, 1));
  expect_violation(v, "mesh-extra-edge", 5);
  EXPECT_EQ(v->where, std::vector<Point>({{1, 1, 1}, {0, 0, 0}}));
}

TEST(D3Mesh, MeshMissingEdge) {
  Graph g({2, 1, 1, 0});
  g.N.insert({2, 1, 1});  // the shared face's center, in no tet
  link(g, {1, 1, 1}, {2, 1, 1});
  link(g, {3, 1, 1}, {2, 1, 1});
  const std::optional<Violation> v = check_mesh(g, two_cubes(true));
  expect_violation(v, "mesh-missing-edge", 5);
  EXPECT_EQ(v->where, std::vector<Point>({{1, 1, 1}, {2, 1, 1}}));
}

}  // namespace mesh

// ---------------------------------------------------------------- layer 5 on real meshes
// bccmis::d3::tetrahedra (spec/mesh3d.md) through the mesh layer: the hand
// examples M15-M19 and every state of random refine/coarsen sequences on
// lattices of 1 to 3 cubes per side, L up to 3.
namespace real_mesh {

std::string lattice_line(const LatticeSize& s) {
  return "lattice " + std::to_string(s.W) + ' ' + std::to_string(s.H) + ' ' + std::to_string(s.D) + ' ' +
         std::to_string(s.L);
}

TEST(D3MeshOfTetrahedra, HandExamplesPass) {
  struct Example {
    LatticeSize size;
    std::vector<Point> refines;
    std::size_t tets;
  };
  const Example examples[] = {
      {{1, 1, 1, 0}, {}, 24},            // spec/mesh3d.md M15
      {{2, 1, 1, 0}, {}, 44},            // spec/mesh3d.md M16
      {{1, 1, 1, 1}, {{2, 2, 2}}, 144},  // spec/mesh3d.md M17
      {{2, 1, 1, 2}, {{4, 4, 4}}, 168},  // spec/mesh3d.md M18
  };
  for (const Example& e : examples) {
    const Graph g = refined(e.size, e.refines);
    ASSERT_EQ(find_violation(g), std::nullopt) << lattice_line(e.size);
    const std::vector<Tet> tets = tetrahedra(g);
    EXPECT_EQ(tets.size(), e.tets) << lattice_line(e.size);
    const std::optional<Violation> v = check_mesh(g, tets);
    EXPECT_EQ(v, std::nullopt) << lattice_line(e.size) << ": " << to_string(*v);
  }
  // spec/mesh3d.md M19: the bisected equal face.
  const Graph g = refined({2, 2, 1, 1}, {{2, 2, 2}});
  const std::vector<Tet> tets = tetrahedra(g);
  const std::optional<Violation> v = check_mesh(g, tets);
  EXPECT_EQ(v, std::nullopt) << to_string(*v);
  // A planted error in a real mesh is still caught.
  std::vector<Tet> removed = tets;
  removed.erase(removed.begin() + static_cast<long>(removed.size() / 2));
  expect_violation(check_mesh(g, removed), "mesh-volume", 5);
}

TEST(D3MeshOfTetrahedra, EveryStateOfRandomSequencesPasses) {
  const Case cases[] = {{{1, 1, 1, 3}, 40}, {{2, 1, 1, 3}, 30}, {{3, 1, 2, 2}, 30}, {{2, 2, 2, 2}, 25},
                        {{3, 3, 1, 1}, 25}, {{1, 2, 3, 2}, 25}, {{3, 3, 3, 1}, 20}, {{2, 3, 1, 0}, 1}};
  constexpr std::uint64_t seeds[] = {20090303};
  int states = 0, graded = 0;
  for (const Case& k : cases)
    for (const std::uint64_t seed : seeds) {
      std::mt19937_64 rng(seed);
      Graph g(k.size);
      std::string trace;
      for (int step = 0; step < k.steps; ++step) {
        random_step(g, rng, trace);
        const std::string where = "seed " + std::to_string(seed) + ", " + lattice_line(k.size) + ":\n" + trace;
        ASSERT_EQ(find_violation(g), std::nullopt) << where;
        const std::vector<Tet> tets = tetrahedra(g);
        const std::optional<Violation> v = check_mesh(g, tets);
        ASSERT_EQ(v, std::nullopt) << where << to_string(*v);
        ++states;
        int lo = k.size.L, hi = 0;
        for (const auto& [c, l] : g.level) lo = std::min(lo, l), hi = std::max(hi, l);
        graded += lo != hi;
      }
    }
  EXPECT_GT(states, 175);
  EXPECT_GT(graded, 75);  // most states mix levels, so split faces are exercised
}

}  // namespace real_mesh

}  // namespace
}  // namespace bccmis::d3
