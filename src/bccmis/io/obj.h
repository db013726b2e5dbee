// bccmis::io: Wavefront OBJ: the writer of the triangle mesh of a height
// field (spec/apps.md, "Output formats").
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "bccmis/triangle_mesh.h"

namespace bccmis::io {

/// `# comment` lines, `v x y z`, `f i j k` (1-based); `comment` on one line.
/// Streams through TextWriter (bccmis/text_writer.h); format_obj returns the
/// same text.
void write_obj(std::ostream& out, const TriangleMesh& m, std::string_view comment);
std::string format_obj(const TriangleMesh& m, std::string_view comment);

}  // namespace bccmis::io
