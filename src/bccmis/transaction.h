// bccmis: all-or-nothing updates of a graph.
//
// refine and coarsen write every change through a Transaction: neighbor sets
// are copied on first use and edited locally, vertex additions and removals
// are recorded. Everything that can allocate happens before commit(); commit()
// only swaps sets and splices already-allocated tree nodes into the graph
// (std::set / std::map node handles), so it cannot throw. If an operation
// throws before commit (std::bad_alloc, or a logic_error on an invalid graph)
// the graph is exactly as it was: the strong exception guarantee.
//
// The class is written once for every graph of the same shape (members N, C,
// neighbors, level and nbr(v), point type G::point_type): the 2D Graph and
// the 3D d3::Graph.
#pragma once

#include <map>
#include <set>
#include <utility>

#include "bccmis/graph.h"

namespace bccmis {

template <class G>
class BasicTransaction {
 public:
  using Point = typename G::point_type;
  using PointSet = std::set<Point>;

  explicit BasicTransaction(G& g) : g_(g) {}
  BasicTransaction(const BasicTransaction&) = delete;
  BasicTransaction& operator=(const BasicTransaction&) = delete;

  /// The staged 𝒩(v), copied from the graph on first use (empty for a new vertex).
  PointSet& nb(const Point& v);

  void add_node(const Point& v);               ///< N = N ∪ {v}
  void remove_node(const Point& v);            ///< N = N \ {v}
  void add_center(const Point& v, int level);  ///< C = C ∪ {v}, with its level
  void remove_center(const Point& v);          ///< C = C \ {v}, and its level
  void remove_vertex(const Point& v);          ///< v is deleted: drop 𝒩(v) entirely

  /// Applies every staged change to the graph. Never throws.
  void commit() noexcept;

 private:
  G& g_;
  std::map<Point, PointSet> staged_;
  PointSet add_nodes_, remove_nodes_, add_centers_, remove_centers_, deleted_;
  std::map<Point, int> add_levels_;
};

/// The 2D reference core's transaction (instantiated in transaction.cpp).
using Transaction = BasicTransaction<Graph>;
extern template class BasicTransaction<Graph>;

// ---- Definitions -------------------------------------------------------------

template <class G>
typename BasicTransaction<G>::PointSet& BasicTransaction<G>::nb(const Point& v) {
  auto it = staged_.find(v);
  if (it == staged_.end()) it = staged_.emplace(v, g_.nbr(v)).first;
  return it->second;
}

template <class G>
void BasicTransaction<G>::add_node(const Point& v) {
  remove_nodes_.erase(v);
  add_nodes_.insert(v);
}

template <class G>
void BasicTransaction<G>::remove_node(const Point& v) {
  add_nodes_.erase(v);
  remove_nodes_.insert(v);
}

template <class G>
void BasicTransaction<G>::add_center(const Point& v, int level) {
  remove_centers_.erase(v);
  add_centers_.insert(v);
  add_levels_[v] = level;
}

template <class G>
void BasicTransaction<G>::remove_center(const Point& v) {
  add_centers_.erase(v);
  add_levels_.erase(v);
  remove_centers_.insert(v);
}

template <class G>
void BasicTransaction<G>::remove_vertex(const Point& v) {
  staged_.erase(v);
  deleted_.insert(v);
}

template <class G>
void BasicTransaction<G>::commit() noexcept {
  // Removals first: erase never allocates.
  for (const Point& v : deleted_) g_.neighbors.erase(v);
  for (const Point& v : remove_nodes_) g_.N.erase(v);
  for (const Point& v : remove_centers_) {
    g_.C.erase(v);
    g_.level.erase(v);
  }
  // Additions: splice the tree nodes allocated while staging into the graph.
  while (!add_nodes_.empty()) g_.N.insert(add_nodes_.extract(add_nodes_.begin()));
  while (!add_centers_.empty()) g_.C.insert(add_centers_.extract(add_centers_.begin()));
  while (!add_levels_.empty()) {
    auto node = add_levels_.extract(add_levels_.begin());
    if (auto it = g_.level.find(node.key()); it != g_.level.end()) {
      it->second = node.mapped();
    } else {
      g_.level.insert(std::move(node));
    }
  }
  // Neighbor sets: swap into existing entries, splice new entries.
  while (!staged_.empty()) {
    auto node = staged_.extract(staged_.begin());
    if (auto it = g_.neighbors.find(node.key()); it != g_.neighbors.end()) {
      it->second.swap(node.mapped());
    } else if (!node.mapped().empty()) {
      g_.neighbors.insert(std::move(node));
    }
  }
  deleted_.clear();
  remove_nodes_.clear();
  remove_centers_.clear();
}

}  // namespace bccmis
