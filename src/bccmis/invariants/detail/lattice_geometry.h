// The checker's own lattice geometry (internal to invariants/).
//
// Written from spec/formats.md's coordinates, independently of
// src/bccmis/geometry.h: level-0 cells have side S = 2^(L+1), a level-l cell
// has side 2^(L+1-l) and half-side h = 2^(L-l); cell (i, j) of level l covers
// [i*2h, (i+1)*2h] x [j*2h, (j+1)*2h] and its center has both coordinates odd
// multiples of h. Every function here is safe on arbitrary int64 input: no
// arithmetic is done on a position before it is known to lie in the domain.
#pragma once

#include <bit>
#include <cstdint>
#include <optional>
#include <string>

#include "bccmis/graph.h"

namespace bccmis::inv {

/// "(x, y)"
inline std::string pos(const Point& p) { return to_string(p); }

/// Where a point lies relative to the domain [0, W*S] x [0, H*S].
enum class Place { Outside, Interior, Boundary, DomainCorner };

struct Domain {
  explicit Domain(const LatticeSize& s) : L(s.L), S(std::int64_t{1} << (s.L + 1)), width(s.W * S), height(s.H * S) {}
  int L;
  std::int64_t S, width, height;

  bool contains(const Point& p) const { return p.x >= 0 && p.y >= 0 && p.x <= width && p.y <= height; }
  Place place(const Point& p) const {
    if (!contains(p)) return Place::Outside;
    const bool on_x = p.x == 0 || p.x == width;
    const bool on_y = p.y == 0 || p.y == height;
    if (on_x && on_y) return Place::DomainCorner;
    if (on_x || on_y) return Place::Boundary;
    return Place::Interior;
  }
  /// Half-side 2^(L-level) of a level-`level` cell; 0 for a level outside
  /// 0..L (a corrupt stored level: the geometry checks then report it, and
  /// the shift never goes out of range).
  std::int64_t half(int level) const {
    if (level < 0 || level > L) return 0;
    return std::int64_t{1} << (L - level);
  }

  /// The level of the cell whose center is at p, judged from p alone: p lies
  /// strictly inside the domain and both coordinates are odd multiples of the
  /// same 2^k with 0 <= k <= L (level L - k). Empty for any other point.
  std::optional<int> center_level(const Point& p) const {
    if (p.x <= 0 || p.y <= 0 || p.x >= width || p.y >= height) return std::nullopt;
    const int kx = std::countr_zero(static_cast<std::uint64_t>(p.x));
    const int ky = std::countr_zero(static_cast<std::uint64_t>(p.y));
    if (kx != ky || kx > L) return std::nullopt;
    return L - kx;
  }
};

/// The role a node plays on the boundary of one cell.
enum class Role { None, Corner, Midpoint };

/// Role of point n on the boundary of the cell centered at c with half-side h
/// (c inside the domain, so c +- h cannot overflow).
inline Role role_of(const Point& c, std::int64_t h, const Point& n) {
  const std::int64_t x0 = c.x - h, x1 = c.x + h, y0 = c.y - h, y1 = c.y + h;
  const bool corner_x = n.x == x0 || n.x == x1;
  const bool corner_y = n.y == y0 || n.y == y1;
  if (corner_x && corner_y) return Role::Corner;
  if ((corner_x && n.y == c.y) || (corner_y && n.x == c.x)) return Role::Midpoint;
  return Role::None;
}

/// "[x0, x1] x [y0, y1]" for the cell centered at c with half-side h.
inline std::string square(const Point& c, std::int64_t h) {
  std::string t = "[";  // appended, not `"[" + ...` (see to_string(Point))
  t += std::to_string(c.x - h);
  t += ", ";
  t += std::to_string(c.x + h);
  t += "] x [";
  t += std::to_string(c.y - h);
  t += ", ";
  t += std::to_string(c.y + h);
  t += ']';
  return t;
}

}  // namespace bccmis::inv
