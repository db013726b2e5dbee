// Closed triangle meshes as shapes (spec/stuffing.md §1): the cube [0,2]^3 by
// hand (distances, crossings, volume, bounds, samples), the readers on small
// files (OBJ quads with every index form, an inward ASCII STL, a binary STL),
// every refusal with its exact message (tests/stuff/bad/), and CGAL's sample
// meshes elephant.off, double-torus-example.off and icosahedron.off.
#include "bccmis/stuff/surface.h"

#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace bccmis::stuff {
namespace {

using Tris = std::vector<std::array<std::uint32_t, 3>>;

const std::string kDir = BCCMIS_STUFF_TEST_DIR;
const std::string kCgal = BCCMIS_CGAL_MESHES_DIR;

/// The cube [0,2]^3: vertex x + 2y + 4z at 2 (x, y, z); two triangles a
/// side, counterclockwise seen from outside.
std::vector<Vec3> cube_vertices() {
  std::vector<Vec3> v;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) v.push_back({2.0 * x, 2.0 * y, 2.0 * z});
  return v;
}
Tris cube_triangles() {
  return {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
          {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ShapeError& e) {
    return e.what();
  }
  return "(no ShapeError)";
}

std::string load_message(const std::string& path) {
  return message_of([&] { load_surface(path); });
}

TEST(SurfaceCube, SignedDistanceAtKnownPoints) {
  const auto s = make_mesh_shape(cube_vertices(), cube_triangles(), "cube");
  EXPECT_DOUBLE_EQ(s->signed_distance({1, 1, 1}), -1);
  EXPECT_DOUBLE_EQ(s->signed_distance({1, 1, 0.5}), -0.5);
  EXPECT_DOUBLE_EQ(s->signed_distance({0.25, 1.5, 1.5}), -0.25);
  EXPECT_DOUBLE_EQ(s->signed_distance({3, 1, 1}), 1);
  EXPECT_DOUBLE_EQ(s->signed_distance({1, -0.5, 1}), 0.5);
  EXPECT_DOUBLE_EQ(s->signed_distance({3, 3, 1}), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(s->signed_distance({3, 3, 3}), std::sqrt(3.0));
  EXPECT_EQ(s->signed_distance({1, 1, 0}), 0);  // on a face
  EXPECT_EQ(s->signed_distance({2, 2, 2}), 0);  // a corner
  EXPECT_EQ(s->signed_distance({2, 1, 2}), 0);  // on an edge
  // side() and distance() answer without the other query: the same sign
  // and magnitude.
  for (const Vec3& p :
       std::vector<Vec3>{{1, 1, 1}, {1, 1, 0.5}, {3, 1, 1}, {1, -0.5, 1}, {3, 3, 3}, {1, 1, 0}, {2, 2, 2}, {2, 1, 2}}) {
    const double f = s->signed_distance(p);
    EXPECT_EQ(s->side(p), (f > 0) - (f < 0));
    EXPECT_EQ(s->distance(p), std::abs(f));
  }
}

TEST(SurfaceCube, NearestIsTheDistanceWithTheClosestPoint) {
  // spec/stuffing.md S39 fact 1: the distance bit for bit, and the tree's
  // closest point: on the surface, at that distance.
  const auto s = make_mesh_shape(cube_vertices(), cube_triangles(), "cube");
  const std::vector<std::pair<Vec3, Vec3>> known{
      {{1, 1, 0.5}, {1, 1, 0}}, {{3, 1, 1}, {2, 1, 1}}, {{3, 3, 3}, {2, 2, 2}}, {{1, -0.5, 1}, {1, 0, 1}}};
  for (const auto& [p, q] : known) {
    const Shape::Nearest n = s->nearest(p);
    EXPECT_EQ(n.distance, s->distance(p));
    ASSERT_TRUE(n.point.has_value());
    EXPECT_EQ(*n.point, q);
  }
  std::mt19937_64 rng(39);
  std::uniform_real_distribution<double> u(-1, 3);
  for (int i = 0; i < 500; ++i) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Shape::Nearest n = s->nearest(p);
    ASSERT_EQ(n.distance, s->distance(p)) << i;
    ASSERT_TRUE(n.point.has_value());
    EXPECT_EQ(s->distance(*n.point), 0) << i;
  }
}

TEST(SurfaceCube, CrossingAtKnownParameter) {
  const auto s = make_mesh_shape(cube_vertices(), cube_triangles(), "cube");
  EXPECT_DOUBLE_EQ(s->crossing({1, 1, 1}, {1, 1, 5}), 0.25);  // z = 2
  EXPECT_DOUBLE_EQ(s->crossing({1, 1, 5}, {1, 1, 1}), 0.75);  // from outside
  EXPECT_DOUBLE_EQ(s->crossing({-2, 0.5, 1.5}, {1, 0.5, 1.5}), 2.0 / 3);
  // Through an edge of two triangles (the diagonal of the side z = 2).
  EXPECT_DOUBLE_EQ(s->crossing({0.5, 0.5, 1}, {0.5, 0.5, 3}), 0.5);
  EXPECT_DOUBLE_EQ(s->crossing({1, 1, 1}, {1, 1, 2}), 1);  // b on the surface
  EXPECT_DOUBLE_EQ(s->crossing({1, 1, 0}, {1, 1, 1}), 0);  // a on the surface
  // A segment crossing twice: the crossing nearest a.
  EXPECT_DOUBLE_EQ(s->crossing({-1, 1, 1}, {4, 1, 1}), 0.2);
}

TEST(SurfaceCube, VolumeBoundsDescribe) {
  const auto s = make_mesh_shape(cube_vertices(), cube_triangles(), "cube");
  EXPECT_EQ(s->volume(), 8.0);
  const Bounds b = s->bounds();
  EXPECT_EQ(b.lo, (Vec3{0, 0, 0}));
  EXPECT_EQ(b.hi, (Vec3{2, 2, 2}));
  EXPECT_EQ(s->describe(), "mesh cube: 12 triangles");
  EXPECT_EQ(make_mesh_shape(cube_vertices(), cube_triangles(), "/some/dir/box.off")->describe(),
            "mesh box.off: 12 triangles");
}

TEST(SurfaceCube, InwardOrientationIsReversed) {
  Tris in = cube_triangles();
  for (auto& t : in) std::swap(t[1], t[2]);
  const auto s = make_mesh_shape(cube_vertices(), in, "cube");
  EXPECT_EQ(s->volume(), 8.0);
  EXPECT_DOUBLE_EQ(s->signed_distance({1, 1, 1}), -1);
}

TEST(SurfaceCube, SamplesLieOnTheSurfaceSpreadByArea) {
  const auto s = make_mesh_shape(cube_vertices(), cube_triangles(), "cube");
  const auto pts = s->sample_surface(6000, 7);
  ASSERT_EQ(pts.size(), 6000u);
  std::array<int, 6> per_side{};
  for (const auto& p : pts) {
    int on = -1;
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p[a], -1e-12);
      EXPECT_LE(p[a], 2 + 1e-12);
      if (std::abs(p[a]) < 1e-12) on = 2 * a;
      if (std::abs(p[a] - 2) < 1e-12) on = 2 * a + 1;
    }
    ASSERT_GE(on, 0) << p[0] << " " << p[1] << " " << p[2];
    ++per_side[static_cast<std::size_t>(on)];
    EXPECT_LT(std::abs(s->signed_distance(p)), 1e-12);
  }
  // Equal areas: 1000 a side expected; 5 standard deviations (~ 29) allowed.
  for (int n : per_side) {
    EXPECT_GT(n, 850);
    EXPECT_LT(n, 1150);
  }
  // Uniform on each triangle: by symmetry the mean is the centre (1, 1, 1);
  // its standard deviation per coordinate is about 0.6 / sqrt(6000) < 0.01.
  for (int a = 0; a < 3; ++a) {
    double mean = 0;
    for (const auto& p : pts) mean += p[static_cast<std::size_t>(a)] / static_cast<double>(pts.size());
    EXPECT_NEAR(mean, 1, 0.04) << "axis " << a;
  }
  EXPECT_EQ(s->sample_surface(100, 7), s->sample_surface(100, 7));
  EXPECT_NE(s->sample_surface(100, 7), s->sample_surface(100, 8));
  // The same seed gives the start of the same sequence.
  const auto few = s->sample_surface(10, 7);
  EXPECT_TRUE(std::equal(few.begin(), few.end(), pts.begin()));
}

TEST(SurfaceCube, MaxDistanceToTriangles) {
  const auto v = cube_vertices();
  const auto t = cube_triangles();
  EXPECT_DOUBLE_EQ(max_distance_to_triangles({{1, 1, 1}}, v, t), 1);
  EXPECT_DOUBLE_EQ(max_distance_to_triangles({{1, 1, 2}, {1, 1, 3.5}, {0.5, 1, 1}}, v, t), 1.5);
  EXPECT_DOUBLE_EQ(max_distance_to_triangles({{4, 4, 1}}, v, t), std::sqrt(8.0));
  EXPECT_EQ(max_distance_to_triangles({}, v, t), 0);
  // Only the triangle z = 0 (0, 2, 3): (0, 2, 2) is 2 above its corner 2.
  EXPECT_DOUBLE_EQ(max_distance_to_triangles({{0, 2, 2}, {2, 0, 0}}, v, {{0, 2, 3}}), 2);
  EXPECT_DOUBLE_EQ(max_distance_to_triangles({{2, 0, 0}}, v, {{0, 2, 3}}), std::sqrt(2.0));
}

// Refusals of meshes in memory: faces and vertices are numbered from 0.
TEST(SurfaceRefusals, InMemory) {
  const auto v = cube_vertices();
  auto with = [&](std::size_t face, std::array<std::uint32_t, 3> t) {
    Tris ts = cube_triangles();
    ts[face] = t;
    return message_of([&] { make_mesh_shape(v, ts, "m"); });
  };
  EXPECT_EQ(message_of([&] { make_mesh_shape(v, {}, "m"); }), "m: empty mesh (no faces)");
  EXPECT_EQ(with(3, {4, 7, 8}), "m: face 3: vertex index 8 out of range (8 vertices)");
  EXPECT_EQ(with(3, {4, 7, 4}), "m: face 3 is degenerate: vertex 4 repeated");
  std::vector<Vec3> mid = v;
  mid.push_back({1, 1, 2});  // vertex 8, the middle of the diagonal 4-7
  Tris ts = cube_triangles();
  ts.push_back({4, 8, 7});
  EXPECT_EQ(message_of([&] { make_mesh_shape(mid, ts, "m"); }),
            "m: face 12 is degenerate: zero area (vertices 4, 8 and 7 are collinear)");
  // Face 2 (4, 5, 7) reversed is (4, 7, 5), which runs 4 -> 7 as face 3 (4, 7, 6) does.
  EXPECT_EQ(with(2, {4, 7, 5}), "m: inconsistent orientation: face 2 and face 3 both run from vertex 4 to vertex 7");
  std::vector<Vec3> nan = v;
  nan[5][1] = std::nan("");
  EXPECT_EQ(message_of([&] { make_mesh_shape(nan, cube_triangles(), "m"); }),
            "m: vertex 5 has a coordinate not finite");
  EXPECT_EQ(message_of([&] {
              max_distance_to_triangles({{0, 0, 0}}, v, {{0, 1, 9}});
            }),
            "max_distance_to_triangles: vertex index 9 out of range (8 vertices)");
}

TEST(SurfaceFiles, ObjQuadsEveryIndexForm) {
  const auto s = load_surface(kDir + "/good/cube_quads.obj");
  EXPECT_EQ(s->describe(), "mesh cube_quads.obj: 12 triangles");
  EXPECT_EQ(s->volume(), 8.0);
  EXPECT_DOUBLE_EQ(s->signed_distance({1, 1, 1}), -1);
  EXPECT_DOUBLE_EQ(s->crossing({1, 1, 1}, {5, 1, 1}), 0.25);
}

TEST(SurfaceFiles, AsciiStlInwardIsReversed) {
  const auto s = load_surface(kDir + "/good/cube_inward.stl");
  EXPECT_EQ(s->describe(), "mesh cube_inward.stl: 12 triangles");
  EXPECT_EQ(s->volume(), 8.0);
  const Bounds b = s->bounds();
  EXPECT_EQ(b.lo, (Vec3{0, 0, 0}));
  EXPECT_EQ(b.hi, (Vec3{2, 2, 2}));
}

TEST(SurfaceFiles, OffWithColours) {
  // The tetrahedron (0, 0, 0), 3 e_x, 3 e_y, 3 e_z: volume 27 / 6.
  const auto s = load_surface(kDir + "/good/tet_colors.off");
  EXPECT_EQ(s->describe(), "mesh tet_colors.off: 4 triangles");
  EXPECT_EQ(s->volume(), 4.5);
  EXPECT_DOUBLE_EQ(s->signed_distance({0.5, 0.5, 0.5}), -0.5);
  EXPECT_DOUBLE_EQ(s->signed_distance({2, 2, 2}), 3 / std::sqrt(3.0));  // (6 - 3) / sqrt 3 from x + y + z = 3
}

TEST(SurfaceFiles, SamplesWeightedByArea) {
  // Three right triangles of area 4.5 and the slanted face x + y + z = 3 of
  // area (sqrt 3 / 4) 18 = 7.794: a fraction 7.794 / 21.294 = 0.366 of the
  // samples on it (standard deviation 0.008 for 4000).
  const auto s = load_surface(kDir + "/good/tet_colors.off");
  const auto pts = s->sample_surface(4000, 3);
  std::size_t slanted = 0;
  for (const auto& p : pts) slanted += std::abs(p[0] + p[1] + p[2] - 3) < 1e-12;
  EXPECT_NEAR(static_cast<double>(slanted) / 4000, 7.794228634059948 / (13.5 + 7.794228634059948), 0.03);
}

/// The cube as a binary STL (80-byte header, count, 50 bytes a triangle).
std::string binary_cube(std::size_t drop_bytes, const char* header) {
  std::string out(80, ' ');
  std::memcpy(out.data(), header, std::strlen(header));
  const auto v = cube_vertices();
  const auto t = cube_triangles();
  const std::uint32_t n = static_cast<std::uint32_t>(t.size());
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(n >> (8 * i)));
  for (const auto& tri : t) {
    float f[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) f[3 + 3 * k + c] = static_cast<float>(v[tri[static_cast<std::size_t>(k)]][c]);
    out.append(reinterpret_cast<const char*>(f), sizeof f);
    out.append(2, '\0');
  }
  out.resize(out.size() - drop_bytes);
  return out;
}

std::string write_temp(const std::string& name, const std::string& data) {
  // One directory per process: builds running their tests at once do not meet.
  const auto dir = std::filesystem::temp_directory_path() / ("bccmis_surface_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << data;
  return path.string();
}

TEST(SurfaceFiles, BinaryStl) {
  // A header starting with "solid" does not make it ASCII when the size fits.
  const auto path = write_temp("bccmis_surface_test_cube.STL", binary_cube(0, "solid but binary"));
  const auto s = load_surface(path);
  EXPECT_EQ(s->describe(), "mesh bccmis_surface_test_cube.STL: 12 triangles");
  EXPECT_EQ(s->volume(), 8.0);
  const auto cut = write_temp("bccmis_surface_test_cut.stl", binary_cube(1, "cube"));
  EXPECT_EQ(load_message(cut),
            cut + ": byte 634: binary STL truncated in triangle 11 of 12 (684 bytes expected, 683 present)");
  std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

// One file per refusal (tests/stuff/bad/): the exact message.
TEST(SurfaceFiles, Refusals) {
  const std::string bad = kDir + "/bad/";
  // The cube without its face (0, 3, 1): the three edges of that triangle are
  // borders; the first face met (0, 2, 3) has the border 3 -> 0.
  EXPECT_EQ(load_message(bad + "open.off"), bad + "open.off: open mesh: 3 border edges, one from vertex 3 to vertex 0");
  // Two tetrahedra on the edge 0-1: faces 0, 1 of the first, 4, 5 of the second.
  EXPECT_EQ(load_message(bad + "nonmanifold_edge.off"),
            bad +
                "nonmanifold_edge.off: non-manifold edge between vertex 1 and vertex 0: 4 faces (face 0 on line 9, "
                "face 1 on line 10, face 4 on line 13 and face 5 on line 14)");
  // Two tetrahedra on the vertex 0.
  EXPECT_EQ(load_message(bad + "nonmanifold_vertex.off"),
            bad +
                "nonmanifold_vertex.off: non-manifold vertex 0: its faces form more than one fan (face 0 on line 10 "
                "and face 4 on line 14 meet only at it)");
  // The second tetrahedron, moved by (1/4, 1/4, 1/4), passes through the
  // slanted face 3 of the first; faces 0-2 lie on the planes x, y, z = 0
  // which it does not reach.
  EXPECT_EQ(load_message(bad + "self_intersecting.off"),
            bad + "self_intersecting.off: self-intersecting (face 3 and face 4)");
  EXPECT_EQ(load_message(bad + "syntax.obj"), bad + "syntax.obj:3:7: bad number '1.5x' (expected a coordinate)");
  EXPECT_EQ(load_message(bad + "index_out_of_range.off"),
            bad + "index_out_of_range.off:9:5: face 2: vertex index 7 out of range (4 vertices)");
  EXPECT_EQ(load_message(bad + "empty.off"), bad + "empty.off: empty mesh (no faces)");
  // 84 + 50 bytes, then 10 of the second of 2 triangles.
  EXPECT_EQ(load_message(bad + "truncated.stl"),
            bad + "truncated.stl: byte 134: binary STL truncated in triangle 1 of 2 (184 bytes expected, 144 present)");
  EXPECT_EQ(load_message(bad + "absent.off"), bad + "absent.off: cannot open: No such file or directory");
  EXPECT_EQ(load_message(bad + "mesh.xyz"),
            bad + "mesh.xyz: unknown extension '.xyz' (expected .off, .obj, .ply or .stl)");
  EXPECT_EQ(load_message(bad + "mesh"), bad + "mesh: unknown extension '' (expected .off, .obj, .ply or .stl)");
}

/// The checks of a closed sample mesh: positive volume, samples on the
/// surface, a far point outside.
void check_closed(const Shape& s) {
  EXPECT_GT(s.volume(), 0);
  const Bounds b = s.bounds();
  double size = 0;
  for (int a = 0; a < 3; ++a) size = std::max(size, b.hi[a] - b.lo[a]);
  ASSERT_GT(size, 0);
  for (const auto& p : s.sample_surface(500, 1)) EXPECT_LT(std::abs(s.signed_distance(p)), 1e-9 * size);
  const Vec3 far{b.hi[0] + 3 * size, b.hi[1] + size, b.lo[2] - size};
  EXPECT_GT(s.signed_distance(far), 3 * size);
  // Inside of the bounding box's centre, towards the far point: a crossing.
  const Vec3 c{(b.lo[0] + b.hi[0]) / 2, (b.lo[1] + b.hi[1]) / 2, (b.lo[2] + b.hi[2]) / 2};
  if (s.signed_distance(c) < 0) {
    const double t = s.crossing(c, far);
    const Vec3 q{c[0] + t * (far[0] - c[0]), c[1] + t * (far[1] - c[1]), c[2] + t * (far[2] - c[2])};
    EXPECT_LT(std::abs(s.signed_distance(q)), 1e-9 * size);
  }
}

TEST(SurfaceCgalMeshes, Elephant) {
  const auto s = load_surface(kCgal + "/elephant.off");
  EXPECT_EQ(s->describe(), "mesh elephant.off: 5558 triangles");
  check_closed(*s);
  // side() and distance() (S3, S5, S16) agree with signed_distance on
  // points spread over the box, inside and outside (seed 7).
  const Bounds b = s->bounds();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int inside = 0;
  for (int i = 0; i < 300; ++i) {
    Vec3 p{};
    for (std::size_t k = 0; k < 3; ++k) p[k] = b.lo[k] + u(rng) * (b.hi[k] - b.lo[k]);
    const double f = s->signed_distance(p);
    EXPECT_EQ(s->side(p), (f > 0) - (f < 0)) << "seed 7, point " << i;
    EXPECT_EQ(s->distance(p), std::abs(f)) << "seed 7, point " << i;
    inside += f < 0 ? 1 : 0;
  }
  EXPECT_GT(inside, 10);
  EXPECT_LT(inside, 290);
}

TEST(SurfaceCgalMeshes, DoubleTorus) {
  const auto s = load_surface(kCgal + "/double-torus-example.off");
  EXPECT_EQ(s->describe(), "mesh double-torus-example.off: 466 triangles");
  check_closed(*s);
}

TEST(SurfaceCgalMeshes, IcosahedronConvex) {
  const auto s = load_surface(kCgal + "/icosahedron.off");
  EXPECT_EQ(s->describe(), "mesh icosahedron.off: 20 triangles");
  check_closed(*s);
  // The vertices lie on the unit sphere, rounded in the file: the inradius of
  // the icosahedron of circumradius 1 is 0.7946544722917661.
  EXPECT_NEAR(s->signed_distance({0, 0, 0}), -0.7946544722917661, 1e-6);
  EXPECT_LT(s->signed_distance({0.1, -0.2, 0.3}), 0);
  // Volume of the icosahedron of circumradius 1: (20/3) r_in * face area.
  const double edge = 4 / std::sqrt(10 + 2 * std::sqrt(5.0));
  EXPECT_NEAR(s->volume(), 5.0 / 12 * (3 + std::sqrt(5.0)) * edge * edge * edge, 1e-5);
}

// Two of CGAL's meshes refused. corner_poly.off: face 1 is the L-shaped
// hexagon 8 6 10 2 1 0 at z = 1 ((0,1) (1,1) (1,0) (2,0) (2,2) (0,2)); its fan
// from (0,1) has the triangle (0,1) (1,1) (1,0) in the notch, overlapping the
// next one (0,1) (1,0) (2,0). prim.off declares 7 faces and has an eighth on
// line 24.
TEST(SurfaceCgalMeshes, Refused) {
  EXPECT_EQ(load_message(kCgal + "/corner_poly.off"),
            kCgal +
                "/corner_poly.off: self-intersecting: the triangles of face 1, a polygon fanned from its first "
                "corner, intersect (face 1 is not convex or not flat)");
  EXPECT_EQ(load_message(kCgal + "/prim.off"), kCgal + "/prim.off:24:3: unexpected text after the last face");
}

}  // namespace
}  // namespace bccmis::stuff
