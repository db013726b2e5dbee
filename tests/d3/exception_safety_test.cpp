// The strong exception guarantee in 3D: refine and coarsen either complete or
// leave the graph exactly as it was, even when an allocation fails. A
// replaced global operator new fails the k-th allocation of an operation, for
// every k until the operation completes (as tests/exception_safety_test.cpp
// does for 2D).
#include <gtest/gtest.h>

#include <cstdlib>
#include <new>

#include "util3.h"

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

namespace bccmis::d3 {
namespace {

// Runs op on copies of g, failing allocation k = 0, 1, 2, ... until op
// succeeds; after each failure the copy must equal g. Returns the number of
// failure points exercised.
template <class Op>
long exercise(const Graph3& g, Op op) {
  const std::string before = canonical_state(g);
  for (long k = 0;; ++k) {
    Graph3 h = g;
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
    if (k > 1000000) {
      ADD_FAILURE() << "operation never completed";
      return k;
    }
  }
}

TEST(D3ExceptionSafety, RefineWithOldJunctionsIsAllOrNothing) {
  const Graph3 g = test::build("lattice 2 1 1 2\nrefine 4 4 4\n");
  const long points = exercise(g, [](Graph3& h) { ASSERT_TRUE(refine(h, {12, 4, 4}).applied()); });
  EXPECT_GT(points, 100);  // the operation allocates: faults were really injected
}

TEST(D3ExceptionSafety, CoarsenKeepingJunctionsIsAllOrNothing) {
  const Graph3 g = test::build("lattice 2 1 1 2\nrefine 4 4 4\nrefine 12 4 4\n");
  const long points = exercise(g, [](Graph3& h) { ASSERT_TRUE(coarsen(h, {4, 4, 4}).applied()); });
  EXPECT_GT(points, 100);
}

TEST(D3ExceptionSafety, CellsBesideFinerAndSameLevelNeighbours) {
  // lattice 2 2 2 1 with (6,2,2) refined: (2,2,2) has old junctions on its
  // face x = 4, (2,6,2) meets the refined cube along an edge only.
  const Graph3 g = test::build("lattice 2 2 2 1\nrefine 6 2 2\n");
  for (const Point3 c : {Point3{2, 2, 2}, Point3{2, 6, 2}}) {
    Graph3 probe = g;
    ASSERT_TRUE(refine(probe, c).applied());
    exercise(g, [&](Graph3& h) { refine(h, c); });
    exercise(probe, [&](Graph3& h) { coarsen(h, c); });
  }
}

}  // namespace
}  // namespace bccmis::d3
