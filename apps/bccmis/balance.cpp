#include "bccmis/balance.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace bccmis {

std::optional<Balance> parse_balance(std::string_view text) {
  if (text == "edge") return Balance::Edge;
  if (text == "corner") return Balance::Corner;
  return std::nullopt;
}

std::string_view name(Balance b) { return b == Balance::Edge ? "edge" : "corner"; }

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

VertexSet touching_neighbors(const Graph& g, const Point& c) {
  // A cell touching c meets c's boundary at a corner of c or along a side
  // piece whose ends are boundary nodes of c, so it lists one of them.
  VertexSet T;
  if (!g.is_center(c)) return T;
  for (const Point& b : g.nbr(c))
    for (const Point& x : g.nbr(b))
      if (x != c) T.insert(x);
  return T;
}

std::optional<RefineRefusal> can_refine_under(const Graph& g, const Point& c, Balance b) {
  const std::optional<RefineRefusal> why = can_refine(g, c);
  if (why || b == Balance::Edge) return why;
  const int l = g.level_of(c);
  for (const Point& x : touching_neighbors(g, c))
    if (g.level_of(x) < l) return RefineRefusal::CoarserNeighbor;
  return std::nullopt;
}

std::optional<CoarsenRefusal> can_coarsen_under(const Graph& g, const Point& n, Balance b) {
  const std::optional<CoarsenRefusal> why = can_coarsen(g, n);
  if (why || b == Balance::Edge) return why;
  // The merged cell has the children's level minus one; a cell touching it
  // may be at most one level finer, i.e. at most the children's level.
  const VertexSet& Y = g.nbr(n);
  for (const Point& y : Y) {
    const int child = g.level_of(y);
    for (const Point& p : g.nbr(y)) {
      if (p == n) continue;
      for (const Point& x : g.nbr(p))
        if (Y.count(x) == 0 && g.level_of(x) > child) return CoarsenRefusal::FinerNeighbor;
    }
  }
  return std::nullopt;
}

namespace {

// The first neighbour of c (under the balance mode) coarser than c.
std::optional<Point> coarser_neighbor(const Graph& g, const Point& c, Balance b) {
  const int l = g.level_of(c);
  for (const Point& x : b == Balance::Edge ? edge_neighbors(g, c) : touching_neighbors(g, c))
    if (g.level_of(x) < l) return x;
  return std::nullopt;
}

// Precondition: c is a center below the maximum level. Every coarser
// neighbour x has level(x) < level(c), so the recursion depth is at most L.
void cascade(Graph& g, const Point& c, Balance b, std::vector<Point>& refined) {
  while (can_refine_under(g, c, b) == RefineRefusal::CoarserNeighbor) {
    const std::optional<Point> x = coarser_neighbor(g, c, b);
    if (!x) break;  // refine() below reports the inconsistency
    cascade(g, *x, b, refined);
  }
  const RefineResult r = refine(g, c);
  if (!r.applied())
    throw std::logic_error("refine_balanced: refine(" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                           ") refused with " + std::string(code(*r.refused)) + " after its cascade");
  refined.push_back(c);
}

}  // namespace

BalancedRefineResult refine_balanced(Graph& g, const Point& c, Balance b) {
  BalancedRefineResult result;
  if (const std::optional<RefineRefusal> why = can_refine(g, c);
      why == RefineRefusal::NoSuchCell || why == RefineRefusal::MaxLevel) {
    result.refused = why;
    return result;
  }
  cascade(g, c, b, result.refined);
  return result;
}

std::size_t coarsen_sweep(Graph& g, const CoarsenPredicate& allow, Balance b) {
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
    if (can_coarsen_under(g, n, b) || !allow(g, n)) continue;
    if (coarsen(g, n).applied()) ++done;
  }
  return done;
}

std::size_t coarsen_where(Graph& g, const CoarsenPredicate& allow, Balance b) {
  std::size_t total = 0;
  while (const std::size_t done = coarsen_sweep(g, allow, b)) total += done;
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

std::optional<std::pair<Point, Point>> find_corner_imbalance(const Graph& g) {
  for (const Point& c : g.C) {
    const int l = g.level_of(c);
    for (const Point& x : touching_neighbors(g, c))
      if (g.level_of(x) > l + 1) return std::make_pair(c, x);
  }
  return std::nullopt;
}

}  // namespace bccmis
