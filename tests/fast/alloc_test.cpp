// Allocation behaviour of bccmis::fast::Lattice (issue 9): no heap allocation
// per operation in steady state, and the strong exception guarantee when an
// allocation fails. Replaces the global operator new
// (testing/counting_allocator.h), so it is its own executable.
#include <gtest/gtest.h>

#include <cstddef>
#include <new>
#include <string>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "testing/counting_allocator.h"

namespace bccmis::fast {
namespace {

namespace alloc = bccmis::testing::alloc;
using alloc::allocations_during;

/// Every level-0 cell, then every level-1 cell, of a W x H lattice.
std::vector<Point> cells_of_level(const LatticeSize& size, int level) {
  std::vector<Point> out;
  const std::int64_t s = cell_side(size, level);
  for (std::int64_t j = 0; j < size.H << level; ++j)
    for (std::int64_t i = 0; i < size.W << level; ++i) out.push_back({i * s + s / 2, j * s + s / 2});
  return out;
}

TEST(FastAllocation, RefineAndCoarsenAllocateNothingInSteadyState) {
  const LatticeSize size{16, 16, 4};
  Lattice lat(size);
  const std::vector<Point> level0 = cells_of_level(size, 0);
  const std::vector<Point> level1 = cells_of_level(size, 1);
  auto cycle = [&] {
    for (const Point& c : level0) ASSERT_TRUE(lat.refine(c).applied());
    for (std::size_t i = 0; i < level1.size(); i += 3) ASSERT_TRUE(lat.refine(level1[i]).applied());
    for (std::size_t i = 0; i < level1.size(); i += 3) ASSERT_TRUE(lat.coarsen(level1[i]).applied());
    for (const Point& c : level0) ASSERT_TRUE(lat.coarsen(c).applied());
  };
  // Warm-up: the pools and the table reach their size (the counter sees it).
  EXPECT_GT(allocations_during(cycle), 0);
  const std::string before = canonical_state(lat);
  const long n = allocations_during([&] {
    for (int k = 0; k < 5; ++k) cycle();
  });
  EXPECT_EQ(n, 0);
  EXPECT_EQ(canonical_state(lat), before);
}

TEST(FastAllocation, RefusalsAndQueriesAllocateNothing) {
  Lattice lat({4, 4, 2});  // S = 8
  ASSERT_TRUE(lat.refine({4, 4}).applied());
  const long n = allocations_during([&] {
    EXPECT_EQ(lat.refine({5, 5}).refused, RefineRefusal::NoSuchCell);
    EXPECT_EQ(lat.refine({6, 2}).refused, RefineRefusal::CoarserNeighbor);
    EXPECT_EQ(lat.coarsen({8, 8}).refused, CoarsenRefusal::NotARefinedCenter);
    EXPECT_EQ(lat.coarsen({12, 4}).refused, CoarsenRefusal::NoSuchNode);
    EXPECT_TRUE(lat.is_center({6, 6}));
    EXPECT_EQ(lat.nbr({4, 4}).size(), 4u);
  });
  EXPECT_EQ(n, 0);
}

TEST(FastAllocation, AFailingAllocationLeavesTheLatticeUnchanged) {
  // A tight lattice: every refine must grow a pool or the table at first.
  const LatticeSize size{6, 6, 3};
  Lattice lat(size);
  lat.shrink_to_fit();
  int failures = 0;
  for (int level = 0; level < 2; ++level)
    for (const Point& c : cells_of_level(size, level)) {
      if (lat.can_refine(c)) continue;  // refused: nothing to try
      const std::string before = canonical_state(lat);
      alloc::countdown = 0;
      bool applied = false;
      try {
        applied = lat.refine(c).applied();  // succeeds when no allocation is needed
      } catch (const std::bad_alloc&) {
        ++failures;
        alloc::countdown = -1;
        ASSERT_EQ(canonical_state(lat), before) << "refine (" << c.x << ", " << c.y << ") threw half-way";
        const auto problem = lat.audit();
        ASSERT_FALSE(problem) << *problem;
      }
      alloc::countdown = -1;
      if (!applied) {
        ASSERT_TRUE(lat.refine(c).applied());
      }
    }
  EXPECT_GT(failures, 3);
  const auto problem = lat.audit();
  EXPECT_FALSE(problem) << *problem;
}

}  // namespace
}  // namespace bccmis::fast
