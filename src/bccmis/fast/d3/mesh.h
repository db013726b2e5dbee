// bccmis::fast: the graded BCC tetrahedral mesh (spec/mesh3d.md) of the fast
// 3D lattice, by the rule d3::tetrahedra applies to Graph
// (d3/detail/tetrahedra.h): the same tetrahedra for the same state.
#pragma once

#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"

namespace bccmis::d3::fast {

/// d3::tetrahedra(g.to_graph()) without the copy: every tetrahedron once,
/// positively oriented, sorted (spec/mesh3d.md M1-M3).
std::vector<d3::Tet> tetrahedra(const Lattice& g);

}  // namespace bccmis::d3::fast
