// Strong exception guarantee under allocation failure, over many states.
//
// The global operator new of this executable (testing/counting_allocator.h)
// counts allocations while a countdown is armed and throws std::bad_alloc on
// the k-th one. For every (state, operation) pair below, the operation is run
// on a copy of the state with k = 0, 1, 2, ... until it completes without
// reaching the fault. After every throw the copy must equal the state before
// (graph equality, which is equality of canonical texts); the run that
// completes must give the same graph as a run without injection. A failure
// prints the minimal reproducer: the trace that builds the state, the
// operation and k.
//
// The states come from seeded random walks on several lattice sizes, so they
// have boundary and interior cells, junctions and several levels; every
// center is tried with refine and every node with coarsen (refused operations
// included: they must not change anything either), and the checked wrappers
// are exercised too.
#include <gtest/gtest.h>

#include <new>
#include <random>
#include <string>
#include <vector>

#include "bccmis/geometry.h"
#include "bccmis/graph.h"
#include "bccmis/invariants/checked.h"
#include "bccmis/io/format.h"
#include "bccmis/ops.h"
#include "testing/counting_allocator.h"

namespace bccmis {
namespace {

namespace alloc = testing::alloc;

struct Op {
  TraceCommand::Kind kind;
  Point at;
  bool checked;
};

std::string describe(const Trace& walk, const Op& op, long k) {
  TraceCommand c;
  c.kind = op.kind;
  c.at = op.at;
  Trace t = walk;
  t.commands.push_back(c);
  return "allocation #" + std::to_string(k) + " failed during " + (op.checked ? "checked " : "") + command_text(c) +
         "; reproducer (the last command is the operation):\n" + format_trace(t);
}

// Applies op to g; throws whatever the operation throws.
void apply(Graph& g, const Op& op) {
  if (op.kind == TraceCommand::Kind::Refine) {
    if (op.checked)
      checked_refine(g, op.at);
    else
      refine(g, op.at);
  } else {
    if (op.checked)
      checked_coarsen(g, op.at);
    else
      coarsen(g, op.at);
  }
}

// Runs op on copies of g failing allocation k = 0, 1, ...; returns false (after
// reporting) on the first broken guarantee.
bool exercise(const Graph& g, const Trace& walk, const Op& op, long& faults) {
  Graph expected = g;
  apply(expected, op);
  for (long k = 0;; ++k) {
    Graph h = g;
    const long injected_before = alloc::failures;
    bool threw = false;
    try {
      threw = alloc::fails_at(k, [&] { apply(h, op); });
    } catch (const std::exception& e) {
      ADD_FAILURE() << "unexpected exception " << e.what() << "\n" << describe(walk, op, k);
      return false;
    }
    if (!threw) {
      EXPECT_EQ(alloc::failures, injected_before);
      if (!(h == expected)) {
        ADD_FAILURE() << "the completed operation differs from a run without injection\n" << describe(walk, op, k);
        return false;
      }
      return true;
    }
    ++faults;
    if (!(h == g)) {
      ADD_FAILURE() << "the graph changed although the operation threw std::bad_alloc\n"
                    << describe(walk, op, k) << "state before:\n"
                    << canonical_state(g) << "state after the throw:\n"
                    << canonical_state(h);
      return false;
    }
    if (k > 1'000'000) {
      ADD_FAILURE() << "the operation never completed\n" << describe(walk, op, k);
      return false;
    }
  }
}

// Builds states by a seeded random walk and exercises every operation on a
// few of them.
void run_walks(const LatticeSize& size, unsigned seed, int steps, int snapshot_every, bool checked) {
  std::mt19937 rng(seed);
  Graph g = make_lattice(size);
  Trace walk;
  walk.size = size;
  long faults = 0, ops = 0;
  for (int step = 0; step <= steps; ++step) {
    if (step % snapshot_every == 0) {
      std::vector<Op> todo;
      for (const Point& c : g.C) todo.push_back({TraceCommand::Kind::Refine, c, checked});
      for (const Point& n : g.N) todo.push_back({TraceCommand::Kind::Coarsen, n, checked});
      for (const Op& op : todo) {
        ++ops;
        if (!exercise(g, walk, op, faults)) return;  // one reproducer per walk is enough
      }
    }
    // One more step of the walk: mostly refine, sometimes coarsen.
    TraceCommand c;
    if (rng() % 3 != 0) {
      c.kind = TraceCommand::Kind::Refine;
      c.at = *std::next(g.C.begin(), static_cast<long>(rng() % g.C.size()));
      if (!refine(g, c.at).applied()) continue;
    } else {
      std::vector<Point> refined;
      for (const Point& n : g.N)
        if (refined_center_level(g.size, n)) refined.push_back(n);
      if (refined.empty()) continue;
      c.kind = TraceCommand::Kind::Coarsen;
      c.at = refined[rng() % refined.size()];
      if (!coarsen(g, c.at).applied()) continue;
    }
    walk.commands.push_back(c);
  }
  ::testing::Test::RecordProperty("operations", static_cast<int>(ops));
  ::testing::Test::RecordProperty("faults", static_cast<int>(faults));
  EXPECT_GT(faults, ops) << "the operations allocate: faults must have been injected";
}

TEST(AllocationFailure, InjectionWorks) {
  alloc::countdown = 2;
  void* a = operator new(8);
  void* b = operator new(8);
  EXPECT_THROW((void)operator new(8), std::bad_alloc);
  EXPECT_EQ(alloc::countdown, -1);
  operator delete(a);
  operator delete(b);
}

TEST(AllocationFailure, SingleCell) { run_walks({1, 1, 3}, 1, 30, 5, false); }
TEST(AllocationFailure, Strip3x1) { run_walks({3, 1, 2}, 2, 30, 6, false); }
TEST(AllocationFailure, Square2x2) { run_walks({2, 2, 3}, 3, 40, 8, false); }
TEST(AllocationFailure, Interior3x3) { run_walks({3, 3, 2}, 4, 40, 10, false); }
TEST(AllocationFailure, Deep1x2) { run_walks({1, 2, 4}, 5, 60, 15, false); }

// The checked wrappers too: an allocation that fails in the checker after the
// operation (first seen at lattice 2 2 2, checked refine 4 4, allocation #309)
// must leave the graph as it was passed in.
TEST(AllocationFailure, CheckedOperations) { run_walks({2, 2, 2}, 6, 0, 6, true); }  // every op on the initial lattice

}  // namespace
}  // namespace bccmis
