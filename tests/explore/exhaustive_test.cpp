// Exhaustive exploration (issue 5): every state reachable from the initial
// lattice by refine and coarsen, for small lattices, with the full checker on
// every state and every operation tried on every vertex (src/bccmis/explore).
//
// The counts must equal the independent leaf model's (tests/model/leaf_model.h):
//   states       == count_balanced_leaf_sets (enumeration of 2:1 edge-balanced
//                   quadtree leaf sets, no operations at all) and
//                == count_reachable_states (BFS over the model's own ops);
//   refine edges == the model BFS's refine edges; coarsen edges == refine edges.
// The table repeats the values of tests/model/leaf_model_test.cpp so that a
// change of the model cannot silently move both sides.
//
// ExhaustiveSmall (up to 512 states) runs with the properties (label
// `property`); ExhaustiveLarge (4250, 66641 and 66642 states) runs under the
// label `exhaustive`, meant for the release build:
//   cmake --preset release && cmake --build --preset release &&
//   ctest --test-dir build/release -L exhaustive
// (the release test preset excludes the label, like bench).
#include <gtest/gtest.h>

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "bccmis/explore/explore.h"
#include "bccmis/io/format.h"
#include "bccmis/ops.h"
#include "model/leaf_model.h"

namespace bccmis {
namespace {

struct Expected {
  int W, H, L;
  std::int64_t states;
  std::int64_t refine_edges;
};

void PrintTo(const Expected& e, std::ostream* os) {
  *os << "lattice " << e.W << " " << e.H << " " << e.L << ": " << e.states << " states, " << e.refine_edges
      << " refine edges";
}

std::string name_of(const testing::TestParamInfo<Expected>& info) {
  std::string name = "W";
  name += std::to_string(info.param.W);
  name += "_H";
  name += std::to_string(info.param.H);
  name += "_L";
  name += std::to_string(info.param.L);
  return name;
}

void expect_explored_counts(const Expected& e) {
  const LatticeSize size{e.W, e.H, e.L};
  const ExploreResult r = explore(size);
  ASSERT_FALSE(r.first_failure.has_value()) << r.first_failure->message << "\nreproducer trace:\n"
                                            << r.first_failure->trace;
  EXPECT_TRUE(r.complete);
  EXPECT_TRUE(r.ok()) << summary(r);
  EXPECT_EQ(r.states, e.states) << summary(r);
  EXPECT_EQ(r.refine_edges, e.refine_edges) << summary(r);
  EXPECT_EQ(r.coarsen_edges, r.refine_edges) << "each refine edge s -> t is undone by one coarsen edge t -> s";
  // Every op on every vertex: 2 calls per vertex per state.
  EXPECT_GE(r.ops_tried, 2 * r.states * 4);
  // The independent counts, computed here from the model.
  EXPECT_EQ(r.states, model::count_balanced_leaf_sets(e.W, e.H, e.L));
  if (e.states <= 5000) {
    const model::ReachableCount m = model::count_reachable_states(e.W, e.H, e.L);
    EXPECT_EQ(r.states, m.states);
    EXPECT_EQ(r.refine_edges, m.refine_edges);
    EXPECT_EQ(r.coarsen_edges, m.coarsen_edges);
  }
}

class ExhaustiveSmall : public testing::TestWithParam<Expected> {};

TEST_P(ExhaustiveSmall, EveryReachableStateIsValidAndCountsMatchTheModel) { expect_explored_counts(GetParam()); }

// States and refine edges: tests/model/leaf_model_test.cpp (by hand and by two
// model methods), plus transposes and a 4 x 1 strip (2^4 states, 4 * 2^3 refines).
INSTANTIATE_TEST_SUITE_P(Lattices, ExhaustiveSmall,
                         testing::Values(Expected{1, 1, 0, 1, 0}, Expected{1, 1, 1, 2, 1}, Expected{2, 1, 1, 4, 4},
                                         Expected{3, 1, 1, 8, 12}, Expected{4, 1, 1, 16, 32}, Expected{2, 2, 1, 16, 32},
                                         Expected{3, 2, 1, 64, 192}, Expected{3, 3, 1, 512, 2304},
                                         Expected{1, 1, 2, 17, 33}, Expected{2, 1, 2, 265, 1042},
                                         Expected{1, 2, 2, 265, 1042}),
                         name_of);

class ExhaustiveLarge : public testing::TestWithParam<Expected> {};

TEST_P(ExhaustiveLarge, EveryReachableStateIsValidAndCountsMatchTheModel) {
  expect_explored_counts(GetParam());
  const Expected& e = GetParam();
  const model::ReachableCount m = model::count_reachable_states(e.W, e.H, e.L);
  EXPECT_EQ(m.states, e.states);
  EXPECT_EQ(m.refine_edges, e.refine_edges);
}

INSTANTIATE_TEST_SUITE_P(Lattices, ExhaustiveLarge,
                         testing::Values(Expected{3, 1, 2, 4250, 25165}, Expected{2, 2, 2, 66641, 529720},
                                         Expected{1, 1, 3, 66642, 529721}),
                         name_of);

// ---- The explorer itself ----------------------------------------------------

TEST(ExploreKey, RoundTripsValidAndBrokenGraphs) {
  Graph g = make_lattice(LatticeSize{2, 1, 2});
  ASSERT_TRUE(refine(g, Point{4, 4}).applied());
  ASSERT_TRUE(refine(g, Point{2, 2}).applied());
  EXPECT_EQ(decode_state_key(encode_state_key(g), g.size), g);
  EXPECT_EQ(encode_state_key(g)[0], '\0');  // the compact encoding

  // Broken graphs take the generic encoding and still round-trip exactly.
  Graph outside = g;
  outside.N.insert(Point{-3, 100});
  Graph no_level = g;
  no_level.level.erase(Point{12, 4});
  Graph stale = g;
  stale.neighbors[Point{5, 5}];  // an empty entry for a vertex that is neither
  Graph both = g;
  both.C.insert(Point{0, 0});
  for (const Graph* h : {&outside, &no_level, &stale, &both}) {
    const std::string key = encode_state_key(*h);
    EXPECT_EQ(key[0], '\1');
    EXPECT_EQ(decode_state_key(key, h->size), *h);
    EXPECT_NE(key, encode_state_key(g));
  }
}

TEST(ExploreKey, DistinguishesEveryState) {
  // Keys are equal iff graphs are: compare against canonical_state on 3 1 2.
  Graph g = make_lattice(LatticeSize{3, 1, 2});
  Graph h = g;
  ASSERT_TRUE(refine(h, Point{12, 4}).applied());
  EXPECT_NE(encode_state_key(g), encode_state_key(h));
  Graph k = h;
  k.neighbors[Point{8, 4}].erase(Point{10, 2});  // one neighbor less
  EXPECT_NE(encode_state_key(h), encode_state_key(k));
  EXPECT_NE(canonical_state(h), canonical_state(k));
}

TEST(Explore, ReportsProgressAndSummary) {
  std::int64_t calls = 0, last_states = 0, last_queued = -1;
  ExploreOptions options;
  options.try_every_op = false;  // counting mode: the progress reports are what is tested here
  options.check_depth = 0;
  options.progress_every = 100;
  options.progress = [&](const ExploreProgress& p) {
    ++calls;
    EXPECT_GE(p.states, last_states);
    last_states = p.states;
    last_queued = p.queued;
  };
  const ExploreResult r = explore(LatticeSize{2, 1, 2}, options);
  EXPECT_TRUE(r.ok());
  EXPECT_GE(calls, 2);  // during the run (batches of states) and once at the end
  EXPECT_EQ(last_states, 265);
  EXPECT_EQ(last_queued, 0);
  const ExploreResult small = explore(LatticeSize{1, 1, 2});
  const std::string line = summary(small);
  EXPECT_NE(line.find("explore 1 1 2: 17 states, 33 refine edges, 33 coarsen edges"), std::string::npos) << line;
  EXPECT_NE(line.find(", ok ("), std::string::npos) << line;
  const std::string json = to_json(small);
  EXPECT_NE(json.find("\"states\": 17"), std::string::npos) << json;
  EXPECT_NE(json.find("\"failure\": null"), std::string::npos) << json;
}

TEST(Explore, ResultDoesNotDependOnTheNumberOfThreads) {
  ExploreOptions one, two;
  one.threads = 1;
  two.threads = 2;
  one.check_depth = two.check_depth = 0;  // the states are checked elsewhere; 265 states = 2 batches
  const ExploreResult a = explore(LatticeSize{2, 1, 2}, one);
  const ExploreResult b = explore(LatticeSize{2, 1, 2}, two);
  EXPECT_EQ(a.states, b.states);
  EXPECT_EQ(a.refine_edges, b.refine_edges);
  EXPECT_EQ(a.ops_tried, b.ops_tried);
  EXPECT_EQ(a.key_bytes, b.key_bytes);
  // The same first failure, with the same reproducer, on a broken operation.
  for (ExploreOptions* o : {&one, &two})
    o->coarsen = [](Graph& g, const Point& n) {
      CoarsenResult r = coarsen(g, n);
      if (r.applied() && n.x > 8) g.level[n] = 0;  // the right cell keeps a wrong level
      return r;
    };
  const ExploreResult fa = explore(LatticeSize{2, 1, 2}, one);
  const ExploreResult fb = explore(LatticeSize{2, 1, 2}, two);
  ASSERT_TRUE(fa.first_failure.has_value());
  ASSERT_TRUE(fb.first_failure.has_value());
  EXPECT_EQ(fa.first_failure->message, fb.first_failure->message);
  EXPECT_EQ(fa.first_failure->trace, fb.first_failure->trace);
}

TEST(Explore, StopsAtMaxStatesAsIncomplete) {
  ExploreOptions options;
  options.max_states = 10;
  const ExploreResult r = explore(LatticeSize{2, 1, 2}, options);
  EXPECT_EQ(r.states, 10);
  EXPECT_FALSE(r.complete);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(summary(r).find("incomplete"), std::string::npos);
}

TEST(Explore, CountingModeGivesTheSameCounts) {
  ExploreOptions options;
  options.try_every_op = false;
  options.check_depth = 0;
  const ExploreResult r = explore(LatticeSize{2, 1, 2}, options);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.states, 265);
  EXPECT_EQ(r.refine_edges, 1042);
  EXPECT_EQ(r.coarsen_edges, 1042);
}

// The explorer's checks can fail: an operation that forgets to undo, one that
// changes a refused state, one that throws. Each is reported with a trace that
// reproduces it from the initial lattice.
TEST(Explore, ReportsABrokenInverseWithAReproducer) {
  ExploreOptions options;
  options.coarsen = [](Graph& g, const Point& n) {
    CoarsenResult r = coarsen(g, n);
    if (r.applied()) g.neighbors[n].insert(Point{9, 9});  // leaves a stray edge
    return r;
  };
  const ExploreResult r = explore(LatticeSize{1, 1, 1}, options);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.first_failure->message, "refine (2, 2) then coarsen (2, 2) does not restore the state");
  EXPECT_EQ(r.first_failure->trace, "lattice 1 1 1\nrefine 2 2\ncoarsen 2 2\n");
  EXPECT_NE(to_json(r).find("\"trace\": \"lattice 1 1 1\\nrefine 2 2\\ncoarsen 2 2\\n\""), std::string::npos);
}

// Options whose refine is the real one followed by corrupt(g, c, result).
ExploreOptions refine_then(void (*corrupt)(Graph&, const Point&, const RefineResult&)) {
  ExploreOptions options;
  options.refine = [corrupt](Graph& g, const Point& c) {
    RefineResult r = refine(g, c);
    corrupt(g, c, r);
    return r;
  };
  return options;
}

// The first failure explore() reports on `size` with `options`.
void expect_first_failure(const LatticeSize& size, const ExploreOptions& options, const std::string& message,
                          const std::string& trace) {
  const ExploreResult r = explore(size, options);
  ASSERT_TRUE(r.first_failure.has_value());
  EXPECT_EQ(r.first_failure->message, message);
  EXPECT_EQ(r.first_failure->trace, trace);
}

TEST(Explore, ReportsARefusalThatChangesTheState) {
  expect_first_failure(LatticeSize{1, 1, 1}, refine_then([](Graph& g, const Point& c, const RefineResult& r) {
                         if (!r.applied() && g.is_node(c) && c == Point{0, 0})
                           g.neighbors[Point{0, 0}].insert(Point{9, 9});
                       }),
                       "refine (0, 0) was refused (no-such-cell) but changed the state", "lattice 1 1 1\nrefine 0 0\n");
}

TEST(Explore, ReportsARefusalThatChangesTheStateWithNothingAfterIt) {
  // 1 1 0 has no legal operation: the change is found by the comparison at
  // the end of the state and blamed on the call that made it.
  expect_first_failure(LatticeSize{1, 1, 0}, refine_then([](Graph& g, const Point& c, const RefineResult& r) {
                         if (r.refused == RefineRefusal::MaxLevel) g.level[c] = 1;
                       }),
                       "refine (1, 1) was refused (max-level) but changed the state", "lattice 1 1 0\nrefine 1 1\n");
}

TEST(Explore, ReportsAnInvalidStateAndAThrowingOperation) {
  ExploreOptions broken = refine_then([](Graph& g, const Point&, const RefineResult& r) {
    if (r.applied()) g.neighbors[Point{0, 0}].clear();  // a corner loses its cell
  });
  broken.check_depth = 4;
  const ExploreResult r = explore(LatticeSize{1, 1, 1}, broken);
  ASSERT_TRUE(r.first_failure.has_value());
  // coarsen (12b) happens to repair the corner, so the inverse holds; the
  // refined state itself is reported when it is visited.
  EXPECT_EQ(r.first_failure->message.rfind("invalid state: symmetry:", 0), 0u) << r.first_failure->message;
  EXPECT_EQ(r.first_failure->trace, "lattice 1 1 1\nrefine 2 2\n");

  ExploreOptions throwing;
  throwing.coarsen = [](Graph&, const Point& n) -> CoarsenResult {
    if (n == Point{2, 2}) throw std::runtime_error("boom");
    return CoarsenResult{CoarsenRefusal::NoSuchNode, {}, {}};
  };
  const ExploreResult t = explore(LatticeSize{1, 1, 1}, throwing);
  ASSERT_TRUE(t.first_failure.has_value());
  EXPECT_EQ(t.first_failure->message, "coarsen (2, 2) right after refine (2, 2) threw: boom");
}

}  // namespace
}  // namespace bccmis
