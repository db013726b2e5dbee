// The decision of one operation as the decision log names it (spec/formats.md,
// refusal codes), for the tests that compare lattices with models. Header
// only; included as "testing/decision.h" (include root tests/).
#pragma once

#include <string>

namespace bccmis::testing {

/// Runs refine (is_refine) or coarsen at `at` on g, a lattice of either
/// dimension, and returns "ok" if it was applied, else the refusal's code.
template <class Lattice, class P>
std::string run_and_decide(Lattice& g, bool is_refine, const P& at) {
  if (is_refine) {
    const auto r = refine(g, at);
    return r.refused ? std::string(code(*r.refused)) : "ok";
  }
  const auto r = coarsen(g, at);
  return r.refused ? std::string(code(*r.refused)) : "ok";
}

}  // namespace bccmis::testing
