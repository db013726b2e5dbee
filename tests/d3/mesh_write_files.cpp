// Writes the graded BCC mesh (spec/mesh3d.md) of two states in the three
// formats, for tests/d3/mesh_readers_test.py to load with meshio and gmsh:
//   <dir>/split.{vtu,msh,mesh}   lattice 2 1 1 2, refine 4 4 4 (spec/mesh3d.md M18)
//   <dir>/graded.{vtu,msh,mesh}  lattice 2 2 1 2, refine 4 4 4, 12 4 4, 2 2 2, 10 2 2
// Exit status 2 on a usage or write error.
#include <fstream>
#include <iostream>
#include <string>

#include "bccmis/d3/mesh.h"
#include "bccmis/d3/ops.h"
#include "bccmis/io/medit.h"
#include "bccmis/io/msh.h"
#include "bccmis/io/vtu.h"

namespace {

using namespace bccmis::d3;

bool write_all(const std::string& stem, const Graph& g) {
  const TetMesh mesh = index_mesh(g, tetrahedra(g));
  std::ofstream vtu(stem + ".vtu"), msh(stem + ".msh"), medit(stem + ".mesh");
  bccmis::io::write_vtu(vtu, mesh);
  bccmis::io::write_msh(msh, mesh);
  bccmis::io::write_medit(medit, mesh);
  return vtu.good() && msh.good() && medit.good();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: d3_mesh_write DIR\n";
    return 2;
  }
  const std::string dir = argv[1];
  Graph split(LatticeSize{2, 1, 1, 2});
  Graph graded(LatticeSize{2, 2, 1, 2});
  bool ok = refine(split, {4, 4, 4}).applied();
  for (const Point c : {Point{4, 4, 4}, Point{12, 4, 4}, Point{2, 2, 2}, Point{10, 2, 2}})
    ok = ok && refine(graded, c).applied();
  if (!ok) {
    std::cerr << "d3_mesh_write: a refinement was refused\n";
    return 2;
  }
  if (!write_all(dir + "/split", split) || !write_all(dir + "/graded", graded)) {
    std::cerr << "d3_mesh_write: cannot write under " << dir << '\n';
    return 2;
  }
  return 0;
}
