// bccmis explore in 3D: breadth-first search over every state reachable from
// the initial W x H x D lattice by refine and coarsen (spec/lattice3d.md §4,
// §5), with the checks of the 2D explorer (bccmis/explore/explore.h) on every
// state and every operation:
//   1. the independent 3D checker (invariants/d3/invariants.h) on every
//      state: layers 1..check_depth, and with check_depth 4 also the mesh
//      layer 5, check_mesh(g, tetrahedra(g));
//   2. refine and coarsen tried on every vertex: an accepted operation must
//      be undone exactly by its inverse, a refused one must change nothing.
// The same explorer as in 2D (detail/explorer.h), instantiated on d3::Graph;
// the state key is the 2D one with points numbered
// id = (x * (H*S + 1) + y) * (D*S + 1) + z.
#pragma once

#include <string>

#include "bccmis/d3/lattice.h"
#include "bccmis/explore/explore.h"

namespace bccmis::d3 {

using ExploreOptions = BasicExploreOptions<Graph>;
using ExploreResult = BasicExploreResult<LatticeSize>;

/// Explores every state reachable from Graph(size). Throws LatticeError for
/// an invalid size; failures are reported in the result, as in 2D.
ExploreResult explore(const LatticeSize& size, const ExploreOptions& options = {});

/// One line for humans, e.g.
/// `explore 1 1 1 2: 257 states, 1025 refine edges, 1025 coarsen edges, 63314 ops tried, ok (10.42 s)`.
std::string summary(const ExploreResult& result);

/// One line of JSON: the 2D fields with "D" after "H".
std::string to_json(const ExploreResult& result);

/// The exact key of a 3D graph and its inverse.
std::string encode_state_key(const Graph& g);
Graph decode_state_key(const std::string& key, const LatticeSize& size);

}  // namespace bccmis::d3
