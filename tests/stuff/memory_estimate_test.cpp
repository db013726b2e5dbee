// S25 (spec/stuffing.md): the memory estimate before building, with
// S35.8's second mesh under --crease-cuts, tested on its line: a limit equal
// to the estimate lets the run go on, the next double below refuses it; a
// limit equal to the estimate of one mesh refuses the run with
// --crease-cuts. CGAL's fandisk at level 2 (creases and corners), where the
// estimate is every cube of the fitted lattice.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "bccmis/stuff/crease_cuts.h"
#include "bccmis/stuff/memory_estimate.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/normalisation.h"

namespace bccmis::stuff {
namespace {

const std::string kCgal = BCCMIS_CGAL_MESHES_DIR;
constexpr int kLevel = 2;

/// The estimate mesh_shape() makes: the shape in S24's local coordinates,
/// the options at the fitted level.
MemoryEstimate estimate_of(const Shape& world, int meshes, int level = kLevel, double available = HUGE_VAL) {
  const std::unique_ptr<Shape> local = world.normalised(normalisation_of(world.bounds()));
  StuffOptions options;
  options.max_level = level;
  options.max_level = fit_lattice(local->bounds(), options).size.L;
  return estimate_memory(*local, options, available, meshes);
}

Settings with_limit(double limit, double crease_cuts, int level = kLevel) {
  Settings s;
  s.lattice.max_level = level;
  s.features.on = true;
  s.features.crease_cuts = crease_cuts;
  s.memory_limit = limit;
  return s;
}

/// The message of mesh_shape's refusal, or "" when the run went on.
std::string refusal(const Shape& shape, const Settings& s) {
  try {
    mesh_shape(shape, s);
  } catch (const ShapeError& e) {
    return e.what();
  }
  return "";
}

//= spec/stuffing.md S25 type=test
TEST(MemoryEstimate, CreaseCutsAddASecondMesh) {
  const auto fandisk = load_mesh_file(kCgal + "/fandisk.off");
  const MemoryEstimate one = estimate_of(*fandisk, 1), two = estimate_of(*fandisk, 2);
  ASSERT_GT(one.leaves, 0);
  EXPECT_EQ(two.leaves, one.leaves);
  EXPECT_EQ(one.bytes(), one.leaves * 1900);
  EXPECT_EQ(two.bytes(), one.leaves * (1900 + 420));
}

//= spec/stuffing.md S25 type=test
TEST(MemoryEstimate, OnTheLineWithAndWithoutCreaseCuts) {
  const auto fandisk = load_mesh_file(kCgal + "/fandisk.off");
  const double one = estimate_of(*fandisk, 1).bytes(), two = estimate_of(*fandisk, 2).bytes();
  // The limit equal to one mesh's estimate: the run without --crease-cuts
  // goes on, the next double below refuses it, and the run with it (two
  // meshes at once, S35.8) is refused naming the second mesh.
  EXPECT_EQ(refusal(*fandisk, with_limit(one, 0)), "");
  EXPECT_NE(refusal(*fandisk, with_limit(std::nextafter(one, 0.0), 0)), "");
  const std::string why = refusal(*fandisk, with_limit(one, kCreaseCutDistance));
  EXPECT_NE(why.find("(1900 bytes per estimated leaf, and 420 for S35.8's second mesh)"), std::string::npos) << why;
  // The limit equal to two meshes' estimate: with --crease-cuts the run goes
  // on; the next double below refuses it.
  EXPECT_EQ(refusal(*fandisk, with_limit(two, kCreaseCutDistance)), "");
  EXPECT_NE(refusal(*fandisk, with_limit(std::nextafter(two, 0.0), kCreaseCutDistance)), "");
}

//= spec/stuffing.md S25 type=test
TEST(MemoryEstimate, TheLevelHintNeverBelowTheCoarsestLevelAllowed) {
  // At the default 4 cells the coarsest max level is 2 (4 x 2^2 > 10). At
  // level 3 the estimate over 4 is level 2's: a limit equal to it names
  // -L 2, the next double below names no level (not -L 1, which S2 refuses).
  // Below every cube's estimate S25 estimates by the probe (available -1).
  const auto fandisk = load_mesh_file(kCgal + "/fandisk.off");
  EXPECT_EQ(coarsest_max_level(StuffOptions{}), 2);
  const double three = estimate_of(*fandisk, 1, 3, -1).bytes();
  const std::string fits = refusal(*fandisk, with_limit(three / 4, 0, 3));
  EXPECT_NE(fits.find("; -L 2 would fit"), std::string::npos) << fits;
  const std::string none = refusal(*fandisk, with_limit(std::nextafter(three / 4, 0.0), 0, 3));
  EXPECT_NE(none.find("; even -L 2, the coarsest max level these options allow, would not fit"), std::string::npos)
      << none;
  const std::string tiny = refusal(*fandisk, with_limit(1e-12, 0, 3));
  EXPECT_NE(tiny.find("even -L 2"), std::string::npos) << tiny;
}

}  // namespace
}  // namespace bccmis::stuff
