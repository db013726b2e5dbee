// The only translation unit of the 3D checker that includes CGAL: layer 6,
// CGAL's exact predicates, its tet-soup loader and its 3D Delaunay
// triangulation as a second referee of a tetrahedral mesh
// (spec/invariants.md, "3D layer 6").
#include "bccmis/invariants/cgal/d3/tetrahedralization_check.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace bccmis::d3 {

namespace {

using K = CGAL::Epeck;

// The loader (build_triangulation) is written for Mesh_3's triangulations: it
// sets a dimension on every vertex and subdomain and surface-patch indices on
// every cell. These bases accept and drop them, so the loaded triangulation
// is a plain Triangulation_3.
template <class GT, class Vb = CGAL::Triangulation_vertex_base_3<GT>>
struct SoupVertex : Vb {
  template <class TDS2>
  struct Rebind_TDS {
    using Vb2 = typename Vb::template Rebind_TDS<TDS2>::Other;
    using Other = SoupVertex<GT, Vb2>;
  };
  using Vb::Vb;
  void set_dimension(int) {}
};

template <class GT, class Cb = CGAL::Triangulation_cell_base_3<GT>>
struct SoupCell : Cb {
  using Surface_patch_index = int;
  using Subdomain_index = int;
  template <class TDS2>
  struct Rebind_TDS {
    using Cb2 = typename Cb::template Rebind_TDS<TDS2>::Other;
    using Other = SoupCell<GT, Cb2>;
  };
  using Cb::Cb;
  void set_subdomain_index(int) {}
  void set_surface_patch_index(int, int) {}
  int surface_patch_index(int) const { return 0; }
};

using SoupTds = CGAL::Triangulation_data_structure_3<SoupVertex<K>, SoupCell<K>>;
using Soup = CGAL::Triangulation_3<K, SoupTds>;

using DelaunayTds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<std::size_t, K>,
                                                         CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Delaunay = CGAL::Delaunay_triangulation_3<K, DelaunayTds>;

const char* const kSection = "spec/invariants.md 3D layer 6";

// An int64 as an exact number (doubles are exact up to 2^53).
K::FT exact(std::int64_t v) {
  if (v > -(std::int64_t{1} << 53) && v < (std::int64_t{1} << 53)) return K::FT(static_cast<double>(v));
  const std::int64_t hi = v >> 32;  // arithmetic shift: v = hi * 2^32 + lo
  const auto lo = static_cast<std::uint32_t>(v & 0xffffffff);
  return K::FT(static_cast<double>(hi)) * K::FT(4294967296.0) + K::FT(static_cast<double>(lo));
}

K::Point_3 point(const Point& p) { return {exact(p.x), exact(p.y), exact(p.z)}; }

Violation violation(std::string code, std::vector<Point> where, const std::string& text) {
  Violation v;
  v.code = std::move(code);
  v.where = std::move(where);
  v.message = v.code + ": " + text;
  v.section = kSection;
  v.layer = 6;
  return v;
}

std::string names(const Tet& t) {
  return to_string(t[0]) + ", " + to_string(t[1]) + ", " + to_string(t[2]) + ", " + to_string(t[3]);
}

std::optional<Violation> check_orientation(std::span<const Tet> tets) {
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tet& t = tets[i];
    const CGAL::Orientation o = CGAL::orientation(point(t[0]), point(t[1]), point(t[2]), point(t[3]));
    if (o != CGAL::POSITIVE)
      return violation("cgal-orientation", {t.begin(), t.end()},
                       "tet #" + std::to_string(i) + " (" + names(t) + ") is " +
                           (o == CGAL::NEGATIVE ? "negatively oriented" : "flat") + " by CGAL::orientation");
  }
  return std::nullopt;
}

std::optional<Violation> invalid(std::size_t count, const std::string& why) {
  return violation("cgal-invalid", {},
                   "the " + std::to_string(count) + " tets do not load into a valid CGAL Triangulation_3: " + why);
}

// Loads the tets into tr with CGAL's tet-soup loader (every temporary of the
// load freed on return). False when the loader refuses them; CGAL's
// assertions may throw CGAL::Failure_exception.
bool load(std::span<const Tet> tets, Soup& tr) {
  std::map<Point, int> index;
  for (const Tet& t : tets)
    for (const Point& p : t) index.emplace(p, 0);
  std::vector<K::Point_3> points;
  points.reserve(index.size());
  for (auto& [p, i] : index) {
    i = static_cast<int>(points.size());
    points.push_back(point(p));
  }
  std::vector<std::array<int, 5>> cells;  // 4 vertex indices and a subdomain
  cells.reserve(tets.size());
  for (const Tet& t : tets) cells.push_back({index.at(t[0]), index.at(t[1]), index.at(t[2]), index.at(t[3]), 1});
  std::vector<Soup::Vertex_handle> handles;
  const std::map<std::array<int, 3>, int> no_border_facets;
  // c3t3_loader_failed = true: build only; the validity checks follow.
  return CGAL::build_triangulation<Soup, true>(tr, points, cells, no_border_facets, handles);
}

// Loads the tets with CGAL's tet-soup loader and asks CGAL whether the result
// is a valid triangulation. Assumes every tet is positively oriented.
std::optional<Violation> check_loaded(std::span<const Tet> tets) {
  if (tets.empty()) return invalid(0, "no tets");
  Soup tr;
  // Builds with CGAL's assertions on throw where the others return false; the
  // stage names the failure alike in both.
  const char* stage = "the loader refused them (a triangle of three or more tets)";
  try {
    if (!load(tets, tr)) return invalid(tets.size(), stage);
    stage = "Triangulation_data_structure_3::is_valid fails";
    if (!tr.tds().is_valid()) return invalid(tets.size(), stage);
    stage = "Triangulation_3::is_valid fails";
    if (!tr.is_valid()) return invalid(tets.size(), stage);
  } catch (const CGAL::Failure_exception&) {
    return invalid(tets.size(), stage);
  }
  // Triangulation_3::is_valid ignores badly oriented cells in builds without
  // assertions: check them here.
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    if (CGAL::orientation(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(), c->vertex(3)->point()) !=
        CGAL::POSITIVE)
      return invalid(tets.size(), "a cell is not positively oriented");
  if (tr.number_of_finite_cells() != tets.size())
    return invalid(tets.size(), "it has " + std::to_string(tr.number_of_finite_cells()) + " finite cells");
  return std::nullopt;
}

// On a uniform lattice, every tet without a hull vertex is a cell of the
// Delaunay triangulation of N ∪ C.
std::optional<Violation> check_delaunay(const Graph& g, std::span<const Tet> tets) {
  if (g.level.empty()) return std::nullopt;
  const int level = g.level.begin()->second;
  for (const auto& [c, l] : g.level)
    if (l != level) return std::nullopt;  // graded: not Delaunay, nothing required
  std::vector<Point> vertices(g.N.begin(), g.N.end());
  vertices.insert(vertices.end(), g.C.begin(), g.C.end());
  std::vector<std::pair<K::Point_3, std::size_t>> input;
  input.reserve(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) input.emplace_back(point(vertices[i]), i);
  Delaunay dt(input.begin(), input.end());
  std::map<Point, Delaunay::Vertex_handle> handle;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) handle[vertices[v->info()]] = v;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tet& t = tets[i];
    std::array<Delaunay::Vertex_handle, 4> h;
    bool hull = false;
    for (std::size_t k = 0; k < 4; ++k) {
      const auto it = handle.find(t[k]);
      if (it == handle.end()) {
        hull = true;
        break;
      }
      h[k] = it->second;
    }
    if (hull) continue;
    Delaunay::Cell_handle cell;
    if (!dt.is_cell(h[0], h[1], h[2], h[3], cell))
      return violation("cgal-delaunay", {t.begin(), t.end()},
                       "tet #" + std::to_string(i) + " (" + names(t) +
                           ") has no hull vertex but is not a cell of CGAL's Delaunay triangulation of N ∪ C "
                           "on a uniform lattice");
  }
  return std::nullopt;
}

}  // namespace

std::optional<Violation> find_tetrahedralization_violation(const Graph& g, std::span<const Tet> tets) {
  if (auto v = check_orientation(tets)) return v;
  if (auto v = check_loaded(tets)) return v;
  return check_delaunay(g, tets);
}

std::optional<std::size_t> hold_triangulation(std::span<const Tet> tets, const std::function<void(std::size_t)>& held) {
  Soup tr;
  try {
    if (!load(tets, tr)) return std::nullopt;
  } catch (const CGAL::Failure_exception&) {
    return std::nullopt;
  }
  const std::size_t cells = tr.number_of_finite_cells();
  held(cells);
  return cells;
}

}  // namespace bccmis::d3
