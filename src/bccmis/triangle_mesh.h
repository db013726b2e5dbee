// bccmis: a triangle mesh of a 2D lattice with heights (the height-field
// tessellation, spec/apps.md), as the writers of bccmis/io/ take it.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "bccmis/graph.h"

namespace bccmis {

/// A triangle mesh. x and y are in level-0 cell units (the domain is
/// [0, W] x [0, H]), z is the height; triangles are counter-clockwise seen
/// from +z. Vertices are the nodes and centers of the lattice, in sorted
/// position order (nodes first).
struct TriangleMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<Point> vertex_position;                 ///< lattice position of each vertex
  std::vector<std::array<std::size_t, 3>> triangles;  ///< 0-based vertex indices
  std::vector<Point> triangle_cell;                   ///< the center of the cell each triangle belongs to
  std::vector<int> triangle_level;                    ///< that cell's level
  std::vector<double> triangle_error;                 ///< optional: that cell's error (empty: none)
};

}  // namespace bccmis
