// bccmis::io: VTK's parallel unstructured grid index (.pvtu), the file that
// lists the .vtu pieces of a mesh written by several MPI ranks
// (`bccmis-mpi stuff`, spec/distributed.md D1).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/encoding.h"

namespace bccmis::io {

/// The VTKFile of type "PUnstructuredGrid" whose pieces are `pieces` (file
/// names, written as they are, not escaped), declaring the arrays
/// write_vtu_piece writes: Float64 points, the point data "kind" (UInt8)
/// and "global_id" (Int64) and the cell data "level" (Int32).
void write_pvtu(std::ostream& out, const std::vector<std::string>& pieces);

/// A piece of a .pvtu: write_vtu's file of `mesh` with the point data
/// "global_id" (Int64, `global_id[i]` for vertex i, spec/distributed.md D7)
/// after "kind", in the same encoding.
void write_vtu_piece(std::ostream& out, const d3::TetMeshF& mesh, std::span<const std::int64_t> global_id,
                     Encoding encoding);

}  // namespace bccmis::io
