#include "bccmis/io/ply.h"

#include <cstdint>
#include <ostream>

#include "bccmis/io/detail/triangle_text.h"
#include "bccmis/text_writer.h"

namespace bccmis::io {

using detail::kLine;

void write_ply(std::ostream& out, const TriangleMesh& m, std::string_view comment) {
  TextWriter w(out);
  w.put("ply\nformat ascii 1.0\ncomment ");
  w.put(detail::one_line(comment));
  w.put("\nelement vertex ");
  w.put_int(static_cast<std::int64_t>(m.vertices.size()));
  w.put("\nproperty double x\nproperty double y\nproperty double z\nelement face ");
  w.put_int(static_cast<std::int64_t>(m.triangles.size()));
  w.put("\nproperty list uchar int vertex_indices\nproperty int level\nend_header\n");
  detail::write_vertex_lines(w, m.vertices, "");
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    char* p = w.room(kLine);
    *p++ = '3';
    *p++ = ' ';
    p = detail::write_triangle(p, m.triangles[i], 0);
    *p++ = ' ';
    p = TextWriter::write_int(p, m.triangle_level[i]);
    *p++ = '\n';
    w.commit(p);
  }
  w.flush();
}

std::string format_ply(const TriangleMesh& m, std::string_view comment) {
  return detail::text_of([&](std::ostream& out) { write_ply(out, m, comment); });
}

}  // namespace bccmis::io
