// bccmis::distributed: what every rank holds alike (spec/distributed.md):
// the shape in S24's local coordinates and the fit (S2), as mesh_shape()
// makes them, and a lattice: the whole background (S3, replicate()) or the
// rank's own (D10, local_lattice()).
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
  std::optional<d3::fast::Lattice> lattice;  ///< S3 or D10's L_r; released by stuff_piece()
};

/// S24 and S2 for `world` as mesh_shape() does them, without the lattice
/// (D10: each rank then builds its own, local_lattice()). Throws as
/// replicate() does.
Replicated fitted(const stuff::Shape& world, const stuff::StuffOptions& options, int deepest);

/// D14: `moved` (world coordinates, owned) in the lattice `fit` (S14's,
/// fitted to the box the shape sweeps), with S24's map the identity: the
/// serial animation runs in world coordinates. Throws ShapeError as
/// fitted() does when fit's level is above `deepest`.
Replicated in_world(std::unique_ptr<stuff::Shape> moved, const stuff::Fit& fit, const stuff::StuffOptions& options,
                    int deepest);

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
/// D10: the same on a rank's lattice r.lattice = local_lattice(known):
/// nothing (the lattice released) when a block's leaves are not closed in
/// `known` (stuff_blocks' NotClosed): the rank needs a wider ghost layer.
/// With `quality`: S13's quality of the piece's tetrahedra (no boundary
/// count) in S24's local coordinates, before the world map (D11). With
/// `world` false the piece stays in local coordinates (D12: mapped once
/// gathered, after the feature step).
std::optional<LeafPiece> stuff_piece(Replicated& r, std::span<const d3::Point> own, std::span<const d3::Point> known,
                                     stuff::StuffQuality* quality = nullptr, bool world = true);

}  // namespace bccmis::distributed
