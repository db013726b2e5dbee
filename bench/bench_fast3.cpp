// The 3D lattices' refine on a uniform sweep: every cell of a W x H x D
// lattice refined, level by level, up to level L; the time per refine of each
// level and of the whole sweep, for the reference (d3::Graph3) and the fast
// lattice (fast::Lattice3). A plain program (one run, wall-clock time), not a
// Google Benchmark: the sweep is one long workload. With --verify the two
// final canonical states must be equal (exit 1 otherwise).
//
//   bench_fast3 W H D L [reference|fast|both] [--verify]
//
// Numbers and the command that produced them: bench/RESULTS.md, "3D refine".
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bccmis/d3/format.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/fast/lattice3.h"

namespace {

using namespace bccmis;

// Refines every cell level by level; prints one line per level and the total.
// Returns ns per refine over the sweep.
template <class L>
double sweep(const char* name, L& g) {
  using Clock = std::chrono::steady_clock;
  std::size_t refines = 0;
  double total_ns = 0;
  for (int level = 0; level < size_of(g).L; ++level) {
    std::vector<d3::Point3> todo;
    for (const d3::Point3& c : cells(g)) todo.push_back(c);
    const auto start = Clock::now();
    for (const d3::Point3& c : todo)
      if (!refine(g, c).applied()) {
        std::fprintf(stderr, "bench_fast3: %s refused refine %s\n", name, d3::to_string(c).c_str());
        std::exit(1);
      }
    const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count();
    total_ns += ns;
    refines += todo.size();
    std::printf("%-9s level %d -> %d: %9zu refines, %9zu cells, %8.1f ns/refine\n", name, level, level + 1, todo.size(),
                cell_count(g), ns / static_cast<double>(todo.size()));
  }
  const double per = refines ? total_ns / static_cast<double>(refines) : 0;
  std::printf("%-9s sweep: %zu refines in %.3f s, %.1f ns/refine, %zu cells, %zu nodes\n", name, refines,
              total_ns * 1e-9, per, cell_count(g), node_count(g));
  return per;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: bench_fast3 W H D L [reference|fast|both] [--verify]\n");
    return 2;
  }
  const d3::LatticeSize3 size{std::atoll(argv[1]), std::atoll(argv[2]), std::atoll(argv[3]), std::atoi(argv[4])};
  const std::string which = argc > 5 && argv[5][0] != '-' ? argv[5] : "both";
  const bool verify = argc > 5 && std::strcmp(argv[argc - 1], "--verify") == 0;
  double reference_ns = 0, fast_ns = 0;
  std::string reference_state, fast_state;
  if (which != "fast") {
    d3::Graph3 g(size);
    reference_ns = sweep("reference", g);
    if (verify) reference_state = d3::canonical_state(g);
  }
  if (which != "reference") {
    fast::Lattice3 g(size);
    fast_ns = sweep("fast", g);
    if (verify) fast_state = fast::canonical_state(g);
  }
  if (which == "both" && fast_ns > 0) std::printf("ratio reference / fast: %.1f\n", reference_ns / fast_ns);
  if (verify && which == "both" && reference_state != fast_state) {
    std::fprintf(stderr, "bench_fast3: the final canonical states differ\n");
    return 1;
  }
  return 0;
}
