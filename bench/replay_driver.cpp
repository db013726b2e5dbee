// replay_driver: a trace replayed and its outputs written, phase by phase,
// on either implementation, the way `bccmis replay --check=none --log LOG
// --state STATE` does it (bench/RESULTS.md, "Replay output paths").
//
//   replay_driver fast|reference TRACE LOG STATE
//
// Reads TRACE, parses it (the text is freed before the replay), runs
// replay<L>, writes the decision log to LOG and the canonical state to
// STATE with write_canonical_state. Prints, per phase, the CPU time of the
// process, the wall time and the peak RSS so far (getrusage), and the cell
// count, to stderr. No Google Benchmark: the process holds only what a
// replay needs, so its peak RSS is the replay's.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <string_view>

#include "bccmis/fast/lattice.h"
#include "bccmis/graph.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "bccmis/trace.h"

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

class Phases {
 public:
  void end(const char* name) {
    const double cpu = cpu_seconds();
    const auto wall = std::chrono::steady_clock::now();
    std::fprintf(stderr, "%-12s cpu %8.4f s  wall %8.4f s  peak_rss %8ld KiB\n", name, cpu - cpu_,
                 std::chrono::duration<double>(wall - wall_).count(), peak_rss_kib());
    cpu_ = cpu;
    wall_ = wall;
  }

 private:
  double cpu_ = cpu_seconds();
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
};

template <class L>
int run(const char* trace_path, const char* log_path, const char* state_path) {
  const double cpu0 = cpu_seconds();
  Phases phases;
  bccmis::Trace trace;
  {
    std::ifstream in(trace_path, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "replay_driver: cannot open %s\n", trace_path);
      return 2;
    }
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    phases.end("read");
    trace = bccmis::parse_trace(text, trace_path, {std::int64_t{1} << 40});
  }
  phases.end("parse");
  std::string log;
  const L g = bccmis::replay<L>(trace, log);
  phases.end("replay");
  {
    std::ofstream out(log_path, std::ios::binary | std::ios::trunc);
    out << log;
    if (!out.flush()) return 2;
  }
  phases.end("write log");
  {
    std::ofstream out(state_path, std::ios::binary | std::ios::trunc);
    write_canonical_state(out, g);
    if (!out.flush()) return 2;
  }
  phases.end("write state");
  std::fprintf(stderr, "total        cpu %8.4f s  cells %zu  nodes %zu  peak_rss %ld KiB = %.1f bytes per cell\n",
               cpu_seconds() - cpu0, cell_count(g), node_count(g), peak_rss_kib(),
               1024.0 * static_cast<double>(peak_rss_kib()) / static_cast<double>(cell_count(g)));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: replay_driver fast|reference TRACE LOG STATE\n");
    return 2;
  }
  const std::string_view impl = argv[1];
  if (impl == "fast") return run<bccmis::fast::Lattice>(argv[2], argv[3], argv[4]);
  if (impl == "reference") return run<bccmis::Graph>(argv[2], argv[3], argv[4]);
  std::fprintf(stderr, "replay_driver: IMPL is fast or reference, not %s\n", argv[1]);
  return 2;
}
