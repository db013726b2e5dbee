// The checker's stuffed-mesh layer (bccmis/invariants/d3/stuffed_mesh.h) on
// hand-built meshes: one valid case per code, then the same mesh broken in
// one place, and each threshold tested exactly at its line.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "bccmis/invariants/d3/stuffed_mesh.h"

namespace bccmis::d3 {
namespace {

using V = std::array<double, 3>;
using T = std::array<std::uint32_t, 4>;

// The corner tetrahedron: positively oriented (det = 1), dihedral angles 90
// degrees at the three edges through the origin and acos(1/sqrt(3)) =
// 54.7356... degrees at the other three.
const std::vector<V> kCorner{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

StuffedMeshClaims on_surface() {
  StuffedMeshClaims c;
  c.distance = [](const V&) { return 0.0; };
  return c;
}

std::string code(const std::optional<Violation>& v) { return v ? v->code : "none"; }

TEST(StuffedMeshCheck, ValidMeshesPass) {
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, std::vector<T>{{0, 1, 2, 3}}, on_surface())), "none");
  // Two tetrahedra on either side of the triangle (1, 2, 3): it is in two
  // tetrahedra (the line: at most two), the other six triangles form a closed boundary.
  std::vector<V> v = kCorner;
  v.push_back({1, 1, 1});
  EXPECT_EQ(code(check_stuffed_mesh(v, std::vector<T>{{0, 1, 2, 3}, {4, 1, 3, 2}}, on_surface())), "none");
}

TEST(StuffedMeshCheck, OrientationIsExact) {
  // d 1e-20 off the plane x + y + z = 1 through a, b, c: far below the
  // floating-point filter's bound, so the rational arithmetic decides.
  const V a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 1};
  const std::vector<T> tet{{0, 1, 2, 3}};
  EXPECT_EQ(code(check_stuffed_mesh(std::vector<V>{a, b, c, {1e-20, 0.5, 0.5}}, tet, on_surface())), "none");
  EXPECT_EQ(code(check_stuffed_mesh(std::vector<V>{a, b, c, {-1e-20, 0.5, 0.5}}, tet, on_surface())),
            "stuffed-orientation");
  EXPECT_EQ(code(check_stuffed_mesh(std::vector<V>{a, b, c, {0, 0.5, 0.5}}, tet, on_surface())),  // flat
            "stuffed-orientation");
  // Inverted, and a vertex index out of range.
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, std::vector<T>{{0, 2, 1, 3}}, on_surface())), "stuffed-orientation");
  const auto v = check_stuffed_mesh(kCorner, std::vector<T>{{0, 1, 2, 4}}, on_surface());
  ASSERT_TRUE(v);
  EXPECT_EQ(v->message, "stuffed-orientation: tetrahedron 0 names vertex 4 of 4");
}

TEST(StuffedMeshCheck, ATriangleInThreeTetrahedra) {
  std::vector<V> v = kCorner;
  v.push_back({1, 1, 1});
  v.push_back({2, 2, 2});
  const auto r = check_stuffed_mesh(v, std::vector<T>{{0, 1, 2, 3}, {4, 1, 3, 2}, {5, 1, 3, 2}}, on_surface());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->code, "stuffed-face-count");
  EXPECT_EQ(r->message, "stuffed-face-count: the triangle (1, 2, 3) is in more than two tetrahedra");
  EXPECT_EQ(r->layer, 7);
}

TEST(StuffedMeshCheck, BoundaryOnTheSurfaceWithinTheTolerance) {
  const std::vector<T> tet{{0, 1, 2, 3}};
  StuffedMeshClaims c;
  c.tolerance = 0.25;
  c.distance = [](const V& p) { return p[2] == 1 ? -0.25 : 0.0; };  // exactly at the line: accepted
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, tet, c)), "none");
  c.distance = [](const V& p) { return p[2] == 1 ? std::nextafter(-0.25, -1.0) : 0.0; };
  const auto r = check_stuffed_mesh(kCorner, tet, c);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->message, "stuffed-off-surface: boundary vertex 3 is off the surface");
  c.distance = [](const V&) { return std::numeric_limits<double>::quiet_NaN(); };
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, tet, c)), "stuffed-off-surface");
}

TEST(StuffedMeshCheck, AnOpenBoundary) {
  // Two tetrahedra on the same side of the triangle (0, 1, 2): it is in two
  // tetrahedra, yet their other faces cross the edge 0 -> 1 twice the same way.
  std::vector<V> v = kCorner;
  v.push_back({0.1, 0.1, 2});
  const auto r = check_stuffed_mesh(v, std::vector<T>{{0, 1, 2, 3}, {0, 1, 2, 4}}, on_surface());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->code, "stuffed-open");
}

TEST(StuffedMeshCheck, DihedralBoundsAtTheirLines) {
  const std::vector<T> tet{{0, 1, 2, 3}};
  StuffedMeshClaims c = on_surface();
  const double low = std::acos(1 / std::sqrt(3.0)) * 180 / std::numbers::pi;  // 54.7356...
  c.dihedral = std::array{low - 1e-9, 90.0};  // 90 exactly: the right angles are at the line
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, tet, c)), "none");
  c.dihedral = std::array{low - 1e-9, std::nextafter(90.0, 0.0)};
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, tet, c)), "stuffed-dihedral");
  c.dihedral = std::array{low + 1e-9, 90.0};
  EXPECT_EQ(code(check_stuffed_mesh(kCorner, tet, c)), "stuffed-dihedral");
  c.dihedral = std::nullopt;  // unchecked
  c.distance = [](const V&) { return 0.0; };
  EXPECT_EQ(code(check_stuffed_mesh(std::vector<V>{{0, 0, 0}, {100, 0, 0}, {0, 100, 0}, {1, 1, 1e-6}}, tet, c)),
            "none");
}

}  // namespace
}  // namespace bccmis::d3
