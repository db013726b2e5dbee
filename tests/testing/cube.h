// The cube [0,2]^3 as 12 triangles: vertex x + 2y + 4z at 2 (x, y, z), two
// triangles a side, counterclockwise seen from outside. Header only;
// included as "testing/cube.h" (include root tests/).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace bccmis::testing {

inline std::vector<std::array<double, 3>> cube_vertices() {
  std::vector<std::array<double, 3>> v;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) v.push_back({2.0 * x, 2.0 * y, 2.0 * z});
  return v;
}

inline std::vector<std::array<std::uint32_t, 3>> cube_triangles() {
  return {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
          {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
}

}  // namespace bccmis::testing
