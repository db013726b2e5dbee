// The reference Graph and bccmis::fast::Lattice driven in lock-step (issue 9):
// the same trace commands through the one stepper (bccmis/trace.h) on both.
// Before every operation the guards (can_refine and can_coarsen at the
// position, both operations) must agree; after it the decision, the sets it
// returned (Y, J+ / J-), the counts and the canonical state, byte for byte;
// and the fast lattice must pass its own audit (mirrored links, position
// table, free lists). compare_queries() asks every query at every vertex.
//
// Used by tests/fast/differential_test.cpp (RapidCheck) and
// fuzz/fuzz_differential.cpp (libFuzzer). A difference is reported through
// the Fail callback with the trace of the commands run so far, ready to be
// replayed by `bccmis replay`; the callback must not return (it fails the
// property or aborts), and the Twin throws std::logic_error if it does.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "bccmis/fast/lattice.h"
#include "bccmis/graph.h"
#include "bccmis/io/format.h"

namespace bccmis::testing {

class Twin {
 public:
  /// Reports a difference: what differs, and the trace that reproduces it.
  using Fail = std::function<void(const std::string& what, const Trace& so_far)>;

  Twin(const LatticeSize& size, Fail fail);

  const Graph& graph() const { return g_; }
  const fast::Lattice& lattice() const { return lat_; }
  const Trace& trace() const { return trace_; }
  /// Operations applied so far.
  std::size_t applied() const { return applied_; }

  /// Runs refine or coarsen at `at` on both (recorded in the trace) and
  /// compares. With `batch` the fast side runs it through refine_each /
  /// coarsen_each (only the decision is compared then, by the count).
  void run(TraceCommand::Kind kind, const Point& at, bool batch = false);

  /// The fast side goes on from a copy of itself or from
  /// fast::Lattice::from_graph of the reference state.
  void reseat(bool from_reference);

  /// The counts, the canonical states and the fast audit.
  void compare_states(const std::string& when) const;

  /// Every query (neighbors, is_center, is_node, level_of, both guards) at
  /// every vertex and at positions around the domain; cells() and nodes().
  void compare_queries() const;

  [[noreturn]] void fail(const std::string& what) const;

 private:
  void compare_guards(const Point& p) const;

  Fail fail_;
  Graph g_;
  fast::Lattice lat_;
  Trace trace_;
  std::size_t applied_ = 0;
};

}  // namespace bccmis::testing
