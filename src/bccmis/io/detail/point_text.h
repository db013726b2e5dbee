// bccmis::io::detail: a tetrahedral mesh's vertex as text, shared by the
// .vtu, .msh and .mesh writers: lattice points as integers, points in space
// as the shortest decimals that read back to the same doubles.
#pragma once

#include <charconv>
#include <cstddef>
#include <ostream>
#include <type_traits>

#include "bccmis/d3/tet_mesh.h"

namespace bccmis::io::detail {

/// The VTK type of a coordinate of P.
template <class P>
const char* coordinate_type() {
  return std::is_same_v<P, d3::Point> ? "Int64" : "Float64";
}

/// "x y z" and `end`.
inline void write_point(std::ostream& out, const d3::Point& p, char end = '\n') {
  out << p.x << ' ' << p.y << ' ' << p.z << end;
}

/// The shortest decimal that reads back to the same double.
inline void write_point(std::ostream& out, const d3::Vec3& p, char end = '\n') {
  char buf[3 * 32];
  char* it = buf;
  for (std::size_t i = 0; i < 3; ++i) {
    it = std::to_chars(it, buf + sizeof buf, p[i]).ptr;
    *it++ = i < 2 ? ' ' : end;
  }
  out.write(buf, it - buf);
}

}  // namespace bccmis::io::detail
