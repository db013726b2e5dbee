// spec/distributed.md: the replicated lattice (S24, S2, S3) and a rank's
// piece of the mesh on it (D3, D4).
#include "bccmis/distributed/replicated.h"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::distributed {

namespace {

stuff::Fit fit_of(const stuff::Shape& local, const stuff::Normalisation& n, stuff::StuffOptions& options) {
  if (options.size) options.size = std::ldexp(*options.size, -n.exponent);
  const stuff::Fit fit = stuff::fit_lattice(local.bounds(), options);
  options.max_level = fit.size.L;
  return fit;
}

/// D1: the partition's deepest level.
void check_deepest(int level, int deepest) {
  if (level > deepest)
    throw stuff::ShapeError("max level " + std::to_string(level) + ": the partition (p8est) reaches level " +
                            std::to_string(deepest) + " at most (spec/distributed.md D1)");
}

}  // namespace

Replicated fitted(const stuff::Shape& world, const stuff::StuffOptions& options, int deepest) {
  const stuff::Normalisation n = stuff::normalisation_of(world.bounds());
  std::unique_ptr<stuff::Shape> local = world.normalised(n);
  stuff::StuffOptions o = options;
  const stuff::Fit fit = fit_of(*local, n, o);
  check_deepest(fit.size.L, deepest);
  return Replicated{n, std::move(local), o, fit, std::nullopt};
}

Replicated in_world(std::unique_ptr<stuff::Shape> moved, const stuff::Fit& fit, const stuff::StuffOptions& options,
                    int deepest) {
  check_deepest(fit.size.L, deepest);
  stuff::StuffOptions o = options;
  o.max_level = fit.size.L;
  return Replicated{stuff::Normalisation{}, std::move(moved), o, fit, std::nullopt};
}

Replicated replicate(const stuff::Shape& world, const stuff::StuffOptions& options, int deepest) {
  Replicated r = fitted(world, options, deepest);
  r.lattice.emplace(stuff::background_fast(*r.shape, r.fit, r.options));
  return r;
}

namespace {

LeafPiece merged_in_world(const Replicated& r, std::vector<LeafPiece> blocks, stuff::StuffQuality* quality = nullptr,
                          bool world = true) {
  LeafPiece piece = blocks.size() == 1 ? std::move(blocks[0]) : merge_pieces(blocks);
  blocks = {};
  if (quality) *quality = stuff::quality(piece.mesh, 0);  // D11: S24's local coordinates, as the serial run
  if (world) stuff::to_world(piece.mesh, r.normalisation, std::ldexp(r.fit.h, r.normalisation.exponent));
  return piece;
}

}  // namespace

LeafPiece stuff_piece(Replicated& r, std::span<const d3::Point> own) {
  std::vector<LeafPiece> blocks = stuff_blocks(*r.shape, r.fit, *r.lattice, r.options, own);
  r.lattice.reset();
  return merged_in_world(r, std::move(blocks));
}

std::optional<LeafPiece> stuff_piece(Replicated& r, std::span<const d3::Point> own, std::span<const d3::Point> known,
                                     stuff::StuffQuality* quality, bool world) {
  std::vector<LeafPiece> blocks;
  try {
    blocks = stuff_blocks(*r.shape, r.fit, *r.lattice, r.options, own, kLeavesPerBlock, known);
  } catch (const NotClosed&) {
    r.lattice.reset();
    return std::nullopt;
  }
  r.lattice.reset();
  return merged_in_world(r, std::move(blocks), quality, world);
}

}  // namespace bccmis::distributed
