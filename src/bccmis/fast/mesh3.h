// bccmis::fast: the graded BCC tetrahedral mesh (spec/mesh3d.md) of the fast
// 3D lattice, by the rule d3::tetrahedra applies to Graph3
// (d3/detail/tetrahedra.h): the same tetrahedra for the same state.
#pragma once

#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/fast/lattice3.h"

namespace bccmis::fast {

/// d3::tetrahedra(g.to_graph()) without the copy: every tetrahedron once,
/// positively oriented, sorted (spec/mesh3d.md M1-M3).
std::vector<d3::Tet> tetrahedra(const Lattice3& g);

}  // namespace bccmis::fast
