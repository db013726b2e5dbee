// bccmis::p4est_bridge, internal: every rank's leaf quadrants on one rank,
// for the 2D Quadrant and the 3D Quadrant3 alike (plain int32 fields).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace bccmis::p4est_bridge::detail {

/// `mine` from every rank of `comm`, concatenated in rank order, on `root`
/// (empty on the other ranks). Collective over comm.
template <class Q>
std::vector<Q> gather(const std::vector<Q>& mine, MPI_Comm comm, int root) {
  static_assert(sizeof(Q) % sizeof(std::int32_t) == 0);
  constexpr int kInts = static_cast<int>(sizeof(Q) / sizeof(std::int32_t));
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  const int ints = static_cast<int>(mine.size()) * kInts;
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(static_cast<std::size_t>(ranks));
  MPI_Gather(&ints, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm);
  std::vector<Q> all;
  if (rank == root) {
    int total = 0;
    for (int r = 0; r < ranks; ++r) {
      offsets[static_cast<std::size_t>(r)] = total;
      total += counts[static_cast<std::size_t>(r)];
    }
    all.resize(static_cast<std::size_t>(total / kInts));
  }
  MPI_Gatherv(mine.data(), ints, MPI_INT32_T, all.data(), counts.data(), offsets.data(), MPI_INT32_T, root, comm);
  return all;
}

}  // namespace bccmis::p4est_bridge::detail
