#include "bccmis/io/obj.h"

#include <cstdint>
#include <ostream>

#include "bccmis/io/detail/triangle_text.h"
#include "bccmis/text_writer.h"

namespace bccmis::io {

using detail::kLine;

void write_obj(std::ostream& out, const TriangleMesh& m, std::string_view comment) {
  TextWriter w(out);
  w.put("# ");
  w.put(detail::one_line(comment));
  w.put("\n# ");
  w.put_int(static_cast<std::int64_t>(m.vertices.size()));
  w.put(" vertices, ");
  w.put_int(static_cast<std::int64_t>(m.triangles.size()));
  w.put(" triangles\n");
  detail::write_vertex_lines(w, m.vertices, "v ");
  for (const auto& t : m.triangles) {
    char* p = w.room(kLine);
    *p++ = 'f';
    *p++ = ' ';
    p = detail::write_triangle(p, t, 1);
    *p++ = '\n';
    w.commit(p);
  }
  w.flush();
}

std::string format_obj(const TriangleMesh& m, std::string_view comment) {
  return detail::text_of([&](std::ostream& out) { write_obj(out, m, comment); });
}

}  // namespace bccmis::io
