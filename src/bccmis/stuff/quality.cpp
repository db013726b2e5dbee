// What --stats reports of a stuffed mesh (spec/stuffing.md S13): volume,
// dihedral angles and their histogram, boundary triangles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <thread>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

namespace {

/// S13's angle statistics from the cosines (d3::dihedral_cosines): acos is
/// monotone, so the extremes are the angles of the extreme cosines, and an
/// angle's histogram bin and its side of 10 degrees follow from comparing its
/// cosine with the cosines of the bin edges 7.5 + 15k and of 10 degrees.
/// Within kEdgeMargin of such a cosine the angle itself is computed and
/// rounded as d3::dihedral_angles rounds it, so every count equals the count
/// of the rounded angles. Why 1e-12 is enough: an angle's derivative by its
/// cosine is at least 180/pi degrees, so a cosine more than 1e-12 from an
/// edge's is more than 5.7e-11 degrees from the edge, far beyond the
/// rounding of the long double angle to a double (below 4e-14 degrees at
/// 180) and of cosl at the edge.
class AngleEdges {
 public:
  static constexpr long double kEdgeMargin = 1e-12L;
  static constexpr std::size_t kBinEdges = 12;  ///< 7.5, 22.5, ..., 172.5 degrees

  AngleEdges() {
    const long double degree = std::acos(-1.0L) / 180;
    for (std::size_t k = 0; k < kBinEdges; ++k)
      bin_edge_[k] = std::cos((7.5L + 15.0L * static_cast<long double>(k)) * degree);
    ten_ = std::cos(10.0L * degree);
  }

  /// The bin of lround(angle / 15) for the angle of cosine c.
  [[nodiscard]] std::size_t bin(long double c) const {
    std::size_t k = 0;
    for (; k < kBinEdges && c < bin_edge_[k] - kEdgeMargin; ++k) {
    }
    if (k < kBinEdges && c <= bin_edge_[k] + kEdgeMargin)
      return static_cast<std::size_t>(std::lround(d3::dihedral_angle(c) / 15.0));
    return k;
  }

  /// Whether the angle of cosine c is below 10 degrees.
  [[nodiscard]] bool below10(long double c) const {
    if (std::abs(c - ten_) <= kEdgeMargin) return d3::dihedral_angle(c) < 10;
    return c > ten_;
  }

 private:
  std::array<long double, kBinEdges> bin_edge_{};
  long double ten_ = 0;
};

/// The angles of tetrahedra [begin, end): extremes, histogram, below10.
StuffQuality angles(const d3::TetMeshF& mesh, std::size_t begin, std::size_t end) {
  static const AngleEdges edges;
  StuffQuality q;
  q.min_dihedral = 180;
  long double largest_cosine = -1, smallest_cosine = 1;
  for (std::size_t i = begin; i < end; ++i) {
    const auto& t = mesh.tets[i];
    bool small = false;
    for (const long double c :
         d3::dihedral_cosines({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]})) {
      largest_cosine = std::max(largest_cosine, c);
      smallest_cosine = std::min(smallest_cosine, c);
      ++q.histogram[edges.bin(c)];
      small = small || edges.below10(c);
    }
    q.below10 += small ? 1 : 0;
  }
  if (begin < end) {
    q.min_dihedral = d3::dihedral_angle(largest_cosine);
    q.max_dihedral = d3::dihedral_angle(smallest_cosine);
  }
  return q;
}

}  // namespace

StuffQuality quality(const d3::TetMeshF& mesh) { return quality(mesh, boundary_triangles(mesh).size()); }

StuffQuality quality(const d3::TetMeshF& mesh, std::size_t boundary_triangles) {
  // The angles on two threads, each over half of the tetrahedra: extremes,
  // counts and histogram are the same whatever the split.
  const std::size_t half = mesh.tets.size() / 2;
  StuffQuality second;
  std::thread other([&] { second = angles(mesh, half, mesh.tets.size()); });
  StuffQuality q = angles(mesh, 0, half);
  // The volume in one sum, in the order of the tetrahedra.
  long double volume = 0;
  for (const auto& t : mesh.tets) {
    const std::array<Vec3, 4> p{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]};
    long double e[3][3];
    for (int i = 0; i < 3; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        e[i][k] = static_cast<long double>(p[static_cast<std::size_t>(i + 1)][k]) - static_cast<long double>(p[0][k]);
    volume += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
               e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
              6;
  }
  other.join();
  q.min_dihedral = mesh.tets.empty() ? 0 : std::min(q.min_dihedral, second.min_dihedral);
  q.max_dihedral = std::max(q.max_dihedral, second.max_dihedral);
  for (std::size_t k = 0; k < q.histogram.size(); ++k) q.histogram[k] += second.histogram[k];
  q.below10 += second.below10;
  q.volume = static_cast<double>(volume);
  q.boundary_triangles = boundary_triangles;
  return q;
}

}  // namespace bccmis::stuff
