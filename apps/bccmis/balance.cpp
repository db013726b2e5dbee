#include "bccmis/balance.h"

#include <iterator>

#include "bccmis/detail/generic.h"

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
  return detail::can_refine_under(g, c, b);
}

std::optional<CoarsenRefusal> can_coarsen_under(const Graph& g, const Point& n, Balance b) {
  return detail::can_coarsen_under(g, n, b);
}

BalancedRefineResult refine_balanced(Graph& g, const Point& c, Balance b) { return detail::refine_balanced(g, c, b); }

BalancedRefineResult refine_balanced(fast::Lattice& g, const Point& c, Balance b) {
  return detail::refine_balanced(g, c, b);
}

std::size_t coarsen_sweep(Graph& g, const CoarsenPredicate& allow, Balance b) {
  return detail::coarsen_sweep(g, allow, b);
}

std::size_t coarsen_where(Graph& g, const CoarsenPredicate& allow, Balance b) {
  return detail::coarsen_where(g, allow, b);
}

VertexSet boundary_after_coarsen(const Graph& g, const Point& n) { return detail::boundary_after_coarsen(g, n); }

std::optional<std::pair<Point, Point>> find_corner_imbalance(const Graph& g) {
  for (const Point& c : g.C) {
    const int l = g.level_of(c);
    for (const Point& x : touching_neighbors(g, c))
      if (g.level_of(x) > l + 1) return std::make_pair(c, x);
  }
  return std::nullopt;
}

}  // namespace bccmis
