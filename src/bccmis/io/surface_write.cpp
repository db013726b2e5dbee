// A surface made of some triangles of a tetrahedral mesh (the boundary of a
// stuffed mesh, spec/stuffing.md S11) as OFF (off.h) or OBJ (obj.h).
#include <charconv>
#include <cstdint>
#include <ostream>
#include <utility>
#include <vector>

#include "bccmis/io/obj.h"
#include "bccmis/io/off.h"

namespace bccmis::io {

namespace {

/// The vertices the triangles use, renumbered in order of first use; or
/// with `all_vertices` every vertex, numbered as in `mesh`.
std::pair<std::vector<std::uint32_t>, std::vector<std::array<std::uint32_t, 3>>> compact(
    const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris, bool all_vertices) {
  if (all_vertices) {
    std::vector<std::uint32_t> every(mesh.vertices.size());
    for (std::uint32_t v = 0; v < every.size(); ++v) every[v] = v;
    return {every, tris};
  }
  std::vector<std::uint32_t> used, renumber(mesh.vertices.size(), UINT32_MAX);
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& t : tris) {
    std::array<std::uint32_t, 3> r{};
    for (std::size_t i = 0; i < 3; ++i) {
      if (renumber[t[i]] == UINT32_MAX) renumber[t[i]] = static_cast<std::uint32_t>(used.size()), used.push_back(t[i]);
      r[i] = renumber[t[i]];
    }
    out.push_back(r);
  }
  return {used, out};
}

void write_coordinates(std::ostream& out, const d3::Vec3& p) {
  char buf[96];
  char* it = buf;
  for (std::size_t i = 0; i < 3; ++i) {
    it = std::to_chars(it, buf + sizeof buf, p[i]).ptr;
    *it++ = i < 2 ? ' ' : '\n';
  }
  out.write(buf, it - buf);
}

}  // namespace

void write_off(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris,
               bool all_vertices) {
  const auto [used, faces] = compact(mesh, tris, all_vertices);
  out << "OFF\n" << used.size() << ' ' << faces.size() << " 0\n";
  for (const std::uint32_t v : used) write_coordinates(out, mesh.vertices[v]);
  for (const auto& f : faces) out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
}

void write_obj(std::ostream& out, const d3::TetMeshF& mesh, const std::vector<std::array<std::uint32_t, 3>>& tris,
               bool all_vertices) {
  const auto [used, faces] = compact(mesh, tris, all_vertices);
  for (const std::uint32_t v : used) {
    out << "v ";
    write_coordinates(out, mesh.vertices[v]);
  }
  for (const auto& f : faces) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
}

}  // namespace bccmis::io
