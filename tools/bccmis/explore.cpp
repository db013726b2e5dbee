// bccmis explore W H L: every state reachable from the initial W x H lattice,
// each checked, every operation tried (src/bccmis/explore).
//
// Before it starts, the run is sized (spec/cli.md, "explore"): every state is
// a forest of W*H quadtrees of depth <= L, and among them every lattice that
// refines the uniform level-(L-1) lattice's cells, each or not, is reachable
// (a level-(L-1) cell whose neighbors are at level L-1 or L may be refined).
// So there are at least 2^(W*H*4^(L-1)) states (1 for L = 0), and at most
// T(L)^(W*H) with T(0) = 1, T(l) = 1 + T(l-1)^4. An unlimited run whose lower
// bound is above kMaxStates is refused; --max-states makes any run partial.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <unistd.h>

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

StateBounds state_bounds(const LatticeSize& s) {
  const double cells = static_cast<double>(s.W) * static_cast<double>(s.H);
  StateBounds b;
  if (s.L >= 1) b.log2_lower = cells * std::pow(4.0, s.L - 1);
  double log2_tree = 0;  // log2 T(l)
  for (int l = 1; l <= s.L && std::isfinite(log2_tree); ++l)
    log2_tree = log2_tree > 60 ? 4 * log2_tree : std::log2(1 + std::exp2(4 * log2_tree));
  b.log2_upper = cells * log2_tree;
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

}  // namespace

int run(const ExploreCommandOptions& o) {
  const LatticeSize size{o.W, o.H, o.L};
  try {
    validate_lattice_size(size);
  } catch (const LatticeError& e) {
    throw InputError(std::string("explore: ") + e.what());
  }
  const StateBounds bounds = state_bounds(size);
  if (o.max_states == 0 && bounds.log2_lower > std::log2(kMaxStates))
    throw InputError("explore: lattice " + std::to_string(o.W) + " " + std::to_string(o.H) + " " + std::to_string(o.L) +
                     " has at least " + power_of_two(bounds.log2_lower) + " reachable states (at most " +
                     power_of_two(bounds.log2_upper) + "), beyond reach of a full search (limit " +
                     power_of_two(std::log2(kMaxStates)) + "); give --max-states N for a partial run");
  ExploreOptions ex;
  ex.check_depth = o.depth;
  ex.max_states = o.max_states;
  ex.threads = o.threads;
  if (!o.no_progress && ::isatty(2)) {
    ex.progress = [](const ExploreProgress& p) {
      std::fprintf(stderr, "\r%lld states, %lld queued, %lld ops tried, %.1f s   ", static_cast<long long>(p.states),
                   static_cast<long long>(p.queued), static_cast<long long>(p.ops_tried), p.seconds);
    };
  }
  const ExploreResult r = explore(size, ex);
  if (ex.progress) std::fprintf(stderr, "\n");
  std::cout << (o.json ? to_json(r) : summary(r)) << "\n";
  if (r.first_failure && !o.json)
    std::cout << "first failure: " << r.first_failure->message << "\nreproducing trace:\n" << r.first_failure->trace;
  // A run stopped by --max-states is partial, not failed: the summary says "incomplete".
  return r.failures == 0 ? kExitOk : kExitViolation;
}

}  // namespace bccmis::cli
