// spec/distributed.md D7: one number for every vertex of the mesh across
// the pieces: the lowest rank whose piece uses a vertex owns it; owners
// number their vertices in key order after the lower ranks' (MPI_Exscan).
#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/distributed/ranks.h"

namespace bccmis::distributed {

namespace {

/// Every rank's `values` on every rank (MPI_Allgatherv of bytes), rank by rank.
template <class T>
std::vector<std::vector<T>> all_gather(const std::vector<T>& values, MPI_Comm comm) {
  int size = 0;
  MPI_Comm_size(comm, &size);
  const std::uint64_t bytes = values.size() * sizeof(T);
  if (bytes > INT_MAX) throw std::length_error("D7: too many shared vertices to exchange");
  const int count = static_cast<int>(bytes);
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size), 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::int64_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    if (total > INT_MAX) throw std::length_error("D7: too many shared vertices to exchange");
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  if (total > INT_MAX) throw std::length_error("D7: too many shared vertices to exchange");
  std::vector<T> all(static_cast<std::size_t>(total) / sizeof(T));
  MPI_Allgatherv(values.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm);
  std::vector<std::vector<T>> out;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    const auto first = all.begin() + offsets[r] / static_cast<int>(sizeof(T));
    out.emplace_back(first, first + counts[r] / static_cast<int>(sizeof(T)));
  }
  return out;
}

}  // namespace

std::vector<std::int64_t> global_ids(const LeafPiece& piece, MPI_Comm comm, std::vector<std::uint8_t>* owned_by_me) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  // The keys of the shared vertices, in key order (the piece's order).
  std::vector<std::array<d3::Point, 2>> shared;
  for (std::size_t v = 0; v < piece.keys.size(); ++v)
    if (piece.shared[v]) shared.push_back(piece.keys[v]);
  const auto keys = all_gather(shared, comm);
  const auto index_in = [&keys](int r, const std::array<d3::Point, 2>& key) -> std::ptrdiff_t {
    const auto& list = keys[static_cast<std::size_t>(r)];
    const auto at = std::lower_bound(list.begin(), list.end(), key);
    return at != list.end() && *at == key ? at - list.begin() : -1;
  };
  // The owner of each vertex: the lowest rank that uses it.
  std::vector<int> owner(piece.keys.size(), rank);
  std::int64_t owned = 0;
  for (std::size_t v = 0; v < piece.keys.size(); ++v) {
    if (piece.shared[v])
      for (int r = 0; r < rank; ++r)
        if (index_in(r, piece.keys[v]) >= 0) {
          owner[v] = r;
          break;
        }
    owned += owner[v] == rank ? 1 : 0;
  }
  std::int64_t offset = 0;
  MPI_Exscan(&owned, &offset, 1, MPI_INT64_T, MPI_SUM, comm);
  if (rank == 0) offset = 0;  // MPI_Exscan leaves rank 0's undefined
  std::vector<std::int64_t> ids(piece.keys.size(), -1);
  for (std::size_t v = 0; v < piece.keys.size(); ++v)
    if (owner[v] == rank) ids[v] = offset++;
  // The numbers of the shared vertices, in the order of `shared`, from every rank.
  std::vector<std::int64_t> shared_ids;
  for (std::size_t v = 0; v < piece.keys.size(); ++v)
    if (piece.shared[v]) shared_ids.push_back(ids[v]);
  const auto numbers = all_gather(shared_ids, comm);
  for (std::size_t v = 0; v < piece.keys.size(); ++v)
    if (owner[v] != rank)
      ids[v] = numbers[static_cast<std::size_t>(owner[v])][static_cast<std::size_t>(index_in(owner[v], piece.keys[v]))];
  if (owned_by_me) {
    owned_by_me->assign(piece.keys.size(), 0);
    for (std::size_t v = 0; v < piece.keys.size(); ++v) (*owned_by_me)[v] = owner[v] == rank ? 1 : 0;
  }
  return ids;
}

}  // namespace bccmis::distributed
