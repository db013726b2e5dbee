// bccmis::d3: positions and sizes of the 3D lattice (spec/lattice3d.md §1,
// spec/formats.md "3D extension"): the 3D instances of the one source for
// every dimension, bccmis/point.h. Part of the core library, beside the 2D
// Point and LatticeSize, so that the interchange formats read and write both
// dimensions; the 3D graph and its operations are the bccmis_d3 library.
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>

#include "bccmis/point.h"

namespace bccmis::d3 {

/// A 3D lattice position, ordered by (x, y, z).
using Point = BasicPoint<Dimension>;
using PointSet = std::set<Point>;

/// A hash of a 3D lattice position for hash tables: each coordinate times
/// an odd constant of its own, xor-ed, then the high bits folded down.
struct PointHash {
  std::size_t operator()(const Point& p) const noexcept {
    const std::uint64_t h = static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ull ^
                            static_cast<std::uint64_t>(p.y) * 0xC2B2AE3D27D4EB4Full ^
                            static_cast<std::uint64_t>(p.z) * 0x165667B19E3779F9ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// The size of a 3D lattice: W x H x D level-0 cubes, at most L refinements
/// deep.
using LatticeSize = BasicLatticeSize<Dimension>;

/// Throws bccmis::LatticeError unless W, H, D >= 1, L >= 0 and the extents
/// W*S, H*S, D*S are at most 2^62. The message names the offending value.
void validate_lattice_size(const LatticeSize& size);

// to_string(point), level0_side(size) and cell_side(size, level), written
// once for every dimension (bccmis/point.h).
using bccmis::cell_side;
using bccmis::level0_side;
using bccmis::to_string;

}  // namespace bccmis::d3
