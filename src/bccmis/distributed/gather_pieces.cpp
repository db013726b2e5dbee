// spec/distributed.md D5: pieces merged into one (the whole mesh from the
// pieces of the ranks; a rank's piece from its blocks of leaves, D3).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "bccmis/distributed/leaf_piece.h"

namespace bccmis::distributed {

LeafPiece merge_pieces(std::span<const LeafPiece> pieces) {
  // Every vertex of every piece, in key order: (key, piece, local index).
  using Entry = std::tuple<std::array<d3::Point, 2>, std::uint32_t, std::uint32_t>;
  std::vector<Entry> entries;
  for (std::uint32_t p = 0; p < pieces.size(); ++p)
    for (std::uint32_t v = 0; v < pieces[p].keys.size(); ++v) entries.emplace_back(pieces[p].keys[v], p, v);
  std::sort(entries.begin(), entries.end());
  LeafPiece merged;
  for (const LeafPiece& piece : pieces) merged.lattice_tetrahedra += piece.lattice_tetrahedra;  // D11
  d3::TetMeshF& out = merged.mesh;
  std::vector<std::vector<std::uint32_t>> global(pieces.size());
  for (std::size_t p = 0; p < pieces.size(); ++p) global[p].resize(pieces[p].keys.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& [key, p, v] = entries[i];
    if (i == 0 || std::get<0>(entries[i - 1]) != key) {
      out.vertices.push_back(pieces[p].mesh.vertices[v]);
      out.kind.push_back(pieces[p].mesh.kind[v]);
      merged.keys.push_back(key);
      merged.shared.push_back(0);
    }
    merged.shared.back() |= pieces[p].shared[v];
    global[p][v] = static_cast<std::uint32_t>(out.vertices.size() - 1);
  }
  // The leaves in the order of cells(g): (center, piece, index in piece).
  using Leaf = std::tuple<d3::Point, std::uint32_t, std::uint32_t>;
  std::vector<Leaf> leaves;
  for (std::uint32_t p = 0; p < pieces.size(); ++p)
    for (std::uint32_t i = 0; i < pieces[p].leaves.size(); ++i) leaves.emplace_back(pieces[p].leaves[i], p, i);
  std::sort(leaves.begin(), leaves.end());
  for (std::size_t i = 1; i < leaves.size(); ++i)
    if (std::get<0>(leaves[i - 1]) == std::get<0>(leaves[i]))
      throw std::logic_error("gather_pieces: leaf " + d3::to_string(std::get<0>(leaves[i])) +
                             " is in two pieces (spec/distributed.md D2)");
  for (const auto& [center, p, i] : leaves) {
    const LeafPiece& piece = pieces[p];
    merged.leaves.push_back(center);
    merged.leaf_begin.push_back(static_cast<std::uint32_t>(out.tets.size()));
    for (std::uint32_t k = piece.leaf_begin[i]; k < piece.leaf_begin[i + 1]; ++k) {
      std::array<std::uint32_t, 4> t = piece.mesh.tets[k];
      for (std::uint32_t& v : t) v = global[p][v];
      out.tets.push_back(t);
      out.level.push_back(piece.mesh.level[k]);
    }
  }
  merged.leaf_begin.push_back(static_cast<std::uint32_t>(out.tets.size()));
  return merged;
}

d3::TetMeshF gather_pieces(std::span<const LeafPiece> pieces) { return merge_pieces(pieces).mesh; }

}  // namespace bccmis::distributed
