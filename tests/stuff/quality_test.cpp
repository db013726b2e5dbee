// S13's angle statistics (stuff::quality) against the angles one by one:
// the histogram, the count below 10 degrees and the extremes must be those
// of d3::dihedral_angles's rounded angles, binned with lround(a / 15), also
// for tetrahedra whose angle lies on a bin edge (7.5 + 15k degrees) or on 10
// degrees, and a hair (down to 1e-14 degrees) to either side of one; and
// S13a's pass in chunks on threads: the same statistics on 1, 2 and 3
// threads, bit for bit, and a chunk's last and the next chunk's first
// tetrahedron each counted once.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
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

/// S13a's volume: each chunk of kQualityChunk tetrahedra summed in order,
/// the chunks' sums added in chunk order.
double chunked_volume(const d3::TetMeshF& m) {
  long double volume = 0, chunk = 0;
  for (std::size_t i = 0; i < m.tets.size(); ++i) {
    const auto& t = m.tets[i];
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]], &d = m.vertices[t[3]];
    long double e[3][3];
    for (std::size_t k = 0; k < 3; ++k) {
      e[0][k] = static_cast<long double>(b[k]) - static_cast<long double>(a[k]);
      e[1][k] = static_cast<long double>(c[k]) - static_cast<long double>(a[k]);
      e[2][k] = static_cast<long double>(d[k]) - static_cast<long double>(a[k]);
    }
    chunk += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
              e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
             6;
    if ((i + 1) % kQualityChunk == 0 || i + 1 == m.tets.size()) volume += std::exchange(chunk, 0.0L);
  }
  return static_cast<double>(volume);
}

/// quality(m) on 1, 2 and 3 threads: the same, bit for bit, and that of the
/// angles one by one with S13a's volume.
void expect_same_on_threads(const d3::TetMeshF& m) {
  const StuffQuality one = quality(m, 1);
  expect_angles_one_by_one(m, one);
  EXPECT_EQ(one.volume, chunked_volume(m));
  for (const int threads : {2, 3}) {
    SCOPED_TRACE(threads);
    EXPECT_TRUE(quality(m, threads) == one);
  }
}

TEST(StuffQualityThreads, TheSameOnOneTwoAndThreeThreads) {
  // Four chunks and a part (3 threads: runs of 1, 2 and 2 chunks), angles
  // from 5 to 175 degrees at random, so volumes of every size.
  d3::TetMeshF m;
  std::mt19937_64 random(1);
  std::uniform_real_distribution<long double> degrees(5, 175);
  while (m.tets.size() < 4 * kQualityChunk + 1000) add_tet_with_angle(m, degrees(random));
  expect_same_on_threads(m);
}

TEST(StuffQualityThreads, OneChunkAndOneMoreTetrahedron) {
  // The line: a mesh of exactly one chunk (one thread's work) and one of a
  // chunk and one tetrahedron (a second chunk, on the second thread). The
  // tetrahedron of 5 degrees is the chunk's last, then the one beyond it:
  // a chunk ending or starting one off misses it or counts it twice.
  for (const std::size_t n : {kQualityChunk, kQualityChunk + 1}) {
    SCOPED_TRACE(n);
    d3::TetMeshF m;
    std::mt19937_64 random(2);
    std::uniform_real_distribution<long double> degrees(30, 150);
    while (m.tets.size() + 1 < n) add_tet_with_angle(m, degrees(random));
    add_tet_with_angle(m, 5);
    expect_same_on_threads(m);
    const StuffQuality q = quality(m, 2);
    EXPECT_EQ(q.below10, 1U);
    std::size_t angles = 0;
    for (const std::size_t k : q.histogram) angles += k;
    EXPECT_EQ(angles, 6 * n);
  }
}

}  // namespace
}  // namespace bccmis::stuff
