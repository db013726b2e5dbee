// Strong exception guarantee: refine and coarsen either complete or leave the
// graph exactly as it was, even when an allocation fails. A replaced global
// operator new fails the k-th allocation of an operation, for every k until
// the operation completes without hitting the fault.
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>

#include "test_util.h"

namespace {
// Allocations left before the injected failure; negative: no injection.
long g_countdown = -1;
long g_failures = 0;
}  // namespace

void* operator new(std::size_t n) {
  if (g_countdown == 0) {
    g_countdown = -1;
    ++g_failures;
    throw std::bad_alloc();
  }
  if (g_countdown > 0) --g_countdown;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace bccmis {
namespace {

// Runs op on copies of g, failing allocation k = 0, 1, 2, ... until op
// succeeds; after each failure the copy must equal g. Returns how many
// distinct failure points were exercised.
template <class Op>
long exercise(const Graph& g, Op op) {
  const std::string before = canonical_state(g);
  for (long k = 0;; ++k) {
    Graph h = g;
    const long failures_before = g_failures;
    bool threw = false;
    g_countdown = k;
    try {
      op(h);
    } catch (const std::bad_alloc&) {
      threw = true;
    }
    g_countdown = -1;
    if (!threw) {
      EXPECT_EQ(g_failures, failures_before);
      return k;
    }
    EXPECT_EQ(canonical_state(h), before) << "allocation " << k << " failed and the graph changed";
    EXPECT_EQ(h, g);
    if (k > 100000) {
      ADD_FAILURE() << "operation never completed";
      return k;
    }
  }
}

TEST(ExceptionSafety, RefineIsAllOrNothingUnderAllocationFailure) {
  const Graph g = test::build("lattice 3 1 1\nrefine 10 2\n");
  const long points = exercise(g, [](Graph& h) { ASSERT_TRUE(refine(h, {6, 2}).applied()); });
  EXPECT_GT(points, 10);  // the operation allocates: the test really injected faults
}

TEST(ExceptionSafety, CoarsenIsAllOrNothingUnderAllocationFailure) {
  const Graph g = test::build("lattice 3 1 1\nrefine 10 2\nrefine 6 2\n");
  const long points = exercise(g, [](Graph& h) { ASSERT_TRUE(coarsen(h, {6, 2}).applied()); });
  EXPECT_GT(points, 10);
}

TEST(ExceptionSafety, BoundaryAndInteriorCells) {
  const Graph g = test::build("lattice 3 3 2\nrefine 12 12\nrefine 4 12\nrefine 12 4\n");
  for (const Point& c : g.C) {
    Graph probe = g;
    if (!refine(probe, c).applied()) continue;
    exercise(g, [&](Graph& h) { refine(h, c); });
    exercise(probe, [&](Graph& h) { coarsen(h, c); });
  }
}

}  // namespace
}  // namespace bccmis
