// bccmis against p4est on random target sets (issue 10): refine_balanced in
// bccmis and p4est_refine + p4est_balance in p4est must reach the same leaf
// set; edge balance against P4EST_CONNECT_FACE, corner balance against
// P4EST_CONNECT_FULL. A failure prints the seed, the lattice and the targets.
#include <gtest/gtest.h>

#include <random>

#include "bccmis/invariants/invariants.h"
#include "p4est/p4est_test_util.h"

namespace bccmis::p4est_bridge {
namespace {

constexpr std::uint64_t kSeed = 20091001;

void differential(Balance mode, p4est_connect_type_t connect, int trials) {
  std::mt19937_64 rng(kSeed + (mode == Balance::Edge ? 0 : 1));
  std::size_t leaves_seen = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const LatticeSize size{std::uniform_int_distribution<std::int64_t>(1, 4)(rng),
                           std::uniform_int_distribution<std::int64_t>(1, 4)(rng),
                           std::uniform_int_distribution<int>(1, 7)(rng)};
    const auto targets = testing::random_targets(size, rng, std::uniform_int_distribution<int>(1, 8)(rng));
    SCOPED_TRACE("seed " + std::to_string(kSeed) + " trial " + std::to_string(trial) + ", balance " +
                 std::string(name(mode)) + ": " + testing::describe(size, targets));
    const Graph g = testing::refine_targets(size, targets, mode);
    ASSERT_EQ(find_violation(g), std::nullopt);
    const Brick brick(size);
    const ForestPtr forest = testing::p4est_targets(brick, targets, connect);
    // The same leaves, and the import of the forest is the same lattice, to the last node.
    ASSERT_NO_FATAL_FAILURE(testing::expect_same_lattice(g, brick, forest.get()));
    leaves_seen += leaves(g).size();
  }
  EXPECT_GT(leaves_seen, static_cast<std::size_t>(trials) * 20) << "the targets refine too little to test much";
}

TEST(Differential, RefineBalancedMatchesP4estFaceBalance) { differential(Balance::Edge, P4EST_CONNECT_FACE, 150); }

TEST(Differential, CornerModeMatchesP4estFullBalance) { differential(Balance::Corner, P4EST_CONNECT_FULL, 150); }

}  // namespace
}  // namespace bccmis::p4est_bridge

int main(int argc, char** argv) { return bccmis::p4est_bridge::testing::run_tests(argc, argv); }
