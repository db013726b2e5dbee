// bccmis::io: VTK's parallel unstructured grid index (.pvtu), the file that
// lists the .vtu pieces of a mesh written by several MPI ranks
// (`bccmis-mpi stuff`, spec/distributed.md D1).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace bccmis::io {

/// The VTKFile of type "PUnstructuredGrid" whose pieces are `pieces` (file
/// names, written as they are, not escaped), declaring the arrays write_vtu
/// writes of a d3::TetMeshF: Float64 points, the point data "kind" (UInt8)
/// and the cell data "level" (Int32).
void write_pvtu(std::ostream& out, const std::vector<std::string>& pieces);

}  // namespace bccmis::io
