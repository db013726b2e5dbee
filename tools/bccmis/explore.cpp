// bccmis explore W H L | W H D L: every state reachable from the initial
// W x H (x D) lattice, each checked, every operation tried (src/bccmis/explore).
//
// Before it starts, the run is sized (spec/cli.md, "explore"): every state is
// a forest of W*H quadtrees (W*H*D octrees) of depth <= L, and among them
// every lattice that refines the uniform level-(L-1) lattice's cells, each or
// not, is reachable (a level-(L-1) cell whose neighbors are at level L-1 or L
// may be refined). With k = 4 children per cell in 2D and 8 in 3D and n root
// cells, there are at least 2^(n*k^(L-1)) states (1 for L = 0), and at most
// T(L)^n with T(0) = 1, T(l) = 1 + T(l-1)^k. An unlimited run whose lower
// bound is above kMaxStates is refused; --max-states makes any run partial.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include "bccmis/explore/d3/explore.h"
#include "bccmis/explore/explore.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

namespace {

/// More states than an unlimited run attempts (at thousands to tens of
/// thousands of states a second and about a hundred bytes a key: hours and
/// gigabytes).
constexpr double kMaxStates = 1e8;

/// log2 of the lower and upper bounds above (saturating at +infinity).
struct StateBounds {
  double log2_lower = 0;
  double log2_upper = 0;
};

/// n root cells with k children each, at most L levels deep.
StateBounds state_bounds(double roots, double k, int L) {
  StateBounds b;
  if (L >= 1) b.log2_lower = roots * std::pow(k, L - 1);
  double log2_tree = 0;  // log2 T(l)
  for (int l = 1; l <= L && std::isfinite(log2_tree); ++l)
    log2_tree = log2_tree > 60 ? k * log2_tree : std::log2(1 + std::exp2(k * log2_tree));
  b.log2_upper = roots * log2_tree;
  return b;
}

std::string power_of_two(double log2) {
  char buf[96];
  if (!std::isfinite(log2)) return "2^inf";
  if (log2 < 64) {
    std::snprintf(buf, sizeof buf, "%.0f", std::exp2(log2));
    return buf;
  }
  std::snprintf(buf, sizeof buf, "2^%.0f", log2);
  return buf;
}

/// Refuses a run whose state space is beyond reach (unless --max-states).
void check_reach(const ExploreCommandOptions& o, const StateBounds& bounds) {
  if (o.max_states != 0 || bounds.log2_lower <= std::log2(kMaxStates)) return;
  std::string lattice;
  for (const std::int64_t v : o.lattice) lattice += (lattice.empty() ? "" : " ") + std::to_string(v);
  throw InputError("explore: lattice " + lattice + " has at least " + power_of_two(bounds.log2_lower) +
                   " reachable states (at most " + power_of_two(bounds.log2_upper) +
                   "), beyond reach of a full search (limit " + power_of_two(std::log2(kMaxStates)) +
                   "); give --max-states N for a partial run");
}

/// Runs the explorer on `size` (either dimension) and prints the report.
template <class G, class Size>
int explore_and_report(const ExploreCommandOptions& o, const Size& size) {
  BasicExploreOptions<G> ex;
  ex.check_depth = o.depth;
  ex.max_states = o.max_states;
  ex.threads = o.threads;
  if (!o.no_progress && ::isatty(2)) {
    ex.progress = [](const ExploreProgress& p) {
      std::fprintf(stderr, "\r%lld states, %lld queued, %lld ops tried, %.1f s   ", static_cast<long long>(p.states),
                   static_cast<long long>(p.queued), static_cast<long long>(p.ops_tried), p.seconds);
    };
  }
  const auto r = explore(size, ex);
  if (ex.progress) std::fprintf(stderr, "\n");
  std::cout << (o.json ? to_json(r) : summary(r)) << "\n";
  if (r.first_failure && !o.json)
    std::cout << "first failure: " << r.first_failure->message << "\nreproducing trace:\n" << r.first_failure->trace;
  // A run stopped by --max-states is partial, not failed: the summary says "incomplete".
  return r.failures == 0 ? kExitOk : kExitViolation;
}

/// L as an int (validate_lattice_size then judges it).
int level_argument(std::int64_t L) {
  if (L < std::numeric_limits<int>::min() || L > std::numeric_limits<int>::max())
    throw InputError("explore: L = " + std::to_string(L) + " is out of range");
  return static_cast<int>(L);
}

}  // namespace

int run(const ExploreCommandOptions& o) {
  const std::vector<std::int64_t>& v = o.lattice;
  if (v.size() == 4) {
    const d3::LatticeSize size{v[0], v[1], v[2], level_argument(v[3])};
    try {
      d3::validate_lattice_size(size);
    } catch (const LatticeError& e) {
      throw InputError(std::string("explore: ") + e.what());
    }
    check_reach(o, state_bounds(static_cast<double>(size.W) * static_cast<double>(size.H) * static_cast<double>(size.D),
                                8, size.L));
    return explore_and_report<d3::Graph>(o, size);
  }
  if (v.size() != 3) throw InputError("explore: give W H L (2D) or W H D L (3D)");
  const LatticeSize size{v[0], v[1], level_argument(v[2])};
  try {
    validate_lattice_size(size);
  } catch (const LatticeError& e) {
    throw InputError(std::string("explore: ") + e.what());
  }
  check_reach(o, state_bounds(static_cast<double>(size.W) * static_cast<double>(size.H), 4, size.L));
  return explore_and_report<Graph>(o, size);
}

}  // namespace bccmis::cli
