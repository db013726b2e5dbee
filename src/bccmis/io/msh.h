// bccmis::io: Gmsh MSH 4.1 (.msh), ASCII or binary, of a tetrahedral mesh
// with its components and boundary as physical groups (spec/mesh3d.md M21).
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/encoding.h"
#include "bccmis/io/orientation.h"
#include "bccmis/io/regions.h"

namespace bccmis::io {

/// Gmsh MSH 4.1: one volume entity and one physical volume
/// ("component_K", tag K) per connected component of the tetrahedra (M23),
/// one surface entity per component holding its boundary triangles, all in
/// the physical surface "boundary" (tag components + 1); every node in
/// volume 1; tetrahedron i has element tag i + 1, boundary triangle j tag
/// tets + j + 1; node tags from 1.
void write_msh(std::ostream& out, const d3::TetMesh& mesh, Encoding encoding = Encoding::ascii);
void write_msh(std::ostream& out, const d3::TetMeshF& mesh, Encoding encoding = Encoding::ascii);
/// The same with the mesh's regions already found (regions_of(mesh.tets)).
void write_msh(std::ostream& out, const d3::TetMeshF& mesh, const Regions& regions,
               Encoding encoding = Encoding::ascii);

/// The tetrahedra of the MSH 4.1 text `text` (as write_msh writes it, or
/// Gmsh), ASCII or binary: $MeshFormat 4.1 0 8 or 4.1 1 8, $Nodes (not parametric), $Elements whose
/// 4-node tetrahedra (type 4) are read, in the file's order, with their
/// nodes (every node becomes a vertex, in the file's order; kind 0, level
/// 0), triangles, lines and points (types 2, 1, 15) skipped; any other
/// section skipped to its $End line. Throws ParseError (file `name`, line,
/// column; in a binary section the column counts bytes) on anything else: another version or element
/// type, a count or number that does not parse, a coordinate not finite, a
/// node tag repeated or unknown, a tetrahedron with a repeated vertex or not
/// positively oriented (by `orientation`).
d3::TetMeshF read_msh(std::string_view text, const std::string& name, Orientation orientation);

}  // namespace bccmis::io
