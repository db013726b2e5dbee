// spec/distributed.md D9: the leaves a rank stuffs besides its own: the
// ghost layer (the stars of its tetrahedra's vertices) and the closure of
// S6's dependencies across the partition's boundary.
#include <algorithm>
#include <array>
#include <bit>
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

/// A set of lattice points: open addressing (linear probing, load at most
/// 1/2, no deletion), the lookups of D9's ghost layer (several per vertex
/// of every own tetrahedron) without a node per point.
class FlatPointSet {
 public:
  /// Room for `expected` points before the first growth.
  explicit FlatPointSet(std::size_t expected)
      : slots_(std::bit_ceil(std::max<std::size_t>(16, 2 * expected)), kEmpty) {}
  /// Adds p; true when it was not there.
  bool insert(const d3::Point& p) {
    std::size_t i = slot(p);
    if (slots_[i] == p) return false;
    if (2 * (used_ + 1) > slots_.size()) {
      std::vector<d3::Point> old = std::move(slots_);
      slots_.assign(2 * old.size(), kEmpty);
      for (const d3::Point& q : old)
        if (!(q == kEmpty)) slots_[slot(q)] = q;
      i = slot(p);
    }
    slots_[i] = p;
    ++used_;
    return true;
  }
  bool contains(const d3::Point& p) const { return slots_[slot(p)] == p; }

 private:
  /// Where p is, or the empty slot where it would go.
  std::size_t slot(const d3::Point& p) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = d3::PointHash{}(p)&mask;
    while (!(slots_[i] == kEmpty) && !(slots_[i] == p)) i = (i + 1) & mask;
    return i;
  }
  static constexpr d3::Point kEmpty{-1, -1, -1};  // no lattice point: coordinates are >= 0
  std::vector<d3::Point> slots_;
  std::size_t used_ = 0;
};

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

/// The own leaves and the ghosts (with repeats), sorted, each once (the
/// order of cells(g)).
std::vector<d3::Point> sorted_union(std::span<const d3::Point> own, std::vector<d3::Point> ghosts) {
  ghosts.insert(ghosts.end(), own.begin(), own.end());
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
  return ghosts;
}

}  // namespace

std::vector<d3::Point> leaves_to_stuff(const stuff::Shape& shape, const stuff::Fit& fit, const d3::fast::Lattice& g,
                                       const stuff::StuffOptions& options, std::span<const d3::Point> own,
                                       LayerDepth depth) {
  std::vector<d3::Point> mine(own.begin(), own.end());
  std::sort(mine.begin(), mine.end());
  if (depth == LayerDepth::none) return mine;
  FlatPointSet own_set(own.size());
  for (const d3::Point& u : own) own_set.insert(u);
  const auto is_own = [&own_set](const d3::Point& u) { return own_set.contains(u); };
  std::vector<d3::Tet> tets;
  // (a) D starts as the vertices of the own leaves' tetrahedra (`first`,
  // each once, however many tetrahedra share it); their stars are the
  // ghost layer. A leaf's tetrahedra have its center, the nodes on its
  // boundary (at most 26 apart from a finer neighbour's) and the centers
  // or hull points across its faces: a few vertices a leaf in all.
  std::vector<d3::Point> first;
  {
    FlatPointSet seen(4 * own.size());
    for (const d3::Point& u : mine) {
      tets.clear();
      d3::detail::leaf_tetrahedra(g, u, tets);
      for (const d3::Tet& t : tets)
        for (const d3::Point& x : t)
          if (seen.insert(x)) first.push_back(x);
    }
  }
  FlatPointSet first_set(first.size());
  for (const d3::Point& x : first) first_set.insert(x);
  PointHashSet later;               // D's vertices added by the closure
  std::vector<d3::Point> ghosts;    // stuffed leaves that are not own, repeats allowed
  std::vector<d3::Point> frontier;  // vertices of D with a leaf that is not own in their star
  const auto star_of = [&](const d3::Point& x) {
    bool beyond = false;
    each_star_leaf(g, x, [&](const d3::Point& u) {
      if (!is_own(u)) ghosts.push_back(u), beyond = true;
    });
    if (beyond) frontier.push_back(x);
  };
  for (const d3::Point& x : first) star_of(x);
  const auto in_d = [&](const d3::Point& y) { return first_set.contains(y) || later.contains(y); };
  // (b) The closure: y < x joins D when x is in D and the cut point on xy
  // violates x (S5, S6), with star(y); until no vertex joins. An edge at x
  // lies in a tetrahedron of a leaf of star(x), and an edge of an own
  // leaf's tetrahedron has both ends in D: only the leaves of star(x) that
  // are not own hold edges to look at, and only at the frontier's vertices.
  // A ghost's tetrahedra are extracted once (`extracted`: where they are in
  // `ghost_tets`), however many frontier vertices its star holds.
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
  std::unordered_map<d3::Point, std::array<std::size_t, 2>, d3::PointHash> extracted;
  std::vector<d3::Tet> ghost_tets;
  std::vector<d3::Point> star;
  while (!frontier.empty()) {
    const d3::Point x = frontier.back();
    frontier.pop_back();
    star.clear();
    each_star_leaf(g, x, [&](const d3::Point& u) {
      if (!is_own(u)) star.push_back(u);
    });
    for (const d3::Point& u : star) {
      const auto [at, added] = extracted.try_emplace(u, std::array<std::size_t, 2>{ghost_tets.size(), 0});
      if (added) {
        d3::detail::leaf_tetrahedra(g, u, ghost_tets);
        at->second[1] = ghost_tets.size();
      }
      for (std::size_t k = at->second[0]; k < at->second[1]; ++k) {
        const d3::Tet t = ghost_tets[k];
        if (std::find(t.begin(), t.end(), x) == t.end()) continue;
        for (const d3::Point& y : t)
          if (y < x && !in_d(y) && violated_by(x, y)) {
            later.insert(y);
            star_of(y);
          }
      }
    }
  }
  return sorted_union(mine, std::move(ghosts));
}

}  // namespace bccmis::distributed
