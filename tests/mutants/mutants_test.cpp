// Every property must be able to fail (issue 5): the same property bodies as
// tests/properties_test.cpp and the explorer run against planted-bug copies of
// refine/coarsen (tests/mutants/mutant_ops.cpp), each with a fixed seed and a
// fixed budget, and must report the bug.
//
// Each mutant lists the properties that MUST catch it, and the ones that must
// NOT (to show which bugs only the properties, not the checker alone, can see).
// The test prints the full catch matrix (every property on every mutant). The properties run through
// RapidCheck's checkTestable with explicit TestParams (seed, budget, no
// shrinking) so that each mutant gets its own budget and no console noise.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/detail/TestListener.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bccmis/explore/explore.h"
#include "mutants/mutant_ops.h"
#include "testing/generators.h"

namespace bccmis::proptest {
namespace {

using mutants::Flaw;

constexpr std::uint64_t kSeed = 20090303;
constexpr int kBudget = 150;        // test cases per (mutant, property)
constexpr int kPassingBudget = 50;  // for the runs that must pass (baseline, equivalent mutant)

Ops mutant_ops(Flaw flaw, const std::string& name) {
  Ops ops;
  ops.name = name;
  ops.refine = [flaw](Graph& g, const Point& c) { return mutants::refine(g, c, flaw); };
  ops.coarsen = [flaw](Graph& g, const Point& n) { return mutants::coarsen(g, n, flaw); };
  ops.can_refine = [flaw](const Graph& g, const Point& c) { return mutants::can_refine(g, c, flaw); };
  ops.can_coarsen = [flaw](const Graph& g, const Point& n) { return mutants::can_coarsen(g, n, flaw); };
  return ops;
}

struct PropertyBody {
  std::string name;
  void (*body)(const Ops&, const Scenario&);
};

const std::vector<PropertyBody>& properties() {
  static const std::vector<PropertyBody> all = {
      {"valid", &prop_valid_after_every_op},
      {"refine-coarsen", &prop_refine_then_coarsen},
      {"coarsen-refine", &prop_coarsen_then_refine},
      {"refusal", &prop_refusal_leaves_state_unchanged},
      {"counts", &prop_vertex_counts},
      {"coarsen-all", &prop_coarsen_everything},
      {"decisions", &prop_decisions_match_geometry},
  };
  return all;
}

struct Verdict {
  bool caught = false;
  std::string how;  // the failure description (first line) or "passed N"
};

// Swallows RapidCheck's reporting: the verdicts are asserted and printed here,
// and a deliberately failing property must not be reported at exit as a
// failure to reproduce.
class QuietListener : public rc::detail::TestListener {
 public:
  void onTestCaseFinished(const rc::detail::CaseDescription&) override {}
  void onShrinkTried(const rc::detail::CaseDescription&, bool) override {}
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}
};

Verdict run_property(const PropertyBody& p, const Ops& ops, int budget = kBudget) {
  rc::detail::TestParams params;
  params.seed = kSeed;
  params.maxSuccess = budget;
  params.maxSize = 100;
  params.disableShrinking = true;
  rc::detail::TestMetadata metadata;
  metadata.id = ops.name + "/" + p.name;
  metadata.description = metadata.id;
  QuietListener quiet;
  const auto result = rc::detail::checkTestable([&] { p.body(ops, *genScenario()); }, metadata, params, quiet);
  Verdict v;
  if (result.template is<rc::detail::FailureResult>()) {
    v.caught = true;
    const std::string& d = result.template get<rc::detail::FailureResult>().description;
    // The description holds RapidCheck's "file:line:" and assertion lines and
    // then our message, which starts with "[<mutant name>] ": keep that line.
    const std::size_t at = d.find("[" + ops.name + "] ");
    const std::size_t start = at == std::string::npos ? 0 : at;
    v.how = d.substr(start, d.find('\n', start) - start);
  } else if (result.template is<rc::detail::SuccessResult>()) {
    v.how = "passed " + std::to_string(result.template get<rc::detail::SuccessResult>().numSuccess);
  } else {
    v.how = "gave up or errored";
  }
  return v;
}

struct Expectation {
  Flaw flaw;
  std::string name;
  std::set<std::string> must_catch;  // properties that must fail
  std::set<std::string> must_pass;   // properties that must not fail (the checker alone cannot see it)
  bool explorer_catches;             // explore(2 1 2) reports a failure
};

const std::vector<Expectation>& expectations() {
  static const std::vector<Expectation> all = {
      {Flaw::Skip4d, "Skip4d", {"valid"}, {}, true},
      {Flaw::Skip6d, "Skip6d", {"valid"}, {}, true},
      {Flaw::Forget10c, "Forget10c", {"valid"}, {}, true},
      {Flaw::LiteralBoundary6, "LiteralBoundary6", {"valid"}, {}, true},
      {Flaw::WeakCoarsenGuard, "WeakCoarsenGuard", {"decisions"}, {}, true},
      {Flaw::CoarsenDifferentState, "CoarsenDifferentState", {"refine-coarsen", "decisions"}, {"valid"}, true},
      {Flaw::CornerBalance, "CornerBalance", {"decisions"}, {"valid", "refine-coarsen", "coarsen-refine"}, false},
      {Flaw::RefusalRefinesNeighbor, "RefusalRefinesNeighbor", {"refusal"}, {"valid"}, true},
  };
  return all;
}

std::string name_of(const testing::TestParamInfo<Expectation>& info) { return info.param.name; }
void PrintTo(const Expectation& e, std::ostream* os) { *os << "mutant " << e.name; }

class Mutant : public testing::TestWithParam<Expectation> {};

TEST_P(Mutant, IsCaughtByThePropertiesAndTheExplorer) {
  const Expectation& e = GetParam();
  const Ops ops = mutant_ops(e.flaw, e.name);
  std::map<std::string, Verdict> verdicts;
  int caught = 0;
  std::cout << "mutant " << e.name << ":\n";
  for (const PropertyBody& p : properties()) {
    const Verdict v = run_property(p, ops);
    verdicts[p.name] = v;
    caught += v.caught;
    std::cout << "  " << p.name << ": " << (v.caught ? "CAUGHT: " : "not caught: ") << v.how << "\n";
  }
  EXPECT_GT(caught, 0) << "no property caught mutant " << e.name;
  for (const std::string& p : e.must_catch)
    EXPECT_TRUE(verdicts[p].caught) << "property '" << p << "' did not catch mutant " << e.name;
  for (const std::string& p : e.must_pass)
    EXPECT_FALSE(verdicts[p].caught) << "property '" << p << "' was expected not to see mutant " << e.name
                                     << " (the checker alone cannot): " << verdicts[p].how;

  ExploreOptions options;
  options.refine = ops.refine;
  options.coarsen = ops.coarsen;
  const ExploreResult r = explore(LatticeSize{2, 1, 2}, options);
  std::cout << "  explore 2 1 2: " << summary(r) << "\n";
  if (e.explorer_catches) {
    EXPECT_TRUE(r.first_failure.has_value()) << summary(r);
  } else {
    EXPECT_FALSE(r.first_failure.has_value()) << summary(r);
  }
}

INSTANTIATE_TEST_SUITE_P(Flaws, Mutant, testing::ValuesIn(expectations()), name_of);

// Forget10cOnly drops (10c) but keeps (11d), which repeats it (erratum E9):
// an equivalent mutant. Nothing may flag it, or the properties have false
// positives; the explorer sees exactly the reference counts.
TEST(MutantEquivalent, Forget10cOnlyIsIndistinguishableFromTheCore) {
  const Ops ops = mutant_ops(Flaw::Forget10cOnly, "Forget10cOnly");
  for (const PropertyBody& p : properties()) {
    const Verdict v = run_property(p, ops, kPassingBudget);
    EXPECT_FALSE(v.caught) << p.name << ": " << v.how;
  }
  ExploreOptions options;
  options.refine = ops.refine;
  options.coarsen = ops.coarsen;
  const ExploreResult r = explore(LatticeSize{2, 1, 2}, options);
  EXPECT_TRUE(r.ok()) << summary(r);
  EXPECT_EQ(r.states, 265);
  EXPECT_EQ(r.refine_edges, 1042);
}

// Flaw::None is the core, statement for statement: every property passes and
// the explorer finds the reference counts. (Otherwise a "caught" mutant could
// be caught for a bug in the copy rather than the planted one.)
TEST(MutantBaseline, UnbrokenCopyPassesEverything) {
  const Ops ops = mutant_ops(Flaw::None, "None");
  for (const PropertyBody& p : properties()) {
    const Verdict v = run_property(p, ops, kPassingBudget);
    EXPECT_FALSE(v.caught) << p.name << ": " << v.how;
  }
  for (const LatticeSize size : {LatticeSize{2, 1, 2}, LatticeSize{2, 2, 1}}) {
    ExploreOptions options;
    options.refine = ops.refine;
    options.coarsen = ops.coarsen;
    const ExploreResult r = explore(size, options);
    EXPECT_TRUE(r.ok()) << summary(r);
    EXPECT_EQ(r.states, model::count_balanced_leaf_sets(static_cast<int>(size.W), static_cast<int>(size.H), size.L));
  }
}

// What a failing property prints, shown on a mutant (disabled: it fails on
// purpose). Run it with
//   RC_PARAMS="seed=20090303" tests/mutants_property_test
//     --gtest_also_run_disabled_tests --gtest_filter='MutantDemo.*'
// to see the shrunk scenario, the reproducer trace and RapidCheck's
// `RC_PARAMS="reproduce=..."` line.
RC_GTEST_PROP(MutantDemo, DISABLED_RefineThenCoarsenOnCoarsenDifferentState, ()) {
  prop_refine_then_coarsen(mutant_ops(Flaw::CoarsenDifferentState, "CoarsenDifferentState"), *genScenario());
}

// Each tests/regressions/mutant-<Name>.trace still reproduces its mutant
// (and, in tests/properties_test.cpp, replays cleanly on the core).
TEST(MutantRegressions, EachTraceStillCatchesItsMutant) {
  int traces = 0;
  for (const mutants::FlawInfo& f : mutants::all_flaws()) {
    const std::filesystem::path path = std::filesystem::path(BCCMIS_REGRESSIONS_DIR) / ("mutant-" + f.name + ".trace");
    if (f.flaw == Flaw::Forget10cOnly) {
      EXPECT_FALSE(std::filesystem::exists(path)) << "an equivalent mutant has no reproducer";
      continue;
    }
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const auto problem = check_trace(mutant_ops(f.flaw, f.name), parse_trace(text.str(), path.filename().string()));
    EXPECT_TRUE(problem.has_value()) << path.filename().string() << " no longer catches " << f.name;
    if (problem) std::cout << f.name << ": " << *problem << "\n";
    ++traces;
  }
  EXPECT_EQ(traces, static_cast<int>(mutants::all_flaws().size()) - 1);
}

}  // namespace
}  // namespace bccmis::proptest
