// The generalized winding number of a triangle soup (spec/stuffing.md
// S17-S19): the solid angle against values known independently, closed,
// inward and open meshes, the far-field bound against the exact sum, and the
// side of points off and on the triangles.
#include "bccmis/soup/winding_number.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "testing/icosphere.h"

namespace {

using bccmis::soup::Triangle;
using bccmis::soup::Vec3;
using bccmis::soup::WindingNumber;

struct Soup {
  std::vector<Vec3> v;
  std::vector<Triangle> t;
};

// The cube [lo, hi]^3, two triangles a face, outward.
Soup cube(double lo = 0, double hi = 1) {
  Soup s;
  for (int i = 0; i < 8; ++i) s.v.push_back({i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.t.push_back({q[0], q[1], q[2]});
    s.t.push_back({q[0], q[2], q[3]});
  }
  return s;
}

void append(Soup& to, const Soup& from) {
  const auto base = static_cast<std::uint32_t>(to.v.size());
  to.v.insert(to.v.end(), from.v.begin(), from.v.end());
  for (const Triangle& t : from.t) to.t.push_back({t[0] + base, t[1] + base, t[2] + base});
}

Soup reversed(Soup s) {
  for (Triangle& t : s.t) std::swap(t[1], t[2]);
  return s;
}

// The icosahedron subdivided `levels` times, on the unit sphere, outward
// (20 4^levels triangles).
Soup icosphere(int levels) {
  Soup s;
  bccmis::testing::subdivided_icosahedron(
      levels,
      [](const Vec3& x) {
        const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        return Vec3{x[0] / n, x[1] / n, x[2] / n};
      },
      s.v, s.t);
  return s;
}

// The upper half of a unit sphere without its cap, as latitude rings: the
// pole, `rings` rings, the last on the equator z = 0 (exactly), `sectors`
// vertices a ring; triangles oriented outward (away from the origin).
Soup open_hemisphere(int rings, int sectors) {
  Soup s;
  s.v.push_back({0, 0, 1});
  for (int r = 1; r <= rings; ++r) {
    const double phi = (std::numbers::pi / 2) * r / rings;
    for (int k = 0; k < sectors; ++k) {
      const double th = 2 * std::numbers::pi * k / sectors;
      s.v.push_back({std::sin(phi) * std::cos(th), std::sin(phi) * std::sin(th), r == rings ? 0.0 : std::cos(phi)});
    }
  }
  auto at = [&](int r, int k) { return static_cast<std::uint32_t>(1 + (r - 1) * sectors + (k % sectors)); };
  for (int k = 0; k < sectors; ++k) s.t.push_back({0, at(1, k), at(1, k + 1)});
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < sectors; ++k) {
      s.t.push_back({at(r, k), at(r + 1, k), at(r + 1, k + 1)});
      s.t.push_back({at(r, k), at(r + 1, k + 1), at(r, k + 1)});
    }
  return s;
}

WindingNumber make(const Soup& s) { return WindingNumber(s.v, s.t); }

double distance_to_unit_sphere(const Vec3& p) {
  return std::abs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1);
}

// spec/stuffing.md S17: the triangle (1,0,0), (0,1,0), (0,0,1) covers one
// octant of the directions from the origin; counter-clockwise seen from
// outside, the origin sees its back: +1/8; reversed -1/8.
TEST(SoupWindingNumber, OctantIsOneEighth) {
  const Soup s{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2}}};
  EXPECT_NEAR(make(s).direct({0, 0, 0}), 1.0 / 8, 1e-15);
  EXPECT_NEAR(make(reversed(s)).direct({0, 0, 0}), -1.0 / 8, 1e-15);
  // From the far side of the triangle's plane the origin's reflection sees
  // its front: the mirror image of the octant, -1/8.
  EXPECT_NEAR(make(s).direct({2.0 / 3, 2.0 / 3, 2.0 / 3}), -1.0 / 8, 1e-15);
}

// spec/stuffing.md S17: a cube's face seen from the cube's centre covers 1/6
// of the directions; the 12 triangles give 1 inside, 0 outside.
TEST(SoupWindingNumber, CubeFaceIsOneSixthAndCubeIsOne) {
  const Soup c = cube(-1, 1);
  const Soup face{c.v, {c.t[0], c.t[1]}};
  EXPECT_NEAR(make(face).direct({0, 0, 0}), 1.0 / 6, 1e-15);
  const WindingNumber w = make(c);
  EXPECT_NEAR(w.direct({0, 0, 0}), 1, 1e-14);
  EXPECT_NEAR(w.direct({0.9, -0.3, 0.99}), 1, 1e-12);
  EXPECT_NEAR(w.direct({3, 0, 0}), 0, 1e-14);
  EXPECT_NEAR(w.direct({1.01, 0.5, 0.5}), 0, 1e-12);
}

// spec/stuffing.md S17: a small far triangle subtends about A cos(theta) / d^2.
TEST(SoupWindingNumber, FarTriangleIsItsProjectedArea) {
  const double h = 1e-3;
  const Soup s{{{10, 0, 0}, {10, h, 0}, {10, 0, h}}, {{0, 1, 2}}};
  // Normal +x (counter-clockwise seen from +x), so the origin sees its back.
  const double expected = (h * h / 2) / (10.0 * 10.0) / (4 * std::numbers::pi);
  EXPECT_NEAR(make(s).direct({0, 0, 0}), expected, expected * 1e-3);
}

// spec/stuffing.md S17: closed meshes give 1 inside and 0 outside, -1 inside
// when oriented inward.
TEST(SoupWindingNumber, ClosedSphereIsOneInsideZeroOutside) {
  const Soup s = icosphere(3);
  const WindingNumber w = make(s), inward = make(reversed(s));
  std::mt19937_64 rng(27);
  std::uniform_real_distribution<double> u(-2, 2);
  int checked = 0;
  while (checked < 300) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (r > 0.95 && r < 1.05) continue;  // the sphere's facets lie within 0.95 and 1
    const double expected = r < 1 ? 1 : 0;
    ASSERT_NEAR(w.direct(p), expected, 1e-12) << p[0] << " " << p[1] << " " << p[2];
    ASSERT_NEAR(inward.direct(p), -expected, 1e-12) << p[0] << " " << p[1] << " " << p[2];
    ++checked;
  }
}

// spec/stuffing.md S17: an open hemisphere whose rim lies in z = 0, seen from
// the origin (the centre of the missing cap): every direction with z > 0
// meets it once and no other direction meets it, so w = 1/2 exactly; the
// origin is not on a triangle, and the tie counts as inside (S18).
TEST(SoupWindingNumber, OpenHemisphereIsOneHalfAtTheCapCentre) {
  const WindingNumber w = make(open_hemisphere(12, 24));
  EXPECT_NEAR(w.direct({0, 0, 0}), 0.5, 1e-14);
  EXPECT_NEAR(w.direct({0.2, -0.1, 0}), 0.5, 1e-14);  // any point of the cap's plane inside the rim
  EXPECT_EQ(w.side({0, 0, 0}), -1);
  EXPECT_EQ(w.side({0, 0, 1e-9}), -1);  // above the cap plane: more than half the directions
  EXPECT_EQ(w.side({0, 0, -1e-9}), 1);
}

// spec/stuffing.md S18: |estimate - w| <= error at every point, and the
// bound is not vacuous: below 0.1 at points farther than far_distance from
// the soup, where the far field does the work. exact[i] = w(points[i]).
void check_bound(const WindingNumber& w, const std::vector<Vec3>& points, const std::vector<double>& exact,
                 std::uint64_t seed, double far_distance, const std::vector<double>& distances, double beta) {
  int far_points = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const auto e = w.estimate(p, beta);
    ASSERT_LE(std::abs(e.value - exact[i]), e.error)
        << "seed " << seed << " point " << i << " (" << p[0] << ", " << p[1] << ", " << p[2] << ") beta " << beta
        << ": estimate " << e.value << " error " << e.error << " direct " << exact[i];
    if (distances[i] > far_distance && beta >= WindingNumber::kBeta) {
      ++far_points;
      ASSERT_LT(e.error, 0.1) << "seed " << seed << " point " << i << " distance " << distances[i];
    }
  }
  if (far_distance > 0 && beta >= WindingNumber::kBeta) {
    EXPECT_GT(far_points, static_cast<int>(points.size()) / 8);
  }
}

std::vector<double> direct_at(const WindingNumber& w, const std::vector<Vec3>& points) {
  std::vector<double> exact;
  for (const Vec3& p : points) exact.push_back(w.direct(p));
  return exact;
}

// A deep hierarchy (5120 triangles, 10 levels): the bound at points from the
// centre to 4 radii out, a third of them within 0.03 of the sphere.
TEST(SoupWindingNumber, EstimateBoundHoldsOnA5kSphere) {
  const Soup s = icosphere(4);  // 5120 triangles, edges about 0.07
  ASSERT_EQ(s.t.size(), 5120u);
  const WindingNumber w = make(s);
  const std::uint64_t seed = 2718;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dir(-1, 1), radius(0, 4), near(0.97, 1.03);
  std::vector<Vec3> points;
  std::vector<double> distances;
  for (int i = 0; i < 240; ++i) {
    Vec3 d{dir(rng), dir(rng), dir(rng)};
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double r = i % 3 == 0 ? near(rng) : radius(rng);
    const Vec3 p{d[0] / n * r, d[1] / n * r, d[2] / n * r};
    points.push_back(p);
    // The facets lie between radius cos(edge) ~ 0.998 and 1.
    distances.push_back(std::max(0.0, distance_to_unit_sphere(p) - 3e-3));
  }
  const std::vector<double> exact = direct_at(w, points);
  check_bound(w, points, exact, seed, 1.2, distances, WindingNumber::kBeta);
  // The bound holds for any beta > 1 too (looser, coarser).
  const std::vector<Vec3> few(points.begin(), points.begin() + 60);
  check_bound(w, few, exact, seed, 0, distances, 1.2);
  check_bound(w, few, exact, seed, 0, distances, 2);
}

// spec/stuffing.md S18: near the surface of a closed mesh (w is 0 or 1) side()
// decides by the far field and its refinement, never by the sum over every
// triangle, and rightly: points between a quarter and two edge lengths from
// the sphere, both sides.
TEST(SoupWindingNumber, SideNearA5kSphereNeedsNoFullSum) {
  const Soup s = icosphere(4);
  const WindingNumber w = make(s);
  std::mt19937_64 rng(31);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> offset(0.02, 0.14);
  const std::uint64_t before = w.full_sums();
  for (int i = 0; i < 200; ++i) {
    Vec3 d{g(rng), g(rng), g(rng)};
    const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double r = i % 2 ? 1 + offset(rng) : 1 - offset(rng);
    const Vec3 p{d[0] / n * r, d[1] / n * r, d[2] / n * r};
    ASSERT_EQ(w.side(p), r < 1 ? -1 : 1) << "point " << i << " radius " << r;
  }
  EXPECT_EQ(w.full_sums(), before);
}

TEST(SoupWindingNumber, EstimateBoundHoldsOnARandomSoup) {
  const std::uint64_t seed = 1207;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1), small(-0.08, 0.08);
  Soup s;
  for (std::uint32_t i = 0; i < 2000; ++i) {
    const Vec3 c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) s.v.push_back({c[0] + small(rng), c[1] + small(rng), c[2] + small(rng)});
    s.t.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  const WindingNumber w = make(s);
  std::uniform_real_distribution<double> box(-2, 3);
  std::vector<Vec3> points;
  std::vector<double> distances;
  for (int i = 0; i < 500; ++i) {
    const Vec3 p = i % 2 ? Vec3{u(rng), u(rng), u(rng)} : Vec3{box(rng), box(rng), box(rng)};
    double d = 0;  // the distance to the box [-0.08, 1.08]^3 that holds the soup
    for (int k = 0; k < 3; ++k) d = std::max(d, std::max(-0.08 - p[k], p[k] - 1.08));
    points.push_back(p);
    distances.push_back(d);
  }
  const std::vector<double> exact = direct_at(w, points);
  check_bound(w, points, exact, seed, 1.5, distances, WindingNumber::kBeta);
  const std::vector<Vec3> few(points.begin(), points.begin() + 150);
  check_bound(w, few, exact, seed, 0, distances, 1.1);
}

// spec/stuffing.md S18: side() agrees with the exact sum wherever that sum
// decides, including points where a loose far field (beta 1.1) is on the
// wrong side of 1/2: the decision never rests on the approximation. Near
// the cap's plane w is near 1/2 and the first pass often does not decide:
// the refinement then decides most of those without the full sum.
TEST(SoupWindingNumber, SideIsRightWhereTheFarFieldIsWrong) {
  const Soup s = open_hemisphere(24, 48);
  const WindingNumber w = make(s);
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> xy(-0.9, 0.9), z(-0.05, 0.05);
  int wrong_far_field = 0, decided = 0, undecided_first = 0;
  const std::uint64_t before = w.full_sums();
  for (int i = 0; i < 600; ++i) {
    const Vec3 p{xy(rng), xy(rng), z(rng)};
    const auto exact = w.direct_bounded(p);
    if (std::abs(exact.value - 0.5) <= exact.error) continue;
    ++decided;
    const int expected = exact.value >= 0.5 ? -1 : 1;
    ASSERT_EQ(w.side(p), expected) << "point " << i << " (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    const auto first = w.estimate(p);
    if (std::abs(first.value - 0.5) <= first.error) ++undecided_first;
    const auto loose = w.estimate(p, 1.1);
    ASSERT_LE(std::abs(loose.value - exact.value), loose.error + exact.error);
    if ((loose.value >= 0.5 ? -1 : 1) != expected) ++wrong_far_field;
  }
  EXPECT_GT(decided, 400);
  EXPECT_GT(wrong_far_field, 0);  // the planted trap: the value alone would decide wrongly
  EXPECT_GT(undecided_first, 0);  // the refinement was needed ...
  EXPECT_LT(w.full_sums() - before, static_cast<std::uint64_t>(undecided_first));  // ... and mostly sufficed
}

// spec/stuffing.md S18, S20a: an estimate certifies w >= threshold when
// value - threshold >= error (1 + 4u), w < threshold when value - threshold
// < -error (1 + 4u); on the first line it decides, one step (a difference
// 2^-52 smaller in magnitude) inside either line it does not, one step
// beyond the second it does. With error 1 and threshold 1/2 every value
// and difference below is exact: the lines are 1/2 +- (1 + 2^-51).
TEST(SoupWindingNumber, CertifiedSignStandsOnItsLine) {
  const double margin = 1 + 0x1p-51;  // 1 (1 + 4u)
  const double step = 0x1p-52;
  auto sign = [](double value) { return WindingNumber::certified_sign({value, 1}, 0.5); };
  EXPECT_EQ(sign(0.5 + margin), 1);
  EXPECT_EQ(sign(0.5 + (margin - step)), 0);
  EXPECT_EQ(sign(0.5 - margin), 0);  // not below the line: undecided
  EXPECT_EQ(sign(0.5 - (margin + step)), -1);
  EXPECT_EQ(sign(0.5), 0);
  EXPECT_EQ(WindingNumber::certified_sign({0.5, 0}, 0.5), 1);  // no error: w >= 1/2 exactly (the tie rule)
}

// spec/stuffing.md S19: points exactly on a clean closed cube are on the
// surface (0): a face, a face's diagonal, an edge, a corner.
TEST(SoupWindingNumber, SideOnACubeIsZero) {
  const WindingNumber w = make(cube(0, 2));
  EXPECT_EQ(w.side({1, 1, 1}), -1);
  EXPECT_EQ(w.side({3, 1, 1}), 1);
  EXPECT_EQ(w.side({2.5, 2.5, -1}), 1);
  for (const Vec3& p : std::vector<Vec3>{{0.5, 1.5, 0},
                                         {1.5, 0.25, 2},
                                         {1, 1, 0},
                                         {2, 1, 1},
                                         {0.5, 0.5, 2},
                                         {1, 0, 0},
                                         {0, 0, 0},
                                         {2, 2, 2},
                                         {0, 1.25, 2}})
    EXPECT_EQ(w.side(p), 0) << p[0] << " " << p[1] << " " << p[2];
}

// spec/stuffing.md S19: every triangle twice: w = 2 inside, 0 outside; a
// point on a face has limits 2 and 0, which straddle 1/2: on the surface.
TEST(SoupWindingNumber, SideOnADoubledCubeIsZero) {
  Soup s = cube(0, 2);
  append(s, cube(0, 2));
  const WindingNumber w = make(s);
  EXPECT_NEAR(w.direct({1, 1, 1}), 2, 1e-12);
  EXPECT_EQ(w.side({1, 1, 1}), -1);
  EXPECT_EQ(w.side({0.5, 1.5, 0}), 0);
  EXPECT_EQ(w.side({1, 1, 0}), 0);
}

// spec/stuffing.md S19: a face inside the solid, between w = 1 and w = 2, is
// inside; the surface of the union is 0.
TEST(SoupWindingNumber, SideOnAnInteriorFaceIsInside) {
  Soup s = cube(0, 2);
  Soup upper = cube(0, 2);
  for (Vec3& v : upper.v) v[2] += 1;  // [0,2] x [0,2] x [1,3]
  append(s, upper);
  const WindingNumber w = make(s);
  EXPECT_NEAR(w.direct({1, 1, 1.5}), 2, 1e-12);
  EXPECT_NEAR(w.direct({1, 1, 0.5}), 1, 1e-12);
  EXPECT_EQ(w.side({0.5, 1.5, 1}), -1);  // the upper cube's bottom face, inside the lower cube
  EXPECT_EQ(w.side({1, 1, 1}), -1);      // the same face, on its diagonal
  EXPECT_EQ(w.side({1.5, 0.5, 2}), -1);  // the lower cube's top face, inside the upper cube
  EXPECT_EQ(w.side({0.5, 1.5, 0}), 0);   // the union's bottom
  EXPECT_EQ(w.side({0.5, 1.5, 3}), 0);   // the union's top
}

// spec/stuffing.md S19: back-to-back coincident faces cancel: a point on them
// has the side around them.
TEST(SoupWindingNumber, SideOnBackToBackFacesIsTheSurroundingSide) {
  const Soup sheet{{{0.25, 0.25, 1}, {1.75, 0.25, 1}, {1.75, 1.75, 1}, {0.25, 1.75, 1}}, {{0, 1, 2}, {0, 2, 3}}};
  Soup s = cube(0, 2);
  append(s, sheet);
  append(s, reversed(sheet));
  Soup outside_sheet = sheet;
  for (Vec3& v : outside_sheet.v) v[2] = 5;
  append(s, outside_sheet);
  append(s, reversed(outside_sheet));
  const WindingNumber w = make(s);
  EXPECT_EQ(w.side({0.5, 1.5, 1}), -1);    // inside the cube, on the pair
  EXPECT_EQ(w.side({1, 1, 1}), -1);        // on the pair's diagonal
  EXPECT_EQ(w.side({0.25, 0.25, 1}), -1);  // a corner of the pair: the rays cancel too
  EXPECT_EQ(w.side({0.5, 1.5, 5}), 1);     // outside, on the pair
  EXPECT_EQ(w.side({1, 1, 5}), 1);
  // One sheet alone (no partner) inside the cube: the limits are 1 +- 1/2,
  // both >= 1/2: inside. Its rim is not a uniform cover: 0.
  Soup one = cube(0, 2);
  append(one, sheet);
  const WindingNumber w1 = make(one);
  EXPECT_EQ(w1.side({0.5, 1.5, 1}), -1);
  EXPECT_EQ(w1.side({1, 0.25, 1}), 0);
}

// The hierarchy is not fooled by a soup with one triangle, none, or many
// identical centroids.
TEST(SoupWindingNumber, SmallAndDegenerateSoups) {
  const WindingNumber none = make(Soup{});
  EXPECT_EQ(none.size(), 0u);
  EXPECT_EQ(none.direct({0, 0, 0}), 0);
  EXPECT_EQ(none.side({0, 0, 0}), 1);
  // A degenerate triangle (collinear corners) contributes nothing; a point
  // on it is not on the soup.
  const WindingNumber line = make(Soup{{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 1, 2}}});
  EXPECT_EQ(line.direct({0, 1, 0}), 0);
  EXPECT_EQ(line.side({1, 1, 1}), 1);
  // 100 copies of the cube, nested alike: w = 100 inside.
  Soup many;
  for (int i = 0; i < 100; ++i) append(many, cube(0, 1));
  const WindingNumber w = make(many);
  EXPECT_NEAR(w.direct({0.5, 0.5, 0.5}), 100, 1e-10);
  const auto e = w.estimate({0.5, 0.5, 0.5});
  EXPECT_LE(std::abs(e.value - 100), e.error);
  EXPECT_EQ(w.side({0.5, 0.5, 0.5}), -1);
  EXPECT_EQ(w.side({0.5, 0.5, 1}), 0);
  EXPECT_EQ(w.side({5, 0.5, 0.5}), 1);
  const auto far = w.estimate({50, 0.5, 0.5});
  EXPECT_LT(far.error, 1e-3);
}

}  // namespace
