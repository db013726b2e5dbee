// spec/stuffing.md S37, S38, S39: what a distance asked at another offset of
// a moving shape, or at another point, and a point of the surface, say of
// the distance here and now.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace bccmis::stuff::detail {

/// |f| known to lie in [lo, hi]; the value itself when lo == hi.
struct DistanceBound {
  double lo = 0;
  double hi = std::numeric_limits<double>::infinity();
  /// S39: which remembered distance's point of the surface goes with the
  /// bound (an index the moving lattice gives), or kNoPoint.
  static constexpr std::uint32_t kNoPoint = 0xFFFFFFFFu;
  std::uint32_t nearest = kNoPoint;

  bool exact() const { return lo == hi; }
  /// Whether |f| <= t, when the bound decides it.
  std::optional<bool> at_most(double t) const {
    if (hi <= t) return true;
    if (lo > t) return false;
    return std::nullopt;
  }
};

/// S37: the bound of a value f0 asked `drift` away (the distance between
/// the two offsets), `e` the rounding's share; f0 itself at no drift.
inline DistanceBound drifted(double f0, double drift, double e) {
  if (drift == 0) return {f0, f0};
  return {std::max(0.0, f0 - drift - e), f0 + drift + e};
}

/// S38: the bound of f at a point `r` away from where f is known to lie in
/// `f` (the same offset), `e` the rounding's share.
inline DistanceBound widened(const DistanceBound& f, double r, double e) {
  return {std::max(0.0, f.lo - r - e), f.hi + r + e, f.nearest};
}

/// S39: the bound at x lowered to x's distance from q, a point of the
/// surface now, `e` the rounding's share (nothing known if rounding beyond
/// e left it empty); the value itself stays.
inline DistanceBound closer(DistanceBound f, const std::array<double, 3>& x, const std::array<double, 3>& q, double e) {
  if (f.exact()) return f;
  const double dx = x[0] - q[0], dy = x[1] - q[1], dz = x[2] - q[2];
  f.hi = std::min(f.hi, std::sqrt(dx * dx + dy * dy + dz * dz) + e);
  return f.lo <= f.hi ? f : DistanceBound{};
}

/// Both bounds hold: the value when either is one, else their
/// intersection (nothing known if rounding beyond e left it empty).
inline DistanceBound both(const DistanceBound& a, const DistanceBound& b) {
  DistanceBound r{std::max(a.lo, b.lo), std::min(a.hi, b.hi),
                  a.nearest != DistanceBound::kNoPoint ? a.nearest : b.nearest};
  if (a.exact())
    r.lo = r.hi = a.lo;
  else if (b.exact())
    r.lo = r.hi = b.lo;
  else if (r.lo > r.hi)
    return {};
  return r;
}

}  // namespace bccmis::stuff::detail
