// bccmis::distributed::animate_on_ranks: the frames of a shape moving
// along a straight path, each meshed on every rank in the serial
// animation's lattice (spec/distributed.md D14), the forest kept and moved
// by a step a frame (D15), reported and checked per frame (D17), the entry
// point of `bccmis-mpi stuff --animate`.
#pragma once

#include <mpi.h>

#include <cstdint>
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
  stuff::StuffOptions lattice;  ///< -L, --min-level, --cells, --size, --threads
  int frames = 1;               ///< steps after frame 0 (> 0)
  stuff::Vec3 path{};           ///< the whole motion: frame k at offset k path / frames (S15)
  bool pieces = false;          ///< a .vtu piece per rank and frame: D7's global ids
  bool gather = false;          ///< each frame's whole mesh on rank 0 (D5)
  bool check = false;           ///< D17: the moved forest against the built one; D12's check (gather)
  bool compare = false;         ///< D17: also every later frame from the brick (its forest and stuffing), timed
  double threshold = kRepartitionThreshold;  ///< D15: repartitioned when the imbalance exceeds it
};

/// One frame, as animate_on_ranks() hands it on (D17's report).
struct RankFrame {
  int index = 0;
  RankRun* run = nullptr;      ///< valid during the call only; the callback may take its contents
  ForestStep step;             ///< D15's step to this frame (frame 0: all zero)
  std::int64_t leaves = 0;     ///< the forest's global leaf count
  double seconds = 0;          ///< rank 0's wall seconds from moving the shape to the end of the stuffing
  double scratch_seconds = 0;  ///< with compare, frames after 0: the same frame built from the brick
};

/// D14 on every rank: the lattice fitted to the swept box (S14,
/// fit_moving), then for k = 0 .. frames the shape translated by
/// frame_offset(path, k, frames) meshed by stuff_on_ranks in that lattice,
/// in world coordinates, on D10's forest (frame 0) moved by D15's step
/// (later frames), and handed to `on_frame` on every rank (which may run
/// collectives: every rank calls it for the same frame). With `check`,
/// D17: every later frame's moved forest compared with D10's forest built
/// for it (forest_digest), and D12's check on the gathered frame.
/// Collective over `comm`; each step ends with D6's agreement: the lowest
/// failing rank throws its error (ShapeError, an empty frame's, worded by
/// empty_frame_message as the serial animation's, or CheckError, a check's,
/// prefixed "frame K: "), every other rank RankFailed. A test hook (D17):
/// with BCCMIS_TEST_CHECK_PREVIOUS_FRAME set in every rank's environment,
/// the check's forest is built at frame k - 1's offset, so the check fails.
void animate_on_ranks(const std::shared_ptr<const stuff::Shape>& world, const RankAnimation& s, MPI_Comm comm,
                      const std::function<void(const RankFrame&)>& on_frame);

}  // namespace bccmis::distributed
