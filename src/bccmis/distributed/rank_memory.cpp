// spec/distributed.md D16: S25's estimate split over the ranks (rank_memory.h).
#include "bccmis/distributed/rank_memory.h"

#include <cmath>
#include <string>

namespace bccmis::distributed {

double rank_bytes(double leaves, const RankRole& role) {
  double bytes = kRankBytesPerLeaf * leaves / role.ranks;  // 1. the rank's share
  if (role.rank != 0) return bytes;
  if (role.gathers) bytes += kGatheredMeshes * stuff::kSecondMeshBytesPerLeaf * leaves;  // 2. D12's copies
  if (role.crease_cuts) bytes += stuff::kBytesPerLeaf * leaves;  // 3. S35.8's B (or C) on rank 0
  return bytes;
}

void refuse_what_will_not_fit_on_rank(const stuff::Shape& shape, const stuff::StuffOptions& options,
                                      double available_bytes, const RankRole& role) {
  // S25: every cube when that fits, else the probe (which never exceeds every cube).
  const double every_cube = stuff::estimate_memory(shape, options, HUGE_VAL).leaves;
  if (rank_bytes(every_cube, role) <= available_bytes) return;
  const double leaves = stuff::estimate_memory(shape, options, -1).leaves;
  const double bytes = rank_bytes(leaves, role);
  if (bytes <= available_bytes) return;
  const std::string per_leaf = std::to_string(static_cast<int>(kRankBytesPerLeaf)) + " bytes per estimated leaf";
  const std::string ranks = std::to_string(role.ranks) + " rank" + (role.ranks == 1 ? "" : "s");
  std::string how = per_leaf + " over " + ranks;
  if (role.rank == 0 && role.gathers)
    how += ", and " + std::to_string(static_cast<int>(kGatheredMeshes)) + " x " +
           std::to_string(static_cast<int>(stuff::kSecondMeshBytesPerLeaf)) + " for the mesh gathered on rank 0" +
           (role.crease_cuts
                ? ", and " + std::to_string(static_cast<int>(stuff::kBytesPerLeaf)) + " for S35.8's candidates"
                : "");
  throw stuff::ShapeError(stuff::too_much_memory(stuff::fit_lattice(shape.bounds(), options).size.L, leaves, bytes,
                                                 available_bytes,
                                                 "on rank " + std::to_string(role.rank) + " by D16's estimate", how,
                                                 " to a rank", stuff::coarsest_max_level(options)));
}

}  // namespace bccmis::distributed
