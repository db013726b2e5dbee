// bccmis explore: breadth-first search over every lattice state reachable
// from the initial W x H lattice by refine and coarsen (Erleben 2009, §2.1,
// §2.2), checking every state and every operation on the way.
//
// For every reachable state the explorer
//   1. runs the invariant checker (invariants/, layers 1..check_depth);
//   2. tries refine and coarsen on every vertex (node or center) of the state:
//      - an accepted operation must be undone exactly by its inverse (§3:
//        refine(c) then coarsen(c), coarsen(n) then refine(n), compared on the
//        exact key below), and its result is queued if it is new;
//      - a refused operation must leave the state exactly unchanged.
// States are deduplicated by an exact key: a compact binary encoding of the
// whole Graph (N, C, every neighbor set, every level), from which the graph
// is decoded again. Two graphs have equal keys iff they are equal.
//
// States are processed in parallel batches (ExploreOptions::threads); the
// operations under test must be safe to call concurrently on different graphs.
// The operations under test are pluggable (ExploreOptions::refine/coarsen) so
// that tests can run the explorer on planted-bug mutants.
//
// The explorer is written once over the lattice type (detail/explorer.h);
// this header is its 2D instantiation on Graph, bccmis/explore/d3/explore.h the
// 3D one on d3::Graph.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "bccmis/graph.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis {

/// A snapshot handed to the progress callback.
struct ExploreProgress {
  std::int64_t states = 0;         ///< states fully processed so far
  std::int64_t queued = 0;         ///< discovered states not processed yet
  std::int64_t refine_edges = 0;   ///< accepted refines so far
  std::int64_t coarsen_edges = 0;  ///< accepted coarsens so far
  std::int64_t ops_tried = 0;      ///< refine/coarsen calls so far (inverses not counted)
  double seconds = 0;              ///< wall time since the start
};

/// The options of a run on lattice type G (ExploreOptions in 2D).
template <class G>
struct BasicExploreOptions {
  /// Layers of the checker run on every state (1..4); 0 skips the checker.
  int check_depth = 4;
  /// Try refine and coarsen on every vertex of every state (the full check).
  /// When false, only refine on centers and coarsen on nodes are tried, and
  /// refused calls are not compared with the state (counting only).
  bool try_every_op = true;
  /// Stop after this many states (0: no limit). The result is then incomplete.
  std::int64_t max_states = 0;
  /// Stop at the first failure (otherwise keep exploring and count failures).
  bool stop_at_first_failure = true;
  /// Worker threads (0: one per hardware thread). The result does not depend
  /// on it: states are numbered, counted and reported in BFS order.
  int threads = 0;
  /// Called (on the calling thread) about every `progress_every` states and
  /// once at the end.
  std::function<void(const ExploreProgress&)> progress;
  std::int64_t progress_every = 4096;
  /// The operations under test; empty means bccmis::refine / bccmis::coarsen.
  std::function<refine_result_t<G>(G&, const point_type_t<G>&)> refine;
  std::function<coarsen_result_t<G>(G&, const point_type_t<G>&)> coarsen;
};

using ExploreOptions = BasicExploreOptions<Graph>;

/// The first thing that went wrong, with a reproducer.
struct ExploreFailure {
  std::string message;  ///< one line
  std::string trace;    ///< a trace (spec/formats.md) from the initial lattice that reproduces it
};

/// The result of a run on a lattice whose size type is S (ExploreResult in 2D).
template <class S>
struct BasicExploreResult {
  S size;
  std::int64_t states = 0;         ///< distinct reachable states processed
  std::int64_t refine_edges = 0;   ///< (state, cell) pairs where refine was accepted
  std::int64_t coarsen_edges = 0;  ///< (state, node) pairs where coarsen was accepted
  std::int64_t ops_tried = 0;      ///< refine/coarsen calls (inverses not counted)
  std::int64_t refused = 0;        ///< calls that were refused
  std::int64_t failures = 0;       ///< failed checks (at most 1 with stop_at_first_failure)
  std::int64_t max_vertices = 0;   ///< the largest |N| + |C| seen
  std::int64_t key_bytes = 0;      ///< total size of the stored state keys
  bool complete = false;           ///< every reachable state was processed
  double seconds = 0;              ///< wall time
  std::optional<ExploreFailure> first_failure;

  /// complete and no failure.
  bool ok() const { return complete && failures == 0; }
};

using ExploreResult = BasicExploreResult<LatticeSize>;

/// Explores every state reachable from make_lattice(size). Throws LatticeError
/// for an invalid size. Never throws for a failing operation or state: those
/// are reported in the result (an exception thrown by an operation counts as a
/// failure).
ExploreResult explore(const LatticeSize& size, const ExploreOptions& options = {});

/// One line for humans, e.g.
/// `explore 1 1 2: 17 states, 33 refine edges, 33 coarsen edges, 1234 ops tried, ok (0.01 s)`.
std::string summary(const ExploreResult& result);

/// One line of JSON with every field of the result (the failure, if any,
/// under "failure": {"message": ..., "trace": ...}).
std::string to_json(const ExploreResult& result);

/// The exact key of a graph (the encoding used for deduplication), and its
/// inverse: decode_state_key(encode_state_key(g)) == g for every Graph g.
std::string encode_state_key(const Graph& g);
Graph decode_state_key(const std::string& key, const LatticeSize& size);

}  // namespace bccmis
