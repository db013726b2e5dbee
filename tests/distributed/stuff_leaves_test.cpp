// spec/distributed.md D3-D5 in one process: the pieces of a split of the
// leaves, each stuffed in blocks, gathered, are stuff()'s mesh exactly (the same vertices in the
// same order, bit for bit, the same tetrahedra in the same order), for
// splits in runs (as p8est partitions) and interleaved (every leaf's
// neighbours on other pieces); a piece survives its byte encoding.
#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed {
namespace {

struct Case {
  const char* shape;
  int level;
  int cells;
  const char* name;
};

class StuffLeaves : public ::testing::TestWithParam<Case> {};

/// The leaves in `parts` pieces: runs of consecutive leaves, or leaf i in
/// piece i mod parts.
std::vector<std::vector<d3::Point>> split(const std::vector<d3::Point>& leaves, std::size_t parts, bool runs) {
  std::vector<std::vector<d3::Point>> out(parts);
  for (std::size_t i = 0; i < leaves.size(); ++i)
    out[runs ? i * parts / leaves.size() : i % parts].push_back(leaves[i]);
  return out;
}

void expect_same(const d3::TetMeshF& got, const d3::TetMeshF& want) {
  ASSERT_EQ(got.vertices.size(), want.vertices.size());
  ASSERT_EQ(got.tets.size(), want.tets.size());
  EXPECT_TRUE(got.vertices == want.vertices);  // bit for bit
  EXPECT_TRUE(got.kind == want.kind);
  EXPECT_TRUE(got.tets == want.tets);
  EXPECT_TRUE(got.level == want.level);
}

TEST_P(StuffLeaves, GatheredPiecesAreTheSerialMesh) {
  const auto shape = stuff::make_builtin(GetParam().shape);
  stuff::StuffOptions options;
  options.max_level = GetParam().level;
  options.cells = GetParam().cells;
  const stuff::Fit fit = stuff::fit_lattice(shape->bounds(), options);
  const d3::fast::Lattice g = stuff::background_fast(*shape, fit, options);
  const stuff::Stuffed serial = stuff::stuff(*shape, fit, g, options);
  ASSERT_GT(serial.cut_points, 0u);
  ASSERT_GT(serial.warped, 0u);  // S6 decides across the pieces' boundaries
  const std::vector<d3::Point> leaves = g.cells();
  const std::pair<std::size_t, bool> splits[] = {{1, true}, {3, true}, {2, false}};  // (parts, runs)
  for (const auto& [parts, runs] : splits) {
    SCOPED_TRACE(std::to_string(parts) + (runs ? " runs" : " interleaved"));
    std::vector<LeafPiece> pieces;
    for (const auto& own : split(leaves, parts, runs)) {
      // In blocks of 1,500 leaves (D3): a piece is stuffed a block at a time.
      pieces.push_back(from_bytes(to_bytes(stuff_leaves(*shape, fit, g, options, own, 1500))));
      if (parts > 1) {
        EXPECT_LT(pieces.back().mesh.tets.size(), serial.mesh.tets.size());
      }
    }
    expect_same(gather_pieces(pieces), serial.mesh);
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, StuffLeaves,
                         ::testing::Values(Case{"torus", 2, 6, "torus"}, Case{"spheres:r=0.7,d=1", 2, 6, "spheres"}),
                         [](const auto& p) { return std::string(p.param.name); });

// D9: a layer one cell too thin (the own leaves alone) changes the
// gathered mesh of two interleaved pieces (every leaf's neighbours on the
// other piece); D9's leaves give the serial mesh there.
TEST(StuffLeavesLayer, ThinnerLayersAreCaught) {
  const auto shape = stuff::make_builtin("torus");
  stuff::StuffOptions options;
  options.max_level = 2;
  options.cells = 6;
  const stuff::Fit fit = stuff::fit_lattice(shape->bounds(), options);
  const d3::fast::Lattice g = stuff::background_fast(*shape, fit, options);
  const d3::TetMeshF serial = stuff::stuff(*shape, fit, g, options).mesh;
  const std::vector<d3::Point> leaves = g.cells();
  const auto gathered = [&](std::size_t parts, bool runs, LayerDepth depth) {
    std::vector<LeafPiece> pieces;
    for (const auto& own : split(leaves, parts, runs))
      pieces.push_back(
          stuff_leaves(*shape, fit, g, options, own, leaves_to_stuff(*shape, fit, g, options, own, depth)));
    return gather_pieces(pieces);
  };
  const auto same = [&serial](const d3::TetMeshF& m) {
    return m.vertices == serial.vertices && m.kind == serial.kind && m.tets == serial.tets;
  };
  EXPECT_FALSE(same(gathered(2, false, LayerDepth::none)));
  EXPECT_TRUE(same(gathered(2, false, LayerDepth::closed)));
}

TEST(PieceBytes, TruncatedOrInconsistentBytesAreRefused) {
  LeafPiece piece;
  piece.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  piece.mesh.kind = {0, 0, 0, 0};
  piece.keys.resize(4);
  piece.shared.resize(4);
  piece.mesh.tets = {{0, 1, 2, 3}};
  piece.mesh.level = {2};
  piece.leaves = {{1, 1, 1}};
  piece.leaf_begin = {0, 1};
  const std::vector<std::byte> bytes = to_bytes(piece);
  EXPECT_EQ(from_bytes(bytes).mesh.tets, piece.mesh.tets);
  EXPECT_THROW(from_bytes(std::span(bytes).first(bytes.size() - 1)), std::runtime_error);
  piece.mesh.tets[0][3] = 4;  // a vertex that is not there
  EXPECT_THROW(from_bytes(to_bytes(piece)), std::runtime_error);
}

}  // namespace
}  // namespace bccmis::distributed
