// What --stats reports of a stuffed mesh (spec/stuffing.md S13): volume,
// dihedral angles and their histogram, boundary triangles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/detail/parallel_ranges.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

using Tets = std::vector<std::array<std::uint32_t, 4>>;

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
    for (std::size_t k = 0; k < kBinEdges; ++k) {
      const long double edge = std::cos((7.5L + 15.0L * static_cast<long double>(k)) * degree);
      below_edge_[k] = edge - kEdgeMargin;
      above_edge_[k] = edge + kEdgeMargin;
    }
    ten_ = std::cos(10.0L * degree);
  }

  /// The bin of lround(angle / 15) for the angle of cosine c.
  [[nodiscard]] std::size_t bin(long double c) const {
    std::size_t k = 0;
    for (; k < kBinEdges && c < below_edge_[k]; ++k) {
    }
    if (k < kBinEdges && c <= above_edge_[k])
      return static_cast<std::size_t>(std::lround(d3::dihedral_angle(c) / 15.0));
    return k;
  }

  /// Whether the angle of cosine c is below 10 degrees.
  [[nodiscard]] bool below10(long double c) const {
    if (std::abs(c - ten_) <= kEdgeMargin) return d3::dihedral_angle(c) < 10;
    return c > ten_;
  }

 private:
  std::array<long double, kBinEdges> below_edge_{}, above_edge_{};  ///< each edge's cosine -/+ kEdgeMargin
  long double ten_ = 0;
};

/// S13a: what the tetrahedra [begin, end) of one chunk add to the
/// statistics: their extreme cosines, histogram and count below 10 degrees,
/// and their volume summed in their order.
struct ChunkSums {
  long double largest_cosine = -1, smallest_cosine = 1;
  std::array<std::size_t, 13> histogram{};
  std::size_t below10 = 0;
  long double volume = 0;
};

ChunkSums chunk_sums(const std::vector<Vec3>& vertices, const Tets& tets, std::size_t begin, std::size_t end) {
  static const AngleEdges edges;
  ChunkSums s;
  for (std::size_t i = begin; i < end; ++i) {
    const auto& t = tets[i];
    const std::array<Vec3, 4> p{vertices[t[0]], vertices[t[1]], vertices[t[2]], vertices[t[3]]};
    bool small = false;
    for (const long double c : d3::dihedral_cosines(p)) {
      s.largest_cosine = std::max(s.largest_cosine, c);
      s.smallest_cosine = std::min(s.smallest_cosine, c);
      ++s.histogram[edges.bin(c)];
      small = small || edges.below10(c);
    }
    s.below10 += small ? 1 : 0;
    long double e[3][3];
    for (int r = 0; r < 3; ++r)
      for (std::size_t k = 0; k < 3; ++k)
        e[r][k] = static_cast<long double>(p[static_cast<std::size_t>(r + 1)][k]) - static_cast<long double>(p[0][k]);
    s.volume += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                 e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
                6;
  }
  return s;
}

}  // namespace

StuffQuality quality(const d3::TetMeshF& mesh, int threads) {
  return quality(mesh, boundary_triangles(mesh).size(), threads);
}

StuffQuality quality(const d3::TetMeshF& mesh, std::size_t boundary_triangles, int threads) {
  return quality(mesh.vertices, mesh.tets, boundary_triangles, threads);
}

StuffQuality quality(const std::vector<Vec3>& vertices, const Tets& tets, std::size_t boundary_triangles, int threads) {
  // S13a: the chunks of kQualityChunk tetrahedra, contiguous runs of them on
  // each thread, each chunk's sums in its own place, joined in chunk order.
  const std::size_t n = tets.size();
  std::vector<ChunkSums> chunks((n + kQualityChunk - 1) / kQualityChunk);
  detail::for_each_range(chunks.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t c = first; c < last; ++c)
      chunks[c] = chunk_sums(vertices, tets, c * kQualityChunk, std::min(n, (c + 1) * kQualityChunk));
  });
  StuffQuality q;
  ChunkSums all;
  for (const ChunkSums& c : chunks) {
    all.largest_cosine = std::max(all.largest_cosine, c.largest_cosine);
    all.smallest_cosine = std::min(all.smallest_cosine, c.smallest_cosine);
    for (std::size_t k = 0; k < q.histogram.size(); ++k) q.histogram[k] += c.histogram[k];
    q.below10 += c.below10;
    all.volume += c.volume;
  }
  if (n > 0) {
    q.min_dihedral = d3::dihedral_angle(all.largest_cosine);
    q.max_dihedral = d3::dihedral_angle(all.smallest_cosine);
  }
  q.volume = static_cast<double>(all.volume);
  q.boundary_triangles = boundary_triangles;
  return q;
}

}  // namespace bccmis::stuff
