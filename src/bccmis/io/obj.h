// bccmis::io: Wavefront OBJ: the writers of the triangle mesh of a height
// field (spec/apps.md, "Output formats") and of the boundary of a stuffed
// mesh (spec/stuffing.md S11), and the reader of surfaces.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/triangle_soup.h"
#include "bccmis/triangle_mesh.h"

namespace bccmis::io {

/// `# comment` lines, `v x y z`, `f i j k` (1-based); `comment` on one line.
/// Streams through TextWriter (bccmis/text_writer.h); format_obj returns the
/// same text.
void write_obj(std::ostream& out, const TriangleMesh& m, std::string_view comment);
std::string format_obj(const TriangleMesh& m, std::string_view comment);

/// The triangle soup of the OBJ text `data` (file name `file` for messages):
/// `v x y z` vertices and `f` faces (v, v/vt, v//vn or v/vt/vn; 1-based, or
/// negative counting back from the last vertex read), polygons fanned from
/// their first corner; other statements and comments are ignored. Throws
/// ReadError (`file:line:column: message`) on a bad number, an index out of
/// range or a face of fewer than 3 vertices.
TriangleSoup read_obj(const std::string& file, const std::string& data);

/// The triangles `tris` of `mesh` as a surface: the vertices they use, in
/// order of first use, or with `all_vertices` every vertex of `mesh` in its
/// order (the volume mesh's numbering, spec/stuffing.md S11); each
/// coordinate the shortest decimal that reads back to the same double
/// (io/surface_write.cpp).
void write_obj(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris,
               bool all_vertices = false);

}  // namespace bccmis::io
