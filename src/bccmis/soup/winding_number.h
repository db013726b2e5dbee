// bccmis::soup: the solid of a triangle soup by its generalized winding
// number (spec/stuffing.md, "The solid of a triangle soup"; Jacobson, Kavan,
// Sorkine-Hornung 2013), evaluated by a hierarchy with a far-field
// approximation and an exact near field (Barill et al. 2018), with a
// rigorous error bound so that no inside/outside decision depends on the
// approximation.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace bccmis::soup {

using Vec3 = std::array<double, 3>;
using Triangle = std::array<std::uint32_t, 3>;

/// w(q) = (1 / 4 pi) * sum over the triangles of their signed solid angle at
/// q (positive when q sees the triangle's back, i.e. on the side its
/// counter-clockwise normal points away from). A closed, outward oriented
/// surface gives 1 inside and 0 outside; any soup gives a harmonic function
/// off the triangles that jumps by 1 across each triangle.
class WindingNumber {
 public:
  /// Builds the hierarchy over the soup (indices must be in range; the
  /// caller checks). The vertices and triangles are copied.
  WindingNumber(std::vector<Vec3> vertices, std::vector<Triangle> triangles);
  ~WindingNumber();
  WindingNumber(WindingNumber&&) noexcept;
  WindingNumber& operator=(WindingNumber&&) noexcept;

  /// An approximate w with a bound on its error: |w(q) - value| <= error.
  struct Estimate {
    double value = 0;
    double error = 0;
  };
  Estimate estimate(const Vec3& q) const;

  /// The far-field opening parameter of estimate(q): a node of the hierarchy
  /// is replaced by its expansion when |q - c| > beta r (spec/stuffing.md
  /// S18). estimate(q) uses kBeta; side() starts with beta 3.5 and, while the
  /// bound does not decide, opens the far nodes with the largest bounds.
  static constexpr double kBeta = 4;
  /// estimate(q) with another beta (> 1; smaller is faster and looser). The
  /// bound holds for every beta > 1, which the tests use to plant estimates
  /// that are on the wrong side of 1/2.
  Estimate estimate(const Vec3& q, double beta) const;

  /// The sign of w(q) - threshold that an estimate certifies (S18): 1 when
  /// value - threshold >= error (1 + 4u) (the difference's rounding), -1 when
  /// value - threshold < -error (1 + 4u), else 0 (the bound does not decide).
  static int certified_sign(const Estimate& e, double threshold);

  /// direct(q) with a bound on its rounding error (S18).
  Estimate direct_bounded(const Vec3& q) const;

  /// w(q) summed over every triangle (no approximation; the O(n) oracle).
  double direct(const Vec3& q) const;

  /// Inside (-1) when w(q) >= 1/2, outside (+1) when w(q) < 1/2, decided
  /// exactly when the estimate is too close to 1/2 to decide. A point that
  /// lies exactly on a triangle (exact predicates) gives 0 when the two
  /// sides of that triangle are one inside and one outside (q is on the
  /// solid's surface), else the side both of them are on.
  int side(const Vec3& q) const;

  std::size_t size() const;

  /// How many decisions of side() (counting each of the two limits on a
  /// triangle) so far had no far node left: the O(n) sum (for benchmarks).
  std::uint64_t full_sums() const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace bccmis::soup
