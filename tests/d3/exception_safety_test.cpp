// The strong exception guarantee in 3D: refine and coarsen either complete or
// leave the graph exactly as it was, even when an allocation fails. A
// replaced global operator new fails the k-th allocation of an operation, for
// every k until the operation completes (as tests/exception_safety_test.cpp
// does for 2D).
#include <gtest/gtest.h>

#include "testing/fault_injection.h"

#include "util.h"

namespace bccmis::d3 {
namespace {

using bccmis::testing::exercise;

TEST(D3ExceptionSafety, RefineWithOldJunctionsIsAllOrNothing) {
  const Graph g = test::build("lattice 2 1 1 2\nrefine 4 4 4\n");
  const long points = exercise(g, [](Graph& h) { ASSERT_TRUE(refine(h, {12, 4, 4}).applied()); });
  EXPECT_GT(points, 100);  // the operation allocates: faults were really injected
}

TEST(D3ExceptionSafety, CoarsenKeepingJunctionsIsAllOrNothing) {
  const Graph g = test::build("lattice 2 1 1 2\nrefine 4 4 4\nrefine 12 4 4\n");
  const long points = exercise(g, [](Graph& h) { ASSERT_TRUE(coarsen(h, {4, 4, 4}).applied()); });
  EXPECT_GT(points, 100);
}

TEST(D3ExceptionSafety, CellsBesideFinerAndSameLevelNeighbours) {
  // lattice 2 2 2 1 with (6,2,2) refined: (2,2,2) has old junctions on its
  // face x = 4, (2,6,2) meets the refined cube along an edge only.
  const Graph g = test::build("lattice 2 2 2 1\nrefine 6 2 2\n");
  for (const Point c : {Point{2, 2, 2}, Point{2, 6, 2}}) {
    Graph probe = g;
    ASSERT_TRUE(refine(probe, c).applied());
    exercise(g, [&](Graph& h) { refine(h, c); });
    exercise(probe, [&](Graph& h) { coarsen(h, c); });
  }
}

}  // namespace
}  // namespace bccmis::d3
