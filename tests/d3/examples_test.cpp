// The hand-written expectations of spec/examples/d3/*: each trace replayed,
// its decision log and final canonical state compared byte for byte with the
// .expected file, and d3/face_refined.state with the state after the first
// refine of d3/face.trace.
#include <gtest/gtest.h>

#include "util.h"

namespace bccmis::d3 {
namespace {

void expect_example(const std::string& name) {
  std::string log;
  const Graph g = test::replay(test::example(name + ".trace"), &log);
  EXPECT_EQ(log + canonical_state(g), test::example(name + ".expected")) << name;
}

TEST(D3Examples, RootOfLattice1111) {
  //= bccmis3d#eq-R3a type=test
  expect_example("d3/root");
}

TEST(D3Examples, OneCubeOfLattice2112RefinedRefusedAndCoarsened) {
  //= bccmis3d#claim-inverse type=test
  expect_example("d3/face");
  EXPECT_EQ(canonical_state(test::build("lattice 2 1 1 2\nrefine 4 4 4\n")), test::example("d3/face_refined.state"));
}

TEST(D3Examples, EveryRefusalCode) { expect_example("d3/refusals"); }

TEST(D3Examples, CanonicalStateOfOneCube) {
  // The example of spec/formats.md, "3D extension".
  EXPECT_EQ(canonical_state(Graph(LatticeSize{1, 1, 1, 0})),
            "bccmis-state 1\nlattice 1 1 1 0\n"
            "C 1 1 1 0 : 0 0 0 0 0 2 0 2 0 0 2 2 2 0 0 2 0 2 2 2 0 2 2 2\n"
            "N 0 0 0 : 1 1 1\nN 0 0 2 : 1 1 1\nN 0 2 0 : 1 1 1\nN 0 2 2 : 1 1 1\n"
            "N 2 0 0 : 1 1 1\nN 2 0 2 : 1 1 1\nN 2 2 0 : 1 1 1\nN 2 2 2 : 1 1 1\nend 1 8\n");
}

}  // namespace
}  // namespace bccmis::d3
