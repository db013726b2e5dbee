#include "bccmis/io/obj.h"

#include <cstdint>
#include <ostream>
#include <string_view>
#include <vector>

#include "bccmis/io/detail/line_scanner.h"
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

TriangleSoup read_obj(const std::string& file, const std::string& data) {
  detail::LineScanner t(file, data);
  TriangleSoup s;
  s.vertex_base = 1;
  std::size_t faces = 0;
  std::vector<std::uint32_t> poly;
  while (t.next_line()) {
    const std::string_view key = t.token();
    if (key == "v") {
      const double x = t.number("a coordinate"), y = t.number("a coordinate"), z = t.number("a coordinate");
      s.vertices.push_back({x, y, z});  // an optional weight or colour is ignored
    } else if (key == "f") {
      poly.clear();
      for (std::string_view tok = t.token(); !tok.empty(); tok = t.token()) {
        const std::string_view idx = tok.substr(0, tok.find('/'));  // v, v/vt, v//vn, v/vt/vn
        const long long v = t.integer(idx, "a vertex index");
        const long long n = static_cast<long long>(s.vertices.size());
        // 1-based; negative counts back from the last vertex read so far.
        const long long abs = v > 0 ? v : n + v + 1;
        if (v == 0 || abs < 1 || abs > n)
          t.fail("face " + std::to_string(faces) + ": vertex index " + std::to_string(v) + " out of range (" +
                 std::to_string(n) + " vertices so far)");
        poly.push_back(static_cast<std::uint32_t>(abs - 1));
      }
      if (poly.size() < 3)
        t.fail("face " + std::to_string(faces) + " has " + std::to_string(poly.size()) +
               " vertices (at least 3 needed)");
      detail::add_polygon(s, poly, faces++, t.line());
    }
    // Other statements (vt, vn, g, o, s, usemtl, mtllib, l, ...) and comments are ignored.
  }
  return s;
}

}  // namespace bccmis::io
