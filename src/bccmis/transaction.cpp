#include "bccmis/transaction.h"

namespace bccmis {

PointSet& Transaction::nb(const Point& v) {
  auto it = staged_.find(v);
  if (it == staged_.end()) it = staged_.emplace(v, g_.nbr(v)).first;
  return it->second;
}

void Transaction::add_node(const Point& v) {
  remove_nodes_.erase(v);
  add_nodes_.insert(v);
}

void Transaction::remove_node(const Point& v) {
  add_nodes_.erase(v);
  remove_nodes_.insert(v);
}

void Transaction::add_center(const Point& v, int level) {
  remove_centers_.erase(v);
  add_centers_.insert(v);
  add_levels_[v] = level;
}

void Transaction::remove_center(const Point& v) {
  add_centers_.erase(v);
  add_levels_.erase(v);
  remove_centers_.insert(v);
}

void Transaction::remove_vertex(const Point& v) {
  staged_.erase(v);
  deleted_.insert(v);
}

void Transaction::commit() noexcept {
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
