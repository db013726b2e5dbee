// bccmis::io: Gmsh MSH 4.1 (.msh), ASCII or binary, of a tetrahedral mesh
// with its components and boundary as physical groups (spec/mesh3d.md M21).
#pragma once

#include <iosfwd>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/encoding.h"

namespace bccmis::io {

/// Gmsh MSH 4.1: one volume entity and one physical volume
/// ("component_K", tag K) per connected component of the tetrahedra (M23),
/// one surface entity per component holding its boundary triangles, all in
/// the physical surface "boundary" (tag components + 1); every node in
/// volume 1; tetrahedron i has element tag i + 1, boundary triangle j tag
/// tets + j + 1; node tags from 1.
void write_msh(std::ostream& out, const d3::TetMesh& mesh, Encoding encoding = Encoding::ascii);
void write_msh(std::ostream& out, const d3::TetMeshF& mesh, Encoding encoding = Encoding::ascii);

}  // namespace bccmis::io
