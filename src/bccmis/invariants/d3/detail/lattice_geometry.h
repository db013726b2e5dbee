// The 3D checker's own cube geometry and layer entry points (internal to
// invariants/d3/).
//
// Written from spec/lattice3d.md §1, independently of src/bccmis/d3/: a
// level-l cube has side 2^(L+1-l) and half-side h = 2^(L-l); its center has
// all three coordinates odd multiples of h; the domain is the box
// [0, W*S] x [0, H*S] x [0, D*S] with S = 2^(L+1). Every function is safe on
// arbitrary int64 input once the lattice size passed layer 1: no arithmetic
// is done on a position before it is known to lie in the box.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/invariants/d3/invariants.h"

namespace bccmis::d3::inv {

std::optional<Violation> check_combinatorial(const Graph& g);  // layer 1, combinatorial.cpp
std::optional<Violation> check_structural(const Graph& g);     // layer 2, structural.cpp
std::optional<Violation> check_grading(const Graph& g);        // layer 3, grading.cpp
std::optional<Violation> check_geometry(const Graph& g);       // layer 4, geometry.cpp
/// lattice-size alone (part of layer 1; check_mesh runs it first).
std::optional<Violation> check_lattice_size(const LatticeSize& s);

/// "(x, y, z)"
inline std::string pos(const Point& p) { return to_string(p); }

/// A Violation whose message is "<code>: <text>"; a section "§..." is one of
/// spec/lattice3d.md, any other is used as given.
inline Violation violation(int layer, std::string code, std::vector<Point> where, const std::string& text,
                           const std::string& section) {
  Violation v;
  v.message = code + ": " + text;
  v.code = std::move(code);
  v.where = std::move(where);
  v.section = section.starts_with("§") ? "spec/lattice3d.md " + section : section;
  v.layer = layer;
  return v;
}

inline std::int64_t coord(const Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
inline Point make_point(const std::array<std::int64_t, 3>& a) { return {a[0], a[1], a[2]}; }

/// The box of a valid lattice size.
struct Box {
  explicit Box(const LatticeSize& s) : L(s.L), S(std::int64_t{1} << (s.L + 1)), extent{s.W * S, s.H * S, s.D * S} {}
  int L;
  std::int64_t S;
  std::array<std::int64_t, 3> extent;

  bool contains(const Point& p) const {
    for (int a = 0; a < 3; ++a)
      if (coord(p, a) < 0 || coord(p, a) > extent[a]) return false;
    return true;
  }
  /// How many coordinates of an inside point lie strictly inside the box.
  int interior_coordinates(const Point& p) const {
    int k = 0;
    for (int a = 0; a < 3; ++a) k += coord(p, a) > 0 && coord(p, a) < extent[a];
    return k;
  }
  /// Half-side 2^(L-level); 0 for a level outside 0..L.
  std::int64_t half(int level) const {
    if (level < 0 || level > L) return 0;
    return std::int64_t{1} << (L - level);
  }
  /// The level of the cube centred at p, judged from p alone: p strictly
  /// inside the box with all three coordinates odd multiples of the same
  /// 2^k, k <= L (level L - k). Empty for any other point.
  std::optional<int> center_level(const Point& p) const {
    for (int a = 0; a < 3; ++a)
      if (coord(p, a) <= 0 || coord(p, a) >= extent[a]) return std::nullopt;
    const int k = std::countr_zero(static_cast<std::uint64_t>(p.x));
    if (std::countr_zero(static_cast<std::uint64_t>(p.y)) != k) return std::nullopt;
    if (std::countr_zero(static_cast<std::uint64_t>(p.z)) != k) return std::nullopt;
    if (k > L) return std::nullopt;
    return L - k;
  }
};

/// Where a point lies on the closed cube of center c and half-side h: the
/// number of coordinates at c ± h (3 corner, 2 on an edge, 1 on a face, 0
/// inside), or -1 outside.
inline int on_cube(const Point& c, std::int64_t h, const Point& p) {
  int at = 0;
  for (int a = 0; a < 3; ++a) {
    const std::int64_t d = coord(p, a) - coord(c, a);  // both inside the box: no overflow
    if (d < -h || d > h) return -1;
    at += d == -h || d == h;
  }
  return at;
}

/// The role of a point on a cube's closed boundary.
enum class Role { Corner, EdgeMidpoint, FaceCenter, Other };

/// Corner (3 coordinates at ±h), edge midpoint (2 at ±h, the third equal to
/// c's), face center (1 at ±h, the other two equal to c's), or Other.
inline Role role_on(const Point& c, std::int64_t h, const Point& p) {
  int at = 0, mid = 0;
  for (int a = 0; a < 3; ++a) {
    const std::int64_t d = coord(p, a) - coord(c, a);
    if (d < -h || d > h) return Role::Other;
    at += d == -h || d == h;
    mid += d == 0;
  }
  if (at == 3) return Role::Corner;
  if (at == 2 && mid == 1) return Role::EdgeMidpoint;
  if (at == 1 && mid == 2) return Role::FaceCenter;
  return Role::Other;
}

/// "[x0, x1] x [y0, y1] x [z0, z1]"
inline std::string cube_text(const Point& c, std::int64_t h) {
  std::string t;
  for (int a = 0; a < 3; ++a) {
    if (a) t += " x ";
    t += "[" + std::to_string(coord(c, a) - h) + ", " + std::to_string(coord(c, a) + h) + "]";
  }
  return t;
}

}  // namespace bccmis::d3::inv
