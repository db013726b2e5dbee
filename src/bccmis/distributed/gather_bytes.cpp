// spec/distributed.md D5: every rank's bytes on one rank (MPI_Gatherv).
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/distributed/ranks.h"

namespace bccmis::distributed {

std::vector<std::vector<std::byte>> gather_bytes(std::span<const std::byte> bytes, int root, MPI_Comm comm) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // MPI_Gatherv counts and offsets in int: every rank learns whether the
  // pieces are too large, before any rank waits in MPI_Gatherv.
  std::uint64_t total = bytes.size();
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_UINT64_T, MPI_SUM, comm);
  if (total > INT_MAX)
    throw std::length_error("the pieces hold " + std::to_string(total) +
                            " bytes, too many to gather on one rank (at most 2^31 - 1); write a .pvtu instead");
  const int count = static_cast<int>(bytes.size());
  std::vector<int> counts(rank == root ? static_cast<std::size_t>(size) : 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm);
  std::vector<int> offsets(counts.size(), 0);
  std::vector<std::byte> all;
  if (rank == root) {
    for (std::size_t r = 1; r < counts.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(bytes.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, root, comm);
  std::vector<std::vector<std::byte>> out;
  for (std::size_t r = 0; r < counts.size(); ++r)
    out.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
  return out;
}

}  // namespace bccmis::distributed
