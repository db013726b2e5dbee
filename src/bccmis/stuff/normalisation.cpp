// S24's map between a shape's coordinates and the mesher's (normalisation.h).
#include "bccmis/stuff/normalisation.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace bccmis::stuff {

namespace {
std::string shortest(double x) {
  char buf[32];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}
/// x 2^k (S24): ldexp(x, 0) is x, and most shapes need no scaling; every
/// query of the views below passes here (a moving shape's step asks about
/// a million).
double scaled(double x, int k) { return k == 0 ? x : std::ldexp(x, k); }
}  // namespace

Vec3 Normalisation::to_local(const Vec3& p) const {
  return {scaled(p[0] - translation[0], -exponent), scaled(p[1] - translation[1], -exponent),
          scaled(p[2] - translation[2], -exponent)};
}

Vec3 Normalisation::to_world(const Vec3& p) const {
  return {translation[0] + scaled(p[0], exponent), translation[1] + scaled(p[1], exponent),
          translation[2] + scaled(p[2], exponent)};
}

Normalisation normalisation_of(const Bounds& box) {
  double E = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i]) || box.hi[i] < box.lo[i])
      throw ShapeError("the shape's bounding box is empty or not finite");
    const double extent = box.hi[i] - box.lo[i];
    if (!std::isfinite(extent))
      throw ShapeError("the shape's extent along axis " + std::to_string(i) + " overflows a double (from " +
                       shortest(box.lo[i]) + " to " + shortest(box.hi[i]) + ")");
    E = std::max(E, extent);
  }
  if (!(E > 0)) throw ShapeError("the shape's bounding box has no extent");
  Normalisation n;
  // S24: 2^k <= E < 2^(k+1).
  n.exponent = std::ilogb(E);
  for (std::size_t i = 0; i < 3; ++i) {
    // S24: translate only a box whose centre lies more than 64 extents from
    // the origin; then every coordinate x of the box has t/2 <= x <= 2t (or
    // the mirror), so x - t is exact (Sterbenz).
    const double centre = 0.5 * box.lo[i] + 0.5 * box.hi[i];
    if (std::abs(centre) > 64 * E) n.translation[i] = centre;
  }
  return n;
}

namespace {

/// Every corner of `triangles` through `map`.
template <class Map>
std::vector<std::array<Vec3, 3>> mapped(std::vector<std::array<Vec3, 3>> triangles, const Map& map) {
  for (auto& t : triangles)
    for (Vec3& p : t) p = map(p);
  return triangles;
}

/// A shape evaluated in its own coordinates, seen through a Normalisation.
class NormalisedView final : public Shape {
 public:
  NormalisedView(const Shape& s, const Normalisation& n) : s_(s), n_(n) {}
  double signed_distance(const Vec3& p) const override { return down(s_.signed_distance(n_.to_world(p))); }
  double distance(const Vec3& p) const override { return down(s_.distance(n_.to_world(p))); }
  bool distance_is_lipschitz() const override { return s_.distance_is_lipschitz(); }
  Nearest nearest(const Vec3& p) const override {
    Nearest n = s_.nearest(n_.to_world(p));
    n.distance = down(n.distance);
    if (n.point) n.point = n_.to_local(*n.point);
    return n;
  }
  int side(const Vec3& p) const override { return s_.side(n_.to_world(p)); }
  double crossing(const Vec3& a, const Vec3& b) const override { return s_.crossing(n_.to_world(a), n_.to_world(b)); }
  Bounds bounds() const override {
    const Bounds b = s_.bounds();
    return {n_.to_local(b.lo), n_.to_local(b.hi)};
  }
  double volume() const override { return std::ldexp(s_.volume(), -3 * n_.exponent); }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    std::vector<Vec3> out = s_.sample_surface(n, seed);
    for (Vec3& p : out) p = n_.to_local(p);
    return out;
  }
  const SoupReport* soup_report() const override { return s_.soup_report(); }
  std::string describe() const override { return s_.describe(); }
  std::optional<SurfaceComponents> surface_components() const override {
    auto c = s_.surface_components();
    if (c) c->thinnest = down(c->thinnest);
    return c;
  }
  std::vector<std::array<Vec3, 3>> surface_triangles() const override {
    return mapped(s_.surface_triangles(), [this](const Vec3& p) { return n_.to_local(p); });
  }

 private:
  double down(double d) const { return scaled(d, -n_.exponent); }
  const Shape& s_;
  Normalisation n_;
};

/// A shape built in local coordinates, presented in world coordinates.
class Placed final : public Shape {
 public:
  Placed(std::unique_ptr<Shape> local, const Normalisation& n) : local_(std::move(local)), n_(n) {}
  double signed_distance(const Vec3& p) const override { return up(local_->signed_distance(n_.to_local(p))); }
  double distance(const Vec3& p) const override { return up(local_->distance(n_.to_local(p))); }
  bool distance_is_lipschitz() const override { return local_->distance_is_lipschitz(); }
  Nearest nearest(const Vec3& p) const override {
    Nearest n = local_->nearest(n_.to_local(p));
    n.distance = up(n.distance);
    if (n.point) n.point = n_.to_world(*n.point);
    return n;
  }
  int side(const Vec3& p) const override { return local_->side(n_.to_local(p)); }
  double crossing(const Vec3& a, const Vec3& b) const override {
    return local_->crossing(n_.to_local(a), n_.to_local(b));
  }
  Bounds bounds() const override {
    const Bounds b = local_->bounds();
    return {n_.to_world(b.lo), n_.to_world(b.hi)};
  }
  double volume() const override { return std::ldexp(local_->volume(), 3 * n_.exponent); }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    std::vector<Vec3> out = local_->sample_surface(n, seed);
    for (Vec3& p : out) p = n_.to_world(p);
    return out;
  }
  const SoupReport* soup_report() const override { return local_->soup_report(); }
  std::string describe() const override { return local_->describe(); }
  std::optional<SurfaceComponents> surface_components() const override {
    auto c = local_->surface_components();
    if (c) c->thinnest = up(c->thinnest);
    return c;
  }
  std::vector<std::array<Vec3, 3>> surface_triangles() const override {
    return mapped(local_->surface_triangles(), [this](const Vec3& p) { return n_.to_world(p); });
  }
  std::unique_ptr<Shape> normalised(const Normalisation& n) const override {
    return n == n_ ? view_normalised(*local_, Normalisation{}) : view_normalised(*this, n);
  }

 private:
  double up(double d) const { return scaled(d, n_.exponent); }
  std::unique_ptr<Shape> local_;
  Normalisation n_;
};

}  // namespace

std::unique_ptr<Shape> placed(std::unique_ptr<Shape> local, const Normalisation& n) {
  return std::make_unique<Placed>(std::move(local), n);
}

std::unique_ptr<Shape> view_normalised(const Shape& shape, const Normalisation& n) {
  return std::make_unique<NormalisedView>(shape, n);
}

std::unique_ptr<Shape> Shape::normalised(const Normalisation& n) const { return view_normalised(*this, n); }

}  // namespace bccmis::stuff
