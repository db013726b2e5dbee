#include "bccmis/apps/balance.h"

#include "bccmis/apps/detail/generic.h"

namespace bccmis {

std::optional<CoarsenRefusal> can_coarsen_under(const Graph& g, const Point& n, Balance b) {
  return detail::can_coarsen_under(g, n, b);
}

std::size_t coarsen_sweep(Graph& g, const CoarsenPredicate& allow, Balance b) {
  return detail::coarsen_sweep(g, allow, b);
}

std::size_t coarsen_where(Graph& g, const CoarsenPredicate& allow, Balance b) {
  return detail::coarsen_where(g, allow, b);
}

PointSet boundary_after_coarsen(const Graph& g, const Point& n) { return detail::boundary_after_coarsen(g, n); }

}  // namespace bccmis
