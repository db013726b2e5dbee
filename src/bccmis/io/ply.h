// bccmis::io: PLY 1.0: writing the triangle mesh of a height field as ASCII
// (spec/apps.md, "Output formats"), reading a triangle mesh, ASCII or binary
// (spec/formats.md, "PLY input"; ply_read.cpp).
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "bccmis/io/triangle_soup.h"
#include "bccmis/triangle_mesh.h"

namespace bccmis::io {

/// Vertex x y z (double), face vertex_indices (uchar count, int indices)
/// followed by an int `level` per face; `comment` on one line. Streams
/// through TextWriter (bccmis/text_writer.h); format_ply returns the same text.
void write_ply(std::ostream& out, const TriangleMesh& m, std::string_view comment);
std::string format_ply(const TriangleMesh& m, std::string_view comment);

/// The triangle soup of the PLY file `data` (file name `file` for messages):
/// `format ascii 1.0`, `binary_little_endian 1.0` or `binary_big_endian 1.0`;
/// the `vertex` element's scalar properties x, y, z of any type; the `face`
/// element's list `vertex_indices` (or `vertex_index`) of integer indices,
/// polygons fanned from their first corner; every other property and element
/// skipped. Throws ReadError: `file:line:column: message` in the header and
/// an ASCII body, `file: byte N: message` in a binary body (a truncated file,
/// an index out of range, a coordinate that is not finite, bytes after the
/// last element).
TriangleSoup read_ply(const std::string& file, const std::string& data);

}  // namespace bccmis::io
