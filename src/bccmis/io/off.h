// bccmis::io: OFF (Object File Format) surfaces: reading them, and writing
// the boundary of a stuffed mesh (spec/stuffing.md S11).
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/triangle_soup.h"

namespace bccmis::io {

/// The triangle soup of the OFF text `data` (file name `file` for messages):
/// the header OFF or a variant (STOFF, COFF, NOFF, CNOFF, ...) whose extra
/// per-vertex values are ignored, the vertex, face and edge counts, the
/// vertices, the faces (polygons fanned from their first corner), nothing
/// after them but blank lines and comments. Throws ReadError
/// (`file:line:column: message`) on anything else: a bad number, a negative
/// count, a face of fewer than 3 vertices, an index out of range.
TriangleSoup read_off(const std::string& file, const std::string& data);

/// The triangles `tris` of `mesh` as a surface: the vertices they use, in
/// order of first use, or with `all_vertices` every vertex of `mesh` in its
/// order (the volume mesh's numbering, spec/stuffing.md S11); each
/// coordinate the shortest decimal that reads back to the same double
/// (io/surface_write.cpp).
void write_off(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris,
               bool all_vertices = false);

}  // namespace bccmis::io
