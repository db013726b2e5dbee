// bccmis::io: Medit .mesh, ASCII (MeshVersionFormatted 2, Dimension 3):
// the writer, and the reader of what it writes (spec/cli.md, render):
// MeshVersionFormatted, Dimension 3, Vertices with a reference each,
// Tetrahedra with a reference each, optionally Triangles (read and checked,
// then ignored), End.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/orientation.h"
#include "bccmis/io/regions.h"

namespace bccmis::io {

/// Vertices with the kind as reference, Tetrahedra (1-based) with the level
/// as reference (0 past the end of `level`), End.
void write_medit(std::ostream& out, const d3::TetMesh& mesh);
void write_medit(std::ostream& out, const d3::TetMeshF& mesh);
/// The same with the mesh's regions already found (regions_of(mesh.tets)).
void write_medit(std::ostream& out, const d3::TetMeshF& mesh, const Regions& regions);

/// The tetrahedral mesh in `text`: vertices with their reference as kind
/// (0..255), tetrahedra (1-based indices in the file) with their reference as
/// level (0..63). Throws ParseError (file `name`, line, column) on anything
/// else: an unknown keyword, a missing or repeated section, a count or number
/// that does not parse or is out of range, a coordinate that is not finite,
/// an index out of range, a tetrahedron with a repeated vertex or that is not
/// positively oriented (by `orientation`), or text after End.
d3::TetMeshF read_medit(std::string_view text, const std::string& name, Orientation orientation);

}  // namespace bccmis::io
