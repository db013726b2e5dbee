// bccmis::distributed on MPI ranks (spec/distributed.md D2, D5, D6): the
// partition of the leaves by p8est, the agreement on a status, and the
// pieces sent to one rank. Every function is collective over `comm`.
#pragma once

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/fast/d3/lattice.h"

namespace bccmis::distributed {

/// D2: this rank's leaves of g (the same lattice on every rank): the leaves
/// of its octants after p8est_partition of the forest of g's leaves on the
/// brick of its level-0 cubes. Throws std::invalid_argument when L is above
/// P8EST_QMAXLEVEL (18).
std::vector<d3::Point> own_leaves(const d3::fast::Lattice& g, MPI_Comm comm);

/// D6: what the ranks agree on after a stage: the lowest rank whose `code`
/// is not 0 and its code, or {-1, 0} when every rank succeeded.
struct Agreement {
  int rank = -1;
  int code = 0;
  bool ok() const { return rank < 0; }
};
Agreement agree(int code, MPI_Comm comm);

/// D7: the global number of each vertex of this rank's piece (in the
/// piece's order): 0 .. n-1 over the n vertices of the mesh, the same for
/// one key on every rank, the serial numbering on one rank.
std::vector<std::int64_t> global_ids(const LeafPiece& piece, MPI_Comm comm);

/// D5: every rank's bytes on `root` (in rank order; empty elsewhere).
/// Throws std::length_error (on every rank) when the ranks hold 2^31 or
/// more bytes in all.
std::vector<std::vector<std::byte>> gather_bytes(std::span<const std::byte> bytes, int root, MPI_Comm comm);

}  // namespace bccmis::distributed
