// S35.9's flips at a refused move (spec/stuffing.md S35.9), on hand-made
// two-tetrahedron meshes: a 2-3 flip whose three pieces pass S31's test is
// made and lets the move through; the same flip with its piece without the
// moved vertex positively oriented but outside S10's interval is not. S35.10's
// sequence of two flips on a piece of CGAL's anchor at level 4.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/conform_features.h"
#include "bccmis/stuff/features.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {
namespace {

// t = (v, f1, f2, a) and u = (v, f2, f1, e) share the face v f1 f2, the only
// face of either that is not a boundary triangle; every vertex is a boundary
// vertex (no room for S34). The corner x is 0.73 from v and more than 1.5
// from the others: with h = 1, v is its only candidate. With v at x, t
// fails S31's test (dihedral angle 6.25 degrees) and u passes; the 2-3 flip
// across v f1 f2 makes (e, f1, f2, a), the piece without v, and (v, e, f2,
// a), (v, f1, e, a), which pass with v at x.
const Vec3 kV{0.25, 1.25, 0.5}, kF1{0, 0, -1}, kF2{0, 0, 1}, kA{-0.125, 0.375, 0.125};
const Vec3 kCorner{-0.125, 1.625, 1};
// e where the piece without v passes (its angles 12.6-155.2 degrees), and
// where it is positively oriented with angles of 6.5 and 167.3 degrees.
const Vec3 kGoodE{1.5, -1.125, 1}, kBadE{1.125, -1.5, 0.625};

d3::TetMeshF two_tetrahedra(const Vec3& e) {
  d3::TetMeshF m;
  m.vertices = {kV, kF1, kF2, kA, e};
  m.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
  m.kind.assign(m.vertices.size(), 0);
  m.level.assign(m.tets.size(), 0);
  return m;
}

Features corner_at_x() {
  Features f;
  f.corners = {kCorner};
  return f;
}

// S31's test: positively oriented, every dihedral angle in S10's interval.
bool in_interval(const d3::TetMeshF& m, const std::array<std::uint32_t, 4>& t) {
  const std::array<Vec3, 4> p{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]};
  if (orientation(p[0], p[1], p[2], p[3]) <= 0) return false;
  for (const double a : d3::dihedral_angles(p))
    if (!(a >= kDihedralBounds[0] && a <= kDihedralBounds[1])) return false;
  return true;
}

double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// A piece of a stuffed mesh: the target x, vertex 0 the vertex to move
// there, the other vertices and the tetrahedra (lines "x", "v", "t").
struct Piece {
  Vec3 x{};
  d3::TetMeshF mesh;
};

Piece read_piece(const std::string& path) {
  Piece p;
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "x") s >> p.x[0] >> p.x[1] >> p.x[2];
    if (key == "v") s >> p.mesh.vertices.emplace_back()[0] >> p.mesh.vertices.back()[1] >> p.mesh.vertices.back()[2];
    if (key == "t")
      s >> p.mesh.tets.emplace_back()[0] >> p.mesh.tets.back()[1] >> p.mesh.tets.back()[2] >> p.mesh.tets.back()[3];
  }
  p.mesh.kind.assign(p.mesh.vertices.size(), 0);
  p.mesh.level.assign(p.mesh.tets.size(), 0);
  return p;
}

// Triangles each turned to start at its smallest vertex, then sorted.
std::vector<std::array<std::uint32_t, 3>> same_order(std::vector<std::array<std::uint32_t, 3>> triangles) {
  for (auto& f : triangles) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

//= spec/stuffing.md S35 type=test
TEST(Flips, AFlipWhosePiecesPassLetsTheRefusedMoveThrough) {
  d3::TetMeshF m = two_tetrahedra(kGoodE);
  const auto boundary = boundary_triangles(m);
  const FeatureConformity r = conform_features(m, boundary, corner_at_x(), 1.0);
  EXPECT_EQ(r.corners_conformed, 1u);
  EXPECT_EQ(r.flips, 1u);
  ASSERT_EQ(m.tets.size(), 3u);  // 2-3: one appended
  EXPECT_EQ(m.vertices[0], kCorner);
  for (const auto& t : m.tets) EXPECT_TRUE(in_interval(m, t)) << t[0] << t[1] << t[2] << t[3];
  EXPECT_EQ(same_order(boundary_triangles(m)), same_order(boundary));  // the same triangles, oriented the same
}

//= spec/stuffing.md S35 type=test
TEST(Flips, APieceWithoutTheVertexOutsideTheIntervalStopsTheFlip) {
  // The piece (e, f1, f2, a) does not hold v, so checking the pieces with v
  // at x for orientation only, or only those at v, lets this flip through
  // and leaves a tetrahedron outside S10's interval in the mesh.
  d3::TetMeshF m = two_tetrahedra(kBadE);
  const d3::TetMeshF before = m;
  const FeatureConformity r = conform_features(m, boundary_triangles(m), corner_at_x(), 1.0);
  EXPECT_EQ(r.corners_conformed, 0u);
  EXPECT_EQ(r.flips, 0u);
  EXPECT_EQ(m.tets, before.tets);
  EXPECT_EQ(m.vertices, before.vertices);
  for (const auto& t : m.tets) EXPECT_TRUE(in_interval(m, t)) << t[0] << t[1] << t[2] << t[3];
}

//= spec/stuffing.md S35 type=test
TEST(Flips, ASequenceOfTwoFlipsLetsThroughAMoveNoSingleFlipSaves) {
  // S35.10 on a piece of CGAL's anchor at level 4: vertex 0's move to x,
  // asked for as a corner at x. The boundary vertices within h = |x - v0|
  // of x are corners before it (each snapped onto itself and taken), so
  // vertex 0 is x's only candidate. Without flips (A) the move is refused;
  // with them, a sequence of two flips lets it through (S35.9's single
  // flips do not), the mesh stays in S10's interval and its boundary the
  // same triangles.
  const Piece piece = read_piece(std::string(BCCMIS_STUFF_TEST_DIR) + "/flips/anchor_L4_two_flips.txt");
  ASSERT_EQ(piece.mesh.tets.size(), 65u);
  const auto boundary = boundary_triangles(piece.mesh);
  const double h = distance(piece.x, piece.mesh.vertices[0]);
  Features f;
  std::vector<std::uint32_t> near;
  for (const auto& t : boundary)
    for (const std::uint32_t a : t)
      if (a != 0 && distance(piece.x, piece.mesh.vertices[a]) <= h) near.push_back(a);
  std::sort(near.begin(), near.end());
  near.erase(std::unique(near.begin(), near.end()), near.end());
  ASSERT_FALSE(near.empty());
  for (const std::uint32_t a : near) f.corners.push_back(piece.mesh.vertices[a]);
  f.corners.push_back(piece.x);
  for (const auto& t : piece.mesh.tets) ASSERT_TRUE(in_interval(piece.mesh, t));

  d3::TetMeshF a = piece.mesh;
  EXPECT_EQ(conform_features(a, boundary, f, h, true, false).corners_conformed, near.size());  // A: x refused
  d3::TetMeshF m = piece.mesh;
  const FeatureConformity r = conform_features(m, boundary, f, h);
  EXPECT_EQ(r.corners_conformed, near.size() + 1);
  EXPECT_EQ(r.flips, 2u);
  EXPECT_EQ(m.vertices[0], piece.x);
  for (const auto& t : m.tets) EXPECT_TRUE(in_interval(m, t)) << t[0] << " " << t[1] << " " << t[2] << " " << t[3];
  EXPECT_EQ(same_order(boundary_triangles(m)), same_order(boundary));
}

}  // namespace
}  // namespace bccmis::stuff
