// bccmis: lattice positions and lattice sizes, one source for every dimension
// (spec/formats.md, "Coordinates" and "3D extension"; spec/lattice3d.md §1).
//
// As p4est compiles p8est from the same files, a point and a size are one
// template over a dimension tag: bccmis::Dimension for 2D, d3::Dimension for
// 3D. Only the member lists are written per dimension (the specialisations
// below, aggregates, so that {x, y} and {.x = ...} initialise them);
// comparison, to_string and validation are written once. The tag's namespace
// is an associated namespace of the point and size types, so that
// argument-dependent lookup finds the 3D functions (d3::make_lattice, ...) for
// a 3D point or size. The names users see are aliases: Point and LatticeSize
// here, d3::Point and d3::LatticeSize in bccmis/d3/point.h.
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>

namespace bccmis {

/// The 2D dimension tag: the words messages use for its boxes and extents.
struct Dimension {
  static constexpr int value = 2;
  static constexpr const char* box = "cell";
  static constexpr std::array<const char*, 2> extent_names{"width W", "height H"};
  /// "side W": how a message names the domain side of an extent.
  static std::string domain_side(const char* extent_name, std::int64_t /*count*/) {
    return std::string("side ") + extent_name[std::char_traits<char>::length(extent_name) - 1];
  }
};

namespace d3 {
/// The 3D dimension tag.
struct Dimension {
  static constexpr int value = 3;
  static constexpr const char* box = "cube";
  static constexpr std::array<const char*, 3> extent_names{"width W", "height H", "depth D"};
  /// "extent 5": how a message names the domain extent of an extent.
  static std::string domain_side(const char* /*extent_name*/, std::int64_t count) {
    return "extent " + std::to_string(count);
  }
};
}  // namespace d3

/// A lattice position in integer coordinates (spec/formats.md,
/// "Coordinates"), ordered lexicographically by axis. The members per
/// dimension: x, y (2D); x, y, z (3D).
template <class Dim>
struct BasicPoint;

template <>
struct BasicPoint<Dimension> {
  static constexpr int dimension = Dimension::value;
  std::int64_t x = 0;
  std::int64_t y = 0;
  constexpr std::array<std::int64_t, 2> axes() const { return {x, y}; }
};

template <>
struct BasicPoint<d3::Dimension> {
  static constexpr int dimension = d3::Dimension::value;
  std::int64_t x = 0;
  std::int64_t y = 0;
  std::int64_t z = 0;
  constexpr std::array<std::int64_t, 3> axes() const { return {x, y, z}; }
};

/// The size of a lattice: W x H (x D) level-0 boxes, at most L refinements
/// deep. Level-0 boxes have side S = 2^(L+1); a level-l box has side
/// 2^(L+1-l), so every center, corner, edge midpoint and face center down to
/// level L is an integer point. The members per dimension: W, H, L (2D);
/// W, H, D, L (3D).
template <class Dim>
struct BasicLatticeSize;

template <>
struct BasicLatticeSize<Dimension> {
  std::int64_t W = 1;
  std::int64_t H = 1;
  int L = 0;
  constexpr std::array<std::int64_t, 2> extents() const { return {W, H}; }
};

template <>
struct BasicLatticeSize<d3::Dimension> {
  std::int64_t W = 1;
  std::int64_t H = 1;
  std::int64_t D = 1;
  int L = 0;
  constexpr std::array<std::int64_t, 3> extents() const { return {W, H, D}; }
};

/// Lexicographic order by axis: x, then y (then z). Written on the members,
/// not on axes(), so that a Debug build's std::set<Point> stays one call per
/// comparison.
template <class Dim>
constexpr std::strong_ordering operator<=>(const BasicPoint<Dim>& a, const BasicPoint<Dim>& b) {
  if (const auto by_x = a.x <=> b.x; by_x != 0) return by_x;
  if constexpr (Dim::value == 2) {
    return a.y <=> b.y;
  } else {
    if (const auto by_y = a.y <=> b.y; by_y != 0) return by_y;
    return a.z <=> b.z;
  }
}

template <class Dim>
constexpr bool operator==(const BasicPoint<Dim>& a, const BasicPoint<Dim>& b) {
  if constexpr (Dim::value == 2)
    return a.x == b.x && a.y == b.y;
  else
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

template <class Dim>
constexpr bool operator==(const BasicLatticeSize<Dim>& a, const BasicLatticeSize<Dim>& b) {
  return a.extents() == b.extents() && a.L == b.L;
}

/// "(x, y)" or "(x, y, z)": how messages name a position. A braced point,
/// to_string({x, y}), is a 2D one.
template <class Dim = Dimension>
std::string to_string(const BasicPoint<Dim>& p) {
  // Built by appending: g++ 12 at -O3 gives a false -Wrestrict (GCC bug
  // 105651) on `"literal" + std::string` once inlined.
  std::string t = "(";
  const char* separator = "";
  for (const std::int64_t coordinate : p.axes()) {
    t += separator;
    t += std::to_string(coordinate);
    separator = ", ";
  }
  t += ')';
  return t;
}

/// A 2D lattice position.
using Point = BasicPoint<Dimension>;
using PointSet = std::set<Point>;
/// The size of a 2D lattice: W x H level-0 cells, at most L refinements deep.
using LatticeSize = BasicLatticeSize<Dimension>;

/// Thrown when a lattice size is out of range (an extent < 1, L < 0, or a
/// domain side extent*S above 2^62). The message names the offending value.
struct LatticeError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Largest allowed domain side W*S, H*S (and D*S).
inline constexpr std::int64_t kMaxDomainSide = std::int64_t{1} << 62;

/// Throws LatticeError unless W, H >= 1, L >= 0 and the domain sides W*S and
/// H*S are at most 2^62. The message names the offending value. (The 3D
/// overload is d3::validate_lattice_size; both are one source, point.cpp.)
void validate_lattice_size(const LatticeSize& size);

/// Side of a level-0 cell of any dimension: S = 2^(L+1). A braced size,
/// level0_side({W, H, L}), is a 2D LatticeSize.
template <class Size = LatticeSize>
requires requires(const Size& s) { s.L; }
std::int64_t level0_side(const Size& size) { return std::int64_t{1} << (size.L + 1); }

/// Side of a level-`level` cell of any dimension: 2^(L+1-level).
template <class Size = LatticeSize>
requires requires(const Size& s) { s.L; }
std::int64_t cell_side(const Size& size, int level) { return std::int64_t{1} << (size.L + 1 - level); }

}  // namespace bccmis
