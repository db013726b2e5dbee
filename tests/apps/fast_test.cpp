// The applications on the fast implementation (src/bccmis/apps/detail/generic.h):
// refine_balanced and tessellate on bccmis::fast::Lattice make the reference's
// decisions. The reference instantiation is checked on its own by
// balance_test.cpp (against a geometric closure) and
// heightfield_test.cpp (fields with known answers); here the fast one is
// compared with it call by call: the same cells refined in the same order,
// the same sweeps, the same final state.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/image.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"

namespace bccmis {
namespace {

constexpr std::uint32_t kSeed = 20090303;

std::string state_of(const fast::Lattice& f) { return canonical_state(f.to_graph()); }

void expect_consistent(const fast::Lattice& f) {
  const std::optional<std::string> problem = f.audit();
  EXPECT_FALSE(problem) << *problem;
}

TEST(AppsFast, RefineBalancedMakesTheReferenceCascade) {
  std::mt19937 rng(kSeed);
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  const std::vector<LatticeSize> sizes{{1, 1, 3}, {3, 2, 4}, {2, 2, 5}, {4, 3, 4}};
  int cascades = 0;
  for (const Balance mode : {Balance::Edge, Balance::Corner})
    for (const LatticeSize& size : sizes) {
      Graph g = make_lattice(size);
      fast::Lattice f(size);
      for (int k = 0; k < 60; ++k) {
        // Any position of the domain's grid: mostly cells, some refused.
        const std::vector<Point> cells(g.C.begin(), g.C.end());
        Point c = cells[rng() % cells.size()];
        if (rng() % 10 == 0) c.x += 1;
        SCOPED_TRACE("request " + std::to_string(k) + " at (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                     "), mode " + std::string(name(mode)));
        const BalancedRefineResult r = refine_balanced(g, c, mode);
        const BalancedRefineResult q = refine_balanced(f, c, mode);
        ASSERT_EQ(q.refused, r.refused);
        ASSERT_EQ(q.refined, r.refined);
        if (r.refined.size() > 1) ++cascades;
        ASSERT_EQ(state_of(f), canonical_state(g));
      }
      expect_consistent(f);
      ASSERT_TRUE(is_valid(g));
      if (mode == Balance::Corner) {
        EXPECT_FALSE(find_corner_imbalance(g));
      }
    }
  EXPECT_GT(cascades, 20) << "the requests should exercise the cascade";
}

struct Sweep {
  int sweep;
  std::size_t operations, cells;
  bool operator==(const Sweep&) const = default;
};

struct Outcome {
  TessellateReport report;
  std::vector<Sweep> sweeps;
  std::string state;
};

Outcome reference_run(Graph& g, const HeightSampler& s, const TessellateSettings& t) {
  Outcome r;
  r.report = tessellate(g, s, t, [&](int sweep, const Graph& now, std::size_t ops) {
    r.sweeps.push_back({sweep, ops, now.C.size()});
  });
  r.state = canonical_state(g);
  return r;
}

Outcome fast_run(fast::Lattice& f, const HeightSampler& s, const TessellateSettings& t) {
  Outcome r;
  r.report = tessellate(f, s, t, [&](int sweep, const fast::Lattice& now, std::size_t ops) {
    r.sweeps.push_back({sweep, ops, now.cell_count()});
  });
  r.state = state_of(f);
  return r;
}

void expect_same_run(const Outcome& fast_result, const Outcome& ref) {
  EXPECT_EQ(fast_result.report.refinements, ref.report.refinements);
  EXPECT_EQ(fast_result.report.coarsenings, ref.report.coarsenings);
  EXPECT_EQ(fast_result.report.sweeps, ref.report.sweeps);
  EXPECT_EQ(fast_result.report.converged, ref.report.converged);
  EXPECT_EQ(fast_result.sweeps, ref.sweeps);
  EXPECT_EQ(fast_result.state, ref.state);
}

TEST(AppsFast, TessellateEqualsTheReference) {
  const std::vector<std::string> images{BCCMIS_APPS_SAMPLES "/terrain128.pgm", BCCMIS_APPS_SAMPLES "/crater64.pgm"};
  int runs = 0;
  for (const std::string& image : images) {
    const HeightField field = read_height_field(image);
    for (const Balance mode : {Balance::Edge, Balance::Corner})
      for (const ErrorMeasure measure : {ErrorMeasure::MaxPixel, ErrorMeasure::RandomSamples}) {
        SCOPED_TRACE(image + ", " + std::string(name(mode)) + ", " + std::string(name(measure)));
        const LatticeSize size{5, 4, 5};
        const HeightSampler s(field, size, 1.0);
        TessellateSettings t;
        t.tolerance = 0.02;
        t.error = {measure, 8, 7};
        t.balance = mode;
        Graph g = make_lattice(size);
        fast::Lattice f(size);
        const Outcome ref = reference_run(g, s, t);
        const Outcome fast_result = fast_run(f, s, t);
        ASSERT_GT(ref.report.refinements, 50u) << "the field should need refinement";
        expect_same_run(fast_result, ref);
        expect_consistent(f);

        // Incremental re-tessellation: coarsen at a looser tolerance, then refine.
        t.tolerance = 0.06;
        t.coarsen = true;
        const Outcome ref2 = reference_run(g, s, t);
        const Outcome fast2 = fast_run(f, s, t);
        ASSERT_GT(ref2.report.coarsenings, 10u) << "a looser tolerance should merge cells";
        expect_same_run(fast2, ref2);
        expect_consistent(f);
        ++runs;
      }
  }
  EXPECT_EQ(runs, 8);
}

TEST(AppsFast, TessellateFromAStateEqualsTheReference) {
  // A start that did not come from the initial lattice: refined at random,
  // then handed to both implementations as a state.
  std::mt19937 rng(kSeed + 1);
  SCOPED_TRACE("seed " + std::to_string(kSeed + 1));
  const LatticeSize size{4, 4, 5};
  Graph g = make_lattice(size);
  for (int k = 0; k < 40; ++k) {
    const std::vector<Point> cells(g.C.begin(), g.C.end());
    refine_balanced(g, cells[rng() % cells.size()]);
  }
  fast::Lattice f = fast::Lattice::from_graph(g);
  const HeightField field = read_height_field(BCCMIS_APPS_SAMPLES "/crater64.pgm");
  const HeightSampler s(field, size, 1.0);
  TessellateSettings t;
  t.tolerance = 0.04;
  t.coarsen = true;
  const Outcome ref = reference_run(g, s, t);
  const Outcome fast_result = fast_run(f, s, t);
  ASSERT_GT(ref.report.coarsenings, 0u);
  expect_same_run(fast_result, ref);
  expect_consistent(f);
}

}  // namespace
}  // namespace bccmis
