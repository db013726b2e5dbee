#include "bccmis/apps/balance.h"

#include "bccmis/apps/detail/generic.h"

namespace bccmis {

std::optional<Balance> parse_balance(std::string_view text) {
  if (text == "edge") return Balance::Edge;
  if (text == "corner") return Balance::Corner;
  return std::nullopt;
}

std::string_view name(Balance b) { return b == Balance::Edge ? "edge" : "corner"; }

namespace {

PointSet neighbors_under(const Graph& g, const Point& c, Balance b) {
  PointSet X;
  if (g.is_center(c)) detail::for_each_neighbor(g, c, b, [&](const Point& x) { X.insert(x); });
  return X;
}

}  // namespace

PointSet edge_neighbors(const Graph& g, const Point& c) { return neighbors_under(g, c, Balance::Edge); }

PointSet touching_neighbors(const Graph& g, const Point& c) { return neighbors_under(g, c, Balance::Corner); }

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

PointSet boundary_after_coarsen(const Graph& g, const Point& n) { return detail::boundary_after_coarsen(g, n); }

std::optional<std::pair<Point, Point>> find_corner_imbalance(const Graph& g) {
  return detail::find_corner_imbalance(g);
}

}  // namespace bccmis
