// bccmis apps: the triangle mesh of a lattice (every cell's fan: center +
// boundary nodes in counter-clockwise order) and its OBJ, PLY and VTK .vtu
// texts (spec/apps.md, "Output formats"). The writers stream through
// TextWriter (bccmis/text_writer.h); format_* return the same text.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/graph.h"

namespace bccmis::fast {
class Lattice;
}

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

/// The fan triangulation of g (one triangle per stored center-node edge),
/// with z = height(vertex position). The same mesh from either lattice.
TriangleMesh triangulate(const Graph& g, const std::function<double(const Point&)>& height);
TriangleMesh triangulate(const fast::Lattice& g, const std::function<double(const Point&)>& height);

/// Wavefront OBJ: `# comment` lines, `v x y z`, `f i j k` (1-based).
void write_obj(std::ostream& out, const TriangleMesh& m, std::string_view comment);
std::string format_obj(const TriangleMesh& m, std::string_view comment);

/// ASCII PLY 1.0: vertex x y z (double), face vertex_indices (uchar count,
/// int indices) followed by an int `level` per face.
void write_ply(std::ostream& out, const TriangleMesh& m, std::string_view comment);
std::string format_ply(const TriangleMesh& m, std::string_view comment);

/// VTK XML UnstructuredGrid (.vtu, ASCII): triangles (type 5); point data
/// `height`; cell data `level` (Int32) and, when present, `error` (Float64).
void write_vtu(std::ostream& out, const TriangleMesh& m);
std::string format_vtu(const TriangleMesh& m);

}  // namespace bccmis
