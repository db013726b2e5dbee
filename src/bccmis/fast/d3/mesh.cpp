#include "bccmis/fast/d3/mesh.h"

#include "bccmis/d3/detail/tetrahedra.h"

namespace bccmis::d3::fast {

std::vector<d3::Tet> tetrahedra(const Lattice& g) { return d3::detail::tetrahedra_of(g); }

}  // namespace bccmis::d3::fast
