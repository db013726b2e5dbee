// bccmis: all-or-nothing updates of a Graph.
//
// refine and coarsen write every change through a Transaction: neighbour sets
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
  VertexSet& nb(const Vertex& v);

  void add_node(const Vertex& v);                  ///< N = N ∪ {v}
  void remove_node(const Vertex& v);               ///< N = N \ {v}
  void add_center(const Vertex& v, int level);     ///< C = C ∪ {v}, with its level
  void remove_center(const Vertex& v);             ///< C = C \ {v}, and its level
  void remove_vertex(const Vertex& v);             ///< v is deleted: drop 𝒩(v) entirely

  /// Applies every staged change to the graph. Never throws.
  void commit() noexcept;

 private:
  Graph& g_;
  std::map<Vertex, VertexSet> staged_;
  VertexSet add_nodes_, remove_nodes_, add_centers_, remove_centers_, deleted_;
  std::map<Vertex, int> add_levels_;
};

}  // namespace bccmis
