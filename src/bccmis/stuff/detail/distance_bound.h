// spec/stuffing.md S37, S38: what a distance asked at another offset of a
// moving shape, or at another point, says of the distance here and now.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>

namespace bccmis::stuff::detail {

/// |f| known to lie in [lo, hi]; the value itself when lo == hi.
struct DistanceBound {
  double lo = 0;
  double hi = std::numeric_limits<double>::infinity();

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
  return {std::max(0.0, f.lo - r - e), f.hi + r + e};
}

/// Both bounds hold: the value when either is one, else their
/// intersection (nothing known if rounding beyond e left it empty).
inline DistanceBound both(const DistanceBound& a, const DistanceBound& b) {
  if (a.exact()) return a;
  if (b.exact()) return b;
  const DistanceBound r{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
  return r.lo <= r.hi ? r : DistanceBound{};
}

}  // namespace bccmis::stuff::detail
