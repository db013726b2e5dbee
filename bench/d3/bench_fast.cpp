// The 3D lattices' refine and coarsen on a uniform sweep: every cell of a
// W x H x D lattice refined, level by level, up to level L, then every
// refined cell coarsened again, level by level from the finest, back to the
// initial lattice; the time per operation of each level and of the whole
// sweep, for the reference (d3::Graph) and the fast lattice
// (d3::fast::Lattice, with its memory_bytes() per cell after each level's
// refines: the pools' and the position table's capacity). Within a level
// the operations run in position order (sweep) or, with --random, in a
// shuffled order (fixed seed): on a uniform level every order is allowed. A plain program (one run; the CPU time of
// the thread, CLOCK_THREAD_CPUTIME_ID, so that other processes' time slices
// on a shared machine are not counted), not a Google Benchmark: the sweep is
// one long workload. With --verify the
// two lattices' canonical states must be equal after the refines and after
// the coarsens, and the coarsens must end at the initial lattice (exit 1
// otherwise).
//
//   d3_bench_fast W H D L [reference|fast|both] [--random] [--verify]
//
// Numbers and the commands that produced them: bench/RESULTS.md, "3D refine"
// and "3D coarsen".
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bccmis/d3/lattice.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/io/d3/format.h"

namespace {

using namespace bccmis;

// The calling thread's CPU time in ns.
double thread_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

struct Totals {
  double refine_ns = 0;
  double coarsen_ns = 0;
  std::string refined_state;    // after the refines (--verify)
  std::string coarsened_state;  // after the coarsens (--verify)
};

// The thread time of op(p) for each p of `points`, each of which must be
// applied (exit 1 on a refusal).
template <class Op>
double timed_all(const char* name, const char* what, const std::vector<d3::Point>& points, Op op) {
  const double start = thread_ns();
  for (const d3::Point& p : points)
    if (!op(p)) {
      std::fprintf(stderr, "d3_bench_fast: %s refused %s %s\n", name, what, d3::to_string(p).c_str());
      std::exit(1);
    }
  return thread_ns() - start;
}

// Refines every cell level by level, then coarsens back; prints one line per
// level and phase and the totals.
template <class L, class State>
Totals sweep(const char* name, L& g, bool random, bool verify, const State& state) {
  std::mt19937_64 rng(19);
  std::vector<std::vector<d3::Point>> refined(static_cast<std::size_t>(size_of(g).L));
  std::size_t refines = 0, coarsens = 0;
  Totals t;
  for (int level = 0; level < size_of(g).L; ++level) {
    std::vector<d3::Point>& todo = refined[static_cast<std::size_t>(level)];
    for (const d3::Point& c : cells(g)) todo.push_back(c);
    if (random) std::shuffle(todo.begin(), todo.end(), rng);
    const double ns = timed_all(name, "refine", todo, [&](const d3::Point& c) { return refine(g, c).applied(); });
    t.refine_ns += ns;
    refines += todo.size();
    std::printf("%-9s refine  level %d -> %d: %9zu ops, %9zu cells, %8.1f ns/op", name, level, level + 1, todo.size(),
                cell_count(g), ns / static_cast<double>(todo.size()));
    if constexpr (requires { g.memory_bytes(); })  // capacity of the pools and the table over the cells
      std::printf(", %6.1f B/cell", static_cast<double>(g.memory_bytes()) / static_cast<double>(cell_count(g)));
    std::printf("\n");
  }
  if (verify) t.refined_state = state(g);
  for (int level = size_of(g).L - 1; level >= 0; --level) {
    std::vector<d3::Point>& todo = refined[static_cast<std::size_t>(level)];
    if (random) std::shuffle(todo.begin(), todo.end(), rng);
    const std::size_t before = cell_count(g);
    const double ns = timed_all(name, "coarsen", todo, [&](const d3::Point& n) { return coarsen(g, n).applied(); });
    t.coarsen_ns += ns;
    coarsens += todo.size();
    std::printf("%-9s coarsen level %d -> %d: %9zu ops, %9zu cells, %8.1f ns/op\n", name, level + 1, level, todo.size(),
                before, ns / static_cast<double>(todo.size()));
  }
  if (verify) t.coarsened_state = state(g);
  t.refine_ns = refines ? t.refine_ns / static_cast<double>(refines) : 0;
  t.coarsen_ns = coarsens ? t.coarsen_ns / static_cast<double>(coarsens) : 0;
  std::printf("%-9s %s sweep: %zu refines, %.1f ns/refine; %zu coarsens, %.1f ns/coarsen; %zu cells at the end\n", name,
              random ? "random" : "position-order", refines, t.refine_ns, coarsens, t.coarsen_ns, cell_count(g));
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: d3_bench_fast W H D L [reference|fast|both] [--random] [--verify]\n");
    return 2;
  }
  const d3::LatticeSize size{std::atoll(argv[1]), std::atoll(argv[2]), std::atoll(argv[3]), std::atoi(argv[4])};
  std::string which = "both";
  bool verify = false, random = false;
  for (int i = 5; i < argc; ++i) {
    if (std::strcmp(argv[i], "--verify") == 0)
      verify = true;
    else if (std::strcmp(argv[i], "--random") == 0)
      random = true;
    else
      which = argv[i];
  }
  Totals reference, fast;
  if (which != "fast") {
    d3::Graph g(size);
    reference = sweep("reference", g, random, verify, [](const d3::Graph& x) { return d3::canonical_state(x); });
  }
  if (which != "reference") {
    d3::fast::Lattice g(size);
    fast = sweep("fast", g, random, verify, [](const d3::fast::Lattice& x) { return d3::fast::canonical_state(x); });
  }
  if (which == "both" && fast.refine_ns > 0 && fast.coarsen_ns > 0)
    std::printf("ratio reference / fast: refine %.1f, coarsen %.1f\n", reference.refine_ns / fast.refine_ns,
                reference.coarsen_ns / fast.coarsen_ns);
  if (verify) {
    const std::string initial = d3::canonical_state(d3::Graph(size));
    const Totals& t = which == "reference" ? reference : fast;
    if (which == "both" && reference.refined_state != fast.refined_state) {
      std::fprintf(stderr, "d3_bench_fast: the canonical states after the refines differ\n");
      return 1;
    }
    if (t.coarsened_state != initial || (which == "both" && reference.coarsened_state != initial)) {
      std::fprintf(stderr, "d3_bench_fast: the coarsens did not end at the initial lattice\n");
      return 1;
    }
    std::printf("verify: same canonical states after the refines; back to the initial lattice after the coarsens\n");
  }
  return 0;
}
