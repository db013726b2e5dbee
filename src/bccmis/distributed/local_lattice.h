// bccmis::distributed: the lattice a rank builds from the leaves it knows
// (spec/distributed.md D10), without MPI: L_r from N_r, and the check that
// the leaves a rank stuffs are surrounded by known leaves.
#pragma once

#include <optional>
#include <span>

#include "bccmis/d3/point.h"
#include "bccmis/fast/d3/lattice.h"

namespace bccmis::distributed {

/// D10: L_r, the level-0 lattice of `size` with every proper ancestor of
/// every leaf in `known` refined, coarsest first, through the cascade (edge
/// mode). When `known` are leaves of an S3 lattice G, each of them is a leaf
/// of L_r and L_r is nowhere finer than G. Throws std::invalid_argument on a
/// point that is not a cell center of some level of `size`.
d3::fast::Lattice local_lattice(const d3::LatticeSize& size, std::span<const d3::Point> known);

/// D10's condition: the first leaf u of `stuffed` (in its order) that is not
/// in `known` or touches (closed cubes meet) a leaf of l not in `known`;
/// nothing when every leaf of `stuffed` and every leaf touching one is known.
/// `known` sorted.
std::optional<d3::Point> first_open(const d3::fast::Lattice& l, std::span<const d3::Point> known,
                                    std::span<const d3::Point> stuffed);

}  // namespace bccmis::distributed
