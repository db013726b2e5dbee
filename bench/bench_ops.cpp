// Time benchmarks of the reference core and bccmis::fast::Lattice (issue 9).
//
// Every benchmark replays the same operation sequence through both
// implementations, so the ratios in bench/RESULTS.md compare like with like.
//
//   Refine/<impl>/cells:N/order:O   ns per refine on a lattice of about N
//   Coarsen/<impl>/cells:N/order:O  cells (a W x W lattice of level-0 cells).
//     Why: the paper's O(1) claim. The curve over N must be flat.
//     order:0 (sweep) refines level-0 cells row by row: the memory touched
//     moves along the arrays, so cache misses stay rare at every size and
//     the curve shows the operation itself. order:1 (random) picks the cells
//     in a random permutation: every operation misses the caches once the
//     lattice outgrows them, so the curve shows the memory hierarchy too.
//     An iteration is a batch of B = min(N/4, 4096) operations timed with
//     the thread's CPU clock (manual time); the inverse batch runs untimed,
//     so the lattice stays at N..1.75N cells.
//   RefineEach/fast, CoarsenEach/fast  the same batches through
//     Lattice::refine_each / coarsen_each, which prefetch the position table
//     and records of the operations ahead (same decisions as single calls).
//   Mix/<impl>/cells:N              a random balanced refine/coarsen mix
//     (make_mix: only applied operations, near N cells). Why: what an
//     adaptive simulation does; junctions of every kind, all levels.
//   Uniform6x6/<impl>/level:k       refine every cell of a 6x6 lattice, level
//     by level, to level k (36 * 4^k cells). Why: the paper's initial
//     lattice; a sequence where every refine creates and reuses junctions.
//   LoadLatency/bytes:B             ns per dependent load in a B-byte buffer
//     (pointer chase): what one cache miss costs on this machine.
//   MovingFeature/<impl>            a disk circling a 16x16 lattice (L = 6);
//     per frame, cells meeting it are refined to level L and cells it left
//     are coarsened. Why: the cloth/contact use of §3 (Fig. 6); reports ops
//     and time per frame.
//
// Flags (before Google Benchmark's own):
//   --bccmis_smoke    tiny sizes only (ctest bench-smoke)
//   --bccmis_verify   first replay the mix, the uniform refinement and the
//                     moving feature through both implementations and compare
//                     canonical states; exit 1 on a difference
//   --bccmis_max_cells=N  skip per-operation sizes above N (default 10^7)
//   --bccmis_instructions=IMPL,CELLS,ORDER  run no benchmark: one untimed
//                     round, then 4 batches of 4096 refines and coarsens
//                     (IMPL reference|fast, ORDER 0 sweep|1 random), for
//                     valgrind --tool=callgrind --toggle-collect=... to count
//                     the instructions per operation (bench/RESULTS.md)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "bench_main.h"
#include "workloads.h"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define BCCMIS_BENCH_HAVE_CALLGRIND 1
#else
#define BCCMIS_BENCH_HAVE_CALLGRIND 0
#endif

namespace bccmis::bench {
namespace {

bool g_smoke = false;
std::int64_t g_max_cells = 10'000'000;

// The batches are timed with this thread's CPU time, not wall time: on a
// shared 2-core machine a descheduled thread would otherwise be charged for
// the other processes' time slices. (Cache pollution by them still counts.)
struct Clock {
  using time_point = double;
  static double now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
};

double seconds_since(Clock::time_point t0) { return Clock::now() - t0; }

// ---- Cached lattices (building a 10^7-cell lattice once is enough) --------------------------

template <AdaptiveLattice L>
L& cached_lattice(const LatticeSize& size) {
  static std::unique_ptr<L> state;
  static LatticeSize have{0, 0, 0};
  if (!state || !(have == size)) {
    state.reset();
    state = std::make_unique<L>(size);
    have = size;
  }
  return *state;
}

/// Level-0 centers of the lattice in sweep (row) or random order; only the
/// current lattice's lists are kept.
const std::vector<Point>& cell_order(const LatticeSize& size, bool random) {
  static std::int64_t have_w = -1;
  static std::vector<Point> orders[2];
  if (have_w != size.W) {
    orders[0] = grid_centers(size, 0);
    orders[1] = orders[0];
    std::shuffle(orders[1].begin(), orders[1].end(), std::mt19937_64(42));
    have_w = size.W;
  }
  return orders[random ? 1 : 0];
}

// ---- Refine / Coarsen: ns per operation against lattice size ---------------------------------

template <AdaptiveLattice L>
void run_ops(benchmark::State& st, bool time_refine) {
  const LatticeSize size = square_lattice(st.range(0), 4);
  const bool random = st.range(1) != 0;
  auto& g = cached_lattice<L>(size);
  const std::vector<Point>& cells = cell_order(size, random);
  const std::size_t batch = std::max<std::size_t>(1, std::min<std::size_t>(cells.size() / 4, 4096));
  // One untimed round first: the pools and the table reach the size a batch
  // needs (the growth is a one-time cost, not a per-operation one).
  for (std::size_t i = 0; i < batch; ++i) refine(g, cells[i]);
  for (std::size_t i = 0; i < batch; ++i) coarsen(g, cells[i]);
  std::size_t cursor = 0;
  double timed = 0;
  std::size_t ops = 0;
  for (auto _ : st) {
    const std::size_t begin = cursor;
    cursor = (cursor + batch) % (cells.size() - batch + 1);
    double t = 0;
    std::size_t applied = 0;
    const auto t0 = Clock::now();
    for (std::size_t i = begin; i < begin + batch; ++i) applied += refine(g, cells[i]).applied();
    if (time_refine) t = seconds_since(t0);
    const auto t1 = Clock::now();
    for (std::size_t i = begin; i < begin + batch; ++i) applied += coarsen(g, cells[i]).applied();
    if (!time_refine) t = seconds_since(t1);
    if (applied != 2 * batch) st.SkipWithError("an operation of the batch was refused");
    st.SetIterationTime(t);
    timed += t;
    ops += batch;
  }
  st.counters["cells"] = static_cast<double>(cell_count(g));
  st.counters["batch"] = static_cast<double>(batch);
  st.counters["ns_per_op"] = ops ? timed * 1e9 / static_cast<double>(ops) : 0;
}

template <AdaptiveLattice L>
void BM_Refine(benchmark::State& st) {
  run_ops<L>(st, true);
}
template <AdaptiveLattice L>
void BM_Coarsen(benchmark::State& st) {
  run_ops<L>(st, false);
}

// The same batches through Lattice::refine_each / coarsen_each (look-ahead
// prefetching; same decisions as the single calls).
void run_each(benchmark::State& st, bool time_refine) {
  const LatticeSize size = square_lattice(st.range(0), 4);
  auto& g = cached_lattice<fast::Lattice>(size);
  const std::vector<Point>& cells = cell_order(size, st.range(1) != 0);
  const std::size_t batch = std::max<std::size_t>(1, std::min<std::size_t>(cells.size() / 4, 4096));
  const std::span<const Point> all(cells);
  g.refine_each(all.subspan(0, batch));
  g.coarsen_each(all.subspan(0, batch));
  std::size_t cursor = 0;
  double timed = 0;
  std::size_t ops = 0;
  for (auto _ : st) {
    const auto part = all.subspan(cursor, batch);
    cursor = (cursor + batch) % (cells.size() - batch + 1);
    double t = 0;
    const auto t0 = Clock::now();
    std::size_t applied = g.refine_each(part);
    if (time_refine) t = seconds_since(t0);
    const auto t1 = Clock::now();
    applied += g.coarsen_each(part);
    if (!time_refine) t = seconds_since(t1);
    if (applied != 2 * batch) st.SkipWithError("an operation of the batch was refused");
    st.SetIterationTime(t);
    timed += t;
    ops += batch;
  }
  st.counters["cells"] = static_cast<double>(g.cell_count());
  st.counters["ns_per_op"] = ops ? timed * 1e9 / static_cast<double>(ops) : 0;
}
void BM_RefineEach(benchmark::State& st) { run_each(st, true); }
void BM_CoarsenEach(benchmark::State& st) { run_each(st, false); }

// ---- Random balanced mix ---------------------------------------------------------------------------

const Mix& cached_mix(std::int64_t cells) {
  static std::map<std::int64_t, std::unique_ptr<Mix>> cache;
  auto& m = cache[cells];
  if (!m) m = std::make_unique<Mix>(make_mix(cells, g_smoke ? 512 : 65536, 7));
  return *m;
}

template <AdaptiveLattice L>
L start_state(const Mix& mix);
template <>
Graph start_state<Graph>(const Mix& mix) {
  return mix.start.to_graph();
}
template <>
fast::Lattice start_state<fast::Lattice>(const Mix& mix) {
  return mix.start;
}

template <AdaptiveLattice L>
void BM_Mix(benchmark::State& st) {
  const Mix& mix = cached_mix(st.range(0));
  const L start = start_state<L>(mix);
  auto g = std::make_unique<L>(start);
  const std::size_t block = std::min<std::size_t>(4096, mix.ops.size());
  std::size_t cursor = 0;
  double timed = 0;
  std::size_t ops = 0;
  for (auto _ : st) {
    if (cursor + block > mix.ops.size()) {  // back to the start (untimed)
      *g = start;
      cursor = 0;
    }
    std::size_t applied = 0;
    const auto t0 = Clock::now();
    for (std::size_t i = cursor; i < cursor + block; ++i) {
      const Op& op = mix.ops[i];
      applied += op.refine ? refine(*g, op.at).applied() : coarsen(*g, op.at).applied();
    }
    const double t = seconds_since(t0);
    if (applied != block) st.SkipWithError("the mix diverged: an operation was refused");
    st.SetIterationTime(t);
    cursor += block;
    timed += t;
    ops += block;
  }
  st.counters["cells"] = static_cast<double>(cell_count(*g));
  st.counters["ns_per_op"] = ops ? timed * 1e9 / static_cast<double>(ops) : 0;
  st.SetItemsProcessed(static_cast<std::int64_t>(ops));
}

// ---- Uniform refinement of a 6x6 lattice ----------------------------------------------------------

template <AdaptiveLattice L>
std::size_t refine_uniformly(L& g, const LatticeSize& size) {
  std::size_t n = 0;
  for (int l = 0; l < size.L; ++l)
    for (const Point& c : grid_centers(size, l)) n += refine(g, c).applied();
  return n;
}

template <AdaptiveLattice L>
void BM_Uniform6x6(benchmark::State& st) {
  const LatticeSize size{6, 6, static_cast<int>(st.range(0))};
  // The positions are computed outside the timing, level by level.
  std::vector<std::vector<Point>> levels;
  for (int l = 0; l < size.L; ++l) levels.push_back(grid_centers(size, l));
  std::size_t refines = 0;
  for (auto _ : st) {
    L g(size);
    std::size_t n = 0;
    for (const auto& level : levels)
      for (const Point& c : level) n += refine(g, c).applied();
    refines += n;
    benchmark::DoNotOptimize(g);
    st.PauseTiming();
    { [[maybe_unused]] L drop = std::move(g); }  // destruction untimed
    st.ResumeTiming();
  }
  st.counters["cells"] = static_cast<double>(36) * static_cast<double>(std::int64_t{1} << (2 * size.L));
  st.counters["refines"] = benchmark::Counter(static_cast<double>(refines), benchmark::Counter::kAvgIterations);
  st.counters["ns_per_refine"] =
      benchmark::Counter(static_cast<double>(refines), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// ---- Moving feature -------------------------------------------------------------------------------

template <AdaptiveLattice L>
void BM_MovingFeature(benchmark::State& st) {
  const LatticeSize size = g_smoke ? LatticeSize{4, 4, 4} : LatticeSize{16, 16, 6};
  MovingFeature<L> anim(size, 0.5 * static_cast<double>(level0_side(size)), 256);
  std::size_t ops = 0;
  for (auto _ : st) ops += anim.frame();
  st.counters["ops_per_frame"] = benchmark::Counter(static_cast<double>(ops), benchmark::Counter::kAvgIterations);
  st.counters["cells"] = static_cast<double>(cell_count(anim.state()));
}

// ---- The machine: latency of a dependent load ---------------------------------------------------

// A random cyclic permutation of 64-byte lines (huge pages advised, like the
// lattice's arrays): ns per load when each load's address depends on the
// previous one. What one cache miss costs at each working-set size bounds
// the per-operation time of any structure that misses once per operation.
void BM_LoadLatency(benchmark::State& st) {
  const auto bytes = static_cast<std::size_t>(st.range(0));
  const std::size_t lines = bytes / 64;
  fast::detail::Array<std::uint64_t> next(lines * 8);
  std::vector<std::uint64_t> order(lines);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(3));
  for (std::size_t i = 0; i < lines; ++i) next[order[i] * 8] = order[(i + 1) % lines] * 8;
  std::uint64_t at = 0;
  for (auto _ : st) {
    for (int k = 0; k < 1024; ++k) at = next[at];
    benchmark::DoNotOptimize(at);
  }
  st.counters["ns_per_load"] = benchmark::Counter(1024.0 * static_cast<double>(st.iterations()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// ---- Registration -------------------------------------------------------------------------------

void register_all() {
  const std::vector<std::int64_t> ref_sizes =
      g_smoke ? std::vector<std::int64_t>{1000} : std::vector<std::int64_t>{1000, 10'000, 100'000, 1'000'000};
  std::vector<std::int64_t> fast_sizes = ref_sizes;
  if (!g_smoke) fast_sizes.push_back(10'000'000);
  auto per_op = [&](const char* name, void (*fn)(benchmark::State&), const std::vector<std::int64_t>& sizes) {
    auto* b = benchmark::RegisterBenchmark(name, fn);
    b->ArgNames({"cells", "order"})->UseManualTime()->Unit(benchmark::kMicrosecond);
    for (const std::int64_t n : sizes)
      if (n <= g_max_cells)
        for (const int order : {0, 1}) b->Args({n, order});
  };
  per_op("Refine/reference", BM_Refine<Graph>, ref_sizes);
  per_op("Coarsen/reference", BM_Coarsen<Graph>, ref_sizes);
  per_op("Refine/fast", BM_Refine<fast::Lattice>, fast_sizes);
  per_op("Coarsen/fast", BM_Coarsen<fast::Lattice>, fast_sizes);
  per_op("RefineEach/fast", BM_RefineEach, fast_sizes);
  per_op("CoarsenEach/fast", BM_CoarsenEach, fast_sizes);

  const std::vector<std::int64_t> mix_sizes =
      g_smoke ? std::vector<std::int64_t>{1000} : std::vector<std::int64_t>{1000, 10'000, 100'000, 1'000'000};
  using Fn = void (*)(benchmark::State&);
  for (const auto& [name, fn] : {std::pair<const char*, Fn>{"Mix/reference", BM_Mix<Graph>},
                                 std::pair<const char*, Fn>{"Mix/fast", BM_Mix<fast::Lattice>}}) {
    auto* b = benchmark::RegisterBenchmark(name, fn);
    b->ArgName("cells")->UseManualTime()->Unit(benchmark::kMicrosecond);
    for (const std::int64_t n : mix_sizes) b->Arg(n);
  }

  const int ref_levels = g_smoke ? 2 : 6, fast_levels = g_smoke ? 2 : 8;
  auto* ur = benchmark::RegisterBenchmark("Uniform6x6/reference", BM_Uniform6x6<Graph>);
  ur->ArgName("level")->Unit(benchmark::kMillisecond);
  for (int k = g_smoke ? 2 : 1; k <= ref_levels; ++k) ur->Arg(k);
  auto* uf = benchmark::RegisterBenchmark("Uniform6x6/fast", BM_Uniform6x6<fast::Lattice>);
  uf->ArgName("level")->Unit(benchmark::kMillisecond);
  for (int k = g_smoke ? 2 : 1; k <= fast_levels; ++k) uf->Arg(k);

  benchmark::RegisterBenchmark("MovingFeature/reference", BM_MovingFeature<Graph>)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("MovingFeature/fast", BM_MovingFeature<fast::Lattice>)->Unit(benchmark::kMicrosecond);

  auto* lat = benchmark::RegisterBenchmark("LoadLatency", BM_LoadLatency);
  lat->ArgName("bytes")->Unit(benchmark::kMicrosecond);
  for (const std::int64_t b : g_smoke ? std::vector<std::int64_t>{1 << 16}
                                      : std::vector<std::int64_t>{1 << 16, 1 << 20, 1 << 22, 1 << 24, 1 << 26, 1 << 28})
    lat->Arg(b);
}

// ---- --bccmis_verify: the workloads give the same states in both ---------------------------------

int verify() {
  int failures = 0;
  auto expect = [&](bool ok, const std::string& what) {
    std::fprintf(stderr, "verify: %s: %s\n", what.c_str(), ok ? "same" : "DIFFERENT");
    failures += !ok;
  };
  {
    const Mix mix = make_mix(g_smoke ? 1000 : 20'000, g_smoke ? 512 : 20'000, 7);
    Graph ref = mix.start.to_graph();
    fast::Lattice fst = mix.start;
    bool agree = canonical_state(ref) == fast::canonical_state(fst);
    for (const Op& op : mix.ops) {
      const bool a = op.refine ? refine(ref, op.at).applied() : coarsen(ref, op.at).applied();
      const bool b = op.refine ? refine(fst, op.at).applied() : coarsen(fst, op.at).applied();
      agree = agree && a && b;
    }
    expect(agree && canonical_state(ref) == fast::canonical_state(fst),
           "mix of " + std::to_string(mix.ops.size()) + " operations");
  }
  {
    const LatticeSize size{6, 6, g_smoke ? 2 : 4};
    Graph ref(size);
    fast::Lattice fst(size);
    const std::size_t a = refine_uniformly<Graph>(ref, size), b = refine_uniformly<fast::Lattice>(fst, size);
    expect(a == b && canonical_state(ref) == fast::canonical_state(fst),
           "uniform 6x6 to level " + std::to_string(size.L) + " (" + std::to_string(a) + " refines)");
  }
  {
    const LatticeSize size{4, 4, 4};
    MovingFeature<Graph> ra(size, 0.5 * static_cast<double>(level0_side(size)), 64);
    MovingFeature<fast::Lattice> fa(size, 0.5 * static_cast<double>(level0_side(size)), 64);
    bool agree = true;
    std::size_t ops = 0;
    for (int f = 0; f < (g_smoke ? 16 : 128); ++f) {
      const std::size_t a = ra.frame(), b = fa.frame();
      ops += a;
      agree = agree && a == b && canonical_state(ra.state()) == fast::canonical_state(fa.state());
    }
    expect(agree, "moving feature (" + std::to_string(ops) + " operations)");
  }
  return failures;
}

template <AdaptiveLattice L>
int instructions_run(std::int64_t cells, bool random) {
  const LatticeSize size = square_lattice(cells, 4);
  L g(size);
  const std::vector<Point>& order = cell_order(size, random);
  const std::size_t batch = std::min<std::size_t>(order.size() / 4, 4096);
  std::size_t applied = 0;
  for (std::size_t round = 0; round < 5; ++round) {
    const std::size_t begin = round * batch % (order.size() - batch + 1);
    for (std::size_t i = begin; i < begin + batch; ++i) applied += refine(g, order[i]).applied();
    for (std::size_t i = begin; i < begin + batch; ++i) applied += coarsen(g, order[i]).applied();
#if BCCMIS_BENCH_HAVE_CALLGRIND
    if (round == 0) CALLGRIND_ZERO_STATS;  // the first round grows the pools: not counted
#endif
  }
  std::printf("%zu operations applied (%zu refines and %zu coarsens measured after the first round)\n", applied,
              4 * batch, 4 * batch);
  return applied == 10 * batch ? 0 : 1;
}

}  // namespace
}  // namespace bccmis::bench

int main(int argc, char** argv) {
  using namespace bccmis::bench;
  bool do_verify = false;
  std::string instructions;
  take_flags(argc, argv, [&](std::string_view a) {
    if (a == "--bccmis_smoke") return g_smoke = true;
    if (a == "--bccmis_verify") return do_verify = true;
    if (a.starts_with("--bccmis_max_cells=")) {
      g_max_cells = std::atoll(a.data() + 19);
      return true;
    }
    if (a.starts_with("--bccmis_instructions=")) {
      instructions = a.substr(22);
      return true;
    }
    return false;
  });
  if (!instructions.empty()) {
    char impl[16] = {};
    long long cells = 0;
    int order = 0;
    if (std::sscanf(instructions.c_str(), "%15[a-z],%lld,%d", impl, &cells, &order) != 3) return 2;
    return std::strcmp(impl, "fast") == 0 ? instructions_run<bccmis::fast::Lattice>(cells, order != 0)
                                          : instructions_run<bccmis::Graph>(cells, order != 0);
  }
  if (do_verify && verify() != 0) return 1;
  register_all();
  return run_benchmarks(argc, argv);
}
