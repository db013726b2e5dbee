// The 3D picture of `bccmis render` (oracle.h render_svg): the leaves a
// slice cuts, by hand on d3/face_refined.state and as a tiling of every
// plane of a graded state; the slice's bounds; the drawn element counts.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bccmis/io/d3/format.h"
#include "bccmis/oracle/oracle.h"
#include "d3/util.h"

namespace bccmis::d3 {
namespace {

Graph face_refined() { return parse_state(test::example("d3/face_refined.state"), "face_refined.state"); }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// face_refined (S = 8, box 16 x 8 x 8): the children of (4,4,4) have side 4,
// the coarse leaf (12,4,4) side 8.
TEST(Render3, SlicedLeavesByHand) {
  const Graph g = face_refined();
  using V = std::vector<Point>;
  // z = 2 passes through the centers of the 4 lower children and cuts the coarse leaf.
  EXPECT_EQ(sliced_leaves(g, {2, 2}), (V{{2, 2, 2}, {2, 6, 2}, {6, 2, 2}, {6, 6, 2}, {12, 4, 4}}));
  // z = 4, the children's face plane: the 4 above it (half-open) and the coarse leaf.
  EXPECT_EQ(sliced_leaves(g, {2, 4}), (V{{2, 2, 6}, {2, 6, 6}, {6, 2, 6}, {6, 6, 6}, {12, 4, 4}}));
  // z = 8, the box's far face: the leaves below it.
  EXPECT_EQ(sliced_leaves(g, {2, 8}), (V{{2, 2, 6}, {2, 6, 6}, {6, 2, 6}, {6, 6, 6}, {12, 4, 4}}));
  // x = 8, the split face: the coarse leaf only; x = 0: the 4 children at x = 2; x = 16: the coarse leaf.
  EXPECT_EQ(sliced_leaves(g, {0, 8}), (V{{12, 4, 4}}));
  EXPECT_EQ(sliced_leaves(g, {0, 0}), (V{{2, 2, 2}, {2, 2, 6}, {2, 6, 2}, {2, 6, 6}}));
  EXPECT_EQ(sliced_leaves(g, {0, 16}), (V{{12, 4, 4}}));
}

// In every plane x, y or z = v of the box, the cut leaves tile the plane: their
// squares' areas sum to the plane's area (no leaf twice, none missing).
TEST(Render3, SlicesTileEveryPlane) {
  const Graph g = test::build(
      "lattice 3 2 2 2\nrefine 4 4 12\nrefine 12 4 12\nrefine 4 12 12\nrefine 4 4 4\nrefine 2 2 14\n"
      "refine 6 2 14\nrefine 2 6 14\nrefine 10 2 14\nrefine 2 2 10\n");
  const std::int64_t S = level0_side(g.size);
  const std::int64_t ext[3] = {g.size.W * S, g.size.H * S, g.size.D * S};
  for (int axis = 0; axis < 3; ++axis)
    for (std::int64_t v = 0; v <= ext[axis]; ++v) {
      std::int64_t area = 0;
      for (const Point& c : sliced_leaves(g, {axis, v})) {
        const std::int64_t side = cell_side(g.size, g.level_of(c));
        area += side * side;
      }
      EXPECT_EQ(area, ext[(axis + 1) % 3] * ext[(axis + 2) % 3]) << "axis " << axis << " = " << v;
    }
}

TEST(Render3, SliceOutsideTheBoxIsRefused) {
  const Graph g = face_refined();
  EXPECT_THROW(render_svg(g, "t", {2, 9}), std::invalid_argument);
  EXPECT_THROW(render_svg(g, "t", {0, -1}), std::invalid_argument);
  EXPECT_THROW(render_svg(g, "t", {3, 0}), std::invalid_argument);
  EXPECT_NO_THROW(render_svg(g, "t", {0, 16}));
}

// The counts of tests/cli/cli.cmake (cli.d3_render_face_default), and the title escaped.
TEST(Render3, FaceRefinedCounts) {
  const Graph g = face_refined();
  EXPECT_EQ(middle_slice(g.size).axis, 2);
  EXPECT_EQ(middle_slice(g.size).value, 4);
  const std::string svg = render_svg(g, "a<b&c", middle_slice(g.size));
  EXPECT_EQ(count(svg, "class=\"tri\""), 46u);
  EXPECT_EQ(count(svg, "class=\"green\""), 29u);
  EXPECT_EQ(count(svg, "class=\"leaf\""), 5u);
  EXPECT_EQ(count(svg, "class=\"node\""), 9u);
  EXPECT_EQ(count(svg, "class=\"junction\""), 3u);
  EXPECT_NE(svg.find("<title>a&lt;b&amp;c</title>"), std::string::npos);
  EXPECT_EQ(green_edges(g).size(), 62u);  // cli.d3_stats: all of them, inside the box too
}

}  // namespace
}  // namespace bccmis::d3
