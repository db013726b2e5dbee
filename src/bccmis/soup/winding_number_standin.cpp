// TEMPORARY STAND-IN, TO BE DELETED when the real winding_number.cpp (branch
// gwn) is merged: WindingNumber as the direct O(n) sum over every triangle of
// its solid angle (Van Oosterom and Strackee 1983), with no hierarchy and no
// certified decision near w = 1/2. estimate() is direct() with a rounding
// bound of n * 16 ulp(1); side() takes a point whose orientation determinant
// with a triangle is exactly 0 and that lies inside it (double predicates,
// not exact) as on that triangle, leaves that triangle out of the sum (the
// average of its two sides) and answers 0 when the result is 1/2 within the
// bound.
#include <cmath>
#include <limits>
#include <utility>

#include "bccmis/soup/winding_number.h"

namespace bccmis::soup {

struct WindingNumber::Impl {
  std::vector<Vec3> v;
  std::vector<Triangle> t;
};

namespace {

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

/// Inside the triangle abc (all in its plane, relative to q): the three
/// cross products point the same way as the normal (or vanish).
bool inside_in_plane(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(minus(b, a), minus(c, a));
  return dot(cross(a, b), n) >= 0 && dot(cross(b, c), n) >= 0 && dot(cross(c, a), n) >= 0 && dot(n, n) > 0;
}

/// Sum of the solid angles / 4 pi, skipping the triangles q lies on.
double sum(const std::vector<Vec3>& V, const std::vector<Triangle>& T, const Vec3& q, bool* on) {
  constexpr double kFourPi = 4 * 3.14159265358979323846;
  double w = 0;
  for (const auto& t : T) {
    const Vec3 a = minus(V[t[0]], q), b = minus(V[t[1]], q), c = minus(V[t[2]], q);
    const double det = dot(a, cross(b, c));
    if (det == 0 && inside_in_plane(a, b, c)) {
      if (on) *on = true;
      continue;
    }
    const double la = norm(a), lb = norm(b), lc = norm(c);
    const double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    w += 2 * std::atan2(det, den) / kFourPi;
  }
  return w;
}

}  // namespace

WindingNumber::WindingNumber(std::vector<Vec3> vertices, std::vector<Triangle> triangles)
    : impl_(new Impl{std::move(vertices), std::move(triangles)}) {}
WindingNumber::~WindingNumber() { delete impl_; }
WindingNumber::WindingNumber(WindingNumber&& o) noexcept : impl_(std::exchange(o.impl_, nullptr)) {}
WindingNumber& WindingNumber::operator=(WindingNumber&& o) noexcept {
  std::swap(impl_, o.impl_);
  return *this;
}

WindingNumber::Estimate WindingNumber::estimate(const Vec3& q) const {
  return {direct(q), 16 * std::numeric_limits<double>::epsilon() * static_cast<double>(impl_->t.size() + 1)};
}

double WindingNumber::direct(const Vec3& q) const { return sum(impl_->v, impl_->t, q, nullptr); }

int WindingNumber::side(const Vec3& q) const {
  bool on = false;
  const double w = sum(impl_->v, impl_->t, q, &on);
  const double bound = 16 * std::numeric_limits<double>::epsilon() * static_cast<double>(impl_->t.size() + 1);
  if (on && std::abs(w - 0.5) <= bound) return 0;
  return w >= 0.5 ? -1 : 1;
}

std::size_t WindingNumber::size() const { return impl_->t.size(); }

}  // namespace bccmis::soup
