// spec/distributed.md D3: what one rank stuffs: its own leaves and the
// leaves of D9, keeping the output of its own.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bccmis/d3/detail/tetrahedra.h"
#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/distributed/local_lattice.h"

namespace bccmis::distributed {

std::vector<LeafPiece> stuff_blocks(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                                    const stuff::StuffOptions& options, std::span<const d3::Point> own,
                                    std::size_t block, std::span<const d3::Point> known) {
  // The blocks follow the order of `own` (D3: any split gives the same
  // piece): p8est's Morton order (D2) makes a block compact, so its ghost
  // layer is thin.
  std::vector<LeafPiece> pieces;
  for (std::size_t first = 0; first < own.size() || first == 0; first += std::max<std::size_t>(block, 1)) {
    const std::span<const d3::Point> leaves = own.subspan(first, std::min(block, own.size() - first));
    // D10: on a rank's lattice, the stuffed leaves' tetrahedra (and with
    // them D9's closure, read from them) are G's when every leaf touching
    // one is known. Beyond the known leaves the lattice is coarser than G,
    // where D9's walk may ask a point that is no center: that walk is open.
    std::vector<d3::Point> stuffed;
    if (known.empty()) {
      stuffed = leaves_to_stuff(shape, fit, g, options, leaves);
    } else {
      try {
        stuffed = leaves_to_stuff(shape, fit, g, options, leaves);
      } catch (const std::out_of_range&) {
        throw NotClosed(leaves.front());
      }
      if (const std::optional<d3::Point> open = first_open(g, known, stuffed)) throw NotClosed(*open);
    }
    pieces.push_back(stuff_leaves(shape, fit, g, options, leaves, stuffed));
  }
  return pieces;
}

LeafPiece stuff_leaves(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                       const stuff::StuffOptions& options, std::span<const d3::Point> own, std::size_t block) {
  std::vector<LeafPiece> pieces = stuff_blocks(shape, fit, g, options, own, block);
  return pieces.size() == 1 ? std::move(pieces[0]) : merge_pieces(pieces);
}

LeafPiece stuff_leaves(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                       const stuff::StuffOptions& options, std::span<const d3::Point> own,
                       std::span<const d3::Point> stuffed) {
  std::vector<d3::Point> mine(own.begin(), own.end());
  std::sort(mine.begin(), mine.end());
  // T_r (D3): the tetrahedra of the stuffed leaves, leaf by leaf in the
  // order of cells(g); own_range[i]: where own leaf i's lattice tetrahedra
  // are in `tets`.
  std::vector<d3::Tet> tets;
  std::vector<std::array<std::size_t, 2>> own_range;
  for (const d3::Point& u : stuffed) {
    const std::size_t first = tets.size();
    d3::detail::leaf_tetrahedra(g, u, tets);
    if (std::binary_search(mine.begin(), mine.end(), u)) own_range.push_back({first, tets.size()});
  }
  const stuff::StuffedPart part = stuff::stuff_part(shape, fit, g, options, tets);
  // D7: the vertices of the ghosts' tetrahedra, sorted.
  std::vector<d3::Point> ghost_points;
  for (std::size_t k = 0, next = 0; k < tets.size(); ++k) {
    while (next < own_range.size() && own_range[next][1] <= k) ++next;
    if (next < own_range.size() && own_range[next][0] <= k) continue;
    ghost_points.insert(ghost_points.end(), tets[k].begin(), tets[k].end());
  }
  std::sort(ghost_points.begin(), ghost_points.end());
  ghost_points.erase(std::unique(ghost_points.begin(), ghost_points.end()), ghost_points.end());
  tets = {};
  const d3::TetMeshF& all = part.stuffed.mesh;
  // Keep the output of the own leaves and the vertices it uses, in the
  // part's vertex order (S8's key order).
  LeafPiece piece;
  piece.leaves = mine;
  for (const auto& [first, last] : own_range) piece.lattice_tetrahedra += last - first;  // D11
  std::vector<std::uint8_t> used(all.vertices.size(), 0);
  for (const auto& [first, last] : own_range)
    for (std::uint32_t k = part.begin[first]; k < part.begin[last]; ++k)
      for (const std::uint32_t v : all.tets[k]) used[v] = 1;
  std::vector<std::uint32_t> index(all.vertices.size(), 0);
  for (std::size_t v = 0; v < all.vertices.size(); ++v) {
    if (!used[v]) continue;
    index[v] = static_cast<std::uint32_t>(piece.mesh.vertices.size());
    piece.mesh.vertices.push_back(all.vertices[v]);
    piece.mesh.kind.push_back(all.kind[v]);
    piece.keys.push_back(part.keys[v]);
    piece.shared.push_back(std::binary_search(ghost_points.begin(), ghost_points.end(), part.keys[v][0]) ? 1 : 0);
  }
  for (const auto& [first, last] : own_range) {
    piece.leaf_begin.push_back(static_cast<std::uint32_t>(piece.mesh.tets.size()));
    for (std::uint32_t k = part.begin[first]; k < part.begin[last]; ++k) {
      std::array<std::uint32_t, 4> t = all.tets[k];
      for (std::uint32_t& v : t) v = index[v];
      piece.mesh.tets.push_back(t);
      piece.mesh.level.push_back(all.level[k]);
    }
  }
  piece.leaf_begin.push_back(static_cast<std::uint32_t>(piece.mesh.tets.size()));
  return piece;
}

}  // namespace bccmis::distributed
