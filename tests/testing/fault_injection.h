// Fault injection for the strong exception guarantee: exercise() runs an
// operation on copies of a lattice failing allocation k = 0, 1, 2, ... until
// the operation completes, and checks after every failure that the copy is
// exactly the original (canonical text and ==). The failures come from the
// counting allocator (testing/counting_allocator.h).
//
// The header defines the replaced operator new and delete (it includes
// testing/counting_allocator.h): include it from exactly one translation unit
// of a test executable of its own.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "bccmis/lattice.h"
#include "testing/counting_allocator.h"

namespace bccmis::testing {

/// Runs op on copies of g, failing allocation k = 0, 1, 2, ... until op
/// succeeds; after each failure the copy must equal g. Returns how many
/// failure points were exercised (at most `limit`).
template <AdaptiveLattice L, class Op>
long exercise(const L& g, Op op, long limit = 1000000) {
  const std::string before = canonical_text(g);
  for (long k = 0;; ++k) {
    L h = g;
    const long failures_before = alloc::failures;
    if (!alloc::fails_at(k, [&] { op(h); })) {
      EXPECT_EQ(alloc::failures, failures_before);
      return k;
    }
    EXPECT_EQ(canonical_text(h), before) << "allocation " << k << " failed and the lattice changed";
    EXPECT_TRUE(h == g) << "allocation " << k << " failed and the lattice changed";
    if (k > limit) {
      ADD_FAILURE() << "operation never completed";
      return k;
    }
  }
}

}  // namespace bccmis::testing
