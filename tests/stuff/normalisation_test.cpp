// spec/stuffing.md S24: the local coordinates of mesh_shape().
#include "bccmis/stuff/normalisation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "bccmis/stuff/mesh_shape.h"

namespace bccmis::stuff {
namespace {

TEST(Normalisation, OrdinaryBoxIsOnlyScaled) {
  const Normalisation n = normalisation_of({{0, 0, 0}, {2, 3, 1}});
  EXPECT_FALSE(n.translates());
  EXPECT_EQ(n.exponent, 1);  // 2 <= 3 < 4
}

TEST(Normalisation, FarBoxIsTranslatedExactly) {
  // S24: the centre 1e15 lies more than 64 extents (2) from the origin.
  const Normalisation n = normalisation_of({{1e15 - 1, -1, -1}, {1e15 + 1, 1, 1}});
  EXPECT_EQ(n.translation, (Vec3{1e15, 0, 0}));
  for (double x : {1e15 - 1, 1e15 - 0.875, 1e15, 1e15 + 0.125, 1e15 + 1}) {
    const Vec3 local = n.to_local({x, 0, 0});
    // Sterbenz: x - t is exact, so adding t back gives x and x minus it gives t.
    EXPECT_EQ(std::ldexp(local[0], n.exponent) + 1e15, x);
    EXPECT_EQ(x - std::ldexp(local[0], n.exponent), 1e15);
  }
}

TEST(Normalisation, RefusesAnOverflowingExtent) {
  EXPECT_THROW(normalisation_of({{-1e308, 0, 0}, {1e308, 1, 1}}), ShapeError);
  EXPECT_THROW(normalisation_of({{0, 0, 0}, {INFINITY, 1, 1}}), ShapeError);
}

// S24: a power-of-two scale changes nothing but the scale: the sphere of
// radius 2^-1000 is the unit sphere's mesh times 2^-1000, coordinate for
// coordinate (before S24 its squared distances underflowed).
TEST(Normalisation, TinySphereIsTheUnitSphereScaled) {
  Settings s;
  s.lattice.max_level = 1;
  s.lattice.cells = 6;
  s.memory_limit = 1e9;
  const Meshed unit = mesh_shape(*make_sphere({0, 0, 0}, 1), s);
  const Meshed tiny = mesh_shape(*make_sphere({0, 0, 0}, std::ldexp(1.0, -1000)), s);
  ASSERT_FALSE(unit.stuffed.mesh.tets.empty());
  ASSERT_EQ(unit.stuffed.mesh.vertices.size(), tiny.stuffed.mesh.vertices.size());
  EXPECT_EQ(unit.stuffed.mesh.tets, tiny.stuffed.mesh.tets);
  for (std::size_t v = 0; v < unit.stuffed.mesh.vertices.size(); ++v)
    for (std::size_t k = 0; k < 3; ++k)
      ASSERT_EQ(std::ldexp(unit.stuffed.mesh.vertices[v][k], -1000), tiny.stuffed.mesh.vertices[v][k]) << v;
}

}  // namespace
}  // namespace bccmis::stuff
