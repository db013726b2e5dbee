// bccmis::distributed: the lattice every rank builds alike in this slice
// (spec/distributed.md, "This slice replicates the lattice"): the shape in
// S24's local coordinates, the fit (S2) and the background (S3), as
// mesh_shape() makes them.
#pragma once

#include <memory>
#include <optional>
#include <span>

#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed {

struct Replicated {
  stuff::Normalisation normalisation;        ///< S24
  std::unique_ptr<stuff::Shape> shape;       ///< in local coordinates
  stuff::StuffOptions options;               ///< max_level: the level used
  stuff::Fit fit;                            ///< local
  std::optional<d3::fast::Lattice> lattice;  ///< S3; released by stuff_piece()
};

/// S24, S2, S3 for `world` as mesh_shape() does them. Throws ShapeError as
/// fit_lattice() does, and, before building anything, when the level used
/// is above `deepest` (the partition's deepest level, D2). `world` must
/// outlive the result.
Replicated replicate(const stuff::Shape& world, const stuff::StuffOptions& options, int deepest);

/// D3, D4: stuff_leaves() on the replicated lattice, the piece's vertices
/// mapped to world coordinates (S24's to_world; ShapeError as there). The
/// lattice is released once the blocks are stuffed, before their pieces
/// are merged (D3, D10): its bytes and the merge's are not held at once.
LeafPiece stuff_piece(Replicated& r, std::span<const d3::Point> own);

}  // namespace bccmis::distributed
