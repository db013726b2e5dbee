// bccmis::d3: positions and sizes of the 3D lattice (spec/lattice3d.md §1,
// spec/formats.md "3D extension"). Part of the core library, beside the 2D
// Point and LatticeSize, so that the interchange formats read and write both
// dimensions; the 3D graph and its operations are the bccmis_d3 library.
#pragma once

#include <compare>
#include <cstdint>
#include <set>
#include <string>

#include "bccmis/graph.h"  // LatticeError, kMaxDomainSide, level0_side, cell_side

namespace bccmis::d3 {

/// A lattice position in integer coordinates, ordered by (x, y, z).
struct Point {
  static constexpr int dimension = 3;
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  friend auto operator<=>(const Point&, const Point&) = default;
  friend bool operator==(const Point&, const Point&) = default;
};

using PointSet = std::set<Point>;

/// "(x, y, z)": how messages name a position.
std::string to_string(const Point& p);

/// The size of a 3D lattice: W x H x D level-0 cubes, at most L refinements
/// deep. Level-0 cubes have side S = 2^(L+1); a level-l cube has side
/// 2^(L+1-l), so every center, corner, edge midpoint and face center down to
/// level L is an integer point.
struct LatticeSize {
  std::int64_t W = 1;
  std::int64_t H = 1;
  std::int64_t D = 1;
  int L = 0;
  friend bool operator==(const LatticeSize&, const LatticeSize&) = default;
};

/// Throws bccmis::LatticeError unless W, H, D >= 1, L >= 0 and the extents
/// W*S, H*S, D*S are at most 2^62. The message names the offending value.
void validate_lattice_size(const LatticeSize& size);

// level0_side(size) and cell_side(size, level), written once for every
// dimension (bccmis/graph.h).
using bccmis::cell_side;
using bccmis::level0_side;

}  // namespace bccmis::d3
