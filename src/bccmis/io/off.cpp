// The OFF reader (off.h).
#include "bccmis/io/off.h"

#include <limits>
#include <string_view>
#include <vector>

#include "bccmis/io/detail/line_scanner.h"

namespace bccmis::io {

TriangleSoup read_off(const std::string& file, const std::string& data) {
  detail::LineScanner t(file, data);
  TriangleSoup s;
  auto next = [&](const char* what) {
    do {
      if (!t.next_line()) {
        t.fail(std::string("unexpected end of file, expected ") + what);
      }
    } while (t.line_blank());
  };
  next("the OFF header");
  const std::string_view head = t.token();
  // OFF, or a variant with texture coordinates, colours or normals per vertex
  // (STOFF, COFF, NOFF, CNOFF, ...), which follow the coordinates and are ignored.
  const bool off = head.size() >= 3 && head.substr(head.size() - 3) == "OFF" &&
                   head.substr(0, head.size() - 3).find_first_not_of("STCN") == std::string_view::npos;
  if (!off) t.fail("expected the OFF header 'OFF' (or STOFF, COFF, NOFF, CNOFF), found '" + std::string(head) + "'");
  if (t.line_blank()) next("the vertex, face and edge counts");
  const long long nv = t.integer("the vertex count");
  const long long nf = t.integer("the face count");
  t.integer("the edge count");
  if (nv < 0) t.fail("negative vertex count");
  if (nf < 0) t.fail("negative face count");
  if (!t.line_blank()) {
    t.token();
    t.fail("unexpected text after the counts");
  }
  if (nv > std::numeric_limits<std::uint32_t>::max()) t.fail("too many vertices");
  for (long long i = 0; i < nv; ++i) {
    next("a vertex");
    const double x = t.number("a coordinate"), y = t.number("a coordinate"), z = t.number("a coordinate");
    s.vertices.push_back({x, y, z});  // anything after the coordinates (a colour) is ignored
  }
  std::vector<std::uint32_t> poly;
  for (long long f = 0; f < nf; ++f) {
    next("a face");
    const long long n = t.integer("the number of vertices of a face");
    if (n < 3) t.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices (at least 3 needed)");
    poly.clear();
    for (long long i = 0; i < n; ++i) {
      const long long v = t.integer("a vertex index");
      if (v < 0 || v >= nv)
        t.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(v) + " out of range (" +
               std::to_string(nv) + " vertices)");
      poly.push_back(static_cast<std::uint32_t>(v));
    }
    detail::add_polygon(s, poly, static_cast<std::size_t>(f), t.line());
  }
  while (t.next_line())
    if (!t.line_blank()) {
      t.token();
      t.fail("unexpected text after the last face");
    }
  return s;
}

}  // namespace bccmis::io
