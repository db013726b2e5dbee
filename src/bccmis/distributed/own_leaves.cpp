// spec/distributed.md D2: the leaves of a rank, partitioned by p8est.
#include <vector>

#include "bccmis/distributed/ranks.h"
#include "bccmis/p4est/bridge.h"

namespace bccmis::distributed {

std::vector<d3::Point> own_leaves(const d3::fast::Lattice& g, MPI_Comm comm) {
  using namespace p4est_bridge;
  const BrickOf<3> brick(g.size());
  std::vector<LeafOf<3>> leaves;
  for (const d3::Point& c : g.cells()) leaves.push_back({c, g.level_of(c)});
  const ForestPtrOf<3> forest = make_forest<3>(brick, leaves, comm);
  P4<3>::partition(forest.get(), 1, nullptr);  // uniform by count, families kept whole (D2, D15)
  std::vector<d3::Point> own;
  for (const QuadrantOf<3>& q : local_quadrants(forest.get())) own.push_back(brick.to_leaf(q).center);
  return own;
}

}  // namespace bccmis::distributed
