// bccmis::d3: the 3D lattice in the vocabulary every lattice speaks
// (bccmis/lattice.h). Graph models AdaptiveLattice with Point as its point
// type and dimension 3: the accessors are the graph's, written once for every
// dimension in bccmis/lattice.h; the operations (d3/ops.h) and the canonical
// state (io/d3/format.h) are found by argument-dependent lookup, so the stepper
// and every tool written against the concept run on the 3D lattice unchanged.
#pragma once

#include "bccmis/d3/graph.h"
#include "bccmis/d3/ops.h"
#include "bccmis/io/d3/format.h"
#include "bccmis/lattice.h"

namespace bccmis::d3 {

static_assert(AdaptiveLattice<Graph>);
static_assert(Graph::dimension == 3);

}  // namespace bccmis::d3
