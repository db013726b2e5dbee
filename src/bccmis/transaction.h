// bccmis: all-or-nothing updates of a Graph.
//
// refine and coarsen write every change through a Transaction: neighbor sets
// are copied on first use and edited locally, vertex additions and removals
// are recorded. Everything that can allocate happens before commit(); commit()
// only swaps sets and splices already-allocated tree nodes into the graph
// (std::set / std::map node handles), so it cannot throw. If an operation
// throws before commit (std::bad_alloc, or a logic_error on an invalid graph)
// the graph is exactly as it was: the strong exception guarantee.
#pragma once

#include <map>
#include <set>

#include "bccmis/graph.h"

namespace bccmis {

class Transaction {
 public:
  explicit Transaction(Graph& g) : g_(g) {}
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  /// The staged 𝒩(v), copied from the graph on first use (empty for a new vertex).
  PointSet& nb(const Point& v);

  void add_node(const Point& v);                  ///< N = N ∪ {v}
  void remove_node(const Point& v);               ///< N = N \ {v}
  void add_center(const Point& v, int level);     ///< C = C ∪ {v}, with its level
  void remove_center(const Point& v);             ///< C = C \ {v}, and its level
  void remove_vertex(const Point& v);             ///< v is deleted: drop 𝒩(v) entirely

  /// Applies every staged change to the graph. Never throws.
  void commit() noexcept;

 private:
  Graph& g_;
  std::map<Point, PointSet> staged_;
  PointSet add_nodes_, remove_nodes_, add_centers_, remove_centers_, deleted_;
  std::map<Point, int> add_levels_;
};

}  // namespace bccmis
