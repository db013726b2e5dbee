// bccmis::io: VTK XML UnstructuredGrid (.vtu), ASCII: the tetrahedral mesh
// of a 3D lattice or of isosurface stuffing, and the triangle mesh of a
// height field (spec/apps.md, "Output formats").
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/encoding.h"
#include "bccmis/io/orientation.h"
#include "bccmis/triangle_mesh.h"

namespace bccmis::io {

/// Int64 points, VTK_TETRA (10) cells, the point data array "kind" and the
/// cell data array "level"; ASCII, binary (base64 inline, a UInt64 byte
/// count before each array's values) or zlib (binary, each array compressed
/// in blocks: vtkZLibDataCompressor); spec/mesh3d.md M20.
void write_vtu(std::ostream& out, const d3::TetMesh& mesh, Encoding encoding = Encoding::ascii);
/// The same with Float64 points.
void write_vtu(std::ostream& out, const d3::TetMeshF& mesh, Encoding encoding = Encoding::ascii);

/// The tetrahedral mesh of a .vtu as write_vtu writes it (ASCII or base64
/// binary, UInt32 or UInt64 headers, raw or zlib-compressed): Points, Cells of
/// VTK_TETRA only, the point data "kind" and the cell data "level" when
/// present (0 otherwise). Throws ParseError (file `name`, the line and
/// column of the offending element) on anything else, and on a tetrahedron
/// with a repeated vertex or not positively oriented (by `orientation`).
d3::TetMeshF read_vtu(std::string_view text, const std::string& name, Orientation orientation);

/// Triangles (type 5); point data `height`; cell data `level` (Int32) and,
/// when present, `error` (Float64). Streams through TextWriter
/// (bccmis/text_writer.h); format_vtu returns the same text.
void write_vtu(std::ostream& out, const TriangleMesh& m);
std::string format_vtu(const TriangleMesh& m);

}  // namespace bccmis::io
