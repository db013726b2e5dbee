// bccmis::d3: the canonical state of a 3D lattice (spec/formats.md, "3D
// extension"). Printing only; the parser of the 3D forms comes with the 3D
// trace format.
#pragma once

#include <ostream>
#include <string>

#include "bccmis/d3/graph.h"

namespace bccmis::d3 {

/// The canonical text of g: `bccmis-state 1`, `lattice W H D L`, the C lines,
/// the N lines, `end <#C> <#N>`. Two graphs are equal iff their texts are.
std::string canonical_state(const Graph3& g);

/// canonical_state(g) written to `out`.
void write_canonical_state(std::ostream& out, const Graph3& g);

}  // namespace bccmis::d3
