// spec/distributed.md D15, step 3: the repartition's decision on its line.
#include "bccmis/distributed/repartition.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

using bccmis::distributed::imbalance;
using bccmis::distributed::repartition_needed;

//= spec/distributed.md#D15 type=test
// Leaves 5 and 3 on 2 ranks: the mean is 4, the imbalance 5 / 4 = 1.25
// exactly (binary fractions), on the threshold 1.25: not repartitioned; one
// leaf more on the largest rank (6 / 4.5 = 1.33...) is past it.
TEST(Repartition, D15_OnTheThresholdDoesNotRepartition) {
  const std::vector<std::int64_t> on{5, 3}, past{6, 3}, below{5, 4};
  EXPECT_EQ(imbalance(on), 1.25);
  EXPECT_FALSE(repartition_needed(on, 1.25));
  EXPECT_TRUE(repartition_needed(past, 1.25));
  EXPECT_FALSE(repartition_needed(below, 1.25));
}

//= spec/distributed.md#D15 type=test
// Three ranks, the largest 3 of 6 leaves: imbalance 1.5 exactly; a balanced
// forest (imbalance 1) on the threshold 1 is not repartitioned; no leaves
// at all, imbalance 1.
TEST(Repartition, D15_ThreeRanksAndTheEdges) {
  const std::vector<std::int64_t> three{3, 2, 1}, even{4, 4, 4}, none{0, 0};
  EXPECT_EQ(imbalance(three), 1.5);
  EXPECT_FALSE(repartition_needed(three, 1.5));
  EXPECT_TRUE(repartition_needed(three, 1.25));
  EXPECT_EQ(imbalance(even), 1.0);
  EXPECT_FALSE(repartition_needed(even, 1.0));
  EXPECT_EQ(imbalance(none), 1.0);
  EXPECT_FALSE(repartition_needed(none, 1.0));
}

}  // namespace
