// The built-in implicit shapes (spec/stuffing.md §1): exact signed distances,
// crossings by bisection on the sign, closed-form volumes, surface samples
// from an equal-area parametrisation.
#include "bccmis/stuff/shape.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <random>

#include "bccmis/stuff/normalisation.h"

namespace bccmis::stuff {
namespace {

double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

/// "name k1=v1 k2=v2" with the shortest round-trip text of each value.
std::string fmt(const char* name, std::initializer_list<std::pair<const char*, double>> params) {
  std::string out = name;
  for (const auto& [key, value] : params) {
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, value).ptr;
    out += std::string(" ") + key + "=" + std::string(buf, end);
  }
  return out;
}

class Sphere final : public Shape {
 public:
  Sphere(const Vec3& c, double r) : c_(c), r_(r) {
    if (!(r > 0) || !std::isfinite(r)) throw ShapeError("sphere: the radius must be positive and finite");
  }
  double signed_distance(const Vec3& p) const override { return norm(sub(p, c_)) - r_; }
  bool distance_is_lipschitz() const override { return true; }  // S37: the distance to the sphere
  // S39: the point of the sphere on the ray from its center through p.
  Nearest nearest(const Vec3& p) const override {
    const Vec3 v = sub(p, c_);
    const double n = norm(v);
    const Vec3 q = n > 0 ? Vec3{c_[0] + v[0] * (r_ / n), c_[1] + v[1] * (r_ / n), c_[2] + v[2] * (r_ / n)}
                         : Vec3{c_[0] + r_, c_[1], c_[2]};
    return {distance(p), q};
  }
  double crossing(const Vec3& a, const Vec3& b) const override {
    // |a + t d - c|^2 = r^2: the root in [0, 1] of a quadratic, refined by bisection
    // when rounding puts it outside.
    const Vec3 d = sub(b, a), m = sub(a, c_);
    const double A = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const double B = 2 * (m[0] * d[0] + m[1] * d[1] + m[2] * d[2]);
    const double C = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - r_ * r_;
    const double disc = B * B - 4 * A * C;
    if (A > 0 && disc >= 0) {
      const double s = std::sqrt(disc);
      for (double t : {(-B - s) / (2 * A), (-B + s) / (2 * A)})
        if (t >= 0 && t <= 1) return t;
    }
    return bisect_crossing(*this, a, b);
  }
  Bounds bounds() const override {
    return {{c_[0] - r_, c_[1] - r_, c_[2] - r_}, {c_[0] + r_, c_[1] + r_, c_[2] + r_}};
  }
  double volume() const override { return 4.0 / 3.0 * std::numbers::pi * r_ * r_ * r_; }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    // Archimedes: z uniform in [-1, 1] and the angle uniform is uniform by area.
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Vec3> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double z = 2 * u(rng) - 1, phi = 2 * std::numbers::pi * u(rng), s = std::sqrt(1 - z * z);
      out.push_back({c_[0] + r_ * s * std::cos(phi), c_[1] + r_ * s * std::sin(phi), c_[2] + r_ * z});
    }
    return out;
  }
  std::string describe() const override { return fmt("sphere", {{"r", r_}}); }
  std::optional<SurfaceComponents> surface_components() const override { return SurfaceComponents{1, 2 * r_}; }
  std::unique_ptr<Shape> normalised(const Normalisation& n) const override {
    return std::make_unique<Sphere>(n.to_local(c_), std::ldexp(r_, -n.exponent));
  }

 private:
  Vec3 c_;
  double r_;
};

class Torus final : public Shape {
 public:
  Torus(const Vec3& c, double R, double r) : c_(c), R_(R), r_(r) {
    if (!(r > 0) || !(R > r) || !std::isfinite(R)) throw ShapeError("torus: the radii must satisfy 0 < r < R (finite)");
  }
  double signed_distance(const Vec3& p) const override {
    const Vec3 q = sub(p, c_);
    const double ring = std::hypot(q[0], q[1]) - R_;
    return std::hypot(ring, q[2]) - r_;
  }
  bool distance_is_lipschitz() const override { return true; }  // S37: the distance to the torus
  double crossing(const Vec3& a, const Vec3& b) const override { return bisect_crossing(*this, a, b); }
  Bounds bounds() const override {
    const double e = R_ + r_;
    return {{c_[0] - e, c_[1] - e, c_[2] - r_}, {c_[0] + e, c_[1] + e, c_[2] + r_}};
  }
  double volume() const override { return 2 * std::numbers::pi * std::numbers::pi * R_ * r_ * r_; }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    // Area element (R + r cos v) du dv: v by rejection against R + r.
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Vec3> out;
    out.reserve(n);
    while (out.size() < n) {
      const double U = 2 * std::numbers::pi * u(rng), V = 2 * std::numbers::pi * u(rng);
      if (u(rng) * (R_ + r_) > R_ + r_ * std::cos(V)) continue;
      const double w = R_ + r_ * std::cos(V);
      out.push_back({c_[0] + w * std::cos(U), c_[1] + w * std::sin(U), c_[2] + r_ * std::sin(V)});
    }
    return out;
  }
  std::string describe() const override { return fmt("torus", {{"R", R_}, {"r", r_}}); }
  // The box is 2(R + r) wide and 2r high.
  std::optional<SurfaceComponents> surface_components() const override { return SurfaceComponents{1, 2 * r_}; }
  std::unique_ptr<Shape> normalised(const Normalisation& n) const override {
    return std::make_unique<Torus>(n.to_local(c_), std::ldexp(R_, -n.exponent), std::ldexp(r_, -n.exponent));
  }

 private:
  Vec3 c_;
  double R_, r_;
};

class Spheres final : public Shape {
 public:
  Spheres(const Vec3& a, const Vec3& b, double r) : a_(a, r), b_(b, r), ca_(a), cb_(b), r_(r) {}
  double signed_distance(const Vec3& p) const override {
    // The union's distance is the minimum outside; inside near the neck the
    // minimum is still the exact distance to the union's surface up to the
    // neck's crease, which is all the sign and the crossings need.
    return std::min(a_.signed_distance(p), b_.signed_distance(p));
  }
  bool distance_is_lipschitz() const override { return true; }  // S37: |min| of two such
  double crossing(const Vec3& a, const Vec3& b) const override { return bisect_crossing(*this, a, b); }
  Bounds bounds() const override {
    const Bounds x = a_.bounds(), y = b_.bounds();
    Bounds out;
    for (int i = 0; i < 3; ++i) out.lo[i] = std::min(x.lo[i], y.lo[i]), out.hi[i] = std::max(x.hi[i], y.hi[i]);
    return out;
  }
  double volume() const override {
    // Two balls less their lens: the lens of two radius-r balls at distance d
    // has volume pi (4r + d)(2r - d)^2 / 12.
    const double d = norm(sub(ca_, cb_));
    const double lens = d >= 2 * r_ ? 0 : std::numbers::pi * (4 * r_ + d) * (2 * r_ - d) * (2 * r_ - d) / 12;
    return 2 * a_.volume() - lens;
  }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    // Samples of both spheres, dropping those inside the other ball.
    std::vector<Vec3> out;
    std::uint64_t round = 0;
    while (out.size() < n) {
      for (const Vec3& p : a_.sample_surface(n, seed + round))
        if (b_.signed_distance(p) >= 0 && out.size() < n) out.push_back(p);
      for (const Vec3& p : b_.sample_surface(n, seed + round + 1))
        if (a_.signed_distance(p) >= 0 && out.size() < n) out.push_back(p);
      round += 2;
    }
    return out;
  }
  std::string describe() const override { return fmt("spheres", {{"r", r_}, {"d", norm(sub(ca_, cb_))}}); }
  std::optional<SurfaceComponents> surface_components() const override {
    return SurfaceComponents{norm(sub(ca_, cb_)) > 2 * r_ ? 2u : 1u, 2 * r_};
  }
  std::unique_ptr<Shape> normalised(const Normalisation& n) const override {
    return std::make_unique<Spheres>(n.to_local(ca_), n.to_local(cb_), std::ldexp(r_, -n.exponent));
  }

 private:
  Sphere a_, b_;
  Vec3 ca_, cb_;
  double r_;
};

class Translated final : public Shape {
 public:
  Translated(std::shared_ptr<const Shape> s, const Vec3& d) : s_(std::move(s)), d_(d) {}
  double signed_distance(const Vec3& p) const override { return s_->signed_distance(sub(p, d_)); }
  double distance(const Vec3& p) const override { return s_->distance(sub(p, d_)); }
  bool distance_is_lipschitz() const override { return s_->distance_is_lipschitz(); }
  Nearest nearest(const Vec3& p) const override {
    Nearest n = s_->nearest(sub(p, d_));
    if (n.point) n.point = add(*n.point, d_);
    return n;
  }
  int side(const Vec3& p) const override { return s_->side(sub(p, d_)); }
  double crossing(const Vec3& a, const Vec3& b) const override { return s_->crossing(sub(a, d_), sub(b, d_)); }
  Bounds bounds() const override {
    Bounds b = s_->bounds();
    b.lo = add(b.lo, d_), b.hi = add(b.hi, d_);
    return b;
  }
  double volume() const override { return s_->volume(); }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    std::vector<Vec3> out = s_->sample_surface(n, seed);
    for (Vec3& p : out) p = add(p, d_);
    return out;
  }
  std::string describe() const override { return s_->describe(); }
  std::optional<SurfaceComponents> surface_components() const override { return s_->surface_components(); }
  // S24: (x - d) - (t - d) is x - t.
  std::unique_ptr<Shape> normalised(const Normalisation& n) const override {
    return s_->normalised({sub(n.translation, d_), n.exponent});
  }

 private:
  std::shared_ptr<const Shape> s_;
  Vec3 d_;
};

}  // namespace

double bisect_crossing(const Shape& s, const Vec3& a, const Vec3& b) {
  const double fa = s.signed_distance(a);
  if (fa == 0) return 0;
  const bool a_inside = fa < 0;
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    const Vec3 p{a[0] + mid * (b[0] - a[0]), a[1] + mid * (b[1] - a[1]), a[2] + mid * (b[2] - a[2])};
    const double f = s.signed_distance(p);
    if (f == 0) return mid;
    ((f < 0) == a_inside ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::unique_ptr<Shape> make_sphere(const Vec3& c, double r) { return std::make_unique<Sphere>(c, r); }
std::unique_ptr<Shape> make_torus(const Vec3& c, double R, double r) { return std::make_unique<Torus>(c, R, r); }
std::unique_ptr<Shape> make_spheres(const Vec3& a, const Vec3& b, double r) {
  return std::make_unique<Spheres>(a, b, r);
}
std::unique_ptr<Shape> make_builtin(const std::string& spec) {
  const std::size_t colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  struct Param {
    const char* key;
    double value;
    bool seen = false;
  };
  std::vector<Param> params;
  if (name == "sphere")
    params = {{"r", 1}};
  else if (name == "torus")
    params = {{"R", 1}, {"r", 0.4}};
  else if (name == "spheres")
    params = {{"r", 0.7}, {"d", 1}};
  else
    throw ShapeError("--shape '" + spec + "': unknown shape '" + name + "' (sphere, torus, spheres)");
  const auto bad = [&](const std::string& why) { return ShapeError("--shape '" + spec + "': " + why); };
  if (colon != std::string::npos) {
    std::size_t at = colon + 1;
    while (true) {
      const std::size_t comma = std::min(spec.find(',', at), spec.size());
      const std::string item = spec.substr(at, comma - at);
      const std::size_t eq = item.find('=');
      if (eq == std::string::npos) throw bad("expected KEY=VALUE, got '" + item + "'");
      const std::string key = item.substr(0, eq), text = item.substr(eq + 1);
      auto it = std::find_if(params.begin(), params.end(), [&](const Param& p) { return key == p.key; });
      if (it == params.end()) {
        std::string keys;
        for (const Param& p : params) keys += (keys.empty() ? "" : ", ") + std::string(p.key);
        throw bad("unknown parameter '" + key + "' of " + name + " (" + keys + ")");
      }
      if (it->seen) throw bad("parameter '" + key + "' given twice");
      double v = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (ec != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(v))
        throw bad("'" + text + "' is not a number");
      it->value = v, it->seen = true;
      if (comma == spec.size()) break;
      at = comma + 1;
    }
  }
  try {
    if (name == "sphere") return make_sphere({0, 0, 0}, params[0].value);
    if (name == "torus") return make_torus({0, 0, 0}, params[0].value, params[1].value);
    const double r = params[0].value, d = params[1].value;
    if (!(r > 0) || !(d >= 0)) throw ShapeError("spheres: r must be positive and d not negative");
    return make_spheres({-d / 2, 0, 0}, {d / 2, 0, 0}, r);
  } catch (const ShapeError& e) {
    throw bad(e.what());
  }
}

std::unique_ptr<Shape> translated(std::shared_ptr<const Shape> s, const Vec3& d) {
  return std::make_unique<Translated>(std::move(s), d);
}

}  // namespace bccmis::stuff
