// The 3D checker (this folder holds the 3D counterpart of
// src/bccmis/invariants/: layers 1-4 one per file, the mesh layer and the
// stuffed-mesh layer). 3D layer 1, combinatorial (spec/lattice3d.md §1): N
// and C and the neighbour sets form a symmetric bipartite graph over existing
// vertices, and exactly the centers carry a level.
//
// The lattice size is checked here; the rest, shared with the 2D checker, is
// ../detail/combinatorial.h. The first failing check in this order is reported:
//   lattice-size       W, H, D >= 1; 0 <= L <= 61; W*S, H*S, D*S <= 2^62
//   partition          N ∩ C = ∅
//   neighbor-entry     every v in N ∪ C has an entry in the neighbour map
//   stale-entry        no entry for a position that is not a vertex
//   dangling-neighbor  every listed neighbour is a vertex
//   bipartite          nodes list only centers, centers only nodes
//   symmetry           w ∈ N(v) ⇔ v ∈ N(w)
//   empty-neighbors    no vertex has an empty neighbour set
//   missing-level      every center has a level
//   stray-level        only centers have a level
#include <optional>

#include "bccmis/invariants/d3/detail/lattice_geometry.h"
#include "bccmis/invariants/detail/combinatorial.h"

namespace bccmis::d3::inv {

std::optional<Violation> check_lattice_size(const LatticeSize& s) {
  const std::string text = "lattice " + std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.D) +
                           " " + std::to_string(s.L) + " is out of range: ";
  if (s.W < 1 || s.H < 1 || s.D < 1) return violation(1, "lattice-size", {}, text + "W, H and D must be >= 1", "§1");
  if (s.L < 0 || s.L > 61) return violation(1, "lattice-size", {}, text + "L must be in 0..61", "§1");
  const std::int64_t max_cubes = (std::int64_t{1} << 62) >> (s.L + 1);  // W*S <= 2^62
  if (s.W > max_cubes || s.H > max_cubes || s.D > max_cubes)
    return violation(1, "lattice-size", {}, text + "an extent W*2^(L+1), H*2^(L+1) or D*2^(L+1) exceeds 2^62", "§1");
  return std::nullopt;
}

std::optional<Violation> check_combinatorial(const Graph& g) {
  if (auto v = check_lattice_size(g.size)) return v;
  return inv_common::check_combinatorial(g, {"§1", "§1", "§1"}, violation);
}

}  // namespace bccmis::d3::inv
