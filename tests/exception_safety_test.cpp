// Strong exception guarantee: refine and coarsen either complete or leave the
// graph exactly as it was, even when an allocation fails. A replaced global
// operator new fails the k-th allocation of an operation, for every k until
// the operation completes without hitting the fault.
#include <gtest/gtest.h>

#include "testing/fault_injection.h"

#include "test_util.h"

namespace bccmis {
namespace {

using bccmis::testing::exercise;

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
