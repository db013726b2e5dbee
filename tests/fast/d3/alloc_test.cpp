// Allocation behaviour of bccmis::d3::fast::Lattice: no heap allocation per
// refine or coarsen in steady state (free records for what an operation
// creates), and the strong exception guarantee when the growth an operation
// needs fails. Replaces the global operator new (testing/counting_allocator.h),
// so it is its own executable.
#include <gtest/gtest.h>

#include <cstddef>
#include <new>
#include <string>
#include <vector>

#include "bccmis/d3/ops.h"
#include "bccmis/fast/d3/lattice.h"
#include "testing/counting_allocator.h"

namespace {

using namespace bccmis;
namespace alloc = bccmis::testing::alloc;

// Refines every cell to level `to`, then coarsens back to level 0, finest
// first; returns the number of operations applied.
std::size_t round_trip(d3::fast::Lattice& g, int to, std::vector<d3::Point>& scratch) {
  std::size_t applied = 0;
  for (int level = 0; level < to; ++level) {
    scratch.clear();
    for (const d3::Point& c : g.cells()) scratch.push_back(c);
    for (const d3::Point& c : scratch) applied += g.refine(c).applied();
  }
  for (int level = to - 1; level >= 0; --level) {
    scratch.clear();
    for (const d3::Point& n : g.nodes())
      if (d3::refined_center_level(g.size(), n) == level) scratch.push_back(n);
    for (const d3::Point& n : scratch) applied += g.coarsen(n).applied();
  }
  return applied;
}

TEST(Fast3Alloc, NoAllocationPerOperationInSteadyState) {
  d3::fast::Lattice g({2, 1, 1, 3});
  std::vector<d3::Point> scratch;
  const std::string initial = d3::fast::canonical_state(g);
  round_trip(g, 3, scratch);  // warm-up: the pools and the table reach their size
  scratch.reserve(4096);
  // Count only inside refine and coarsen: the lists are built first.
  long inside = 0;
  for (int level = 0; level < 3; ++level) {
    std::vector<d3::Point> todo = g.cells();
    inside += alloc::allocations_during([&] {
      for (const d3::Point& c : todo) EXPECT_TRUE(g.refine(c).applied());
    });
  }
  for (int level = 2; level >= 0; --level) {
    std::vector<d3::Point> todo;
    for (const d3::Point& n : g.nodes())
      if (d3::refined_center_level(g.size(), n) == level) todo.push_back(n);
    inside += alloc::allocations_during([&] {
      for (const d3::Point& n : todo) EXPECT_TRUE(g.coarsen(n).applied());
    });
  }
  EXPECT_EQ(inside, 0);
  EXPECT_EQ(d3::fast::canonical_state(g), initial);
}

TEST(Fast3Alloc, AFailedGrowthLeavesTheLatticeUnchanged) {
  // Each refine from the initial lattice needs the pools and the table to
  // grow; the k-th allocation fails for k = 0, 1, 2, ... until one succeeds.
  int failures = 0;
  for (long k = 0; k < 64; ++k) {
    d3::fast::Lattice g({1, 1, 1, 2});
    const std::string before = d3::fast::canonical_state(g);
    alloc::countdown = k;
    try {
      const auto r = g.refine({4, 4, 4});
      alloc::countdown = -1;
      EXPECT_TRUE(r.applied());
      break;
    } catch (const std::bad_alloc&) {
      alloc::countdown = -1;
      ++failures;
      EXPECT_EQ(d3::fast::canonical_state(g), before) << "allocation " << k;
      EXPECT_FALSE(g.audit()) << "allocation " << k;
    }
  }
  EXPECT_GT(failures, 0);  // the first refine does grow
}

}  // namespace
