// bccmis::io: Gmsh MSH 4.1 (.msh), ASCII, of a tetrahedral mesh.
#pragma once

#include <iosfwd>

#include "bccmis/d3/tet_mesh.h"

namespace bccmis::io {

/// Gmsh MSH 4.1 ASCII: one volume entity (tag 1) holding every node and
/// every 4-node tetrahedron (element type 4); node and element tags from 1.
void write_msh(std::ostream& out, const d3::TetMesh& mesh);
void write_msh(std::ostream& out, const d3::TetMeshF& mesh);

}  // namespace bccmis::io
