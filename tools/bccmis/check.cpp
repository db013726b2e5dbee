// bccmis check STATE: the checker on a canonical state of either dimension;
// and the helpers every
// subcommand that checks shares.
#include <iostream>
#include <map>

#include "bccmis/d3/mesh.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/invariants/d3/invariants.h"
#include "commands.h"
#include "io.h"
#if BCCMIS_HAVE_TRIANGULATION_CHECK
#include "bccmis/invariants/cgal/d3/tetrahedralization_check.h"
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

std::optional<std::string> check_message(const Graph& g, int depth) {
  if (auto v = check_graph(g, depth)) return to_string(*v);
  return std::nullopt;
}

std::optional<std::string> check_message(const fast::Lattice& g, int depth) {
  Graph copy;
  return check_message(as_graph(g, copy), depth);
}

std::optional<std::string> check_message(const d3::Graph& g, int depth) {
  if (auto v = d3::find_violation(g, depth < 5 ? depth : 4)) return to_string(*v);
  if (depth < 5) return std::nullopt;
  const std::vector<d3::Tet> tets = d3::tetrahedra(g);
  if (auto v = d3::check_mesh(g, tets)) return to_string(*v);
#if BCCMIS_HAVE_TRIANGULATION_CHECK
  if (auto v = d3::find_tetrahedralization_violation(g, tets)) return to_string(*v);
#endif
  return std::nullopt;
}

std::optional<std::string> check_message(const d3::fast::Lattice& g, int depth) {
  return check_message(g.to_graph(), depth);
}

namespace {

template <class G>
std::string levels_summary(const G& g) {
  std::map<int, std::size_t> per_level;
  for (const auto& [c, l] : g.level) ++per_level[l];
  return summary(per_level, g.N.size());
}

}  // namespace

std::string summary(const Graph& g) { return levels_summary(g); }
std::string summary(const d3::Graph& g) { return levels_summary(g); }
std::string summary(const d3::fast::Lattice& g) {
  std::map<int, std::size_t> per_level;
  for (const d3::Point& c : g.cells()) ++per_level[g.level_of(c)];
  return summary(per_level, g.node_count());
}
std::string summary(const fast::Lattice& g) {
  std::map<int, std::size_t> per_level;
  g.for_each_cell([&](const Point&, int level) { ++per_level[level]; });
  return summary(per_level, g.node_count());
}

int run(const CheckOptions& o) {
  const std::string name = display_name(o.state);
  return std::visit(
      [&](const auto& g) {
        if (auto v = check_message(g, o.depth)) {
          std::cerr << "bccmis check: " << name << ": " << *v << "\n";
          return int{kExitViolation};
        }
        if (!o.quiet) std::cout << name << ": valid (depth " << o.depth << "): " << summary(g) << "\n";
        return int{kExitOk};
      },
      read_any_state(o.state));
}

}  // namespace bccmis::cli
