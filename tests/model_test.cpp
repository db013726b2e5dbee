// Model-based test (issue 5): rc::state runs random command sequences against
// the graph (the system under test) and the independent quadtree-leaf model
// (tests/model/leaf_model.h, written without the graph code).
//
// Commands: Refine (a live leaf), Coarsen (the parent of live leaves),
// RefineIllegal and CoarsenIllegal (positions the model refuses: wrong kind,
// max level, coarser or finer neighbors, refined children, points that are
// no vertex at all). After every command
//   - the graph's decision (ok or the refusal code) equals the model's,
//   - the graph's centers (position, level) are exactly the model's leaves and
//     its nodes exactly the leaves' corners,
//   - the full checker (layers 1-4) passes.
// A failure prints the minimal command list and the reproducer trace.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>
#include <rapidcheck/state.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "testing/decision.h"
#include "testing/generators.h"

namespace bccmis::proptest {
namespace {

struct Sut {
  explicit Sut(const LatticeSize& size) : g(make_lattice(size)) { trace.size = size; }
  Graph g;
  Trace trace;
};

using Cmd = rc::state::Command<model::State, Sut>;

Point point_of(const model::Pos& p) { return Point{p.x, p.y}; }

// Runs op at `at` on the graph and compares everything with the model.
void run_and_compare(OpKind op, const Point& at, const model::State& before, Sut& sut) {
  sut.trace.commands.push_back(TraceCommand{trace_kind(op), at, 0});
  auto fail = [&](const std::string& msg) { RC_FAIL(msg + "\nreproducer trace:\n" + format_trace(sut.trace)); };
  const std::string expected = model_decision(before, op, at);
  std::string have;
  try {
    have = testing::run_and_decide(sut.g, op == OpKind::Refine, at);
  } catch (const std::exception& e) {
    fail(std::string("the operation threw: ") + e.what());
  }
  const std::string what = std::string(op == OpKind::Refine ? "refine " : "coarsen ") + point_text(at);
  if (have != expected) fail(what + ": the graph says " + have + ", the model says " + expected);
  model::State after = before;
  if (expected == "ok") model_apply(after, op, at);
  if (const auto diff = projection_mismatch(sut.g, after)) fail("after " + what + ": " + *diff);
  if (const auto v = find_violation(sut.g)) fail("after " + what + ": " + to_string(*v));
}

// Applies op at `at` to the model if the model accepts it.
void apply_to_model(OpKind op, const Point& at, model::State& m) {
  if (model_decision(m, op, at) == "ok") model_apply(m, op, at);
}

std::vector<model::Leaf> parents_of_leaves(const model::State& m) {
  std::set<model::Leaf> parents;
  for (const model::Leaf& c : m.leaves)
    if (c.level > 0) parents.insert(model::parent_of(c));
  return {parents.begin(), parents.end()};
}

std::vector<model::Pos> corners_of_leaves(const model::State& m) {
  std::set<model::Pos> corners;
  for (const model::Leaf& c : m.leaves) {
    const model::Rect r = model::rect_of(m.lat, c);
    for (const model::Pos p :
         {model::Pos{r.x0, r.y0}, model::Pos{r.x1, r.y0}, model::Pos{r.x0, r.y1}, model::Pos{r.x1, r.y1}})
      corners.insert(p);
  }
  return {corners.begin(), corners.end()};
}

// An integer position in and around the domain.
Point any_position(const model::State& m) {
  const std::int64_t S = m.lat.side(0);
  return Point{*rc::gen::inRange<std::int64_t>(-2, m.lat.W * S + 3),
               *rc::gen::inRange<std::int64_t>(-2, m.lat.H * S + 3)};
}

// A command that runs `op` at `at` on the model (if it accepts) and on the
// graph, and compares them.
template <OpKind op>
struct OpAt : Cmd {
  Point at;
  void apply(model::State& m) const override { apply_to_model(op, at, m); }
  void run(const model::State& m, Sut& sut) const override { run_and_compare(op, at, m, sut); }
};

struct Refine : OpAt<OpKind::Refine> {
  explicit Refine(const model::State& m) { at = point_of(model::center_of(m.lat, *rc::gen::elementOf(m.leaves))); }
  void show(std::ostream& os) const override { os << "Refine" << point_text(at); }
};

struct Coarsen : OpAt<OpKind::Coarsen> {
  explicit Coarsen(const model::State& m) {
    const std::vector<model::Leaf> parents = parents_of_leaves(m);
    RC_PRE(!parents.empty());
    at = point_of(model::center_of(m.lat, *rc::gen::elementOf(parents)));
  }
  void show(std::ostream& os) const override { os << "Coarsen" << point_text(at); }
};

struct RefineIllegal : OpAt<OpKind::Refine> {
  explicit RefineIllegal(const model::State& m) {
    switch (*rc::gen::inRange(0, 3)) {
      case 0: at = point_of(*rc::gen::elementOf(corners_of_leaves(m))); break;  // a node
      case 1:
        at = point_of(model::center_of(m.lat, *rc::gen::elementOf(m.leaves)));
        break;  // a leaf (max level, coarser neighbor)
      default: at = any_position(m); break;
    }
    RC_PRE(model_decision(m, OpKind::Refine, at) != "ok");
  }
  void show(std::ostream& os) const override { os << "RefineIllegal" << point_text(at); }
};

struct CoarsenIllegal : OpAt<OpKind::Coarsen> {
  explicit CoarsenIllegal(const model::State& m) {
    const std::vector<model::Leaf> parents = parents_of_leaves(m);
    switch (*rc::gen::inRange(0, 4)) {
      case 0: at = point_of(*rc::gen::elementOf(corners_of_leaves(m))); break;               // grid node, junction, ...
      case 1: at = point_of(model::center_of(m.lat, *rc::gen::elementOf(m.leaves))); break;  // a center
      case 2:  // a refined cell whose children are refined or have finer neighbors
        RC_PRE(!parents.empty());
        at = point_of(model::center_of(m.lat, *rc::gen::elementOf(parents)));
        break;
      default: at = any_position(m); break;
    }
    RC_PRE(model_decision(m, OpKind::Coarsen, at) != "ok");
  }
  void show(std::ostream& os) const override { os << "CoarsenIllegal" << point_text(at); }
};

RC_GTEST_PROP(ModelBased, GraphAgreesWithTheLeafModelOnEveryCommand, ()) {
  LatticeSize size;
  size.W = *rc::gen::inRange<std::int64_t>(1, 4);
  size.H = *rc::gen::inRange<std::int64_t>(1, 4);
  size.L = *rc::gen::inRange(1, 4);
  const model::State initial = model_initial(size);
  Sut sut(size);
  RC_ASSERT(!projection_mismatch(sut.g, initial).has_value());
  rc::state::check(
      initial, sut,
      rc::state::gen::execOneOfWithArgs<Refine, Refine, Refine, Coarsen, Coarsen, RefineIllegal, CoarsenIllegal>());
}

// The projection check itself can fail: a graph one refine ahead of the model,
// or with one level changed, is reported.
TEST(ModelBased, ProjectionMismatchIsDetected) {
  const LatticeSize size{2, 1, 2};
  const model::State m = model_initial(size);
  Graph g = make_lattice(size);
  EXPECT_FALSE(projection_mismatch(g, m).has_value());
  ASSERT_TRUE(refine(g, Point{4, 4}).applied());
  const auto diff = projection_mismatch(g, m);
  ASSERT_TRUE(diff.has_value());
  EXPECT_NE(diff->find("(4, 4)"), std::string::npos) << *diff;

  Graph h = make_lattice(size);
  h.level[Point{12, 4}] = 1;
  ASSERT_TRUE(projection_mismatch(h, m).has_value());
}

}  // namespace
}  // namespace bccmis::proptest
