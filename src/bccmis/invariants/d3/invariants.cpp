// find_violation for the 3D lattice: the layers in order, each only after the
// lower ones passed.
#include "bccmis/invariants/d3/invariants.h"

#include <stdexcept>

#include "bccmis/invariants/d3/detail/lattice_geometry.h"

namespace bccmis::d3 {

std::string to_string(const Violation& v) { return v.message + " [" + v.section + "]"; }

std::optional<Violation> check_layer(const Graph& g, int layer) {
  // Layers 2-4 compute 2^(L+1) and the extents: with a size layer 1 rejects
  // they report that instead of computing with it.
  if (layer >= 2 && layer <= 4)
    if (auto v = inv::check_lattice_size(g.size)) return v;
  switch (layer) {
    case 1: return inv::check_combinatorial(g);
    case 2: return inv::check_structural(g);
    case 3: return inv::check_grading(g);
    case 4: return inv::check_geometry(g);
    default: throw std::invalid_argument("check_layer: layer " + std::to_string(layer) + " is not 1..4");
  }
}

std::optional<Violation> find_violation(const Graph& g, int depth) {
  for (int layer = 1; layer <= depth && layer <= 4; ++layer)
    if (auto v = check_layer(g, layer)) return v;
  return std::nullopt;
}

bool is_valid(const Graph& g, int depth) { return !find_violation(g, depth); }

}  // namespace bccmis::d3
