// bccmis against p8est on random 3D target sets: refine_balanced on the 3D
// lattice and p8est_refine + p8est_balance reach the same leaf set; edge
// balance (faces and edges) against P8EST_CONNECT_EDGE, corner balance
// against P8EST_CONNECT_FULL. And the control: P8EST_CONNECT_FACE differs
// from edge balance on some target sets. A failure prints the seed, the
// lattice and the targets.
#include <gtest/gtest.h>

#include <random>

#include "bccmis/invariants/d3/invariants.h"
#include "p4est/p4est_test_util.h"

namespace bccmis::p4est_bridge {
namespace {

constexpr std::uint64_t kSeed = 20091003;

d3::LatticeSize random_size(std::mt19937_64& rng) {
  const int L = std::uniform_int_distribution<int>(1, 4)(rng);
  auto side = [&] { return std::uniform_int_distribution<std::int64_t>(1, L >= 3 ? 2 : 3)(rng); };
  return {side(), side(), side(), L};
}

void differential(Balance mode, p8est_connect_type_t connect, int trials) {
  std::mt19937_64 rng(kSeed + (mode == Balance::Edge ? 0 : 1));
  std::size_t leaves_seen = 0, cascaded = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const d3::LatticeSize size = random_size(rng);
    const auto targets = d3::cascade_model::random_targets(size, rng, std::uniform_int_distribution<int>(1, 4)(rng));
    SCOPED_TRACE("seed " + std::to_string(kSeed) + " trial " + std::to_string(trial) + ", balance " +
                 std::string(name(mode)) + ": " + d3::cascade_model::describe(size, targets));
    const d3::Graph g = d3::cascade_model::refine_targets(size, targets, mode, &cascaded);
    ASSERT_EQ(d3::find_violation(g), std::nullopt);
    const Brick3 brick(size);
    const Forest3Ptr forest = testing::p8est_targets(brick, targets, connect);
    // The same leaves, and the import of the forest is the same lattice, to the last node.
    ASSERT_NO_FATAL_FAILURE(testing::expect_same_lattice(g, brick, forest.get()));
    leaves_seen += leaves(g).size();
  }
  EXPECT_GT(leaves_seen, static_cast<std::size_t>(trials) * 30) << "the targets refine too little to test much";
  EXPECT_GT(cascaded, static_cast<std::size_t>(trials)) << "the cascades refined too little to test much";
}

TEST(Differential3, RefineBalancedMatchesP8estEdgeBalance) { differential(Balance::Edge, P8EST_CONNECT_EDGE, 60); }

TEST(Differential3, CornerModeMatchesP8estFullBalance) { differential(Balance::Corner, P8EST_CONNECT_FULL, 60); }

// The comparison can tell the modes apart: on the same random target sets,
// P8EST_CONNECT_FACE leaves fewer leaves than edge balance in some trials,
// and edge balance fewer than P8EST_CONNECT_FULL in some trials.
TEST(Differential3, FaceEdgeAndFullBalanceDiffer) {
  std::mt19937_64 rng(kSeed + 2);
  int face_differs = 0, full_differs = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const d3::LatticeSize size = random_size(rng);
    const auto targets = d3::cascade_model::random_targets(size, rng, 3);
    const Brick3 brick(size);
    const auto count = [&](p8est_connect_type_t c) {
      return testing::p8est_targets(brick, targets, c)->global_num_quadrants;
    };
    const std::size_t edge = leaves(d3::cascade_model::refine_targets(size, targets, Balance::Edge)).size();
    face_differs += static_cast<std::size_t>(count(P8EST_CONNECT_FACE)) != edge;
    full_differs += static_cast<std::size_t>(count(P8EST_CONNECT_FULL)) != edge;
  }
  EXPECT_GT(face_differs, 0) << "seed " << kSeed + 2;
  EXPECT_GT(full_differs, 0) << "seed " << kSeed + 2;
}

}  // namespace
}  // namespace bccmis::p4est_bridge

int main(int argc, char** argv) { return bccmis::p4est_bridge::testing::run_tests(argc, argv); }
