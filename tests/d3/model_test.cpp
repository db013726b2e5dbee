// RapidCheck properties of the 3D lattice against the independent octree-leaf
// model (tests/d3/leaf_model.h) and the independent 3D checker:
//   - rc::state: every refine and coarsen decision (ok or the refusal code)
//     and every resulting state agree with the model, whose decisions come
//     from the leaves alone and whose graph is derived geometrically;
//   - coarsen then refine of the same node is the identity; a refused call
//     leaves the canonical state byte for byte as it was;
//   - the checker's layers 1-4 and the mesh layer hold after every step of
//     random sequences on random lattices (1..3 cubes per side, L <= 4);
//   - refining everything level by level, then coarsening everything, gives
//     back the initial lattice.
// The seed and budget are fixed in tests/d3/d3.cmake; a failure prints the
// reproducer trace and RapidCheck's reproduce string.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/invariants/d3/invariants.h"
#include "check.h"
#include "testing/decision.h"
#include "util.h"

namespace bccmis::d3 {
namespace {

std::string lattice_text(const LatticeSize& s) {
  return std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.D) + " " + std::to_string(s.L);
}

std::string point_text(const Point& p) {
  return std::to_string(p.x) + ' ' + std::to_string(p.y) + ' ' + std::to_string(p.z);
}

template <class Range>
Point pick(const Range& r) {
  auto it = r.begin();
  std::advance(it, static_cast<long>(*rc::gen::inRange<std::size_t>(0, r.size())));
  return *it;
}

/// A point of the lattice's integer box, vertex or not.
Point any_point(const LatticeSize& size) {
  const std::int64_t S = model::side(size, 0);
  return Point{*rc::gen::inRange<std::int64_t>(-1, size.W * S + 2), *rc::gen::inRange<std::int64_t>(-1, size.H * S + 2),
               *rc::gen::inRange<std::int64_t>(-1, size.D * S + 2)};
}

/// The first problem of g by the whole checker: layers 1-4, then the mesh.
std::string checker_problem(const Graph& g) {
  if (const auto v = find_violation(g, 4)) return to_string(*v);
  std::vector<Tet> tets;
  try {
    tets = tetrahedra(g);
  } catch (const std::exception& e) {
    return std::string("tetrahedra threw: ") + e.what();
  }
  if (const auto v = check_mesh(g, tets)) return to_string(*v);
  return {};
}

// ---- rc::state: the graph against the leaf model ---------------------------------

struct Model {
  LatticeSize size;
  model::Leaves leaves;
};

struct Sut {
  explicit Sut(const LatticeSize& size) : g(size) { trace = "lattice " + lattice_text(size) + "\n"; }
  Graph g;
  std::string trace;  // the commands so far, as a 3D trace
};

using Cmd = rc::state::Command<Model, Sut>;

/// Runs the operation on the graph and compares the decision and the state.
void run_and_compare(bool is_refine, const Point& at, const Model& before, Sut& sut) {
  const std::string what = std::string(is_refine ? "refine " : "coarsen ") + point_text(at);
  sut.trace += what + "\n";
  auto fail = [&](const std::string& msg) { RC_FAIL(msg + "\nreproducer trace:\n" + sut.trace); };
  const std::string expected = is_refine ? model::refine_decision(before.size, before.leaves, at)
                                         : model::coarsen_decision(before.size, before.leaves, at);
  const std::string state_before = canonical_state(sut.g);
  std::string have;
  try {
    have = bccmis::testing::run_and_decide(sut.g, is_refine, at);
  } catch (const std::exception& e) {
    fail(what + " threw: " + e.what());
  }
  if (have != expected) fail(what + ": the graph says " + have + ", the model says " + expected);
  if (have != "ok" && canonical_state(sut.g) != state_before) fail(what + " was refused but changed the state");
  model::Leaves after = before.leaves;
  if (expected == "ok") {
    if (is_refine)
      model::apply_refine(before.size, after, at);
    else
      model::apply_coarsen(before.size, after, at);
  }
  if (test::leaves_of(sut.g) != after) fail("after " + what + ": the leaves differ from the model's");
  if (const std::string why = test::state_problem(sut.g); !why.empty())
    fail("after " + what + ": the graph is not the geometric graph of its leaves: " + why);
}

// kind 0: one of `preferred`; kind 1: a corner of one of the leaves
// (`centers`), which corner(box) of its cube says (a node); otherwise any
// point in or around the domain.
template <class Corner>
Point pick_point(const Model& m, int kind, const std::vector<Point>& preferred, const std::vector<Point>& centers,
                 Corner corner) {
  if (kind == 0) return pick(preferred);
  if (kind == 1) {
    const Point c = pick(centers);
    return corner(model::cube(m.size, c, m.leaves.at(c)));
  }
  return any_point(m.size);
}

struct Refine : Cmd {
  Point at;
  explicit Refine(const Model& m) {
    // Mostly leaves, sometimes nodes (no-such-cell) or any point.
    std::vector<Point> centers;
    for (const auto& [c, l] : m.leaves) centers.push_back(c);
    const int kind = *rc::gen::weightedElement<int>({{6, 0}, {1, 1}, {1, 2}});
    at = pick_point(m, kind, centers, centers, [](const model::Box& b) { return Point{b.lo[0], b.hi[1], b.lo[2]}; });
  }
  void apply(Model& m) const override {
    if (model::refine_decision(m.size, m.leaves, at) == "ok") model::apply_refine(m.size, m.leaves, at);
  }
  void run(const Model& m, Sut& sut) const override { run_and_compare(true, at, m, sut); }
  void show(std::ostream& os) const override { os << "refine " << point_text(at); }
};

struct Coarsen : Cmd {
  Point at;
  explicit Coarsen(const Model& m) {
    // Mostly the centers of refined cubes (the parents of present leaves),
    // sometimes a leaf's corner or any point.
    std::vector<Point> parents, centers;
    for (const auto& [c, l] : m.leaves) {
      centers.push_back(c);
      if (l == 0) continue;
      const std::int64_t s = model::side(m.size, l - 1);
      parents.push_back(Point{c.x / s * s + s / 2, c.y / s * s + s / 2, c.z / s * s + s / 2});
    }
    const int kind = *rc::gen::weightedElement<int>({{parents.empty() ? 0 : 6, 0}, {1, 1}, {1, 2}});
    at = pick_point(m, kind, parents, centers, [](const model::Box& b) { return Point{b.hi[0], b.lo[1], b.hi[2]}; });
  }
  void apply(Model& m) const override {
    if (model::coarsen_decision(m.size, m.leaves, at) == "ok") model::apply_coarsen(m.size, m.leaves, at);
  }
  void run(const Model& m, Sut& sut) const override { run_and_compare(false, at, m, sut); }
  void show(std::ostream& os) const override { os << "coarsen " << point_text(at); }
};

RC_GTEST_PROP(D3ModelBased, GraphAgreesWithTheLeafModelOnEveryCommand, ()) {
  //= bccmis3d#claim-inverse type=test
  LatticeSize size;
  size.W = *rc::gen::element<std::int64_t>(1, 2);
  size.H = *rc::gen::element<std::int64_t>(1, 2);
  size.D = *rc::gen::element<std::int64_t>(1, 2);
  size.L = *rc::gen::element(1, 2, 3);
  RC_TAG("lattice " + lattice_text(size));
  Model initial{size, test::leaves_of(Graph(size))};
  Sut sut(size);
  rc::state::check(initial, sut, rc::state::gen::execOneOfWithArgs<Refine, Refine, Coarsen>());
}

// The model's decisions are not the graph's by construction: a balanced state
// where the model refuses (coarser-neighbor), and where it accepts.
TEST(D3LeafModel, DecidesFromTheLeaves) {
  const LatticeSize size{2, 1, 1, 2};
  model::Leaves leaves = test::leaves_of(Graph(size));
  ASSERT_EQ(model::refine_decision(size, leaves, {4, 4, 4}), "ok");
  model::apply_refine(size, leaves, {4, 4, 4});
  EXPECT_EQ(model::refine_decision(size, leaves, {6, 2, 2}), "coarser-neighbor");  // touches the level-0 cube
  EXPECT_EQ(model::refine_decision(size, leaves, {2, 2, 2}), "ok");
  EXPECT_EQ(model::refine_decision(size, leaves, {12, 4, 4}), "ok");
  EXPECT_EQ(model::refine_decision(size, leaves, {4, 4, 4}), "no-such-cell");
  EXPECT_EQ(model::coarsen_decision(size, leaves, {4, 4, 4}), "ok");
  EXPECT_EQ(model::coarsen_decision(size, leaves, {12, 4, 4}), "no-such-node");
  EXPECT_EQ(model::coarsen_decision(size, leaves, {0, 0, 0}), "not-a-refined-center");
  model::apply_refine(size, leaves, {2, 2, 2});
  EXPECT_EQ(model::coarsen_decision(size, leaves, {4, 4, 4}), "children-refined");
  EXPECT_EQ(model::refine_decision(size, leaves, {2, 2, 2}), "no-such-cell");
  EXPECT_EQ(model::refine_decision(size, leaves, {1, 1, 1}), "max-level");
}

TEST(D3LeafModel, RefusesACoarsenNextToALevelTwoFinerLeaf) {
  // 1 1 1 3: the level-2 cube (6, 6, 6) at the middle is refined once its
  // face-or-edge neighbours are at level 2; then coarsening (12, 4, 4) would
  // put a level-1 cube against its level-3 leaves.
  const LatticeSize size{1, 1, 1, 3};
  model::Leaves leaves = test::leaves_of(Graph(size));
  Graph g(size);
  auto refine_both = [&](const Point& c) {
    const std::string expected = model::refine_decision(size, leaves, c);
    const RefineResult r = refine(g, c);
    EXPECT_EQ(r.refused ? std::string(code(*r.refused)) : "ok", expected) << to_string(c);
    if (expected == "ok") model::apply_refine(size, leaves, c);
    return expected;
  };
  EXPECT_EQ(refine_both({8, 8, 8}), "ok");
  EXPECT_EQ(refine_both({4, 4, 4}), "ok");
  EXPECT_EQ(refine_both({6, 6, 6}), "coarser-neighbor");
  for (const Point c :
       {Point{12, 4, 4}, Point{4, 12, 4}, Point{4, 4, 12}, Point{12, 12, 4}, Point{12, 4, 12}, Point{4, 12, 12}})
    EXPECT_EQ(refine_both(c), "ok");
  EXPECT_EQ(refine_both({6, 6, 6}), "ok");
  EXPECT_EQ(model::coarsen_decision(size, leaves, {12, 4, 4}), "finer-neighbor");
  const CoarsenResult r = coarsen(g, {12, 4, 4});
  ASSERT_TRUE(r.refused.has_value());
  EXPECT_EQ(code(*r.refused), "finer-neighbor");
  EXPECT_EQ(model::coarsen_decision(size, leaves, {6, 6, 6}), "ok");
  EXPECT_EQ(model::coarsen_decision(size, leaves, {4, 12, 12}), "finer-neighbor");  // along an edge only
  EXPECT_EQ(can_coarsen(g, {4, 12, 12}), CoarsenRefusal::FinerNeighbor);
  EXPECT_EQ(can_coarsen(g, {6, 6, 6}), std::nullopt);
  EXPECT_EQ(test::leaves_of(g), leaves);
}

// ---- Identities and refusals -----------------------------------------------------

/// A random reachable state: n operations at random vertices.
Graph random_state(const LatticeSize& size, int n) {
  Graph g(size);
  for (int i = 0; i < n; ++i) {
    if (*rc::gen::weightedElement<int>({{3, 0}, {2, 1}}) == 0) {
      refine(g, pick(g.C));
    } else {
      std::vector<Point> centers;
      for (const Point& v : g.N)
        if (refined_center_level(g.size, v)) centers.push_back(v);
      if (!centers.empty()) coarsen(g, pick(centers));
    }
  }
  return g;
}

const LatticeSize kSizes[] = {{1, 1, 1, 2}, {2, 1, 1, 2}, {1, 2, 2, 2}, {1, 1, 1, 3}, {2, 2, 2, 1}};

LatticeSize some_size() { return *rc::gen::elementOf(std::vector<LatticeSize>(std::begin(kSizes), std::end(kSizes))); }

RC_GTEST_PROP(D3Properties, CoarsenThenRefineIsTheIdentity, ()) {
  //= bccmis3d#claim-inverse type=test
  const Graph g = random_state(some_size(), *rc::gen::inRange(0, 30));
  std::vector<Point> coarsenable;
  for (const Point& n : g.N)
    if (!can_coarsen(g, n)) coarsenable.push_back(n);
  RC_PRE(!coarsenable.empty());
  const Point n = pick(coarsenable);
  RC_LOG() << "lattice " << lattice_text(g.size) << ", coarsen then refine " << point_text(n) << "\n";
  Graph h = g;
  RC_ASSERT(coarsen(h, n).applied());
  RC_ASSERT(refine(h, n).applied());
  RC_ASSERT(canonical_state(h) == canonical_state(g));
  RC_ASSERT(h == g);
}

// If `refused`, the state `after` must still be `before` and the guard
// must have given the same refusal; 1 if refused, else 0.
template <class Refusal>
int changed_nothing_if_refused(const std::optional<Refusal>& refused, const Graph& after, const std::string& before,
                               const std::optional<Refusal>& guard) {
  if (!refused) return 0;
  RC_ASSERT(canonical_state(after) == before);
  RC_ASSERT(guard == refused);
  return 1;
}

RC_GTEST_PROP(D3Properties, RefusedCallsChangeNothing, ()) {
  const Graph g = random_state(some_size(), *rc::gen::inRange(0, 30));
  const std::string before = canonical_state(g);
  // Any point of the box, a vertex or not, and every vertex of the state.
  std::vector<Point> targets{any_point(g.size), any_point(g.size)};
  targets.insert(targets.end(), g.C.begin(), g.C.end());
  targets.insert(targets.end(), g.N.begin(), g.N.end());
  int refused = 0;
  for (const Point& p : targets) {
    Graph h = g;
    const RefineResult r = refine(h, p);
    refused += changed_nothing_if_refused(r.refused, h, before, can_refine(g, p));
    Graph k = g;
    const CoarsenResult c = coarsen(k, p);
    refused += changed_nothing_if_refused(c.refused, k, before, can_coarsen(g, p));
  }
  RC_ASSERT(refused > 0);
}

// ---- The checker after every step ----------------------------------------------

RC_GTEST_PROP(D3Properties, CheckerAndMeshHoldAfterEveryStep, ()) {
  LatticeSize size;
  size.W = *rc::gen::element<std::int64_t>(1, 2, 3);
  size.H = *rc::gen::element<std::int64_t>(1, 2, 3);
  size.D = *rc::gen::element<std::int64_t>(1, 2, 3);
  size.L = *rc::gen::element(0, 1, 2, 3, 4);
  RC_TAG("lattice " + lattice_text(size));
  Graph g(size);
  std::string trace = "lattice " + lattice_text(size) + "\n";
  RC_ASSERT(checker_problem(g) == std::string());
  const int steps = *rc::gen::inRange(1, 12);
  for (int i = 0; i < steps; ++i) {
    std::vector<Point> parents;
    for (const Point& v : g.N)
      if (refined_center_level(g.size, v)) parents.push_back(v);
    const bool refining = parents.empty() || *rc::gen::weightedElement<int>({{3, 0}, {1, 1}}) == 0;
    const Point at = refining ? pick(g.C) : pick(parents);
    trace += std::string(refining ? "refine " : "coarsen ") + point_text(at) + "\n";
    if (refining)
      refine(g, at);
    else
      coarsen(g, at);
    const std::string why = checker_problem(g);
    if (!why.empty()) RC_FAIL(why + "\nreproducer trace:\n" + trace);
  }
  RC_CLASSIFY(static_cast<std::int64_t>(g.C.size()) > size.W * size.H * size.D, "refined");
}

// ---- Everything refined, then everything coarsened --------------------------------

RC_GTEST_PROP(D3Properties, RefiningEverythingThenCoarseningEverythingGivesBackTheLattice, ()) {
  LatticeSize size;
  size.W = *rc::gen::element<std::int64_t>(1, 2);
  size.H = *rc::gen::element<std::int64_t>(1, 2);
  size.D = *rc::gen::element<std::int64_t>(1, 2);
  size.L = size.W * size.H * size.D == 1 ? *rc::gen::element(1, 2, 3) : *rc::gen::element(1, 2);
  RC_TAG("lattice " + lattice_text(size));
  const Graph initial(size);
  Graph g = initial;
  // Level by level, the cells of each level in a random order: all accepted.
  for (int l = 0; l < size.L; ++l) {
    std::vector<Point> cells(g.C.begin(), g.C.end());
    std::shuffle(cells.begin(), cells.end(), std::mt19937(*rc::gen::arbitrary<std::uint32_t>()));
    for (const Point& c : cells) {
      RC_ASSERT(g.level_of(c) == l);
      const RefineResult r = refine(g, c);
      if (!r.applied()) RC_FAIL("refine " + point_text(c) + " refused: " + std::string(code(*r.refused)));
    }
  }
  const std::size_t roots = static_cast<std::size_t>(size.W * size.H * size.D);
  RC_ASSERT(g.C.size() == (roots << (3 * size.L)));
  RC_ASSERT(test::state_problem(g) == std::string());
  // Then from the finest parents up, in a random order within a level.
  for (int l = size.L - 1; l >= 0; --l) {
    std::vector<Point> parents;
    for (const Point& v : g.N)
      if (refined_center_level(g.size, v) == l) parents.push_back(v);
    RC_ASSERT(parents.size() == (roots << (3 * l)));
    std::shuffle(parents.begin(), parents.end(), std::mt19937(*rc::gen::arbitrary<std::uint32_t>()));
    for (const Point& n : parents) {
      const CoarsenResult r = coarsen(g, n);
      if (!r.applied()) RC_FAIL("coarsen " + point_text(n) + " refused: " + std::string(code(*r.refused)));
    }
  }
  RC_ASSERT(canonical_state(g) == canonical_state(initial));
  RC_ASSERT(g == initial);
}

}  // namespace
}  // namespace bccmis::d3
