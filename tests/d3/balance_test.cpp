// The 3D cascade (spec/lattice3d.md §8, bccmis/balance.h): hand cases, then
// random target sets on random lattices, each applied in several random
// orders. Every order must reach the same canonical state, that state's
// leaves must be the geometric closure of tests/d3/cascade_model.h (edge
// mode: faces and edges; corner mode: corner points too), and every state
// must pass the independent 3D checker and, in corner mode, have no two
// touching leaves two levels apart by the leaf model's geometry. A failure
// prints the seed, the trial, the lattice and the targets.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "bccmis/balance.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/invariants/d3/invariants.h"
#include "d3/cascade_model.h"
#include "d3/leaf_model.h"
#include "d3/util.h"

namespace bccmis::d3 {
namespace {

using cascade_model::Target;

constexpr std::uint64_t kSeed = 20091002;

// Lattice 2 2 2 2 (S = 8) with the level-0 cube at (4, 4, 4) refined: its
// child (6, 6, 6) meets three level-0 cubes across faces, three across
// edges, and (12, 12, 12) at the corner point (8, 8, 8) only.
Graph corner_case() {
  Graph g(LatticeSize{2, 2, 2, 2});
  EXPECT_TRUE(refine(g, {4, 4, 4}).applied());
  return g;
}

TEST(Cascade3, EdgeModeRefinesTheFaceAndEdgeNeighboursFirst) {
  Graph g = corner_case();
  EXPECT_EQ(can_refine(g, {6, 6, 6}), RefineRefusal::CoarserNeighbor);
  EXPECT_EQ(edge_neighbors(g, {6, 6, 6}), test::vs({{2, 2, 6},
                                                    {2, 6, 2},
                                                    {2, 6, 6},
                                                    {4, 4, 12},
                                                    {4, 12, 4},
                                                    {4, 12, 12},
                                                    {6, 2, 2},
                                                    {6, 2, 6},
                                                    {6, 6, 2},
                                                    {12, 4, 4},
                                                    {12, 4, 12},
                                                    {12, 12, 4}}))
      << "the six level-1 siblings across faces and edges, and six level-0 cubes";
  EXPECT_EQ(touching_neighbors(g, {6, 6, 6}).size(), 7u + 7u);
  const BalancedRefineResult r = refine_balanced(g, {6, 6, 6});
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.refined,
            (std::vector<Point>{{4, 4, 12}, {4, 12, 4}, {4, 12, 12}, {12, 4, 4}, {12, 4, 12}, {12, 12, 4}, {6, 6, 6}}));
  EXPECT_TRUE(g.is_center({12, 12, 12})) << "a corner-only neighbour is not refined in edge mode";
  EXPECT_EQ(find_violation(g), std::nullopt);
  EXPECT_EQ(find_corner_imbalance(g), std::make_optional(std::make_pair(Point{12, 12, 12}, Point{7, 7, 7})))
      << "the level-2 child (7, 7, 7) meets the level-0 cube at the point (8, 8, 8)";
}

TEST(Cascade3, CornerModeAlsoRefinesTheCornerNeighbour) {
  Graph g = corner_case();
  EXPECT_EQ(can_refine_under(g, {6, 6, 6}, Balance::Edge), RefineRefusal::CoarserNeighbor);
  const BalancedRefineResult r = refine_balanced(g, {6, 6, 6}, Balance::Corner);
  ASSERT_TRUE(r.applied());
  EXPECT_EQ(r.refined,
            (std::vector<Point>{
                {4, 4, 12}, {4, 12, 4}, {4, 12, 12}, {12, 4, 4}, {12, 4, 12}, {12, 12, 4}, {12, 12, 12}, {6, 6, 6}}));
  EXPECT_EQ(find_violation(g), std::nullopt);
  EXPECT_EQ(find_corner_imbalance(g), std::nullopt);
}

TEST(Cascade3, RefusedOnlyForNoSuchCellAndMaxLevelChangingNothing) {
  Graph g(LatticeSize{1, 1, 1, 1});
  const Graph before = g;
  EXPECT_EQ(refine_balanced(g, {1, 1, 1}).refused, RefineRefusal::NoSuchCell);
  EXPECT_EQ(g, before);
  ASSERT_TRUE(refine_balanced(g, {2, 2, 2}).applied());
  const Graph refined = g;
  const BalancedRefineResult r = refine_balanced(g, {1, 1, 1}, Balance::Corner);
  EXPECT_EQ(r.refused, RefineRefusal::MaxLevel);
  EXPECT_TRUE(r.refined.empty());
  EXPECT_EQ(g, refined);
}

// The corner rule by the leaf model's geometry: two leaves whose closed
// cubes meet (contact dimension 0 or more) differ by at most one level.
std::string corner_problem(const Graph& g) {
  const model::Leaves leaves(g.level.begin(), g.level.end());
  for (const auto& [a, la] : leaves)
    for (const auto& [b, lb] : leaves)
      if (la - lb > 1 && model::contact_dimension(model::cube(g.size, a, la), model::cube(g.size, b, lb)) >= 0)
        return to_string(a) + " and " + to_string(b) + " touch " + std::to_string(la - lb) + " levels apart";
  return {};
}

// A finest-level target in one of the 8 cubes around a random interior node
// of the level-(L-2) grid: the level-(L-1) cube holding it has that node as
// a corner of its parent, so the level-(L-1) cube diagonally
// across meets the target's cube at a corner point only. Any finest-level
// target when the lattice has no such node.
Target corner_target(const LatticeSize& size, std::mt19937_64& rng) {
  const std::int64_t grid = cell_side(size, std::max(size.L - 2, 0));
  auto axis = [&](std::int64_t n) {
    const std::int64_t cells = n * level0_side(size) / grid;
    if (cells < 2) return 2 * std::uniform_int_distribution<std::int64_t>(0, n * level0_side(size) / 2 - 1)(rng) + 1;
    const std::int64_t node = grid * std::uniform_int_distribution<std::int64_t>(1, cells - 1)(rng);
    return node + (std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1);
  };
  return {{axis(size.W), axis(size.H), axis(size.D)}, size.L};
}

void random_orders(Balance mode, int trials) {
  std::mt19937_64 rng(kSeed + (mode == Balance::Edge ? 0 : 1));
  std::size_t extra = 0;
  int modes_differ = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const int L = std::uniform_int_distribution<int>(1, 3)(rng);
    auto side = [&] { return std::uniform_int_distribution<std::int64_t>(1, L == 3 ? 1 : 2)(rng); };
    const LatticeSize size{side(), side(), side(), L};
    std::vector<Target> targets =
        cascade_model::random_targets(size, rng, std::uniform_int_distribution<int>(1, 5)(rng));
    // Half the targets are finest-level cubes at a corner of a level-1 cube,
    // where cells two levels apart meet at a corner point only.
    for (std::size_t k = 0; k < targets.size(); k += 2) targets[k] = corner_target(size, rng);
    SCOPED_TRACE("seed " + std::to_string(kSeed) + " trial " + std::to_string(trial) + ", balance " +
                 std::string(name(mode)) + ": " + cascade_model::describe(size, targets));
    const std::map<Point, int> expected = cascade_model::closure_leaves(size, targets, mode);
    modes_differ += cascade_model::closure_leaves(size, targets, Balance::Edge) !=
                    cascade_model::closure_leaves(size, targets, Balance::Corner);
    std::string first;
    for (int order = 0; order < 4; ++order) {
      SCOPED_TRACE("order " + std::to_string(order) + ": " + cascade_model::describe(size, targets));
      const Graph g = cascade_model::refine_targets(size, targets, mode, &extra);
      ASSERT_EQ(find_violation(g), std::nullopt);
      ASSERT_EQ(g.level, expected) << "not the smallest balanced refinement holding the targets";
      if (mode == Balance::Corner) {
        ASSERT_EQ(corner_problem(g), "");
        ASSERT_EQ(find_corner_imbalance(g), std::nullopt);
      }
      const std::string text = canonical_text(g);
      if (order == 0)
        first = text;
      else
        ASSERT_EQ(text, first) << "the order of the requests changed the state";
      std::shuffle(targets.begin(), targets.end(), rng);
    }
  }
  EXPECT_GT(extra, static_cast<std::size_t>(trials)) << "the cascades refined too little to test much";
  // In 3D a corner-only contact two levels apart needs an interior node in
  // all three axes; about one target set in ten gets one.
  EXPECT_GE(modes_differ, 3) << "seed " << kSeed << ": too few target sets where the modes differ";
}

TEST(Cascade3, EdgeModeReachesTheEdgeClosureInEveryOrder) { random_orders(Balance::Edge, 40); }

TEST(Cascade3, CornerModeReachesTheCornerClosureInEveryOrder) { random_orders(Balance::Corner, 40); }

}  // namespace
}  // namespace bccmis::d3
