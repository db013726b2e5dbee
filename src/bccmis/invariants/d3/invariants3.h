// Forwarding header kept for the p4est code (src/bccmis/p4est/, tests/p4est/)
// until it is renamed: the 3D checker is bccmis/invariants/d3/invariants.h.
// TODO remove when the p4est code is renamed.
#pragma once

#include "bccmis/invariants/d3/invariants.h"

namespace bccmis::d3 {
using Violation3 = Violation;  // TODO remove when the p4est code is renamed
}  // namespace bccmis::d3
