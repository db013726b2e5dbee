// bccmis::io::detail: the binary half of read_msh (msh.h).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "bccmis/d3/tet_mesh.h"
#include "bccmis/io/orientation.h"

namespace bccmis::io::detail {

/// The tetrahedra of a binary MSH 4.1 file `text` whose "$MeshFormat"
/// header has been read up to `pos`, the byte-order int.
d3::TetMeshF read_msh_binary(std::string_view text, const std::string& name, std::size_t pos, Orientation orientation);

}  // namespace bccmis::io::detail
