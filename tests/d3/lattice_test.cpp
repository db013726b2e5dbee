// The 3D lattice's data (spec/lattice3d.md §1): sizes, the initial lattice,
// the refined-center test from positions, and the lattice concept.
#include <gtest/gtest.h>

#include <limits>
#include <type_traits>
#include <vector>

#include "check.h"
#include "util.h"

namespace bccmis::d3 {
namespace {

TEST(D3Lattice, InitialLattice) {
  const Graph g(LatticeSize{3, 2, 1, 2});
  EXPECT_EQ(g.C.size(), 6u);
  EXPECT_EQ(g.N.size(), 4u * 3u * 2u);
  EXPECT_EQ(g.nbr({4, 4, 4}).size(), 8u);
  EXPECT_EQ(g.nbr({8, 8, 0}), (PointSet{{4, 4, 4}, {4, 12, 4}, {12, 4, 4}, {12, 12, 4}}));
  EXPECT_EQ(test::state_problem(g), "");
}

// Graph and LatticeSize compare every member (the tests compare whole
// states with ==, so a member left out would hide a difference).
TEST(D3Lattice, EqualityComparesEveryMember) {
  const Graph a = test::build("lattice 1 1 1 1\nrefine 2 2 2\n");
  Graph b = a;
  EXPECT_EQ(a, b);
  b.size.L = 2;
  EXPECT_NE(a, b);
  b = a;
  b.N.insert({9, 9, 9});
  EXPECT_NE(a, b);
  b = a;
  b.C.insert({9, 9, 9});
  EXPECT_NE(a, b);
  b = a;
  b.neighbors[{1, 1, 1}].erase({0, 0, 0});
  EXPECT_NE(a, b);
  b = a;
  b.level[{1, 1, 1}] = 0;
  EXPECT_NE(a, b);
  const LatticeSize s{2, 3, 4, 5};
  EXPECT_EQ(s, (LatticeSize{2, 3, 4, 5}));
  EXPECT_NE(s, (LatticeSize{9, 3, 4, 5}));
  EXPECT_NE(s, (LatticeSize{2, 9, 4, 5}));
  EXPECT_NE(s, (LatticeSize{2, 3, 9, 5}));
  EXPECT_NE(s, (LatticeSize{2, 3, 4, 9}));
}

TEST(D3Lattice, SizeValidation) {
  EXPECT_THROW(Graph(LatticeSize{0, 1, 1, 0}), LatticeError);
  EXPECT_THROW(Graph(LatticeSize{1, 0, 1, 0}), LatticeError);
  EXPECT_THROW(Graph(LatticeSize{1, 1, 0, 0}), LatticeError);
  EXPECT_THROW(Graph(LatticeSize{1, 1, 1, -1}), LatticeError);
  EXPECT_THROW(Graph(LatticeSize{1, 1, 1, 62}), LatticeError);
  // An extent of exactly 2^62 is legal (L = 61: S = 2^62); one more cube is not.
  EXPECT_NO_THROW(validate_lattice_size(LatticeSize{1, 1, 1, 61}));
  EXPECT_THROW(validate_lattice_size(LatticeSize{1, 1, 2, 61}), LatticeError);
  EXPECT_NO_THROW(validate_lattice_size(LatticeSize{std::int64_t{1} << 52, 1, 1, 9}));
  EXPECT_THROW(validate_lattice_size(LatticeSize{1, (std::int64_t{1} << 52) + 1, 1, 9}), LatticeError);
  EXPECT_THROW(validate_lattice_size(LatticeSize{1, 1, std::numeric_limits<std::int64_t>::max(), 0}), LatticeError);
  try {
    validate_lattice_size(LatticeSize{1, 1, 0, 0});
    FAIL();
  } catch (const LatticeError& e) {
    EXPECT_NE(std::string(e.what()).find("depth D"), std::string::npos) << e.what();
  }
}

TEST(D3Lattice, RefineAtTheLargestExtent) {
  // Midpoints near 2^62 do not overflow: lattice 1 1 1 61 refined twice.
  Graph g(LatticeSize{1, 1, 1, 61});
  const std::int64_t h = std::int64_t{1} << 61;
  ASSERT_TRUE(refine(g, {h, h, h}).applied());
  const std::int64_t t = h + h / 2;
  EXPECT_TRUE(g.is_center({t, t, t}));
  EXPECT_TRUE(g.is_node({std::int64_t{1} << 62, h, h}));
  ASSERT_TRUE(refine(g, {t, t, t}).applied());
  ASSERT_TRUE(coarsen(g, {t, t, t}).applied());
  ASSERT_TRUE(coarsen(g, {h, h, h}).applied());
  EXPECT_EQ(g, Graph(LatticeSize{1, 1, 1, 61}));
}

TEST(D3Lattice, RefinedCenterLevelFromPosition) {
  //= bccmis3d#pre-coarsen-refined-center type=test
  const LatticeSize size{2, 1, 1, 2};  // S = 8
  EXPECT_EQ(refined_center_level(size, {4, 4, 4}), 0);
  EXPECT_EQ(refined_center_level(size, {12, 4, 4}), 0);
  EXPECT_EQ(refined_center_level(size, {6, 2, 2}), 1);
  EXPECT_EQ(refined_center_level(size, {10, 6, 2}), 1);
  EXPECT_EQ(refined_center_level(size, {5, 5, 5}), std::nullopt);   // a level-2 (= L) center
  EXPECT_EQ(refined_center_level(size, {8, 4, 4}), std::nullopt);   // a face center
  EXPECT_EQ(refined_center_level(size, {4, 4, 8}), std::nullopt);   // on the domain boundary
  EXPECT_EQ(refined_center_level(size, {6, 2, 4}), std::nullopt);   // mixed powers of two
  EXPECT_EQ(refined_center_level(size, {20, 4, 4}), std::nullopt);  // outside
  EXPECT_EQ(refined_center_level(size, {-4, 4, 4}), std::nullopt);
}

// Generic code written against the concept runs on Graph unchanged.
template <AdaptiveLattice L>
std::size_t refine_all_once(L& g) {
  std::size_t applied = 0;
  const auto before = std::vector<point_type_t<L>>(cells(g).begin(), cells(g).end());
  for (const auto& c : before) applied += refine(g, c).applied();
  return applied;
}

TEST(D3Lattice, ModelsTheLatticeConcept) {
  static_assert(AdaptiveLattice<Graph>);
  static_assert(std::is_same_v<point_type_t<Graph>, Point>);
  static_assert(Graph::dimension == 3);
  Graph g(LatticeSize{2, 1, 1, 1});
  EXPECT_EQ(refine_all_once(g), 2u);
  EXPECT_EQ(cell_count(g), 16u);
  EXPECT_EQ(node_count(g), 5u * 3u * 3u);
  EXPECT_EQ(size_of(g), (LatticeSize{2, 1, 1, 1}));
  EXPECT_TRUE(is_node(g, {4, 2, 2}));
  EXPECT_EQ(level_of(g, {1, 1, 1}), 1);
  EXPECT_EQ(neighbors(g, {1, 1, 1}).size(), 8u);
  EXPECT_EQ(canonical_text(g), canonical_state(g));
}

}  // namespace
}  // namespace bccmis::d3
