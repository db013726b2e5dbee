// spec/distributed.md D17: a forest's leaves as a count and an
// order-sensitive sum, to check a moved forest against one built from the
// brick.
#include <mpi.h>

#include <cstdint>
#include <span>
#include <vector>

#include "bccmis/distributed/ranks.h"

namespace bccmis::distributed {

namespace {

// splitmix64's finalizer.
std::uint64_t finalize(std::uint64_t k) {
  k = (k ^ (k >> 30)) * 0xBF58476D1CE4E5B9ull;
  k = (k ^ (k >> 27)) * 0x94D049BB133111EBull;
  return k ^ (k >> 31);
}

// D17's h: the finalizer chained over the center's three coordinates.
std::uint64_t leaf_hash(const d3::Point& c) {
  std::uint64_t h = finalize(static_cast<std::uint64_t>(c.x));
  h = finalize(h ^ static_cast<std::uint64_t>(c.y));
  return finalize(h ^ static_cast<std::uint64_t>(c.z));
}

}  // namespace

std::uint64_t leaves_digest(std::uint64_t first, std::span<const d3::Point> leaves) {
  std::uint64_t sum = 0;  // unsigned: the sum and products are mod 2^64
  std::uint64_t i = first;
  for (const d3::Point& c : leaves) sum += (2 * i++ + 1) * leaf_hash(c);
  return sum;
}

ForestDigest forest_digest(const Forest& forest, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::vector<std::int64_t> counts = forest.leaves_per_rank();
  std::uint64_t first = 0;  // this rank's first global index
  for (int r = 0; r < rank; ++r) first += static_cast<std::uint64_t>(counts[static_cast<std::size_t>(r)]);
  const std::uint64_t sum = leaves_digest(first, forest.own());
  ForestDigest d;
  d.leaves = forest.global_leaves();
  MPI_Allreduce(&sum, &d.sum, 1, MPI_UINT64_T, MPI_SUM, comm);
  return d;
}

}  // namespace bccmis::distributed
