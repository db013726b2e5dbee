// bccmis::distributed: isosurface stuffing split by leaves
// (spec/distributed.md D3-D5), without MPI: what one rank stuffs from a
// lattice (the whole one, or its own, D10), a piece as bytes, and the whole
// mesh gathered from the pieces.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/d3/tet_mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed {

/// D4: the part of the serial mesh made by some leaves. mesh.vertices are in
/// key order (keys[i] is vertex i's S8 key: (p, p) for lattice point p, the
/// cut edge's ends in position order); the output tetrahedra of leaves[i]
/// are mesh.tets[leaf_begin[i] .. leaf_begin[i + 1]].
struct LeafPiece {
  d3::TetMeshF mesh;
  std::vector<std::array<d3::Point, 2>> keys;
  std::vector<d3::Point> leaves;  ///< sorted (the order of cells(g))
  std::vector<std::uint32_t> leaf_begin;
  /// D7: 1 when another piece may use vertex i (its key's first point is a
  /// vertex of a ghost's tetrahedron), 0 when no other piece does.
  std::vector<std::uint8_t> shared;
  /// D11: the lattice tetrahedra of the own leaves (M1-M4), summed by
  /// merge_pieces; not in the byte encoding (to_bytes).
  std::size_t lattice_tetrahedra = 0;
};

/// D3: the own leaves a rank stuffs at once: with about 13 lattice
/// tetrahedra a leaf (96 bytes each) and its D9 leaves, a block's
/// tetrahedra stay within a few tens of megabytes.
inline constexpr std::size_t kLeavesPerBlock = 32768;

/// D9: how far beyond the own leaves a rank stuffs. `closed` is the rule
/// that makes a piece the serial one; `none` exists to show that the tests
/// catch a layer one cell too thin.
enum class LayerDepth {
  none,    ///< the own leaves alone
  closed,  ///< the ghost layer and the closure of S6's dependencies (D9)
};

/// D9: the leaves whose lattice tetrahedra a rank stuffs to decide its own
/// leaves' output as the serial run does: `own` (centers of leaves of g,
/// any order, no repeats) and the ghosts `depth` asks for, sorted. Reads
/// the shape's side at the ghost layer's vertices and its crossing on the
/// cut edges that leave the closure's set.
std::vector<d3::Point> leaves_to_stuff(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                                       const stuff::StuffOptions& options, std::span<const d3::Point> own,
                                       LayerDepth depth = LayerDepth::closed);

/// D3: S5-S9 on the tetrahedra of the leaves `stuffed` (sorted, holding
/// `own`), keeping the output of the leaves `own`. With
/// stuffed = leaves_to_stuff(..., own): exactly those tetrahedra of
/// stuff(shape, fit, g, options) made by the own leaves. Throws as stuff()
/// does (std::logic_error, S4, S12).
LeafPiece stuff_leaves(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                       const stuff::StuffOptions& options, std::span<const d3::Point> own,
                       std::span<const d3::Point> stuffed);
/// D3: the same piece made block by block: the own leaves in the order
/// given (p8est's Morton order makes a block compact) in blocks of `block`
/// leaves, each stuffed with its own D9 leaves
/// (leaves_to_stuff of the block) and the pieces merged (merge_pieces), so
/// that a rank holds the lattice tetrahedra of one block at a time.
LeafPiece stuff_leaves(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                       const stuff::StuffOptions& options, std::span<const d3::Point> own,
                       std::size_t block = kLeavesPerBlock);
/// The blocks' pieces of that stuff_leaves(), before merge_pieces (which
/// needs no lattice, so a caller can release it first). With `known` (sorted,
/// not empty), g is a rank's lattice L_r built from those leaves (D10) and
/// each block's D9 leaves are checked first: NotClosed when one of them or a
/// leaf touching it is not known (first_open).
std::vector<LeafPiece> stuff_blocks(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                                    const stuff::StuffOptions& options, std::span<const d3::Point> own,
                                    std::size_t block = kLeavesPerBlock, std::span<const d3::Point> known = {});

/// D10: the leaves a block stuffs reach beyond the leaves its rank knows
/// (`leaf`, the first open one): a wider ghost layer is needed.
struct NotClosed : std::runtime_error {
  explicit NotClosed(const d3::Point& u)
      : std::runtime_error("the leaves stuffed reach beyond the known leaves at " + d3::to_string(u) +
                           " (spec/distributed.md D10)"),
        leaf(u) {}
  d3::Point leaf;
};

/// D5: pieces whose leaves do not overlap as one piece: vertices in key
/// order, tetrahedra leaf by leaf in leaf order. Throws std::logic_error
/// when a leaf is in two pieces.
LeafPiece merge_pieces(std::span<const LeafPiece> pieces);

/// D5: the whole mesh from the pieces (merge_pieces' mesh). Pieces of every
/// leaf of the lattice give stuff()'s mesh exactly.
d3::TetMeshF gather_pieces(std::span<const LeafPiece> pieces);

/// A piece as bytes (host byte order, for MPI_BYTE between ranks of one
/// machine type) and back. from_bytes throws std::runtime_error on a
/// truncated or inconsistent encoding.
std::vector<std::byte> to_bytes(const LeafPiece& piece);
LeafPiece from_bytes(std::span<const std::byte> bytes);

}  // namespace bccmis::distributed
