#include "bccmis/io/msh.h"

#include <cstddef>
#include <ostream>

#include "bccmis/io/detail/point_text.h"

namespace bccmis::io {

namespace {

template <class P>
void write_msh_impl(std::ostream& out, const d3::BasicTetMesh<P>& mesh) {
  const std::size_t n = mesh.vertices.size(), m = mesh.tets.size();
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  // One entity block: the volume entity 1 holds every node.
  out << "$Nodes\n1 " << n << ' ' << (n ? 1 : 0) << ' ' << n << '\n' << "3 1 0 " << n << '\n';
  for (std::size_t i = 1; i <= n; ++i) out << i << '\n';
  for (const P& p : mesh.vertices) detail::write_point(out, p);
  out << "$EndNodes\n";
  out << "$Elements\n1 " << m << ' ' << (m ? 1 : 0) << ' ' << m << '\n' << "3 1 4 " << m << '\n';
  for (std::size_t i = 0; i < m; ++i) {
    const auto& t = mesh.tets[i];
    out << i + 1 << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << ' ' << t[3] + 1 << '\n';
  }
  out << "$EndElements\n";
}

}  // namespace

void write_msh(std::ostream& out, const d3::TetMesh& mesh) { write_msh_impl(out, mesh); }
void write_msh(std::ostream& out, const d3::TetMeshF& mesh) { write_msh_impl(out, mesh); }

}  // namespace bccmis::io
