// Isosurface stuffing (spec/stuffing.md) on the built-in shapes. Every
// expectation is checked by something other than the stuffing code: the fit
// by hand from S2; orientation against the integer predicate; the mesh by
// its own geometry (a closed boundary whose vertices lie on the surface, the
// enclosed volume by the divergence theorem equal to the sum of the
// tetrahedra, every triangle in at most two tetrahedra), and the volume
// against the shape's closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/invariants/d3/stuffed_mesh.h"
#include "bccmis/stuff/animate.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {
namespace {

// spec/stuffing.md S10: the bounds every test mesh must meet (Labelle and
// Shewchuk's interval for the BCC lattice).
constexpr double kMinDihedral = 10.7792;
constexpr double kMaxDihedral = 164.8092;

TEST(StuffFit, HandExample) {
  // S2: box [0,1]^3, N = 4, L = 2: S = 1 / (4 - 10/4) = 2/3, h = 1/6,
  // N S = 8/3 = 1 + 10/6; 4 cubes on each side, origin -5/6.
  StuffOptions o;
  o.max_level = 2;
  const Fit fit = fit_lattice({{0, 0, 0}, {1, 1, 1}}, o);
  EXPECT_EQ(fit.size.W, 4);
  EXPECT_EQ(fit.size.H, 4);
  EXPECT_EQ(fit.size.D, 4);
  EXPECT_EQ(fit.size.L, 2);
  EXPECT_NEAR(fit.h, 1.0 / 6, 1e-15);
  EXPECT_NEAR(fit.origin[0], -5.0 / 6, 1e-15);
  EXPECT_NEAR(fit.scale, (2.0 / 3) / 8, 1e-15);  // S / 2^(L+1)
  // A flat box: the short sides get the smallest count with count S >= extent + 10h.
  const Fit flat = fit_lattice({{0, 0, 0}, {1, 0.1, 0}}, o);
  EXPECT_EQ(flat.size.W, 4);
  EXPECT_EQ(flat.size.H, 3);  // (0.1 + 10/6) / (2/3) = 2.65
  EXPECT_EQ(flat.size.D, 3);  // (10/6) / (2/3) = 2.5
}

TEST(StuffFit, Refusals) {
  StuffOptions o;
  o.max_level = 1;
  o.cells = 5;  // 5 x 2 = 10, not above 10
  EXPECT_THROW(fit_lattice({{0, 0, 0}, {1, 1, 1}}, o), ShapeError);
  o.cells = 6;
  EXPECT_NO_THROW(fit_lattice({{0, 0, 0}, {1, 1, 1}}, o));
  o.min_level = 2;
  EXPECT_THROW(fit_lattice({{0, 0, 0}, {1, 1, 1}}, o), ShapeError);
  StuffOptions bad;
  bad.size = -1;
  EXPECT_THROW(fit_lattice({{0, 0, 0}, {1, 1, 1}}, bad), ShapeError);
  EXPECT_THROW(fit_lattice({{0, 0, 0}, {0, 0, 0}}, StuffOptions{}), ShapeError);
}

TEST(StuffFit, SizeChoosesTheLevel) {
  // S2: the smallest L with N 2^L h >= E + 10h; E = 2, N = 4, h = 0.1: 4 2^L 0.1 >= 3 gives L = 3.
  StuffOptions o;
  o.size = 0.1;
  const Fit fit = fit_lattice({{-1, -1, -1}, {1, 1, 1}}, o);
  EXPECT_EQ(fit.size.L, 3);
  EXPECT_LE(fit.h, 0.1);
}

TEST(StuffOrientation, AgreesWithTheIntegerPredicate) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> u(-4, 4);
  for (int i = 0; i < 20000; ++i) {
    d3::Point p[4];
    Vec3 q[4];
    for (int k = 0; k < 4; ++k) {
      p[k] = {u(rng), u(rng), u(rng)};
      q[k] = {static_cast<double>(p[k].x), static_cast<double>(p[k].y), static_cast<double>(p[k].z)};
    }
    ASSERT_EQ(orientation(q[0], q[1], q[2], q[3]), d3::orientation(p[0], p[1], p[2], p[3])) << "case " << i;
  }
}

TEST(StuffOrientation, DecidesNearlyFlatCasesExactly) {
  // d one unit in the last place above or below the plane z = 0.3 of a, b, c
  // (counter-clockwise seen from above): the sign of the offset, where the
  // floating-point determinant (about 6e-17) is below its error bound.
  const Vec3 a{0.1, 0.1, 0.3}, b{1.1, 0.1, 0.3}, c{0.1, 1.1, 0.3};
  const double up = std::nextafter(0.3, 1.0), down = std::nextafter(0.3, 0.0);
  EXPECT_EQ(orientation(a, b, c, Vec3{0.3, 0.3, up}), 1);
  EXPECT_EQ(orientation(a, b, c, Vec3{0.3, 0.3, down}), -1);
  EXPECT_EQ(orientation(a, b, c, Vec3{0.7, 0.2, 0.3}), 0);
}

/// The mesh's own checks (see the file comment); returns the quality.
StuffQuality check_mesh(const Shape& shape, const Fit& fit, const Stuffed& s) {
  const d3::TetMeshF& m = s.mesh;
  EXPECT_GT(m.tets.size(), 0U);
  // The checker's stuffed-mesh layer: exact positive orientation, every
  // triangle in at most two tetrahedra, the boundary (found by the checker
  // itself) closed and on the surface, S10's angle bounds.
  d3::StuffedMeshClaims claims;
  claims.distance = [&](const Vec3& p) { return shape.signed_distance(p); };
  claims.tolerance = 1e-9 * fit.h;
  claims.dihedral = std::array{kMinDihedral, kMaxDihedral};
  const auto violation = d3::check_stuffed_mesh(m.vertices, m.tets, claims);
  EXPECT_FALSE(violation) << d3::to_string(*violation);
  // The boundary the mesher reports: the triangles of exactly one tetrahedron.
  std::map<std::array<std::uint32_t, 3>, int> faces;
  for (const auto& t : m.tets)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> f{};
      for (int i = 0, n = 0; i < 4; ++i)
        if (i != skip) f[static_cast<std::size_t>(n++)] = t[static_cast<std::size_t>(i)];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  std::size_t once = 0;
  for (const auto& [f, n] : faces) once += n == 1 ? 1 : 0;
  const auto boundary = boundary_triangles(m);
  EXPECT_EQ(boundary.size(), once);
  // On these smooth shapes the boundary is a manifold (each edge once each
  // way), and it encloses the tetrahedra's volume (divergence theorem).
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  long double enclosed = 0;
  for (const auto& t : boundary) {
    for (std::size_t i = 0; i < 3; ++i) ++edges[{t[i], t[(i + 1) % 3]}];
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    enclosed += (static_cast<long double>(a[0]) * (b[1] * c[2] - b[2] * c[1]) -
                 static_cast<long double>(a[1]) * (b[0] * c[2] - b[2] * c[0]) +
                 static_cast<long double>(a[2]) * (b[0] * c[1] - b[1] * c[0])) /
                6;
  }
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1U) << "open boundary edge " << e.first << "-" << e.second;
  }
  const StuffQuality q = quality(m);
  EXPECT_NEAR(q.volume, static_cast<double>(enclosed), 1e-9 * std::abs(q.volume));
  EXPECT_GE(q.min_dihedral, kMinDihedral);
  EXPECT_LE(q.max_dihedral, kMaxDihedral);
  return q;
}

struct Case {
  const char* name;
  std::shared_ptr<const Shape> shape;
  int level;
  double volume_tolerance;
};

std::vector<Case> cases() {
  return {
      {"sphere L2", make_sphere({0, 0, 0}, 1), 2, 0.08},
      {"sphere L3 off-center", make_sphere({0.123, -0.071, 0.0317}, 1), 3, 0.03},
      {"torus L3", make_torus({0, 0, 0}, 1, 0.4), 3, 0.08},
      {"two spheres L3", make_spheres({-0.5, 0, 0}, {0.5, 0.1, 0}, 0.7), 3, 0.05},
  };
}

TEST(StuffShapes, MeshesAreConformingOnTheSurfaceAndWithinTheBounds) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    StuffOptions o;
    o.max_level = c.level;
    const Fit fit = fit_lattice(c.shape->bounds(), o);
    // The fast path (its equality with the reference: stuffing_fast_test.cpp).
    const d3::fast::Lattice g = background_fast(*c.shape, fit, o);
    const Stuffed s = stuff(*c.shape, fit, g, o);
    const StuffQuality q = check_mesh(*c.shape, fit, s);
    const double exact = c.shape->volume();
    EXPECT_LT(std::abs(q.volume - exact) / exact, c.volume_tolerance) << q.volume << " vs " << exact;
    EXPECT_GT(s.cut_points, 0U);
    std::printf("%s: %zu tets, %zu cut points, %zu warped, dihedral [%.4f, %.4f], volume error %.5f\n", c.name,
                s.mesh.tets.size(), s.cut_points, s.warped, q.min_dihedral, q.max_dihedral, (q.volume - exact) / exact);
  }
}

TEST(StuffShapes, BackgroundIsFinestWithinTheBand) {
  // S3: every leaf whose cube comes within 4h of the surface is level L,
  // checked here with the sphere's exact box distance.
  const auto sphere = make_sphere({0, 0, 0}, 1);
  StuffOptions o;
  o.max_level = 3;
  const Fit fit = fit_lattice(sphere->bounds(), o);
  const d3::fast::Lattice g = background_fast(*sphere, fit, o);
  std::size_t coarse = 0;
  for (const d3::Point& c : g.cells()) {
    const int l = g.level_of(c);
    const double r = 0.5 * static_cast<double>(d3::cell_side(fit.size, l)) * fit.scale;
    const Vec3 p = fit.to_space(c);
    // The nearest and farthest distances from the origin over the cube.
    double near2 = 0, far2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const double lo = p[k] - r, hi = p[k] + r;
      const double n = lo > 0 ? lo : hi < 0 ? -hi : 0, f = std::max(std::abs(lo), std::abs(hi));
      near2 += n * n, far2 += f * f;
    }
    const double box_distance = std::max({std::sqrt(near2) - 1, 1 - std::sqrt(far2), 0.0});
    if (box_distance <= 4 * fit.h) {
      EXPECT_EQ(l, 3) << d3::to_string(c);
    }
    coarse += l < 3 ? 1 : 0;
  }
  EXPECT_GT(coarse, 0U);  // graded: not everything is refined
}

}  // namespace
}  // namespace bccmis::stuff

namespace bccmis::stuff {
namespace {

TEST(StuffAnimate, RememberedDistanceDecidesOnlyBeyondItsDrift) {
  // S37: a distance 1 asked 0.25 away (binary fractions, no rounding, e =
  // 0.125) says |f| <= 1.375 and |f| >= 0.625 now: a comparison exactly at
  // either end is decided (<= at the top, > just below the bottom), one a
  // step inside is not.
  const detail::DistanceBound b = detail::drifted(1.0, 0.25, 0.125);
  EXPECT_EQ(b.at_most(1.375), std::optional<bool>(true));
  EXPECT_EQ(b.at_most(std::nextafter(1.375, 0.0)), std::nullopt);
  EXPECT_EQ(b.at_most(std::nextafter(0.625, 0.0)), std::optional<bool>(false));
  EXPECT_EQ(b.at_most(0.625), std::nullopt);
  // At no drift the value itself decides, on both sides of it.
  const detail::DistanceBound v = detail::drifted(1.0, 0.0, 0.125);
  EXPECT_EQ(v.at_most(1.0), std::optional<bool>(true));
  EXPECT_EQ(v.at_most(std::nextafter(1.0, 0.0)), std::optional<bool>(false));
  // Nothing asked decides nothing; two bounds: the value where one is it,
  // else the intersection, and nothing where rounding left it empty.
  EXPECT_EQ(detail::DistanceBound{}.at_most(1e300), std::nullopt);
  EXPECT_EQ(detail::both(b, v).lo, 1.0);
  EXPECT_EQ(detail::both(b, detail::drifted(1.5, 0.25, 0.125)).lo, 1.125);
  EXPECT_EQ(detail::both(b, detail::drifted(1.5, 0.25, 0.125)).hi, 1.375);
  EXPECT_EQ(detail::both(b, detail::drifted(3.0, 0.25, 0.125)).hi, std::numeric_limits<double>::infinity());
}

TEST(StuffAnimate, ACellsDistanceBoundsItsChildrenWithinTheirOffset) {
  // S38: |f| in [1, 1.5] at a cell's center, children 0.25 away, e = 0.125:
  // in [0.625, 1.875] at theirs; a comparison exactly at either end is
  // decided (<= at the top, > just below the bottom), one a step inside is
  // not; the bottom stops at 0.
  const detail::DistanceBound b = detail::widened({1.0, 1.5}, 0.25, 0.125);
  EXPECT_EQ(b.at_most(1.875), std::optional<bool>(true));
  EXPECT_EQ(b.at_most(std::nextafter(1.875, 0.0)), std::nullopt);
  EXPECT_EQ(b.at_most(std::nextafter(0.625, 0.0)), std::optional<bool>(false));
  EXPECT_EQ(b.at_most(0.625), std::nullopt);
  EXPECT_EQ(detail::widened({0.25, 0.25}, 0.25, 0.125).lo, 0.0);
  EXPECT_EQ(detail::widened({}, 0.25, 0.125).at_most(1e300), std::nullopt);
}

TEST(StuffAnimate, APointOfTheSurfaceBoundsTheDistanceFromAbove) {
  // S39: |f| in [1, 10] at x = (3, 4, 0) with a point of the surface at the
  // origin, e = 0.125: |f| <= 5.125, decided exactly there (<=) and not a
  // step below; the lower end stays; the value itself stays the value; an
  // upper end below the lower end (rounding beyond e) knows nothing.
  const std::array<double, 3> x{3, 4, 0}, q{0, 0, 0};
  const detail::DistanceBound b = detail::closer({1.0, 10.0, 7}, x, q, 0.125);
  EXPECT_EQ(b.hi, 5.125);
  EXPECT_EQ(b.lo, 1.0);
  EXPECT_EQ(b.at_most(5.125), std::optional<bool>(true));
  EXPECT_EQ(b.at_most(std::nextafter(5.125, 0.0)), std::nullopt);
  EXPECT_EQ(detail::closer({7.0, 7.0}, x, q, 0.125).hi, 7.0);
  EXPECT_EQ(detail::closer({6.0, 10.0}, x, q, 0.125).at_most(1e300), std::nullopt);
  // The point goes with a bound to the children and through an intersection.
  EXPECT_EQ(detail::widened(b, 0.25, 0.125).nearest, 7U);
  EXPECT_EQ(detail::both(detail::DistanceBound{}, b).nearest, 7U);
  EXPECT_EQ(detail::both(detail::DistanceBound{}, detail::DistanceBound{}).nearest, detail::DistanceBound::kNoPoint);
}

TEST(StuffAnimate, NearestIsTheDistanceWithAPointOfTheSurface) {
  // S39 fact 1: nearest() gives distance() bit for bit, and a point of the
  // surface at that distance, through the translated and normalised views.
  std::mt19937_64 rng(39);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  const std::shared_ptr<const Shape> ball = make_sphere({0.25, 0, 0}, 0.75);
  const auto moved = translated(ball, {0.1, -0.2, 0.3});
  const Normalisation map{{0.5, 0, 0}, 1};
  const std::unique_ptr<Shape> seen = view_normalised(*moved, map);
  const std::unique_ptr<Shape> back = placed(make_sphere(map.to_local({0.35, -0.2, 0.3}), 0.375), map);
  for (const Shape* shape : std::array<const Shape*, 4>{ball.get(), moved.get(), seen.get(), back.get()})
    for (int i = 0; i < 2000; ++i) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      const Shape::Nearest n = shape->nearest(p);
      ASSERT_EQ(n.distance, shape->distance(p)) << i;
      ASSERT_TRUE(n.point.has_value());
      EXPECT_LE(shape->distance(*n.point), 1e-14) << i;
      EXPECT_NEAR(std::hypot(p[0] - (*n.point)[0], p[1] - (*n.point)[1], p[2] - (*n.point)[2]), n.distance, 1e-14) << i;
    }
  // No point where the distance is not the distance to one surface.
  EXPECT_FALSE(make_builtin("spheres")->nearest({0, 0, 0}).point.has_value());
  EXPECT_FALSE(make_builtin("torus")->nearest({0, 0, 0}).point.has_value());
}

TEST(StuffAnimate, BuiltInDistancesAreOneLipschitzAsClaimed) {
  // S37 fact 1: each built-in shape (and its translated view) claims a
  // 1-Lipschitz distance; random pairs of points near and far from the
  // surface, and pairs a hair apart, never differ by more than their
  // distance (up to rounding).
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> u(-2.5, 2.5), small(-1e-3, 1e-3);
  for (const char* name : {"sphere", "torus", "spheres:r=0.7,d=1"}) {
    SCOPED_TRACE(name);
    const std::shared_ptr<const Shape> shape = make_builtin(name);
    const auto moved = translated(shape, {0.1, -0.2, 0.3});
    EXPECT_TRUE(shape->distance_is_lipschitz());
    EXPECT_TRUE(moved->distance_is_lipschitz());
    for (int i = 0; i < 20000; ++i) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      const Vec3 q =
          i % 2 ? Vec3{u(rng), u(rng), u(rng)} : Vec3{p[0] + small(rng), p[1] + small(rng), p[2] + small(rng)};
      const double d = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      ASSERT_LE(std::abs(moved->distance(p) - moved->distance(q)), d * (1 + 1e-12) + 1e-15) << i;
    }
  }
}

TEST(StuffAnimate, LocalStepsReachTheLatticeBuiltFromScratch) {
  // S15: after every frame the fast lattice updated locally equals the
  // reference background() of the moved shape, built from the initial
  // lattice; and a step does fewer operations than building from scratch.
  const std::shared_ptr<const Shape> ball = make_sphere({0, 0, 0}, 0.4);
  const Vec3 path{1.2, 0.3, 0};
  StuffOptions o;
  o.max_level = 2;
  o.cells = 6;
  const Fit fit = fit_lattice(swept_bounds(*ball, path), o);
  MovingLattice moving(ball, fit, o);
  const std::size_t initial_leaves = fit.size.W * fit.size.H * fit.size.D;
  for (int frame = 1; frame <= 2; ++frame) {  // a wrong bound shows from the second
    SCOPED_TRACE(frame);
    const Vec3 offset{path[0] * frame / 4, path[1] * frame / 4, path[2] * frame / 4};
    const FrameReport r = moving.step(offset);
    const auto moved = translated(ball, offset);
    const d3::Graph scratch = background(*moved, fit, o);
    EXPECT_TRUE(moving.lattice().to_graph() == scratch);
    EXPECT_EQ(r.leaves, scratch.C.size());
    EXPECT_GT(r.refines, 0U);
    EXPECT_GT(r.coarsens, 0U);
    // From scratch, every refined cell is one refine: (leaves - initial) / 7.
    EXPECT_LT(r.refines + r.coarsens, (scratch.C.size() - initial_leaves) / 7);
    check_mesh(*moved, fit, moving.stuffed());
  }
}

// The tetrahedra of a mesh as a sorted list of (level, sorted vertex
// positions with kinds): equal lists are equal meshes up to numbering.
using TetKey = std::pair<int, std::array<std::tuple<double, double, double, int>, 4>>;
std::vector<TetKey> tet_keys(const d3::TetMeshF& m) {
  std::vector<TetKey> out;
  for (std::size_t t = 0; t < m.tets.size(); ++t) {
    TetKey k{m.level[t], {}};
    for (std::size_t i = 0; i < 4; ++i) {
      const auto& p = m.vertices[m.tets[t][i]];
      k.second[i] = {p[0], p[1], p[2], m.kind[m.tets[t][i]]};
    }
    std::sort(k.second.begin(), k.second.end());
    out.push_back(k);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(StuffAnimate, SameTetrahedraIgnoresNumberingOnly) {
  // What --check compares each frame by: the tetrahedra as sets, whatever
  // the vertex and tetrahedron numbering; one ulp, a kind or a level apart
  // is a difference.
  d3::TetMeshF a;
  a.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  a.kind = {0, 0, 2, 1, 0};
  a.tets = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  a.level = {3, 2};
  d3::TetMeshF b;  // vertices reversed, tetrahedra swapped, corners rotated
  b.vertices = {{1, 1, 1}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}};
  b.kind = {0, 1, 2, 0, 0};
  b.tets = {{3, 2, 0, 1}, {4, 3, 2, 1}};
  b.level = {2, 3};
  EXPECT_TRUE(same_tetrahedra(a, b));
  d3::TetMeshF c = b;
  c.vertices[0][2] = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(same_tetrahedra(a, c));
  c = b;
  c.kind[2] = 0;
  EXPECT_FALSE(same_tetrahedra(a, c));
  c = b;
  c.level = {3, 2};
  EXPECT_FALSE(same_tetrahedra(a, c));
  c = b;
  c.tets.pop_back();
  c.level.pop_back();
  EXPECT_FALSE(same_tetrahedra(a, c));
}

TEST(StuffAnimate, LocalStuffingEqualsTheReferenceStuffingOfEachFrame) {
  // S16: the mesh kept up to date by stuffing only the active leaves equals
  // the reference stuffing (std::map path, d3::Graph lattice) of the moved
  // shape built from scratch, tetrahedron for tetrahedron; for small steps,
  // sign flips by a step longer than the band (the second path), and a step
  // back to the start.
  const std::shared_ptr<const Shape> ball = make_sphere({0, 0, 0}, 0.4);
  StuffOptions o;
  o.max_level = 2;
  o.cells = 4;
  for (const Vec3 path : {Vec3{0.06, 0.02, 0}, Vec3{1.1, -0.4, 0.3}}) {
    SCOPED_TRACE(path[0]);
    const Fit fit = fit_lattice(swept_bounds(*ball, path), o);
    MovingLattice moving(ball, fit, o);
    for (const double t : {0.25, 0.5, 1.0, 0.0}) {
      SCOPED_TRACE(t);
      const Vec3 offset{path[0] * t, path[1] * t, path[2] * t};
      const FrameReport r = moving.step(offset);
      const auto moved = translated(ball, offset);
      const Stuffed reference = stuff(*moved, fit, background(*moved, fit, o), o);
      ASSERT_EQ(moving.stuffed().mesh.tets.size(), reference.mesh.tets.size());
      EXPECT_TRUE(tet_keys(moving.stuffed().mesh) == tet_keys(reference.mesh));
      EXPECT_LE(moving.stuffed().lattice_tetrahedra, reference.lattice_tetrahedra);
      EXPECT_EQ(moving.stuffed().cut_points, reference.cut_points);
      EXPECT_EQ(moving.stuffed().warped, reference.warped);
      // Only a part of the lattice is stuffed again.
      EXPECT_GT(r.restuffed_tetrahedra, 0U);
      EXPECT_LT(r.restuffed_tetrahedra, reference.lattice_tetrahedra);
      EXPECT_LT(r.restuffed_leaves, r.leaves);
    }
  }
}

/// A sphere whose distance is a lower bound that wobbles along x, 0.2 to 1
/// times the true one: valid for S3 and S16, but not 1-Lipschitz (S37 fact
/// 1), so it says so.
class WobblyBall final : public Shape {
 public:
  double signed_distance(const Vec3& p) const override {
    return ball_->signed_distance(p) * (0.6 + 0.4 * std::cos(40 * p[0]));
  }
  int side(const Vec3& p) const override { return ball_->side(p); }
  double crossing(const Vec3& a, const Vec3& b) const override { return ball_->crossing(a, b); }
  Bounds bounds() const override { return ball_->bounds(); }
  double volume() const override { return ball_->volume(); }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    return ball_->sample_surface(n, seed);
  }
  std::string describe() const override { return "wobbly ball"; }

 private:
  std::unique_ptr<Shape> ball_ = make_sphere({0, 0, 0}, 0.4);
};

TEST(StuffAnimate, ADistanceThatIsNotOneLipschitzIsAskedAgainEveryFrame) {
  // S37 fact 1: a remembered distance bounds today's only for a 1-Lipschitz
  // distance. The wobbly ball's changes by up to about 6 times the distance
  // moved; its frames still equal the lattice and the stuffing built from
  // scratch, because nothing asked at another offset decides anything.
  const std::shared_ptr<const Shape> ball = std::make_shared<WobblyBall>();
  ASSERT_FALSE(ball->distance_is_lipschitz());
  const Vec3 path{0.2, 0.05, 0};
  StuffOptions o;
  o.max_level = 2;
  o.cells = 4;
  const Fit fit = fit_lattice(swept_bounds(*ball, path), o);
  MovingLattice moving(ball, fit, o);
  for (int frame = 1; frame <= 2; ++frame) {  // a wrong bound shows from the second
    SCOPED_TRACE(frame);
    const Vec3 offset{path[0] * frame / 4, path[1] * frame / 4, path[2] * frame / 4};
    moving.step(offset);
    const auto moved = translated(ball, offset);
    const d3::Graph lattice = background(*moved, fit, o);
    EXPECT_TRUE(moving.lattice().to_graph() == lattice);
    const Stuffed reference = stuff(*moved, fit, lattice, o);
    EXPECT_TRUE(tet_keys(moving.stuffed().mesh) == tet_keys(reference.mesh));
  }
}

/// A shape that counts the distances asked of it, and says whether its
/// distance is 1-Lipschitz as it is told (S37 fact 1).
class CountingShape final : public Shape {
 public:
  CountingShape(std::shared_ptr<const Shape> s, bool lipschitz, bool points = false)
      : s_(std::move(s)), lipschitz_(lipschitz), points_(points) {}
  double signed_distance(const Vec3& p) const override {
    ++signed_asked;
    return s_->signed_distance(p);
  }
  double distance(const Vec3& p) const override {
    ++asked;
    return s_->distance(p);
  }
  bool distance_is_lipschitz() const override { return lipschitz_; }
  Nearest nearest(const Vec3& p) const override {
    if (!points_) return Shape::nearest(p);
    ++asked;
    return s_->nearest(p);
  }
  int side(const Vec3& p) const override { return s_->side(p); }
  double crossing(const Vec3& a, const Vec3& b) const override { return s_->crossing(a, b); }
  Bounds bounds() const override { return s_->bounds(); }
  double volume() const override { return s_->volume(); }
  std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const override {
    return s_->sample_surface(n, seed);
  }
  std::string describe() const override { return s_->describe(); }
  mutable std::size_t asked = 0, signed_asked = 0;

 private:
  std::shared_ptr<const Shape> s_;
  bool lipschitz_, points_;
};

/// The ball of radius 0.4 moved by `path` in quarters through a level-3
/// lattice, counted (CountingShape): the distances asked in each of
/// `frames` steps, and each frame's lattice and mesh; the last lattice is
/// checked against the one built from scratch.
struct CountedRun {
  std::vector<std::size_t> asked;
  std::vector<std::pair<d3::Graph, d3::TetMeshF>> frames;
};
CountedRun run_counted(bool lipschitz, bool points, int frames) {
  const Vec3 path{0.3, -0.1, 0.05};
  StuffOptions o;
  o.max_level = 3;
  o.cells = 4;
  const std::shared_ptr<const Shape> ball = make_sphere({0, 0, 0}, 0.4);
  const Fit fit = fit_lattice(swept_bounds(*ball, path), o);
  const auto counting = std::make_shared<CountingShape>(ball, lipschitz, points);
  MovingLattice moving(counting, fit, o);
  CountedRun out;
  Vec3 offset{};
  for (int frame = 1; frame <= frames; ++frame) {
    counting->asked = 0;
    offset = {path[0] * frame / 4, path[1] * frame / 4, path[2] * frame / 4};
    moving.step(offset);
    out.asked.push_back(counting->asked);
    out.frames.emplace_back(moving.lattice().to_graph(), moving.stuffed().mesh);
  }
  EXPECT_TRUE(out.frames.back().first == background_fast(*translated(ball, offset), fit, o).to_graph());
  return out;
}

/// The same lattices and the same tetrahedra, frame by frame.
void expect_same_frames(const CountedRun& a, const CountedRun& b) {
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t k = 0; k < a.frames.size(); ++k) {
    EXPECT_TRUE(a.frames[k].first == b.frames[k].first) << k;
    EXPECT_TRUE(tet_keys(a.frames[k].second) == tet_keys(b.frames[k].second)) << k;
  }
}

TEST(StuffAnimate, ACellsDistanceSparesItsChildrensQueriesWithTheSameFrames) {
  // S38: in the first step nothing is remembered from an earlier descent
  // (S37), so every query the 1-Lipschitz ball spares against the same
  // ball claimed otherwise is a child decided by its parent's distance;
  // the frames are the same tetrahedra, and the lattice built from scratch.
  const CountedRun asked_always = run_counted(false, false, 2), bounded = run_counted(true, false, 2);
  EXPECT_LT(bounded.asked[0], asked_always.asked[0] * 3 / 4);
  expect_same_frames(asked_always, bounded);
}

TEST(StuffAnimate, APointOfTheSurfaceSparesQueriesWithTheSameFrames) {
  // S39: the same 1-Lipschitz ball with and without its nearest points:
  // with them, fewer distances are asked in every step (the upper end of a
  // remembered or a parent's bound is the moved point's distance), and the
  // frames are the same lattice and tetrahedra, the lattice built from
  // scratch.
  const CountedRun without = run_counted(true, false, 2), with = run_counted(true, true, 2);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_LT(with.asked[k], without.asked[k]) << k;
  expect_same_frames(without, with);
}

TEST(StuffAnimate, NoLeafCoarserThanLevelLIsActive) {
  // S39a: for a shape whose distance is the distance to its surface, every
  // active leaf has level L, so a leaf the step made that the descent did not
  // find is inactive (S38a needs no exception for it). A ball of radius 0.3
  // (h = 1, L = 6, level-0 cells of side 64, where a coarse leaf could be
  // active by S16's threshold alone) moves in steps of 5 across a corner
  // where 8 level-0 cells meet: on every frame the active leaves are
  // exactly the leaves with |f(u)| <= s_u + 1.05 r_w, all of level L, and the
  // coarse leaves come within 25 finest sides of their threshold.
  StuffOptions o;
  o.max_level = 6;
  Fit fit;
  fit.size.W = fit.size.H = fit.size.D = 2;
  fit.size.L = 6;
  fit.scale = 0.5;
  fit.h = 1;
  const std::shared_ptr<const Shape> ball = make_sphere({44.6, 46.6, 47.1}, 0.3);
  MovingLattice moving(ball, fit, o);
  const double reach = 1.05 * std::max(o.alpha_long * fit.h, o.alpha_short * 0.5 * std::sqrt(3.0) * fit.h);
  double nearest_coarse = 1e300;
  for (int frame = 1; frame <= 8; ++frame) {
    SCOPED_TRACE(frame);
    const FrameReport r = moving.step({5.0 * frame, 4.0 * frame, 3.0 * frame});
    std::size_t active = 0;
    for (const d3::Point& u : moving.lattice().cells()) {
      const int level = moving.lattice().level_of(u);
      const double s = static_cast<double>(d3::cell_side(fit.size, level)) * fit.scale;
      const double f = std::abs(moving.shape().signed_distance(fit.to_space(u)));
      active += f <= s + reach;
      if (level < fit.size.L) {
        EXPECT_GT(f, s + reach) << d3::to_string(u);
        if (level <= 1) nearest_coarse = std::min(nearest_coarse, f - s);
      }
    }
    EXPECT_EQ(r.restuffed_leaves, active);
  }
  EXPECT_LT(nearest_coarse, 25.0);
}

TEST(StuffAnimate, ALeafThatLeftTheBandIsSettledByItsSideAlone) {
  // S38a: in steps shorter than the band (m < s + 1.05 r_w at level L, so
  // the descent settles the activity of every leaf it finds), a signed
  // distance is asked only of leaves the step made: a changed cell and its
  // 8 children, at most 9 a refine or coarsen. The leaves beside them and
  // the last frame's active leaves that the descent no longer finds (about
  // twice as many) are inactive without one.
  const Vec3 path{0.06, 0.02, 0};
  StuffOptions o;
  o.max_level = 3;
  o.cells = 4;
  const std::shared_ptr<const Shape> ball = make_sphere({0, 0, 0}, 0.4);
  const Fit fit = fit_lattice(swept_bounds(*ball, path), o);
  const auto counting = std::make_shared<CountingShape>(ball, true);
  MovingLattice moving(counting, fit, o);
  for (int frame = 1; frame <= 3; ++frame) {
    counting->signed_asked = 0;
    const FrameReport r = moving.step({path[0] * frame / 4, path[1] * frame / 4, path[2] * frame / 4});
    EXPECT_LE(counting->signed_asked, 9 * (r.refines + r.coarsens)) << frame;
    EXPECT_GT(r.refines + r.coarsens, 0U) << frame;
  }
}

TEST(StuffAnimate, FramesAreTheSameOnAnyNumberOfThreads) {
  // S28: a step's stuffing computes the vertex values and the cut points on
  // `threads` threads, each over a range of items; the frames are the same,
  // bit for bit, on 1 and 3 threads (uneven ranges; the default, every core,
  // is held to the reference stuffing by the test above).
  const std::shared_ptr<const Shape> ball = make_sphere({0, 0, 0}, 0.4);
  const Vec3 path{0.3, -0.1, 0.05};
  StuffOptions o;
  o.max_level = 3;
  o.cells = 4;
  const Fit fit = fit_lattice(swept_bounds(*ball, path), o);
  std::vector<d3::TetMeshF> frames[2];
  for (const int threads : {1, 3}) {
    o.threads = threads;
    MovingLattice moving(ball, fit, o);
    for (const double t : {0.5, 1.0}) {
      const FrameReport r = moving.step({path[0] * t, path[1] * t, path[2] * t});
      EXPECT_GT(r.restuffed_tetrahedra, 3000U);  // enough vertices and cuts to split
      frames[threads == 1 ? 0 : 1].push_back(moving.stuffed().mesh);
    }
  }
  for (std::size_t f = 0; f < 2; ++f) {
    SCOPED_TRACE(f);
    EXPECT_EQ(frames[1][f].vertices, frames[0][f].vertices);
    EXPECT_EQ(frames[1][f].kind, frames[0][f].kind);
    EXPECT_EQ(frames[1][f].tets, frames[0][f].tets);
    EXPECT_EQ(frames[1][f].level, frames[0][f].level);
  }
}

}  // namespace
}  // namespace bccmis::stuff
