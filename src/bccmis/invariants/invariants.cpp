// find_violation: the layers in order, each only after the lower ones passed.
#include "bccmis/invariants/invariants.h"

#include "bccmis/invariants/detail/layers.h"

namespace bccmis {

std::string to_string(const Violation& v) { return v.message + " [paper " + v.section + "]"; }

std::optional<Violation> check_layer(const Graph& g, int layer) {
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

ViolationError::ViolationError(Violation v, std::string context_)
    : std::runtime_error(context_.empty() ? to_string(v) : context_ + ": " + to_string(v)),
      violation(std::move(v)),
      context(std::move(context_)) {}

}  // namespace bccmis
