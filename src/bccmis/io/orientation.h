// bccmis::io: the orientation test the tetrahedral mesh readers take.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bccmis/d3/tet_mesh.h"

namespace bccmis::io {

/// The sign (-1, 0 or 1) of det[b - a, c - a, d - a], exactly: the test by
/// which a reader takes a tetrahedron as positively oriented.
using Orientation = int (*)(const d3::Vec3& a, const d3::Vec3& b, const d3::Vec3& c, const d3::Vec3& d);

/// "" when the tetrahedron `t` of `vertices` is positively oriented, else
/// the end of a message saying why not: " is flat (det[...] must be
/// positive)" or " is negatively oriented (...)".
inline std::string orientation_fault(Orientation orientation, const std::vector<d3::Vec3>& vertices,
                                     const std::array<std::uint32_t, 4>& t) {
  const auto& v = vertices;
  const int sign = orientation(v[t[0]], v[t[1]], v[t[2]], v[t[3]]);
  if (sign > 0) return "";
  return std::string(sign == 0 ? " is flat" : " is negatively oriented") +
         " (det[v1 - v0, v2 - v0, v3 - v0] must be positive)";
}

}  // namespace bccmis::io
