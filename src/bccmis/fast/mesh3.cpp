#include "bccmis/fast/mesh3.h"

#include "bccmis/d3/detail/tetrahedra.h"

namespace bccmis::fast {

std::vector<d3::Tet> tetrahedra(const Lattice3& g) { return d3::detail::tetrahedra_of(g); }

}  // namespace bccmis::fast
