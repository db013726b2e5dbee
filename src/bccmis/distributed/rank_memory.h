// bccmis::distributed::rank_memory: S25's estimate before building, split
// over the ranks of bccmis-mpi stuff (spec/distributed.md D16): what one
// rank's peak will hold, from the leaves S25 estimates for the whole run.
#pragma once

#include "bccmis/stuff/memory_estimate.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed {

/// D16: where a rank stands in the run, for its estimate.
struct RankRole {
  int rank = 0;
  int ranks = 1;
  bool gathers = false;      ///< the mesh gathered on rank 0 (--gather, or D12's features, --check, --hausdorff)
  bool crease_cuts = false;  ///< S35.8's candidates B and C made on rank 0 (D16)
};

/// D16: the bytes a rank's peak holds per estimated leaf of its share
/// (E / P), measured on ranks: the sphere at level 5 on 2 ranks peaked at
/// 3,660 bytes per leaf of its share (rank 0, 355 MB of 97,000), more than
/// one process's 1,900 (S25): a rank's piece keeps S8's keys, its blocks
/// their ghosts, and MPI its buffers.
inline constexpr double kRankBytesPerLeaf = 3700;

/// D16: the whole meshes (kSecondMeshBytesPerLeaf each) rank 0 holds while
/// gathering: D12's three copies (the bytes, the pieces decoded, the
/// gathered mesh), the first two carrying S8's key beside each vertex, so
/// about four meshes' bytes (measured: 1,400-1,680 bytes a leaf).
inline constexpr double kGatheredMeshes = 4;

/// D16: rank `role.rank`'s peak bytes for a run whose leaves S25 estimates
/// at `leaves` (E): its share of the stuffing, kRankBytesPerLeaf E / P (D2:
/// uniform by count; D10: no rank builds the whole lattice); on rank 0 with
/// the mesh gathered, plus D12's copies of the whole mesh
/// (kGatheredMeshes kSecondMeshBytesPerLeaf E); with --crease-cuts, plus S35.8's serial
/// candidate B (or C) beside them (S25's one-process estimate,
/// kBytesPerLeaf E).
double rank_bytes(double leaves, const RankRole& role);

/// D16: throws stuff::ShapeError, with S25's message naming the rank, when
/// rank_bytes() of S25's leaves for `shape` (local coordinates, `options`
/// at the fitted level) exceeds `available_bytes`; equal fits. The leaves
/// are every cube of the fitted lattice when their rank_bytes() fits, else
/// S25's probe (estimate_memory), as one process does.
void refuse_what_will_not_fit_on_rank(const stuff::Shape& shape, const stuff::StuffOptions& options,
                                      double available_bytes, const RankRole& role);

}  // namespace bccmis::distributed
