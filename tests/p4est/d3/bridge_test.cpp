// The p8est bridge (bridge.h, Dim = 3): the coordinate mapping against p8est's own
// geometry, exact round trips in both directions, and the import's refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "bccmis/balance.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/invariants/d3/invariants.h"
#include "p4est/p4est_test_util.h"

namespace bccmis::p4est_bridge {
namespace {

using testing::import_error;

const d3::LatticeSize kSizes[] = {{1, 1, 1, 3}, {3, 2, 2, 2}, {2, 3, 4, 1}, {4, 4, 2, 2}, {1, 2, 5, 3}};

// Tree (i, j, k) is the unit cube at (i, j, k) in the brick's vertex
// coordinates, as p8est itself maps octant coordinates.
TEST(Brick3, TreeNumberingFollowsTheBrickGeometry) {
  for (const d3::LatticeSize& size : kSizes) {
    const Brick3 brick(size);
    std::vector<bool> seen(static_cast<std::size_t>(size.W * size.H * size.D));
    for (std::int64_t k = 0; k < size.D; ++k)
      for (std::int64_t j = 0; j < size.H; ++j)
        for (std::int64_t i = 0; i < size.W; ++i) {
          const std::int32_t t = brick.tree(i, j, k);
          ASSERT_GE(t, 0);
          EXPECT_FALSE(seen.at(static_cast<std::size_t>(t)));
          seen.at(static_cast<std::size_t>(t)) = true;
          double v[3];
          const p4est_qcoord_t q = P8EST_ROOT_LEN / 8;
          p8est_qcoord_to_vertex(brick.connectivity(), t, q, 3 * q, 5 * q, v);
          EXPECT_EQ(v[0], static_cast<double>(i) + 0.125) << "tree " << t;
          EXPECT_EQ(v[1], static_cast<double>(j) + 0.375) << "tree " << t;
          EXPECT_EQ(v[2], static_cast<double>(k) + 0.625) << "tree " << t;
        }
  }
}

// Every cube of levels 0-3: its octant's center, mapped by p8est to brick
// coordinates and scaled by S, is the cube's center; and back.
TEST(Brick3, LeafAndOctantAgreeWithP8estGeometry) {
  for (const d3::LatticeSize& size : kSizes) {
    const Brick3 brick(size);
    const std::int64_t S = d3::level0_side(size);
    for (int l = 0; l <= std::min(size.L, 3); ++l) {
      const std::int64_t s = d3::cell_side(size, l);
      for (std::int64_t z = s / 2; z < size.D * S; z += s)
        for (std::int64_t y = s / 2; y < size.H * S; y += s)
          for (std::int64_t x = s / 2; x < size.W * S; x += s) {
            const Leaf3 leaf{{x, y, z}, l};
            const Quadrant3 q = brick.to_quadrant(leaf);
            ASSERT_EQ(q.level, l);
            const p4est_qcoord_t half = P8EST_QUADRANT_LEN(l) / 2;
            double v[3];
            p8est_qcoord_to_vertex(brick.connectivity(), q.tree, q.x + half, q.y + half, q.z + half, v);
            const std::string at = "level " + std::to_string(l) + " cube " + d3::to_string(leaf.center);
            EXPECT_EQ(v[0] * static_cast<double>(S), static_cast<double>(x)) << at;
            EXPECT_EQ(v[1] * static_cast<double>(S), static_cast<double>(y)) << at;
            EXPECT_EQ(v[2] * static_cast<double>(S), static_cast<double>(z)) << at;
            EXPECT_EQ(brick.to_leaf(q), leaf);
          }
    }
  }
}

std::string leaf_error(const Brick3& brick, const Quadrant3& q) {
  try {
    brick.to_leaf(q);
  } catch (const ImportError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Brick3, RefusesInvalidOctantsAndSizes) {
  const Brick3 brick({3, 2, 2, 4});
  const p4est_qcoord_t len4 = P8EST_QUADRANT_LEN(4);
  EXPECT_EQ(leaf_error(brick, {11, 15 * len4, 15 * len4, 15 * len4, 4}), "accepted");
  EXPECT_NE(leaf_error(brick, {0, 0, 0, 0, 5}).find("deeper than the lattice's L = 4"), std::string::npos);
  EXPECT_NE(leaf_error(brick, {12, 0, 0, 0, 0}).find("no such tree"), std::string::npos);
  EXPECT_NE(leaf_error(brick, {-1, 0, 0, 0, 0}).find("no such tree"), std::string::npos);
  EXPECT_NE(leaf_error(brick, {0, 0, 0, len4 / 2, 4}).find("not a level-4 octant"), std::string::npos);
  EXPECT_NE(leaf_error(brick, {0, 0, len4, 0, 3}).find("not a level-3 octant"), std::string::npos);
  EXPECT_THROW(Brick3({1, 1, 1, P8EST_QMAXLEVEL + 1}), std::invalid_argument);
  EXPECT_NO_THROW(Brick3({1, 1, 1, P8EST_QMAXLEVEL}));
}

// A random lattice W x H x D x L: L in [min_level, max_level], then W in
// [1, 3], H in [1, 2], and D = 2 below level 3, else 1 (small enough for
// the cascade).
d3::LatticeSize random_size(std::mt19937_64& rng, int min_level, int max_level) {
  const int L = std::uniform_int_distribution<int>(min_level, max_level)(rng);
  const std::int64_t W = std::uniform_int_distribution<std::int64_t>(1, 3)(rng);
  const std::int64_t H = std::uniform_int_distribution<std::int64_t>(1, 2)(rng);
  return {W, H, L >= 3 ? 1 : 2, L};
}

// bccmis -> p8est -> bccmis: random lattices reached by the cascade (and
// some coarsening) export to an edge-balanced forest with the same leaves
// and import back to the same canonical state.
TEST(RoundTrip3, FromBccmisIsExact) {
  const std::uint64_t seed = 20091004;
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 30; ++trial) {
    const d3::LatticeSize size = random_size(rng, 0, 3);
    const auto targets =
        size.L == 0 ? std::vector<testing::Target3>{} : d3::cascade_model::random_targets(size, rng, 1 + trial % 4);
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial) + ": " +
                 d3::cascade_model::describe(size, targets));
    d3::Graph g = d3::cascade_model::refine_targets(size, targets, Balance::Edge);
    // Some coarsening too, so that the states are not only refine closures.
    for (const d3::Point& n : d3::PointSet(g.N))
      if ((n.x + n.y + n.z) % 3 == 0 && !d3::can_coarsen(g, n)) d3::coarsen(g, n);
    ASSERT_EQ(d3::find_violation(g), std::nullopt);
    const Brick3 brick(size);
    const Forest3Ptr forest = export_forest(brick, g, sc_MPI_COMM_WORLD);
    testing::expect_quadrants_of(brick, g, forest.get());
    const d3::Graph back = import_forest(brick, forest.get());
    EXPECT_EQ(canonical_text(back), canonical_text(g));
  }
}

// p8est -> bccmis -> p8est: random edge-balanced forests import, pass the
// checker, and export to the same octants in the same order.
TEST(RoundTrip3, FromP8estIsExact) {
  const std::uint64_t seed = 20091005;
  std::mt19937_64 rng(seed);
  for (int trial = 0; trial < 30; ++trial) {
    const d3::LatticeSize size = random_size(rng, 1, 4);
    const auto targets = d3::cascade_model::random_targets(size, rng, 1 + trial % 5);
    SCOPED_TRACE("seed " + std::to_string(seed) + " trial " + std::to_string(trial) + ": " +
                 d3::cascade_model::describe(size, targets));
    const Brick3 brick(size);
    const Forest3Ptr forest = testing::p8est_targets(brick, targets, P8EST_CONNECT_EDGE);
    testing::expect_round_trip(brick, forest.get());
  }
}

// spec/lattice3d.md §2, "Face balance alone is not enough": lattice 2 2 1 2
// with the level-0 cubes (1,0,0), (0,1,0), (1,1,0) refined and the child of
// (1,1,0) at the corner (8,8,0) refined again. p8est calls it face balanced
// and not edge balanced; the import refuses it, naming edge balance.
TEST(Import3, RefusesAFaceBalancedForestThatIsNotEdgeBalanced) {
  const d3::LatticeSize size{2, 2, 1, 2};
  std::vector<Leaf3> ls{{{4, 4, 4}, 0}};
  for (const d3::Point c : {d3::Point{12, 4, 4}, d3::Point{4, 12, 4}, d3::Point{12, 12, 4}})
    for (int v = 0; v < 8; ++v) {
      const d3::Point child{c.x + ((v & 1) ? 2 : -2), c.y + ((v & 2) ? 2 : -2), c.z + ((v & 4) ? 2 : -2)};
      if (child == d3::Point{10, 10, 2})
        for (int w = 0; w < 8; ++w)
          ls.push_back({{child.x + ((w & 1) ? 1 : -1), child.y + ((w & 2) ? 1 : -1), child.z + ((w & 4) ? 1 : -1)}, 2});
      else
        ls.push_back({child, 1});
    }
  const Brick3 brick(size);
  const Forest3Ptr forest = make_forest(brick, ls, sc_MPI_COMM_WORLD);
  ASSERT_EQ(p8est_is_balanced(forest.get(), P8EST_CONNECT_FACE), 1);
  ASSERT_EQ(p8est_is_balanced(forest.get(), P8EST_CONNECT_EDGE), 0);
  const std::string why = import_error(brick, local_quadrants(forest.get()));
  EXPECT_NE(why.find("not edge balanced"), std::string::npos) << why;
  // After p8est_balance across edges the same refinement imports.
  p8est_balance(forest.get(), P8EST_CONNECT_EDGE, nullptr);
  EXPECT_EQ(import_error(brick, local_quadrants(forest.get())), "accepted");
}

TEST(Import3, RefusesLeavesDeeperThanL) {
  const Brick3 deep({2, 1, 1, 4});
  const Forest3Ptr forest = testing::p8est_targets(deep, {{{3, 5, 7}, 4}}, P8EST_CONNECT_EDGE);
  const Brick3 shallow({2, 1, 1, 3});  // same trees, one level less
  const std::string why = import_error(shallow, local_quadrants(forest.get()));
  EXPECT_NE(why.find("deeper than the lattice's L = 3"), std::string::npos) << why;
}

TEST(Import3, RefusesOverlapsGapsAndDuplicates) {
  const d3::LatticeSize size{2, 1, 2, 2};
  const Brick3 brick(size);
  const Forest3Ptr forest = testing::p8est_targets(brick, {{{5, 3, 9}, 2}, {{13, 7, 15}, 2}}, P8EST_CONNECT_EDGE);
  const std::vector<Quadrant3> qs = local_quadrants(forest.get());
  ASSERT_EQ(import_error(brick, qs), "accepted");
  for (std::size_t k = 0; k < qs.size(); k += 7) {
    std::vector<Quadrant3> gap = qs;
    gap.erase(gap.begin() + static_cast<std::ptrdiff_t>(k));
    EXPECT_NE(import_error(brick, gap).find("do not cover"), std::string::npos) << "without octant " << k;
    std::vector<Quadrant3> twice = qs;
    twice.push_back(qs[k]);
    EXPECT_NE(import_error(brick, twice).find("listed twice"), std::string::npos) << "octant " << k;
  }
  std::vector<Quadrant3> overlap = qs;
  overlap.push_back({qs.front().tree, 0, 0, 0, 0});  // a whole tree over its own leaves
  EXPECT_NE(import_error(brick, overlap).find("leaves overlap"), std::string::npos);
  EXPECT_THROW(make_forest(brick, std::vector<Leaf3>{{{8, 8, 8}, 0}}, sc_MPI_COMM_WORLD), ImportError);
  std::vector<Leaf3> shifted = leaves(import_quadrants(brick, qs));
  shifted.front().center.z += 2;
  try {
    import_leaves(size, shifted);
    ADD_FAILURE() << "a center off the level's grid was accepted";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a cube of the 3D lattice"), std::string::npos) << e.what();
  }
}

// Edge balance is not corner balance: an edge-balanced forest that is not
// fully balanced imports, and find_corner_imbalance sees the corner pair
// that P8EST_CONNECT_FULL removes.
TEST(Import3, EdgeBalanceIsNotCornerBalance) {
  const d3::LatticeSize size{2, 2, 2, 2};
  const Brick3 brick(size);
  const std::vector<testing::Target3> targets{{{7, 7, 7}, 2}};
  const Forest3Ptr edge = testing::p8est_targets(brick, targets, P8EST_CONNECT_EDGE);
  ASSERT_EQ(p8est_is_balanced(edge.get(), P8EST_CONNECT_FULL), 0);
  EXPECT_TRUE(d3::find_corner_imbalance(import_forest(brick, edge.get())).has_value());
  const Forest3Ptr full = testing::p8est_targets(brick, targets, P8EST_CONNECT_FULL);
  EXPECT_FALSE(d3::find_corner_imbalance(import_forest(brick, full.get())).has_value());
}

}  // namespace
}  // namespace bccmis::p4est_bridge

int main(int argc, char** argv) { return bccmis::p4est_bridge::testing::run_tests(argc, argv); }
