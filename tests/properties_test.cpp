// RapidCheck properties of the reference core (issue 5), one RC_GTEST_PROP
// each. The bodies live in tests/generators.h so that tests/mutants/ can run
// the same properties against planted bugs.
//
// Random W, H in 1..4 and L in 0..3; up to 50 steps biased towards legal
// operations (live cells, refined centers) with illegal ones mixed in. Seeds
// and max_success are fixed in ctest (tests/properties.cmake). A failure
// prints the shrunk scenario, the reproducer trace, and RapidCheck's
// `RC_PARAMS="reproduce=..."` string; save the trace in tests/regressions/.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "testing/generators.h"

namespace bccmis::proptest {
namespace {

RC_GTEST_PROP(Property, EveryStateAfterEveryOperationPassesTheChecker, ()) {
  prop_valid_after_every_op(Ops{}, *genScenario());
}

//= erleben2009#claim-inverse type=test
RC_GTEST_PROP(Property, RefineThenCoarsenGivesTheSameCanonicalState, ()) {
  prop_refine_then_coarsen(Ops{}, *genScenario());
}

//= erleben2009#claim-inverse type=test
RC_GTEST_PROP(Property, CoarsenThenRefineGivesTheSameCanonicalState, ()) {
  prop_coarsen_then_refine(Ops{}, *genScenario());
}

RC_GTEST_PROP(Property, RefusedOperationLeavesTheStateUnchangedWithTheExpectedCode, ()) {
  prop_refusal_leaves_state_unchanged(Ops{}, *genScenario());
}

RC_GTEST_PROP(Property, VertexCountsChangeExactlyAsTheEquationsImply, ()) { prop_vertex_counts(Ops{}, *genScenario()); }

RC_GTEST_PROP(Property, CoarseningEverythingReturnsTheInitialLattice, ()) {
  prop_coarsen_everything(Ops{}, *genScenario());
}

//= erleben2009#pre-refine-level type=test
//= erleben2009#pre-coarsen-balance type=test
RC_GTEST_PROP(Property, DecisionsEqualTheGeometricRule, ()) { prop_decisions_match_geometry(Ops{}, *genScenario()); }

// The generators reach what they are meant to: deep states, both operations
// accepted, and refusals of every kind. A generator that drifted into trivial
// scenarios would make every property above pass vacuously.
TEST(PropertyGenerators, ReachDeepStatesAndEveryDecision) {
  std::set<std::string> codes;
  int max_level = 0;
  const bool ok = rc::check("generator coverage", [&] {
    const Scenario sc = *genScenario();
    Walk w(Ops{}, sc.size);
    for (const Step& s : sc.steps) {
      const Outcome o = w.run(s);
      codes.insert(std::string(s.op == OpKind::Refine ? "refine " : "coarsen ") + o.code);
    }
    for (const auto& [c, l] : w.graph().level) max_level = std::max(max_level, l);
  });
  EXPECT_TRUE(ok);
  EXPECT_EQ(max_level, 3);
  for (const char* want :
       {"refine ok", "refine no-such-cell", "refine max-level", "refine coarser-neighbor", "coarsen ok",
        "coarsen no-such-node", "coarsen not-a-refined-center", "coarsen children-refined", "coarsen finer-neighbor"})
    EXPECT_EQ(codes.count(want), 1u) << want;
}

// Every trace in tests/regressions/ replays on the core with every per-step
// check (checker, decisions against the model, refusals, inverses).
TEST(Regressions, EveryTraceReplaysCleanlyOnTheCore) {
  int traces = 0;
  for (const auto& entry : std::filesystem::directory_iterator(BCCMIS_REGRESSIONS_DIR)) {
    if (entry.path().extension() != ".trace") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const Trace trace = parse_trace(text.str(), entry.path().filename().string());
    const auto problem = check_trace(Ops{}, trace);
    EXPECT_FALSE(problem.has_value()) << entry.path().filename().string() << ": " << *problem;
    ++traces;
  }
  EXPECT_GT(traces, 0) << "no traces in " << BCCMIS_REGRESSIONS_DIR;
}

}  // namespace
}  // namespace bccmis::proptest
