// spec/distributed.md D14, D15, D17: the frames of a moving shape in the
// lattice of S14, the forest built once and moved by a step a frame, each
// frame reported and, with check, its forest checked.
#include "bccmis/distributed/animate_on_ranks.h"

#include <p8est.h>

#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/stuff/animate_shape.h"
#include "bccmis/stuff/stopwatch.h"

namespace bccmis::distributed {

void animate_on_ranks(const std::shared_ptr<const stuff::Shape>& world, const RankAnimation& s, MPI_Comm comm,
                      const std::function<void(const RankFrame&)>& on_frame) {
  // S14: the serial animation's lattice, fitted once by every rank alike.
  std::optional<stuff::Fit> fit;
  on_every_rank(comm, "fitting the lattice", [&] { fit = stuff::fit_moving(*world, s.path, s.lattice); });
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  RankSettings settings;
  settings.lattice = s.lattice;
  settings.pieces = s.pieces;
  settings.gather = s.gather;
  settings.check = s.check && s.gather;  // D12's check needs the gathered mesh (D17)
  // D14: frame k in world coordinates, S24's map the identity.
  const auto frame_at = [&](int k) {
    return in_world(stuff::translated(world, stuff::frame_offset(s.path, k, s.frames)), *fit, s.lattice,
                    P8EST_QMAXLEVEL);
  };
  // D17's test hook: the forest from the brick built at frame k - 1's
  // offset, a wrong forest for the check to refuse (the same on every rank).
  const int previous_frame = std::getenv("BCCMIS_TEST_CHECK_PREVIOUS_FRAME") != nullptr ? 1 : 0;
  std::unique_ptr<Forest> forest;
  for (int k = 0; k <= s.frames; ++k) {
    const auto start = stuff::Clock::now();
    std::optional<Replicated> frame;
    on_every_rank(comm, "moving the shape", [&] { frame.emplace(frame_at(k)); });
    // D10's forest for frame 0, D15's step to frame k after.
    ForestStep step;
    on_every_rank(comm, k == 0 ? "building the forest" : "moving the forest", [&] {
      if (!forest)
        forest = std::make_unique<Forest>(*frame->shape, frame->fit, frame->options, comm);
      else
        step = forest->move_to(*frame->shape, frame->fit, frame->options, s.threshold);
    });
    const std::string name = "frame " + std::to_string(k) + ": ";
    RankFrame f;
    f.index = k;
    f.step = step;
    f.leaves = forest->global_leaves();
    RankRun run;
    settings.empty_message = stuff::empty_frame_message(*world, k, *fit);  // S26's empty frame, as the serial one
    try {
      run = stuff_on_ranks(*frame->shape, *frame, *forest, settings, comm, start);
    } catch (const stuff::CheckError& e) {  // D17 step 2, D12's check of the gathered frame
      throw stuff::CheckError(name + e.what());
    }
    f.seconds = stuff::seconds_since(start);
    // D17: the frame from the brick (after the frame's seconds: it is not
    // the frame's work), its forest checked against the moved one, its
    // stuffing timed with --compare.
    if ((s.check || s.compare) && k > 0) {
      const auto scratch_start = stuff::Clock::now();
      std::optional<Replicated> scratch;
      std::optional<Forest> built;
      on_every_rank(comm, "building the frame from the brick", [&] {
        scratch.emplace(frame_at(k - previous_frame));
        built.emplace(*scratch->shape, scratch->fit, scratch->options, comm);
      });
      if (s.compare) {
        RankSettings same = settings;  // the frame's work (its pieces, its gathering) without the check
        same.check = false;
        stuff_on_ranks(*scratch->shape, *scratch, *built, same, comm, scratch_start);
        f.scratch_seconds = stuff::seconds_since(scratch_start);
      }
      if (s.check)
        on_every_rank(comm, "checking the forest", [&] {
          const ForestDigest moved = forest_digest(*forest, comm);
          const ForestDigest expected = forest_digest(*built, comm);
          if (moved != expected && rank == 0)  // the digests are every rank's: rank 0 reports (D6)
            throw stuff::CheckError(
                name + "the moved forest differs from the forest built for the frame (" + std::to_string(moved.leaves) +
                " leaves against " + std::to_string(expected.leaves) +
                (moved.leaves == expected.leaves ? ", other leaves or order" : "") + "; spec/distributed.md D15, D17)");
        });
    }
    f.run = &run;
    on_frame(f);
  }
}

}  // namespace bccmis::distributed
