// spec/distributed.md D5: a piece as bytes, to send it between ranks: a
// count before each array, then its elements' bytes.
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "bccmis/distributed/leaf_piece.h"

namespace bccmis::distributed {

namespace {

template <class T>
void put(std::vector<std::byte>& out, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::uint64_t n = values.size();
  const std::size_t at = out.size();
  out.resize(at + sizeof n + n * sizeof(T));
  std::memcpy(out.data() + at, &n, sizeof n);
  if (n > 0) std::memcpy(out.data() + at + sizeof n, values.data(), n * sizeof(T));
}

template <class T>
void take(std::span<const std::byte>& in, std::vector<T>& values) {
  std::uint64_t n = 0;
  if (in.size() < sizeof n) throw std::runtime_error("a piece's bytes end early");
  std::memcpy(&n, in.data(), sizeof n);
  in = in.subspan(sizeof n);
  if (n > in.size() / sizeof(T)) throw std::runtime_error("a piece's bytes end early");
  values.resize(n);
  if (n > 0) std::memcpy(values.data(), in.data(), n * sizeof(T));
  in = in.subspan(n * sizeof(T));
}

/// visit(array) for each array of a piece, in the order of the encoding.
template <class Piece, class Visit>
void each_array(Piece& piece, Visit&& visit) {
  visit(piece.mesh.vertices);
  visit(piece.mesh.tets);
  visit(piece.mesh.kind);
  visit(piece.mesh.level);
  visit(piece.keys);
  visit(piece.leaves);
  visit(piece.leaf_begin);
  visit(piece.shared);
}

}  // namespace

std::vector<std::byte> to_bytes(const LeafPiece& piece) {
  std::vector<std::byte> out;
  each_array(piece, [&out](const auto& values) { put(out, values); });
  return out;
}

LeafPiece from_bytes(std::span<const std::byte> in) {
  LeafPiece piece;
  each_array(piece, [&in](auto& values) { take(in, values); });
  const std::size_t n = piece.mesh.vertices.size();
  bool ok = in.empty() && piece.mesh.kind.size() == n && piece.keys.size() == n && piece.shared.size() == n &&
            piece.mesh.level.size() == piece.mesh.tets.size() && piece.leaf_begin.size() == piece.leaves.size() + 1 &&
            piece.leaf_begin.back() == piece.mesh.tets.size();
  for (std::size_t i = 0; ok && i + 1 < piece.leaf_begin.size(); ++i)
    ok = piece.leaf_begin[i] <= piece.leaf_begin[i + 1];
  for (const auto& t : piece.mesh.tets)
    for (const std::uint32_t v : t) ok = ok && v < n;
  if (!ok) throw std::runtime_error("a piece's bytes are inconsistent (spec/distributed.md D4)");
  return piece;
}

}  // namespace bccmis::distributed
