// The p4est bridge (issue 10): the coordinate mapping against p4est's own
// geometry, exact round trips in both directions, and the import's refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "p4est/p4est_test_util.h"

namespace bccmis::p4est_bridge {
namespace {

using testing::import_error;
using testing::p4est_targets;
using testing::random_targets;
using testing::refine_targets;

const LatticeSize kSizes[] = {{1, 1, 3}, {3, 2, 4}, {5, 3, 2}, {2, 7, 5}, {4, 4, 6}};

// The tree of level-0 cell (i, j) is the unit square [i, i+1] x [j, j+1] of
// the brick's vertex coordinates, as p4est itself maps quadrant coordinates.
TEST(Brick, TreeNumberingFollowsTheBrickGeometry) {
  for (const LatticeSize& size : kSizes) {
    const Brick brick(size);
    std::vector<bool> seen(static_cast<std::size_t>(size.W * size.H));
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t i = 0; i < size.W; ++i) {
        const std::int32_t t = brick.tree(i, j);
        ASSERT_GE(t, 0);
        EXPECT_FALSE(seen.at(static_cast<std::size_t>(t)));
        seen.at(static_cast<std::size_t>(t)) = true;
        double v[3];
        p4est_qcoord_to_vertex(brick.connectivity(), t, P4EST_ROOT_LEN / 4, 3 * (P4EST_ROOT_LEN / 4), v);
        EXPECT_EQ(v[0], static_cast<double>(i) + 0.25) << "tree " << t;
        EXPECT_EQ(v[1], static_cast<double>(j) + 0.75) << "tree " << t;
      }
  }
}

// Every cell of every level: its quadrant's center, mapped by p4est to brick
// coordinates and scaled by S, is the cell's center; and back.
TEST(Brick, LeafAndQuadrantAgreeWithP4estGeometry) {
  for (const LatticeSize& size : kSizes) {
    const Brick brick(size);
    const double S = static_cast<double>(level0_side(size));
    for (int l = 0; l <= std::min(size.L, 4); ++l) {
      const std::int64_t s = cell_side(size, l);
      for (std::int64_t y = s / 2; y < size.H * level0_side(size); y += s)
        for (std::int64_t x = s / 2; x < size.W * level0_side(size); x += s) {
          const Leaf leaf{{x, y}, l};
          const Quadrant q = brick.to_quadrant(leaf);
          ASSERT_EQ(q.level, l);
          const p4est_qcoord_t half = P4EST_QUADRANT_LEN(l) / 2;
          double v[3];
          p4est_qcoord_to_vertex(brick.connectivity(), q.tree, q.x + half, q.y + half, v);
          EXPECT_EQ(v[0] * S, static_cast<double>(x)) << "level " << l << " cell (" << x << ", " << y << ")";
          EXPECT_EQ(v[1] * S, static_cast<double>(y)) << "level " << l << " cell (" << x << ", " << y << ")";
          EXPECT_EQ(brick.to_leaf(q), leaf);
        }
    }
  }
}

TEST(Brick, RefusesInvalidQuadrantsAndSizes) {
  const Brick brick({3, 2, 4});
  const p4est_qcoord_t len4 = P4EST_QUADRANT_LEN(4);
  EXPECT_NO_THROW(brick.to_leaf({5, 15 * len4, 15 * len4, 4}));
  const auto message = [&](const Quadrant& q) {
    try {
      brick.to_leaf(q);
    } catch (const ImportError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({0, 0, 0, 5}).find("deeper than the lattice's L = 4"), std::string::npos);
  EXPECT_NE(message({6, 0, 0, 0}).find("no such tree"), std::string::npos);
  EXPECT_NE(message({-1, 0, 0, 0}).find("no such tree"), std::string::npos);
  EXPECT_NE(message({0, len4 / 2, 0, 4}).find("not a level-4 quadrant"), std::string::npos);
  EXPECT_NE(message({0, 0, len4, 3}).find("not a level-3 quadrant"), std::string::npos);
  EXPECT_THROW(Brick({1, 1, P4EST_QMAXLEVEL + 1}), std::invalid_argument);
  EXPECT_NO_THROW(Brick({1, 1, P4EST_QMAXLEVEL}));
}

// A random lattice W x H x L: W in [1, 4], H in [1, max_height], L in
// [min_level, 6], drawn in that order.
LatticeSize random_size(std::mt19937_64& rng, std::int64_t max_height, int min_level) {
  const std::int64_t W = std::uniform_int_distribution<std::int64_t>(1, 4)(rng);
  const std::int64_t H = std::uniform_int_distribution<std::int64_t>(1, max_height)(rng);
  return {W, H, std::uniform_int_distribution<int>(min_level, 6)(rng)};
}

// bccmis -> p4est -> bccmis: random lattices reached by refine_balanced
// export to a face-balanced forest with the same leaves and import back to
// the same canonical state.
TEST(RoundTrip, FromBccmisIsExact) {
  std::mt19937_64 rng(20090310);
  for (int trial = 0; trial < 40; ++trial) {
    const LatticeSize size = random_size(rng, 4, 0);
    const auto targets = size.L == 0 ? std::vector<testing::Target>{} : random_targets(size, rng, 1 + trial % 5);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + testing::describe(size, targets));
    Graph g = refine_targets(size, targets, Balance::Edge);
    // Some coarsening too, so that the states are not only refine closures.
    coarsen_sweep(g, [&](const Graph&, const Point& n) { return (n.x + n.y) % 3 == 0; });
    ASSERT_EQ(find_violation(g), std::nullopt);
    const Brick brick(size);
    const ForestPtr forest = export_forest(brick, g, sc_MPI_COMM_WORLD);
    testing::expect_quadrants_of(brick, g, forest.get());
    const Graph back = import_forest(brick, forest.get());
    EXPECT_EQ(canonical_state(back), canonical_state(g));
  }
}

// p4est -> bccmis -> p4est: random face-balanced forests import, pass the
// checker, and export to the same quadrants in the same order.
TEST(RoundTrip, FromP4estIsExact) {
  std::mt19937_64 rng(20090311);
  for (int trial = 0; trial < 40; ++trial) {
    const LatticeSize size = random_size(rng, 3, 1);
    const auto targets = random_targets(size, rng, 1 + trial % 6);
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + testing::describe(size, targets));
    const Brick brick(size);
    const ForestPtr forest = p4est_targets(brick, targets, P4EST_CONNECT_FACE);
    testing::expect_round_trip(brick, forest.get());
  }
}

TEST(Import, RefusesAForestThatIsNotFaceBalanced) {
  const LatticeSize size{2, 2, 4};
  const Brick brick(size);
  // The cell just above and right of tree 0's center refined to level 3
  // without balance: it shares a face with the level-1 cell to its left.
  const std::int64_t S = level0_side(size);
  const std::vector<testing::Target> targets{{{S / 2 + 1, S / 2 + 1}, 3}};
  const ForestPtr forest = p4est_targets(brick, targets, P4EST_CONNECT_FACE, /*balance=*/false);
  ASSERT_EQ(p4est_is_balanced(forest.get(), P4EST_CONNECT_FACE), 0);
  const std::string why = import_error(brick, local_quadrants(forest.get()));
  EXPECT_NE(why.find("not face balanced"), std::string::npos) << why;
  // After p4est_balance the same refinement imports.
  p4est_balance(forest.get(), P4EST_CONNECT_FACE, nullptr);
  EXPECT_EQ(import_error(brick, local_quadrants(forest.get())), "accepted");
}

TEST(Import, RefusesLeavesDeeperThanL) {
  const Brick deep({2, 1, 5});
  const ForestPtr forest = p4est_targets(deep, {{{3, 5}, 5}}, P4EST_CONNECT_FACE);
  const Brick shallow({2, 1, 4});  // same trees, one level less
  const std::string why = import_error(shallow, local_quadrants(forest.get()));
  EXPECT_NE(why.find("deeper than the lattice's L = 4"), std::string::npos) << why;
}

TEST(Import, RefusesOverlapsGapsAndDuplicates) {
  const LatticeSize size{2, 2, 3};
  const Brick brick(size);
  const ForestPtr forest = p4est_targets(brick, {{{5, 9}, 2}, {{27, 27}, 3}}, P4EST_CONNECT_FACE);
  const std::vector<Quadrant> qs = local_quadrants(forest.get());
  ASSERT_EQ(import_error(brick, qs), "accepted");
  for (std::size_t k = 0; k < qs.size(); k += 5) {
    std::vector<Quadrant> gap = qs;
    gap.erase(gap.begin() + static_cast<std::ptrdiff_t>(k));
    EXPECT_NE(import_error(brick, gap).find("do not cover"), std::string::npos) << "without quadrant " << k;
    std::vector<Quadrant> twice = qs;
    twice.push_back(qs[k]);
    EXPECT_NE(import_error(brick, twice).find("listed twice"), std::string::npos) << "quadrant " << k;
  }
  std::vector<Quadrant> overlap = qs;
  overlap.push_back({qs.front().tree, 0, 0, 0});  // a whole tree over its own leaves
  EXPECT_NE(import_error(brick, overlap).find("leaves overlap"), std::string::npos);
  EXPECT_THROW(make_forest(brick, std::vector<Leaf>{{{8, 8}, 0}}, sc_MPI_COMM_WORLD), ImportError);
  // A leaf list in bccmis coordinates with a center off the level's grid.
  std::vector<Leaf> shifted = leaves(import_quadrants(brick, qs));
  shifted.front().center.x += 2;
  const auto leaf_error = [&](const std::vector<Leaf>& ls) {
    try {
      import_leaves(size, ls);
    } catch (const ImportError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(leaf_error(shifted).find("is not a cell of the lattice"), std::string::npos) << leaf_error(shifted);
}

// Face balance is the core's edge balance, not corner balance: a forest
// balanced across faces only imports, and the apps' corner check sees the
// corner imbalance p4est's P4EST_CONNECT_FULL would have removed.
TEST(Import, FaceBalanceIsEdgeBalance) {
  const LatticeSize size{2, 2, 4};
  const Brick brick(size);
  // A level-4 cell at the center of the domain: face balance leaves
  // level-2 cells touching level-4 cells' level-3 parents diagonally.
  const std::int64_t S = level0_side(size);
  const std::vector<testing::Target> targets{{{S + 1, S + 1}, 4}};
  const ForestPtr face = p4est_targets(brick, targets, P4EST_CONNECT_FACE);
  ASSERT_EQ(p4est_is_balanced(face.get(), P4EST_CONNECT_FULL), 0);
  const Graph g = import_forest(brick, face.get());
  EXPECT_TRUE(find_corner_imbalance(g).has_value());
  const ForestPtr full = p4est_targets(brick, targets, P4EST_CONNECT_FULL);
  EXPECT_FALSE(find_corner_imbalance(import_forest(brick, full.get())).has_value());
}

}  // namespace
}  // namespace bccmis::p4est_bridge

int main(int argc, char** argv) { return bccmis::p4est_bridge::testing::run_tests(argc, argv); }
