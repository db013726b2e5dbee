#include "bccmis/apps/balance3.h"

#include "bccmis/apps/detail/cascade.h"
#include "bccmis/d3/lattice.h"

namespace bccmis::d3 {

namespace {

PointSet3 neighbors_under(const Graph3& g, const Point3& c, Balance b) {
  PointSet3 X;
  if (g.is_center(c)) bccmis::detail::for_each_neighbor(g, c, b, [&](const Point3& x) { X.insert(x); });
  return X;
}

}  // namespace

PointSet3 edge_neighbors(const Graph3& g, const Point3& c) { return neighbors_under(g, c, Balance::Edge); }

PointSet3 touching_neighbors(const Graph3& g, const Point3& c) { return neighbors_under(g, c, Balance::Corner); }

std::optional<RefineRefusal> can_refine_under(const Graph3& g, const Point3& c, Balance b) {
  return bccmis::detail::can_refine_under(g, c, b);
}

BalancedRefineResult3 refine_balanced(Graph3& g, const Point3& c, Balance b) {
  return bccmis::detail::refine_balanced(g, c, b);
}

BalancedRefineResult3 refine_balanced(fast::Lattice3& g, const Point3& c, Balance b) {
  return bccmis::detail::refine_balanced(g, c, b);
}

std::optional<std::pair<Point3, Point3>> find_corner_imbalance(const Graph3& g) {
  return bccmis::detail::find_corner_imbalance(g);
}

}  // namespace bccmis::d3
