// bccmis::distributed::animate_on_ranks: the frames of a shape moving
// along a straight path, each meshed on every rank in the serial
// animation's lattice (spec/distributed.md D14), the forest kept and moved
// by a step a frame (D15), the entry point of `bccmis-mpi stuff --animate`.
#pragma once

#include <mpi.h>

#include <functional>
#include <memory>

#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/repartition.h"
#include "bccmis/distributed/stuff_on_ranks.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed {

/// What an animation on ranks is told (D14).
struct RankAnimation {
  stuff::StuffOptions lattice;               ///< -L, --min-level, --cells, --size, --threads
  int frames = 1;                            ///< steps after frame 0 (> 0)
  stuff::Vec3 path{};                        ///< the whole motion: frame k at offset k path / frames (S15)
  bool pieces = false;                       ///< a .vtu piece per rank and frame: D7's global ids
  bool gather = false;                       ///< each frame's whole mesh on rank 0 (D5)
  double threshold = kRepartitionThreshold;  ///< D15: repartitioned when the imbalance exceeds it
};

/// D14 on every rank: the lattice fitted to the swept box (S14,
/// fit_moving), then for k = 0 .. frames the shape translated by
/// frame_offset(path, k, frames) meshed by stuff_on_ranks in that lattice,
/// in world coordinates, on D10's forest (frame 0) moved by D15's step
/// (later frames, `step` what it did; frame 0's all zero), and handed to
/// `on_frame(k, run, step)` on every rank (which may run collectives:
/// every rank calls it for the same k).
/// Collective over `comm`; each step ends with D6's agreement: the lowest
/// failing rank throws its error (ShapeError, an empty frame's prefixed
/// "frame K: "), every other rank RankFailed.
void animate_on_ranks(const std::shared_ptr<const stuff::Shape>& world, const RankAnimation& s, MPI_Comm comm,
                      const std::function<void(int, RankRun&, const ForestStep&)>& on_frame);

}  // namespace bccmis::distributed
