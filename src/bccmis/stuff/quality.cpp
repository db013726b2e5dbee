// What --stats reports of a stuffed mesh (spec/stuffing.md S13): volume,
// dihedral angles and their histogram, boundary triangles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

StuffQuality quality(const d3::TetMeshF& mesh) {
  StuffQuality q;
  q.min_dihedral = mesh.tets.empty() ? 0 : 180;
  long double volume = 0;
  for (const auto& t : mesh.tets) {
    const std::array<Vec3, 4> p{mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], mesh.vertices[t[3]]};
    bool small = false;
    for (const double a : d3::dihedral_angles(p)) {
      q.min_dihedral = std::min(q.min_dihedral, a);
      q.max_dihedral = std::max(q.max_dihedral, a);
      ++q.histogram[static_cast<std::size_t>(std::lround(a / 15.0))];
      small = small || a < 10;
    }
    q.below10 += small ? 1 : 0;
    long double e[3][3];
    for (int i = 0; i < 3; ++i)
      for (std::size_t k = 0; k < 3; ++k)
        e[i][k] = static_cast<long double>(p[static_cast<std::size_t>(i + 1)][k]) - static_cast<long double>(p[0][k]);
    volume += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
               e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
              6;
  }
  q.volume = static_cast<double>(volume);
  q.boundary_triangles = boundary_triangles(mesh).size();
  return q;
}

}  // namespace bccmis::stuff
