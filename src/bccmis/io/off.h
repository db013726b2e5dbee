// bccmis::io: reading OFF (Object File Format) surfaces.
#pragma once

#include <string>

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

}  // namespace bccmis::io
