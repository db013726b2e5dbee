// Layer 1, combinatorial (Erleben 2009, §2 and §2.2): the sets N and C and the
// neighbor sets form a symmetric bipartite graph over existing vertices, and
// exactly the centers carry a level.
//
// The lattice size is checked here; the rest, shared with the 3D checker, is
// detail/combinatorial.h. The first failing check in this order is reported:
//   lattice-size       1 <= W, H; 0 <= L <= 61; W*S, H*S <= 2^62         §1
//   partition          N ∩ C = ∅                                         §2
//   neighbor-entry     every v in N ∪ C has an entry in the neighbor map  §2
//   stale-entry        no entry for a position that is not a vertex       §2.2
//   dangling-neighbor  every listed neighbor is a vertex                 §2.2
//   bipartite          nodes list only centers, centers only nodes        §2
//   symmetry           w ∈ 𝒩(v) ⇔ v ∈ 𝒩(w)                               §2
//   empty-neighbors    no vertex has an empty neighbor set               §2
//   missing-level      every center has a level                           §2.1 ¶1
//   stray-level        only centers have a level                          §2.1 ¶1
#include <optional>

#include "bccmis/invariants/detail/combinatorial.h"
#include "bccmis/invariants/detail/lattice_geometry.h"
#include "bccmis/invariants/detail/layers.h"

namespace bccmis::inv {

std::optional<Violation> check_combinatorial(const Graph& g) {
  constexpr int layer = 1;

  // lattice-size: the coordinates of spec/formats.md exist (every later
  // layer computes 2^(L+1) and W*S).
  {
    const LatticeSize& s = g.size;
    const std::string text =
        "lattice " + std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.L) + " is out of range: ";
    if (s.W < 1 || s.H < 1) return violation(layer, "lattice-size", {}, text + "W and H must be >= 1", "§1");
    if (s.L < 0 || s.L > 61) return violation(layer, "lattice-size", {}, text + "L must be in 0..61", "§1");
    const std::int64_t max_cells = (std::int64_t{1} << 62) >> (s.L + 1);  // W*S <= 2^62
    if (s.W > max_cells || s.H > max_cells)
      return violation(layer, "lattice-size", {}, text + "the domain side W*2^(L+1) or H*2^(L+1) exceeds 2^62", "§1");
  }

  return inv_common::check_combinatorial(g, {"§2", "§2.2", "§2.1 ¶1"}, violation);
}

}  // namespace bccmis::inv
