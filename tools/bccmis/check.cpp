// bccmis check STATE: the checker on a canonical state; and the helpers every
// subcommand that checks shares.
#include <iostream>
#include <map>

#include "bccmis/fast/lattice.h"
#include "commands.h"
#include "io.h"
#if BCCMIS_HAVE_TRIANGULATION_CHECK
#include "bccmis/invariants/cgal/triangulation_check.h"
#endif

namespace bccmis::cli {

Implementation implementation(std::string_view name) {
  if (name == "reference") return std::type_identity<Graph>{};
  if (name == "fast") return std::type_identity<fast::Lattice>{};
  throw InputError("impl '" + std::string(name) + "' is unknown: use reference or fast");
}

const Graph& as_graph(const fast::Lattice& g, Graph& copy) { return copy = g.to_graph(); }

int max_check_depth() { return BCCMIS_HAVE_TRIANGULATION_CHECK ? 5 : 4; }

std::optional<Violation> check_graph(const Graph& g, int depth) {
  auto v = find_violation(g, depth < 5 ? depth : 4);
#if BCCMIS_HAVE_TRIANGULATION_CHECK
  if (!v && depth >= 5) v = find_triangulation_violation(g);
#endif
  return v;
}

std::string summary(const std::map<int, std::size_t>& cells_per_level, std::size_t nodes) {
  std::size_t cells = 0;
  std::string levels;
  for (const auto& [l, n] : cells_per_level) {
    levels += (levels.empty() ? "" : ", ") + std::string("level ") + std::to_string(l) + ": " + std::to_string(n);
    cells += n;
  }
  return std::to_string(cells) + " cells (" + levels + "), " + std::to_string(nodes) + " nodes";
}

std::string summary(const Graph& g) {
  std::map<int, std::size_t> per_level;
  for (const auto& [c, l] : g.level) ++per_level[l];
  return summary(per_level, g.N.size());
}

int run(const CheckOptions& o) {
  const std::string name = display_name(o.state);
  const Graph g = read_state(o.state);
  if (auto v = check_graph(g, o.depth)) {
    std::cerr << "bccmis check: " << name << ": " << to_string(*v) << "\n";
    return kExitViolation;
  }
  if (!o.quiet) std::cout << name << ": valid (depth " << o.depth << "): " << summary(g) << "\n";
  return kExitOk;
}

}  // namespace bccmis::cli
