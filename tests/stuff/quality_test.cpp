// S13's angle statistics (stuff::quality) against the angles one by one:
// the histogram, the count below 10 degrees and the extremes must be those
// of d3::dihedral_angles's rounded angles, binned with lround(a / 15), also
// for tetrahedra whose angle lies on a bin edge (7.5 + 15k degrees) or on 10
// degrees, and a hair (down to 1e-14 degrees) to either side of one.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {
namespace {

/// What quality() must report, computed from the rounded angles themselves.
StuffQuality angles_one_by_one(const d3::TetMeshF& m) {
  StuffQuality q;
  q.min_dihedral = 180;
  for (const auto& t : m.tets) {
    bool small = false;
    for (const double a :
         d3::dihedral_angles({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], m.vertices[t[3]]})) {
      q.min_dihedral = std::min(q.min_dihedral, a);
      q.max_dihedral = std::max(q.max_dihedral, a);
      ++q.histogram[static_cast<std::size_t>(std::lround(a / 15.0))];
      small = small || a < 10;
    }
    q.below10 += small ? 1 : 0;
  }
  return q;
}

/// quality(m)'s angle statistics `q` are those of the angles one by one.
void expect_angles_one_by_one(const d3::TetMeshF& m, const StuffQuality& q) {
  const StuffQuality expected = angles_one_by_one(m);
  EXPECT_EQ(q.histogram, expected.histogram);
  EXPECT_EQ(q.below10, expected.below10);
  EXPECT_EQ(q.min_dihedral, expected.min_dihedral);
  EXPECT_EQ(q.max_dihedral, expected.max_dihedral);
}

/// A tetrahedron whose dihedral angle at its edge v0v1 (the z axis) is
/// `degrees`: v2 in the half-plane y = 0, x > 0, and v3 at that angle from it.
void add_tet_with_angle(d3::TetMeshF& m, long double degrees) {
  const long double r = degrees * std::acos(-1.0L) / 180;
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({0, 0, 0});
  m.vertices.push_back({0, 0, 1});
  m.vertices.push_back({1, 0, 0.25});
  m.vertices.push_back({static_cast<double>(std::cos(r)), static_cast<double>(std::sin(r)), 0.5});
  m.kind.insert(m.kind.end(), 4, 0);
  m.tets.push_back({base, base + 1, base + 2, base + 3});
  m.level.push_back(0);
}

TEST(StuffQualityAngles, BinEdgesAndTenDegreesCountAsTheRoundedAngles) {
  d3::TetMeshF m;
  std::vector<long double> lines{10};
  for (int k = 0; k < 12; ++k) lines.push_back(7.5L + 15 * k);
  // On each line and 1e-14 .. 1e-6 degrees to either side of it: the
  // rounded angle lands on, below and above the edge.
  for (const long double line : lines) {
    add_tet_with_angle(m, line);
    for (long double hair = 1e-14L; hair <= 1e-6L; hair *= 10) {
      add_tet_with_angle(m, line - hair);
      add_tet_with_angle(m, line + hair);
    }
  }
  // The check reads something: some of these angles round onto an edge or
  // either side of it (the exact counts below are the one-by-one path's).
  const StuffQuality q = quality(m);
  expect_angles_one_by_one(m, q);
  // On the lines, half of the edge cases go up a bin: the 12 bins above
  // 7.5 + 15k each hold at least the tetrahedra placed a micro-degree above.
  for (std::size_t k = 1; k <= 12; ++k) EXPECT_GE(q.histogram[k], 1U) << "bin " << k;
}

TEST(StuffQualityAngles, StuffedMeshesCountAsTheRoundedAngles) {
  for (const int level : {2, 3}) {
    SCOPED_TRACE(level);
    StuffOptions o;
    o.max_level = level;
    const auto shape = make_torus({0.01, -0.02, 0.003}, 1, 0.4);
    const d3::TetMeshF m = stuff_shape(*shape, o).mesh;
    ASSERT_GT(m.tets.size(), 300U);
    expect_angles_one_by_one(m, quality(m));
  }
}

TEST(StuffQualityAngles, AnEmptyMeshHasNoAngles) {
  const StuffQuality q = quality(d3::TetMeshF{});
  EXPECT_EQ(q.min_dihedral, 0);
  EXPECT_EQ(q.max_dihedral, 0);
  EXPECT_EQ(q.below10, 0U);
  for (const std::size_t n : q.histogram) EXPECT_EQ(n, 0U);
}

}  // namespace
}  // namespace bccmis::stuff
