// bccmis::distributed on MPI ranks (spec/distributed.md D2, D5, D6): the
// partition of the leaves by p8est, the agreement on a status, and the
// pieces sent to one rank. Every function is collective over `comm`.
#pragma once

#include <mpi.h>
#include <p8est_ghost.h>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/p4est/bridge.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed {

/// D2: this rank's leaves of g (the same lattice on every rank): the leaves
/// of its octants after p8est_partition of the forest of g's leaves on the
/// brick of its level-0 cubes. Throws std::invalid_argument when L is above
/// P8EST_QMAXLEVEL (18).
std::vector<d3::Point> own_leaves(const d3::fast::Lattice& g, MPI_Comm comm);

/// D10: the forest of the S3 lattice built by p8est on every rank at once
/// (p8est_new on the brick of the level-0 cubes, p8est_refine with S3's
/// test, p8est_balance in edge mode, repeated until no leaf passes the test;
/// p8est_partition uniform by count, families kept whole, D2, D15), and this rank's ghost layer
/// (p8est_ghost, P8EST_CONNECT_FULL, expanded to kGhostLayers layers),
/// widened by expand(). No rank holds
/// the whole lattice. Collective over `comm` (construction and expand()).
/// D10: the layers of leaves around the own ones a rank knows from the
/// start: D9's leaves reach two layers out (an own leaf, a center across
/// its face, the leaves across that center's faces) and each needs its
/// touching leaves known, one more.
inline constexpr int kGhostLayers = 4;

namespace detail {
struct S3Test;
}

/// D15: what a step of a moving shape did to the forest (every rank's).
struct ForestStep {
  std::int64_t coarsened = 0;  ///< families replaced by their parent (step 1)
  std::int64_t refined = 0;    ///< leaves refined, by the test or the balance (step 2)
  int corrections = 0;         ///< partitions corrected for a split family (step 1)
  double imbalance = 1;        ///< before step 3: max_r n_r / (N / P)
  bool repartitioned = false;  ///< step 3
};

class Forest {
 public:
  /// Throws std::invalid_argument when L is above P8EST_QMAXLEVEL (18).
  /// When S3's test throws on some rank, every rank throws (D6): the lowest
  /// such rank its test's exception, the others RankFailed naming
  /// that rank.
  Forest(const stuff::Shape& shape, const stuff::Fit& fit, const stuff::StuffOptions& options, MPI_Comm comm);
  ~Forest();
  Forest(const Forest&) = delete;
  Forest& operator=(const Forest&) = delete;

  /// This rank's leaves (centers) in p8est's order (D2).
  std::vector<d3::Point> own() const;
  /// N_r: the own leaves and the ghost layer's, sorted.
  std::vector<d3::Point> known() const;
  /// One more layer of ghosts (p8est_ghost_expand). Collective.
  void expand();
  /// The leaves of every rank.
  std::int64_t global_leaves() const;
  /// The leaves of each rank, in rank order.
  std::vector<std::int64_t> leaves_per_rank() const;

  /// D15: the forest moved to S3's lattice for `shape` (the same fit and
  /// options): families whose parent fails S3's test coarsened, the
  /// partition corrected while such a family is split between ranks, then
  /// D10's refine and balance loop; p8est_partition (for coarsening) when
  /// the imbalance exceeds `threshold` (repartition_needed); the ghost
  /// layer rebuilt. Collective; S3's test throwing on a rank throws on
  /// every rank as the constructor does (D6).
  ForestStep move_to(const stuff::Shape& shape, const stuff::Fit& fit, const stuff::StuffOptions& options,
                     double threshold);

 private:
  /// D10's loop: refine by `test` to level L and balance until the leaves
  /// stop changing, partitioned each round when `partition`.
  void refine_and_balance(detail::S3Test& test, int L, bool partition);
  /// The ghost layer, kGhostLayers deep, built again.
  void build_ghost();

  p4est_bridge::Brick3 brick_;
  p4est_bridge::Forest3Ptr forest_;
  p8est_ghost_t* ghost_ = nullptr;
};

/// D17: a forest's leaves, to compare two forests of the same fit without
/// gathering them: the global count and the sum over the leaves, in
/// p8est's global order, of (2i + 1) h(center), mod 2^64 (i the global
/// index, h splitmix64 over the coordinates).
struct ForestDigest {
  std::int64_t leaves = 0;
  std::uint64_t sum = 0;
  bool operator==(const ForestDigest&) const = default;
};

/// D17: one rank's term of the sum: its leaves `leaves` in order, the
/// first at global index `first`.
std::uint64_t leaves_digest(std::uint64_t first, std::span<const d3::Point> leaves);

/// D17: `forest`'s digest, the same on every rank. Collective over `comm`.
ForestDigest forest_digest(const Forest& forest, MPI_Comm comm);

/// D6: thrown on every rank but the failing one when a collective step
/// failed on another rank (`rank`, the lowest that failed), which throws
/// its own error.
struct RankFailed : std::runtime_error {
  RankFailed(int failed, const std::string& what)
      : std::runtime_error("rank " + std::to_string(failed) + ": " + what), rank(failed) {}
  int rank;
};

/// D6: the ranks agree (one MPI_Allreduce) on whether a step failed; when
/// one did, every rank throws: the lowest failing rank rethrows `failed`,
/// the others RankFailed naming it and `what` (the step).
void rethrow_on_every_rank(const std::exception_ptr& failed, const std::string& what, MPI_Comm comm);

/// D6: `body` on this rank, then rethrow_on_every_rank: the lowest failing
/// rank rethrows its error, every other rank throws RankFailed. A
/// RankFailed inside `body` (a collective step failed on another rank) is
/// that rank's to report.
template <class Body>
void on_every_rank(MPI_Comm comm, const std::string& what, Body&& body) {
  std::exception_ptr failed;
  try {
    body();
  } catch (const RankFailed&) {
  } catch (...) {
    failed = std::current_exception();
  }
  rethrow_on_every_rank(failed, what, comm);
}

/// D6, D10: this rank's piece (D3, D4), stuffed on its lattice L_r
/// (local_lattice of the leaves it knows) with one more layer of ghosts
/// (forest.expand()) while some rank's stuffed leaves are open; every rank
/// leaves the loop in the same round. An exception on one rank ends the
/// loop on every rank (rethrow_on_every_rank). `r` as fitted() made it;
/// r.lattice is released. Collective over `comm`. With `quality`, the
/// piece's S13 quality in local coordinates (stuff_piece, D11). With
/// `world` false, the piece in S24's local coordinates (D12).
LeafPiece stuff_own_piece(Replicated& r, Forest& forest, MPI_Comm comm, stuff::StuffQuality* quality = nullptr,
                          bool world = true);

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
/// one key on every rank, the serial numbering on one rank. With `owned`:
/// 1 for the vertices this rank owns (the lowest rank using them), else 0.
std::vector<std::int64_t> global_ids(const LeafPiece& piece, MPI_Comm comm, std::vector<std::uint8_t>* owned = nullptr);

/// D11: S13's statistics of the mesh the ranks' pieces make, reduced on
/// rank 0 (elsewhere an empty Meshed): `piece` (world coordinates) and its
/// `quality` in local ones (stuff_own_piece), `ids` and `owned` from
/// global_ids, `leaves` the forest's count; `world` the shape as read and
/// `r` as fitted() made it. The statistics, S27's topology and the warnings
/// of S26 and S27 (from the boundary gathered on rank 0 as triples of
/// global ids), the soup report; no Hausdorff distance, no seconds.
/// Collective; after the last collective, rank 0 throws ShapeError when a
/// component is lost (S27, mesh_warnings).
stuff::Meshed rank_statistics(const stuff::Shape& world, const Replicated& r, const LeafPiece& piece,
                              const stuff::StuffQuality& quality, std::span<const std::int64_t> ids,
                              std::span<const std::uint8_t> owned, std::int64_t leaves, MPI_Comm comm);

/// D5: every rank's bytes on `root` (in rank order; empty elsewhere).
/// Throws std::length_error (on every rank) when the ranks hold 2^31 or
/// more bytes in all.
std::vector<std::vector<std::byte>> gather_bytes(std::span<const std::byte> bytes, int root, MPI_Comm comm);

}  // namespace bccmis::distributed
