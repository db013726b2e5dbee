// spec/distributed.md D9: the leaves a rank stuffs besides its own: the
// ghost layer (the stars of its tetrahedra's vertices) and the closure of
// S6's dependencies across the partition's boundary.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "bccmis/d3/detail/tetrahedra.h"
#include "bccmis/distributed/leaf_piece.h"

namespace bccmis::distributed {

namespace {

using PointHashSet = std::unordered_set<d3::Point, d3::PointHash>;

/// The leaf whose cube holds q, a point inside a level-L cube (odd
/// coordinates), or nothing outside the lattice's box.
std::optional<d3::Point> leaf_at(const d3::fast::Lattice& g, const d3::Point& q) {
  for (int axis = 0; axis < 3; ++axis)
    if (d3::detail::coord(q, axis) < 0 || d3::detail::coord(q, axis) >= d3::detail::extent(g.size(), axis))
      return std::nullopt;
  for (int l = g.size().L; l >= 0; --l) {
    const std::int64_t s = d3::cell_side(g.size(), l);
    const d3::Point c{q.x / s * s + s / 2, q.y / s * s + s / 2, q.z / s * s + s / 2};
    if (g.is_center(c)) return c;
  }
  return std::nullopt;
}

/// D9: star(x), the leaves with a lattice tetrahedron at vertex x
/// (spec/mesh3d.md M2-M4): for a center, its leaf and the leaves across
/// its equal faces; for a node, its neighbours (the leaves with x on their
/// boundary: M4 builds a leaf's tetrahedra from its neighbours, so N is
/// symmetric); for a hull point, the leaves whose closed cube holds it.
template <class Add>
void each_star_leaf(const d3::fast::Lattice& g, const d3::Point& x, Add&& add) {
  if (g.is_center(x)) {
    add(x);
    const std::int64_t s = d3::cell_side(g.size(), g.level_of(x));
    for (int axis = 0; axis < 3; ++axis)
      for (const std::int64_t step : {-s, s}) {
        d3::Point w = x;
        d3::detail::coord(w, axis) += step;
        if (g.is_center(w)) add(w);
      }
    return;
  }
  if (g.is_node(x)) {
    for (const d3::Point& u : g.nbr(x)) add(u);
    return;
  }
  for (const std::int64_t dx : {-1, 1})
    for (const std::int64_t dy : {-1, 1})
      for (const std::int64_t dz : {-1, 1})
        if (const auto u = leaf_at(g, {x.x + dx, x.y + dy, x.z + dz})) add(*u);
}

/// The own leaves and the ghosts, sorted (the order of cells(g)).
std::vector<d3::Point> sorted_union(std::span<const d3::Point> own, std::vector<d3::Point> ghosts) {
  ghosts.insert(ghosts.end(), own.begin(), own.end());
  std::sort(ghosts.begin(), ghosts.end());
  return ghosts;
}

}  // namespace

std::vector<d3::Point> leaves_to_stuff(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                                       const stuff::StuffOptions& options, std::span<const d3::Point> own,
                                       LayerDepth depth) {
  std::vector<d3::Point> mine(own.begin(), own.end());
  std::sort(mine.begin(), mine.end());
  const auto is_own = [&mine](const d3::Point& u) { return std::binary_search(mine.begin(), mine.end(), u); };
  PointHashSet stuffed(own.begin(), own.end());
  std::vector<d3::Point> ghosts;    // stuffed leaves that are not own, in order of discovery
  PointHashSet needed;              // D: the vertices whose S6 decision must be the serial one
  std::vector<d3::Point> frontier;  // vertices of D with a leaf that is not own in their star
  const auto need = [&](const d3::Point& x) {
    if (!needed.insert(x).second) return;
    bool beyond = false;
    each_star_leaf(g, x, [&](const d3::Point& u) {
      if (stuffed.insert(u).second) ghosts.push_back(u);
      beyond = beyond || !is_own(u);
    });
    if (beyond) frontier.push_back(x);
  };
  std::vector<d3::Tet> tets;
  // (a) D starts as the vertices of the own leaves' tetrahedra; their stars
  // are the ghost layer.
  if (depth == LayerDepth::none) return mine;
  for (const d3::Point& u : own) {
    tets.clear();
    d3::detail::leaf_tetrahedra(g, u, tets);
    for (const d3::Tet& t : tets)
      for (const d3::Point& x : t) need(x);
  }
  // (b) The closure: y < x joins D when x is in D and the cut point on xy
  // violates x (S5, S6), with star(y); until no vertex joins. An edge at x
  // lies in a tetrahedron of a leaf of star(x), and an edge of an own
  // leaf's tetrahedron has both ends in D: only the leaves of star(x) that
  // are not own hold edges to look at, and only at the frontier's vertices.
  std::unordered_map<d3::Point, int, d3::PointHash> sign;
  const auto side = [&](const d3::Point& p) {
    const auto [at, added] = sign.try_emplace(p, 0);
    if (added) at->second = shape.side(fit.to_space(p));
    return at->second;
  };
  const auto violated_by = [&](const d3::Point& x, const d3::Point& y) {
    const int sx = side(x), sy = side(y);
    if (!((sx < 0 && sy > 0) || (sx > 0 && sy < 0))) return false;
    const d3::Point& a = std::min(x, y);
    const d3::Point& b = std::max(x, y);
    const double t = std::clamp(shape.crossing(fit.to_space(a), fit.to_space(b)), 0.0, 1.0);
    const double from_x = x < y ? t : 1 - t;
    const bool same_kind = g.is_center(x) == g.is_center(y);
    return from_x < (same_kind ? options.alpha_long : options.alpha_short);
  };
  while (!frontier.empty()) {
    const d3::Point x = frontier.back();
    frontier.pop_back();
    std::vector<d3::Point> star;
    each_star_leaf(g, x, [&](const d3::Point& u) {
      if (!is_own(u)) star.push_back(u);
    });
    for (const d3::Point& u : star) {
      tets.clear();
      d3::detail::leaf_tetrahedra(g, u, tets);
      for (const d3::Tet& t : tets) {
        if (std::find(t.begin(), t.end(), x) == t.end()) continue;
        for (const d3::Point& y : t)
          if (y < x && !needed.contains(y) && violated_by(x, y)) need(y);
      }
    }
  }
  return sorted_union(mine, ghosts);
}

}  // namespace bccmis::distributed
