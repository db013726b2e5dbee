#include "bccmis/balance.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace bccmis {

VertexSet edge_neighbors(const Graph& g, const Point& c) {
  VertexSet X;
  if (!g.is_center(c)) return X;
  const VertexSet& B = g.nbr(c);
  // Two boundary nodes of c share a second cell exactly when they are the
  // ends of one side piece of c (a corner and a corner, or a corner and a
  // junction); that cell lies across the piece.
  for (auto bi = B.begin(); bi != B.end(); ++bi) {
    const VertexSet& Ni = g.nbr(*bi);
    for (auto bj = std::next(bi); bj != B.end(); ++bj) {
      const VertexSet& Nj = g.nbr(*bj);
      for (const Point& x : Ni)
        if (x != c && Nj.count(x) != 0) X.insert(x);
    }
  }
  return X;
}

namespace {

// The first edge-neighbour of c coarser than c, in sorted order.
std::optional<Point> coarser_neighbor(const Graph& g, const Point& c) {
  const int l = g.level_of(c);
  for (const Point& x : edge_neighbors(g, c))
    if (g.level_of(x) < l) return x;
  return std::nullopt;
}

// Precondition: c is a center below the maximum level. Every coarser
// neighbour x has level(x) < level(c), so the recursion depth is at most L.
void cascade(Graph& g, const Point& c, std::vector<Point>& refined) {
  while (can_refine(g, c) == RefineRefusal::CoarserNeighbor) {
    const std::optional<Point> x = coarser_neighbor(g, c);
    if (!x) break;  // refine() below reports the inconsistency
    cascade(g, *x, refined);
  }
  const RefineResult r = refine(g, c);
  if (!r.applied())
    throw std::logic_error("refine_balanced: refine(" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                           ") refused with " + std::string(code(*r.refused)) + " after its cascade");
  refined.push_back(c);
}

}  // namespace

BalancedRefineResult refine_balanced(Graph& g, const Point& c) {
  BalancedRefineResult result;
  if (const std::optional<RefineRefusal> why = can_refine(g, c);
      why == RefineRefusal::NoSuchCell || why == RefineRefusal::MaxLevel) {
    result.refused = why;
    return result;
  }
  cascade(g, c, result.refined);
  return result;
}

std::size_t coarsen_sweep(Graph& g, const CoarsenPredicate& allow) {
  // Only refined centers can be coarsened; the position test is cheap and
  // keeps the pass from calling the predicate on grid nodes and midpoints.
  // Finest first: merging the children of a cell can make the cell itself
  // (one level up) or a neighbour blocked by a finer junction mergeable, so
  // one pass usually reaches the fixpoint.
  std::vector<std::pair<int, Point>> candidates;
  for (const Point& n : g.N)
    if (const std::optional<int> l = refined_center_level(g.size, n)) candidates.push_back({-*l, n});
  std::sort(candidates.begin(), candidates.end());
  std::size_t done = 0;
  for (const auto& [minus_level, n] : candidates) {
    if (can_coarsen(g, n) || !allow(g, n)) continue;
    if (coarsen(g, n).applied()) ++done;
  }
  return done;
}

std::size_t coarsen_where(Graph& g, const CoarsenPredicate& allow) {
  std::size_t total = 0;
  while (const std::size_t done = coarsen_sweep(g, allow)) total += done;
  return total;
}

VertexSet boundary_after_coarsen(const Graph& g, const Point& n) {
  const VertexSet& Y = g.nbr(n);
  const int child_level = Y.empty() ? 0 : g.level_of(*Y.begin());
  const std::int64_t half = cell_side(g.size, child_level);  // half the merged cell's side
  VertexSet B;
  for (const Point& y : Y)
    for (const Point& b : g.nbr(y)) {
      if (b == n || B.count(b) != 0) continue;
      const bool corner = (b.x == n.x - half || b.x == n.x + half) && (b.y == n.y - half || b.y == n.y + half);
      std::size_t outside = 0;
      for (const Point& x : g.nbr(b)) outside += Y.count(x) == 0 ? 1 : 0;
      if (corner || outside >= 2) B.insert(b);
    }
  return B;
}

}  // namespace bccmis
