// The Medit writer (medit.h).
#include <cstddef>
#include <ostream>

#include "bccmis/io/detail/point_text.h"
#include "bccmis/io/medit.h"
#include "bccmis/io/regions.h"

namespace bccmis::io {

namespace {

template <class P>
void write_medit_impl(std::ostream& out, const d3::BasicTetMesh<P>& mesh, const Regions& r) {
  out << "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n" << mesh.vertices.size() << '\n';
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    detail::write_point(out, mesh.vertices[i], ' ');
    out << static_cast<int>(mesh.kind[i]) << '\n';
  }
  out << "\nTetrahedra\n" << mesh.tets.size() << '\n';
  for (std::size_t i = 0; i < mesh.tets.size(); ++i) {
    const auto& t = mesh.tets[i];
    out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << ' '
        << (i < mesh.level.size() ? mesh.level[i] : 0) << '\n';
  }
  out << "\nTriangles\n" << r.boundary.size() << '\n';
  for (std::size_t j = 0; j < r.boundary.size(); ++j) {
    const auto& f = r.boundary[j];
    out << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << ' ' << r.boundary_component[j] + 1 << '\n';
  }
  out << "\nEnd\n";
}

}  // namespace

void write_medit(std::ostream& out, const d3::TetMesh& mesh) { write_medit_impl(out, mesh, regions_of(mesh.tets)); }
void write_medit(std::ostream& out, const d3::TetMeshF& mesh) { write_medit_impl(out, mesh, regions_of(mesh.tets)); }
void write_medit(std::ostream& out, const d3::TetMeshF& mesh, const Regions& regions) {
  write_medit_impl(out, mesh, regions);
}

}  // namespace bccmis::io
