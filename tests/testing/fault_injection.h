// Fault injection for the strong exception guarantee: a replaced global
// operator new that fails the k-th allocation, and exercise(), which runs an
// operation on copies of a lattice failing allocation k = 0, 1, 2, ... until
// the operation completes, and checks after every failure that the copy is
// exactly the original (canonical text and ==).
//
// The header defines the replaced operator new and delete: include it from
// exactly one translation unit of a test executable of its own.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <new>
#include <string>

#include "bccmis/lattice.h"

namespace bccmis::testing::fault {
// Allocations left before the injected failure; negative: no injection.
inline long countdown = -1;
inline long failures = 0;
}  // namespace bccmis::testing::fault

void* operator new(std::size_t n) {
  using namespace bccmis::testing;
  if (fault::countdown == 0) {
    fault::countdown = -1;
    ++fault::failures;
    throw std::bad_alloc();
  }
  if (fault::countdown > 0) --fault::countdown;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace bccmis::testing {

/// Runs op on copies of g, failing allocation k = 0, 1, 2, ... until op
/// succeeds; after each failure the copy must equal g. Returns how many
/// failure points were exercised (at most `limit`).
template <AdaptiveLattice L, class Op>
long exercise(const L& g, Op op, long limit = 1000000) {
  const std::string before = canonical_text(g);
  for (long k = 0;; ++k) {
    L h = g;
    const long failures_before = fault::failures;
    bool threw = false;
    fault::countdown = k;
    try {
      op(h);
    } catch (const std::bad_alloc&) {
      threw = true;
    }
    fault::countdown = -1;
    if (!threw) {
      EXPECT_EQ(fault::failures, failures_before);
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
