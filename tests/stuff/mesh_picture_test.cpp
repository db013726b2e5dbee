// The Medit reader and the mesh pictures of `bccmis render` (mesh_picture.h,
// bccmis/io/medit.h) on meshes small enough to draw by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include "bccmis/io/medit.h"
#include "bccmis/io/parse_error.h"
#include "bccmis/stuff/mesh_picture.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

d3::TetMeshF two_tets() {
  return io::read_medit(slurp(BCCMIS_TEST_DIR "/two_tets.mesh"), "two_tets.mesh", orientation);
}

std::size_t count(const std::string& text, const std::string& pattern) {
  const std::regex re(pattern);
  return static_cast<std::size_t>(std::distance(std::sregex_iterator(text.begin(), text.end(), re), {}));
}

TEST(MeditRead, ReadsTheHandMesh) {
  const d3::TetMeshF m = two_tets();
  ASSERT_EQ(m.vertices.size(), 5u);
  EXPECT_EQ(m.vertices[4], (d3::Vec3{1, -1, -1}));
  EXPECT_EQ(m.kind, (std::vector<std::uint8_t>{0, 0, 1, 1, 1}));
  ASSERT_EQ(m.tets.size(), 2u);
  EXPECT_EQ(m.tets[1], (std::array<std::uint32_t, 4>{0, 1, 3, 4}));
  EXPECT_EQ(m.level, (std::vector<int>{1, 2}));
}

TEST(MeditRead, ReadsBackWhatTheWriterWrites) {
  d3::TetMeshF m;
  m.vertices = {{0.1, 0, 0}, {1e-17, 1, 0}, {0, 0, 1}, {-0.3333333333333333, -2.5e300, 7}};
  m.kind = {0, 1, 2, 1};
  m.tets = {{0, 1, 2, 3}};
  m.level = {5};
  // Orient it positively whatever the coordinates.
  if (orientation(m.vertices[0], m.vertices[1], m.vertices[2], m.vertices[3]) < 0)
    std::swap(m.tets[0][0], m.tets[0][1]);
  std::ostringstream out;
  io::write_medit(out, m);
  const d3::TetMeshF back = io::read_medit(out.str(), "m.mesh", orientation);
  EXPECT_EQ(back.vertices, m.vertices);
  EXPECT_EQ(back.kind, m.kind);
  EXPECT_EQ(back.tets, m.tets);
  EXPECT_EQ(back.level, m.level);
}

// Each refusal with its line and column.
TEST(MeditRead, RefusesWithThePlace) {
  const std::string head = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  const struct {
    std::string text, where;
  } cases[] = {
      {"", "1:1: unexpected end of file: expected 'MeshVersionFormatted'"},
      {"MeshVersion 2", "1:1: expected 'MeshVersionFormatted', got 'MeshVersion'"},
      {"MeshVersionFormatted 2\nDimension 2\n", "2:11: the dimension '2' is out of range [3, 3]"},
      {"MeshVersionFormatted 2\nVertices 0\n", "2:1: 'Vertices' before 'Dimension 3'"},
      {head + "Tetrahedra\n1\n1 2 3 5 0\nEnd\n", "11:7: a vertex index '5' is out of range [1, 4]"},
      {head + "Tetrahedra\n1\n1 2 3 3 0\nEnd\n", "11:7: vertex 3 appears twice"},
      {head + "Tetrahedra\n1\n1 3 2 4 0\nEnd\n", "11:1: tetrahedron 1 is negatively oriented"},
      {head + "Tetrahedra\n1\n1 2 3 4 64\nEnd\n", "11:9: the tetrahedron reference (its level) '64' is out of range"},
      {head + "Tetrahedra\n1\n1 2 3 4 0\n", "12:1: unexpected end of file: expected 'End'"},
      {head + "Tetrahedra\n1\n1 2 3 4 0\nEnd\nx", "13:1: text after 'End'"},
      {head + "Edges\n", "9:1: unknown keyword 'Edges'"},
      {head + "End\n", "9:1: 'End' before a 'Tetrahedra' section"},
      {"MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 nan 0 0\n", "5:3: y coordinate 'nan' is not finite"},
      {"MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0,5 0 0\n", "5:3: expected y coordinate"},
      {"MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0\n", "6:1: unexpected end of file: expected the"},
      {"MeshVersionFormatted 2\nDimension 3\nDimension 3\n", "3:1: a second 'Dimension' section"},
      {"MeshVersionFormatted 2\n\x01", "2:1: unexpected byte '\\x01'"},
  };
  for (const auto& c : cases) {
    try {
      io::read_medit(c.text, "in.mesh", orientation);
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const ParseError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("in.mesh:" + c.where, 0), 0u) << e.what();
    }
  }
}

// The view direction is (1, -2, 1.5). The outward normals of the six boundary
// triangles (the shared face abd is interior): in the first tetrahedron
// bcd (1,0,1), acd (-1,0,1), abc (0,1,-1); in the second bde (1,-1,0),
// ade (-1,-1,0), abe (0,1,-1). Dot products 2.5, 0.5, -3.5, 3, 1, -3.5: four
// face the viewer, two of each level.
TEST(MeshPicture, DrawsTheBoundaryFacingTheViewer) {
  const std::string svg = render_mesh_svg(two_tets(), "two");
  EXPECT_EQ(count(svg, "<polygon class=\"tri\""), 4u);
  EXPECT_EQ(count(svg, "class=\"tri\" data-level=\"1\""), 2u);
  EXPECT_EQ(count(svg, "class=\"tri\" data-level=\"2\""), 2u);
  EXPECT_EQ(count(svg, "class=\"cut-tri\""), 0u);
  EXPECT_NE(svg.find("4 of 6 boundary triangles face the viewer"), std::string::npos);
  // One legend entry per level, in the level's unshaded colour.
  EXPECT_EQ(count(svg, "class=\"legend\""), 2u);
  EXPECT_EQ(count(svg, "class=\"legend\"[^>]*fill=\"#fdd49e\"/><text[^>]*>level 1: 1<"), 1u);
  EXPECT_EQ(count(svg, "class=\"legend\"[^>]*fill=\"#fdae6b\"/><text[^>]*>level 2: 1<"), 1u);
  // The two colours differ in every shade.
  std::smatch m1, m2;
  ASSERT_TRUE(std::regex_search(svg, m1, std::regex("data-level=\"1\"[^>]*fill=\"(#[0-9a-f]{6})\"")));
  ASSERT_TRUE(std::regex_search(svg, m2, std::regex("data-level=\"2\"[^>]*fill=\"(#[0-9a-f]{6})\"")));
  EXPECT_NE(m1[1], m2[1]);
}

// The cut z = 0.25 removes the first tetrahedron (centroid z 0.5); the second
// (centroid z 0) is left with its four faces, abd now on the boundary with
// outward normal (0,1,1): dot -0.5, so bde and ade face the viewer. The cut
// z = 0.5 removes nothing (the centroid must be strictly above).
TEST(MeshPicture, CutAway) {
  const std::string svg = render_mesh_svg(two_tets(), "two", CutPlane{2, 0.25});
  EXPECT_EQ(count(svg, "<polygon class=\"tri\""), 4u);
  EXPECT_EQ(count(svg, "<polygon class=\"cut-tri\" data-level=\"2\""), 2u);
  EXPECT_EQ(count(svg, "<polygon class=\"cut-tri\""), 2u);
  EXPECT_NE(svg.find(">cut at z = 0.25: 1 tetrahedra removed,<"), std::string::npos);
  EXPECT_NE(svg.find(">those with centroid z &gt; 0.25;<"), std::string::npos);
  EXPECT_NE(svg.find(">2 of 4 triangles face the viewer<"), std::string::npos);
  const std::string none = render_mesh_svg(two_tets(), "two", CutPlane{2, 0.5});
  EXPECT_EQ(count(none, "<polygon class=\"cut-tri\""), 4u);
  // Both centroids have x = 1: the cut x = 0.5 removes both.
  EXPECT_EQ(count(render_mesh_svg(two_tets(), "two", CutPlane{0, 0.5}), "<polygon class=\"cut-tri\""), 0u);
  // The viewer is at negative y: the cut y = -0.1 removes the second
  // tetrahedron (centroid y -0.5) and leaves the first (centroid y 0) with
  // bcd, acd and abd facing the viewer (abd outward (0,-1,-1), dot 0.5).
  const std::string y = render_mesh_svg(two_tets(), "two", CutPlane{1, -0.1});
  EXPECT_EQ(count(y, "<polygon class=\"cut-tri\" data-level=\"1\""), 3u);
  EXPECT_EQ(count(y, "<polygon class=\"cut-tri\""), 3u);
  EXPECT_NE(y.find(">cut at y = -0.1: 1 tetrahedra removed,<"), std::string::npos);
  EXPECT_NE(y.find(">those with centroid y &lt; -0.1;<"), std::string::npos);
  EXPECT_NE(y.find(">3 of 4 triangles face the viewer<"), std::string::npos);
  EXPECT_THROW(render_mesh_svg(two_tets(), "two", CutPlane{3, 0}), std::invalid_argument);
}

// Twelve angles: eight of 60 degrees, four of 90 (spec/mesh3d.md: the
// regular BCC tetrahedron).
TEST(AngleHistogram, TheLatticeTetrahedra) {
  const AngleHistogram h = angle_histogram(two_tets());
  EXPECT_EQ(h.angles, 12u);
  for (std::size_t k = 0; k < h.bins.size(); ++k) EXPECT_EQ(h.bins[k], k == 12 ? 8u : k == 18 ? 4u : 0u) << k;
  EXPECT_NEAR(h.min, 60, 1e-9);
  EXPECT_NEAR(h.max, 90, 1e-9);
  const std::string svg = render_histogram_svg(two_tets(), "two");
  EXPECT_EQ(count(svg, "class=\"bar\""), 2u);
  EXPECT_EQ(count(svg, "class=\"bar\" data-bin=\"12\" data-count=\"8\""), 1u);
  EXPECT_EQ(count(svg, "class=\"bar\" data-bin=\"18\" data-count=\"4\""), 1u);
  EXPECT_EQ(count(svg, "class=\"min\""), 1u);
  EXPECT_EQ(count(svg, "class=\"max\""), 1u);
  EXPECT_NE(svg.find("min 60.00"), std::string::npos);
  EXPECT_NE(svg.find("max 90.00"), std::string::npos);
  EXPECT_NE(svg.find("dihedral angle (degrees)"), std::string::npos);
}

// A flat corner: 180 degrees lands in the last bin, and a sliver's small angle in the first.
TEST(AngleHistogram, EdgesOfTheRange) {
  d3::TetMeshF m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1e-3}};
  m.kind = {0, 0, 0, 0};
  m.tets = {{0, 1, 2, 3}};
  m.level = {0};
  const AngleHistogram h = angle_histogram(m);
  EXPECT_EQ(h.angles, 6u);
  EXPECT_GE(h.bins[0], 1u);
  EXPECT_GE(h.bins[35], 1u);
}

}  // namespace
}  // namespace bccmis::stuff
