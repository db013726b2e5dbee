// bccmis::d3: the few position computations the 3D operations need where the
// sets cannot decide. Each use is an entry of spec/choices3d.toml with
// kind = "position" (Q1-Q4).
#pragma once

#include <array>
#include <cstddef>

#include "bccmis/d3/graph.h"

namespace bccmis::d3 {

/// The midpoint of a and b. Callers only pass points whose coordinate
/// differences are even; written to avoid overflow near 2^62.
inline Point midpoint(const Point& a, const Point& b) {
  return {a.x + (b.x - a.x) / 2, a.y + (b.y - a.y) / 2, a.z + (b.z - a.z) / 2};
}

/// One edge of a cube: the indices of its two corners in the cube's corner
/// list (sorted by position).
struct CubeEdge {
  std::size_t i, j;
};

/// One face of a cube: the indices of its four corners.
struct CubeFace {
  std::array<std::size_t, 4> corners;
};

/// The 12 edges of the cube whose 8 corners are `p` (sorted by position), in
/// the order of their corners. Q2: two corners span an edge iff they differ
/// in exactly one coordinate.
inline std::array<CubeEdge, 12> cube_edges(const std::array<Point, 8>& p) {
  std::array<CubeEdge, 12> edges{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t j = i + 1; j < 8; ++j) {
      const int same = (p[i].x == p[j].x) + (p[i].y == p[j].y) + (p[i].z == p[j].z);
      if (same == 2 && k < edges.size()) edges[k++] = {i, j};
    }
  return edges;
}

/// The 6 faces of the cube whose 8 corners are `p` (sorted by position), Q2:
/// four corners span a face iff they share one coordinate, the lowest or the
/// highest of the cube's.
inline std::array<CubeFace, 6> cube_faces(const std::array<Point, 8>& p) {
  std::array<CubeFace, 6> faces{};
  auto coordinate = [](const Point& q, int axis) { return axis == 0 ? q.x : axis == 1 ? q.y : q.z; };
  std::size_t k = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const std::int64_t value : {coordinate(p[0], axis), coordinate(p[7], axis)}) {
      std::size_t m = 0;
      for (std::size_t i = 0; i < 8; ++i)
        if (coordinate(p[i], axis) == value && m < 4) faces[k].corners[m++] = i;
      ++k;
    }
  return faces;
}

}  // namespace bccmis::d3
