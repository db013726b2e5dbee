// bccmis::io: ASCII PLY 1.0 of the triangle mesh of a height field
// (spec/apps.md, "Output formats").
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "bccmis/triangle_mesh.h"

namespace bccmis::io {

/// Vertex x y z (double), face vertex_indices (uchar count, int indices)
/// followed by an int `level` per face; `comment` on one line. Streams
/// through TextWriter (bccmis/text_writer.h); format_ply returns the same text.
void write_ply(std::ostream& out, const TriangleMesh& m, std::string_view comment);
std::string format_ply(const TriangleMesh& m, std::string_view comment);

}  // namespace bccmis::io
