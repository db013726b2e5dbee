// The regular icosahedron subdivided: each triangle into four through its
// edge midpoints, `levels` times (20 4^levels triangles), as the winding
// number's tests and benchmarks and the stuffing peers build their spheres.
// Header only; included as "testing/icosphere.h" (include root tests/).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace bccmis::testing {

/// Writes the subdivided icosahedron into `points` and `triangles`
/// (replacing what they held): the 12 vertices (+-1, +-p, 0) and their
/// cyclic shifts (p the golden ratio), faces counter-clockwise seen from
/// outside. Every vertex, the 12 and each edge midpoint (a + b) / 2, is
/// passed through `project` (e.g. onto the unit sphere, or unchanged).
template <class T, class Index, class Project>
void subdivided_icosahedron(int levels, Project project, std::vector<std::array<T, 3>>& points,
                            std::vector<std::array<Index, 3>>& triangles) {
  using Point = std::array<T, 3>;
  using Triangle = std::array<Index, 3>;
  const T p = (1 + std::sqrt(T(5))) / 2;
  points = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
            {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
  triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
               {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Point& x : points) x = project(x);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<Index, Index>, Index> midpoint;
    auto mid = [&](Index a, Index b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const Point& u = points[a];
      const Point& v = points[b];
      points.push_back(project(Point{(u[0] + v[0]) / 2, (u[1] + v[1]) / 2, (u[2] + v[2]) / 2}));
      return midpoint[key] = static_cast<Index>(points.size() - 1);
    };
    std::vector<Triangle> finer;
    finer.reserve(triangles.size() * 4);
    for (const Triangle& t : triangles) {
      const Index ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }
}

}  // namespace bccmis::testing
