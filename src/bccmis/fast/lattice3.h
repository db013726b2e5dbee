// Forwarding header kept for the p4est code (src/bccmis/p4est/, tools/,
// bench/, tests/p4est/) until it is renamed: the fast 3D lattice is now
// bccmis::d3::fast::Lattice in bccmis/fast/d3/lattice.h.
// TODO remove when the p4est code is renamed.
#pragma once

#include "bccmis/fast/d3/lattice.h"

namespace bccmis::fast {
using Lattice3 = d3::fast::Lattice;  // TODO remove when the p4est code is renamed
}  // namespace bccmis::fast
