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

/// The angles of tetrahedra [begin, end): extremes, histogram, below10.
StuffQuality angles(const d3::TetMeshF& mesh, std::size_t begin, std::size_t end) {
  StuffQuality q;
  q.min_dihedral = 180;
  for (std::size_t i = begin; i < end; ++i) {
    const auto& t = mesh.tets[i];
    bool small = false;
    for (const double a :
         d3::dihedral_angles({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]})) {
      q.min_dihedral = std::min(q.min_dihedral, a);
      q.max_dihedral = std::max(q.max_dihedral, a);
      ++q.histogram[static_cast<std::size_t>(std::lround(a / 15.0))];
      small = small || a < 10;
    }
    q.below10 += small ? 1 : 0;
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
