// bccmis::io: reading STL surfaces, ASCII or binary.
#pragma once

#include <string>

#include "bccmis/io/triangle_soup.h"

namespace bccmis::io {

/// The triangle soup of the STL file `data` (file name `file` for messages),
/// each corner that repeats exactly merged into one vertex. Binary when the
/// size matches the triangle count at byte 80 (binary headers may start with
/// "solid" too); otherwise ASCII when the file starts with "solid" or is text
/// (is_text, surface_format.h), binary when it is not. The facet normals are
/// kept in `normals` but never refused: in ASCII whatever follows `facet` on
/// its line is accepted (a missing, `nan` or garbled normal reads as NaN).
/// Throws ReadError: in ASCII
/// `file:line:column: message` on a keyword or number out of place, in binary
/// `file: byte N: message` on a truncated file, bytes after the triangles or a
/// coordinate that is not finite.
TriangleSoup read_stl(const std::string& file, const std::string& data);

}  // namespace bccmis::io
