// The height-field case of Erleben 2009 §3 (Fig. 4-5) on both
// implementations (issue 9): a 256x256 image, a 6x6 initial lattice, the
// paper's random-sample error measure. The paper reports 1-5 s.
//
//   Heightfield/<impl>/measure:M   one whole tessellation (tessellate() of
//     src/bccmis/apps/heightfield.h) from the initial lattice, M = 0 the paper's
//     measure (16 random samples per cell), M = 1 the exact max over every
//     pixel. Both implementations run the same application code
//     (src/bccmis/apps/detail/generic.h) and make the same decisions, so the
//     difference is the lattice: graph queries (neighbors, levels, the
//     cascade's checks) and the operations.
//   HeightfieldOps/<impl>           only the lattice work of that result:
//     the refinements that reach its final leaf set, coarsest level first,
//     without measuring errors.
//
// Time is CPU time of the thread (manual time), so other processes on the
// shared machine do not count; counters give cells, nodes, operations and
// sweeps of one run.
//
// Flags (before Google Benchmark's own):
//   --bccmis_smoke          a 64x64 image and L = 4 (ctest bench-smoke)
//   --bccmis_verify         first tessellate with both implementations and
//                           compare the canonical states; exit 1 on a difference
//   --bccmis_image=PATH     another image (default apps/samples/terrain256.pgm)
#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <iostream>
#include <string>
#include <vector>

#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/image.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/geometry.h"
#include "bccmis/io/format.h"
#include "bench_main.h"

namespace bccmis::bench {
namespace {

bool g_smoke = false;
std::string g_image = BCCMIS_APPS_SAMPLES "/terrain256.pgm";

double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The paper's settings: 6x6 level-0 cells, tolerance 0.02 of the height
// range, L = 6 (spec/apps.md, "Timing").
LatticeSize paper_size() { return g_smoke ? LatticeSize{6, 6, 4} : LatticeSize{6, 6, 6}; }

TessellateSettings settings(int measure) {
  TessellateSettings t;
  t.tolerance = 0.02;
  t.error = {measure == 0 ? ErrorMeasure::RandomSamples : ErrorMeasure::MaxPixel, 16, 1};
  return t;
}

const HeightField& field() {
  static const HeightField f = read_height_field(g_smoke ? BCCMIS_APPS_SAMPLES "/crater64.pgm" : g_image);
  return f;
}

template <AdaptiveLattice L>
void BM_Heightfield(benchmark::State& st) {
  const HeightSampler s(field(), paper_size(), 1.0);
  const TessellateSettings t = settings(static_cast<int>(st.range(0)));
  TessellateReport last;
  std::size_t cells = 0, nodes = 0;
  for (auto _ : st) {
    L g(paper_size());
    const double t0 = thread_seconds();
    last = tessellate(g, s, t);
    st.SetIterationTime(thread_seconds() - t0);
    cells = cell_count(g);
    nodes = node_count(g);
    benchmark::DoNotOptimize(cells);
  }
  st.counters["cells"] = static_cast<double>(cells);
  st.counters["nodes"] = static_cast<double>(nodes);
  st.counters["ops"] = static_cast<double>(last.refinements + last.coarsenings);
  st.counters["sweeps"] = static_cast<double>(last.sweeps);
}

// The refinements reaching the leaf set of g: every refined center (a cell
// of some state on the way), coarsest level first, sorted within a level.
std::vector<Point> refinements_of(const Graph& g) {
  std::vector<std::vector<Point>> by_level(static_cast<std::size_t>(g.size.L) + 1);
  for (const Point& n : g.N)
    if (const std::optional<int> l = refined_center_level(g.size, n))
      by_level[static_cast<std::size_t>(*l)].push_back(n);
  std::vector<Point> order;
  for (const auto& level : by_level) order.insert(order.end(), level.begin(), level.end());
  return order;
}

template <AdaptiveLattice L>
void BM_HeightfieldOps(benchmark::State& st) {
  const HeightSampler s(field(), paper_size(), 1.0);
  Graph result = make_lattice(paper_size());
  tessellate(result, s, settings(0));
  const std::vector<Point> order = refinements_of(result);
  for (auto _ : st) {
    L g(paper_size());
    const double t0 = thread_seconds();
    std::size_t applied = 0;
    for (const Point& c : order) applied += refine(g, c).applied() ? 1 : 0;
    st.SetIterationTime(thread_seconds() - t0);
    if (applied != order.size()) {
      st.SkipWithError("a refinement of the recorded sequence was refused");
      break;
    }
  }
  st.counters["ops"] = static_cast<double>(order.size());
  st.counters["ns_per_op"] = benchmark::Counter(
      static_cast<double>(order.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

int verify() {
  const HeightSampler s(field(), paper_size(), 1.0);
  for (int measure : {0, 1}) {
    Graph g(paper_size());
    fast::Lattice f(paper_size());
    const TessellateReport a = tessellate(g, s, settings(measure));
    const TessellateReport b = tessellate(f, s, settings(measure));
    const std::string sa = canonical_state(g), sb = canonical_state(f.to_graph());
    if (sa != sb || a.refinements != b.refinements || a.sweeps != b.sweeps) {
      std::cerr << "bench_heightfield: the implementations differ (measure " << measure << ")\n";
      return 1;
    }
    // The replayed sequence reaches the same leaves.
    Graph replayed = make_lattice(paper_size());
    for (const Point& c : refinements_of(g)) refine(replayed, c);
    if (canonical_state(replayed) != sa) {
      std::cerr << "bench_heightfield: the recorded refinements do not reach the tessellation\n";
      return 1;
    }
    std::cerr << "bench_heightfield: verified measure " << measure << ": " << g.C.size() << " cells, " << a.refinements
              << " refinements, " << a.sweeps << " sweeps, equal states\n";
  }
  return 0;
}

template <AdaptiveLattice L>
void register_impl(const std::string& impl) {
  benchmark::RegisterBenchmark(("Heightfield/" + impl).c_str(), BM_Heightfield<L>)
      ->ArgName("measure")
      ->Arg(0)
      ->Arg(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark(("HeightfieldOps/" + impl).c_str(), BM_HeightfieldOps<L>)
      ->UseManualTime()
      ->Unit(benchmark::kMicrosecond);
}

void register_all() {
  register_impl<Graph>("reference");
  register_impl<fast::Lattice>("fast");
}

}  // namespace
}  // namespace bccmis::bench

int main(int argc, char** argv) {
  using namespace bccmis::bench;
  bool do_verify = false;
  take_flags(argc, argv, [&](std::string_view a) {
    if (a == "--bccmis_smoke") return g_smoke = true;
    if (a == "--bccmis_verify") return do_verify = true;
    if (a.starts_with("--bccmis_image=")) {
      g_image = a.substr(15);
      return true;
    }
    return false;
  });
  try {
    if (do_verify && verify() != 0) return 1;
  } catch (const std::exception& e) {
    std::cerr << "bench_heightfield: " << e.what() << "\n";
    return 2;
  }
  register_all();
  return run_benchmarks(argc, argv);
}
