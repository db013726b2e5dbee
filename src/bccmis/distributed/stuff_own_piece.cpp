// spec/distributed.md D6, D10: a rank's piece on its own lattice, the ghost
// layer widened a round while some rank's stuffed leaves are open.
#include <cstdint>
#include <exception>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bccmis/distributed/local_lattice.h"
#include "bccmis/distributed/ranks.h"

namespace bccmis::distributed {

LeafPiece stuff_own_piece(Replicated& r, Forest& forest, MPI_Comm comm, stuff::StuffQuality* quality, bool world) {
  const std::vector<d3::Point> own = forest.own();
  std::optional<LeafPiece> piece;
  for (;;) {
    std::exception_ptr failed;
    if (!piece) try {
        const std::vector<d3::Point> known = forest.known();
        r.lattice.emplace(local_lattice(r.fit.size, known));
        piece = stuff_piece(r, own, known, quality, world);
        if (!piece && static_cast<std::int64_t>(known.size()) == forest.global_leaves())
          throw std::logic_error("every leaf is known and the stuffed leaves are still open (spec/distributed.md D10)");
      } catch (...) {
        r.lattice.reset();
        failed = std::current_exception();
      }
    // D6: an exception on one rank ends the loop on every rank.
    rethrow_on_every_rank(failed, "stuffing its piece", comm);
    // D10: every rank leaves the loop in the round no rank is open.
    int open = piece ? 0 : 1;
    MPI_Allreduce(MPI_IN_PLACE, &open, 1, MPI_INT, MPI_MAX, comm);
    if (open == 0) return std::move(*piece);
    forest.expand();
  }
}

}  // namespace bccmis::distributed
