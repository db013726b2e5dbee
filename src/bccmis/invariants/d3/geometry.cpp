// 3D layer 4, lattice geometry (spec/lattice3d.md §1): levels and positions,
// the leaves tile the box, and each node's cells are exactly the leaves whose
// closed cube contains it.
//
// In this order:
//   level-range      0 <= level(c) <= L
//   outside-domain   every vertex lies in the closed box
//   center-position  a level-l center has all coordinates odd multiples of 2^(L-l)
//   overlap          no ancestor cube of a leaf is a leaf
//   coverage         the leaves' volumes sum to W*H*D*S^3
//   node-cells       N(n) = the leaves whose closed cube contains n
//
// Overlap and coverage use the octree the cells imply: the ancestors of every
// leaf (the refined cubes) are collected walking up until an ancestor already
// seen. The volume sum is exact without big integers: counts per level are
// carried upward, 8 level-(l+1) cubes into one level-l cube. node-cells is
// point location: for each level and each of the 8 octants at n inside the
// box, the cube of that level holding the octant, looked up in C.
#include <optional>
#include <set>
#include <vector>

#include "bccmis/invariants/d3/detail/lattice_geometry.h"

namespace bccmis::d3::inv {

namespace {

bool odd_multiple(std::int64_t v, std::int64_t h) { return v % h == 0 && (v / h) % 2 != 0; }

// The center of the level-k cube containing the (inside, positive) point p.
Point ancestor(const Box& box, const Point& p, int k) {
  const std::int64_t h = box.half(k), s = 2 * h;
  return {p.x / s * s + h, p.y / s * s + h, p.z / s * s + h};
}

}  // namespace

std::optional<Violation> check_geometry(const Graph& g) {
  constexpr int layer = 4;
  const Box box(g.size);
  const int L = g.size.L;

  for (const Point& c : g.C) {
    const int l = g.level.at(c);
    if (l < 0 || l > L)
      return violation(layer, "level-range", {c},
                       "center " + pos(c) + " has level " + std::to_string(l) + ", outside 0.." + std::to_string(L),
                       "§1");
  }

  // After layer 1 the keys of the neighbour map are exactly N ∪ C, sorted.
  for (const auto& [v, nbrs] : g.neighbors)
    if (!box.contains(v))
      return violation(layer, "outside-domain", {v},
                       std::string(g.C.count(v) ? "center " : "node ") + pos(v) + " lies outside the box [0, " +
                           std::to_string(box.extent[0]) + "] x [0, " + std::to_string(box.extent[1]) + "] x [0, " +
                           std::to_string(box.extent[2]) + "]",
                       "§1");

  for (const Point& c : g.C) {
    const int l = g.level.at(c);
    const std::int64_t h = box.half(l);
    if (odd_multiple(c.x, h) && odd_multiple(c.y, h) && odd_multiple(c.z, h)) continue;
    const std::optional<int> implied = box.center_level(c);
    std::string text = "center " + pos(c) + " has level " + std::to_string(l) + " but ";
    if (implied)
      text += "its position is the center of a level-" + std::to_string(*implied) + " cube";
    else
      text += "is not the center of any cube: a level-" + std::to_string(l) +
              " center has all three coordinates odd multiples of " + std::to_string(h);
    return violation(layer, "center-position", {c}, text, "§1");
  }

  // overlap: collect the refined cubes (ancestors of leaves).
  std::set<Point> refined;
  for (const Point& c : g.C) {
    const int l = g.level.at(c);
    for (int k = l - 1; k >= 0; --k) {
      const Point a = ancestor(box, c, k);
      if (g.C.count(a))
        return violation(layer, "overlap", {a, c},
                         "the level-" + std::to_string(l) + " cube " + cube_text(c, box.half(l)) + " of center " +
                             pos(c) + " lies inside the level-" + std::to_string(k) + " cube " +
                             cube_text(a, box.half(k)) + " of center " + pos(a),
                         "§1");
      if (!refined.insert(a).second) break;  // a and its ancestors were walked already
    }
  }

  // coverage: the volume in level-0 cubes, carrying 8 level-(l+1) cubes into
  // one level-l cube (no overflow: the counts are at most |C|).
  {
    std::vector<std::int64_t> count(static_cast<std::size_t>(L) + 1, 0);
    for (const Point& c : g.C) ++count[static_cast<std::size_t>(g.level.at(c))];
    bool whole = true;
    std::int64_t carry = 0;
    for (int l = L; l >= 1; --l) {
      const std::int64_t t = count[static_cast<std::size_t>(l)] + carry;
      if (t % 8 != 0) whole = false;
      carry = t / 8;
    }
    std::int64_t wh = 0, cubes = 0;
    const bool fits = !__builtin_mul_overflow(g.size.W, g.size.H, &wh) && !__builtin_mul_overflow(wh, g.size.D, &cubes);
    if (!(whole && fits && count[0] + carry == cubes)) {
      const std::string sum = "the leaves' volumes do not sum to the box's W*H*D*S^3 (" + std::to_string(g.size.W) +
                              "*" + std::to_string(g.size.H) + "*" + std::to_string(g.size.D) + " level-0 cubes)";
      auto gap = [&](const Point& p, int k) {
        return violation(layer, "coverage", {p},
                         sum + ": the level-" + std::to_string(k) + " cube " + cube_text(p, box.half(k)) +
                             " centered at " + pos(p) + " contains no leaf",
                         "§1");
      };
      for (const Point& r : refined) {
        const int k = *box.center_level(r);
        const std::int64_t q = box.half(k + 1);
        for (int i = 0; i < 8; ++i) {
          const Point child{r.x + ((i & 4) ? q : -q), r.y + ((i & 2) ? q : -q), r.z + ((i & 1) ? q : -q)};
          if (!g.C.count(child) && !refined.count(child)) return gap(child, k + 1);
        }
      }
      // Every level-0 cube present is a leaf or refined, so a missing one
      // turns up within |C| + |refined| + 1 steps even on a huge lattice.
      const std::int64_t h0 = box.half(0);
      std::size_t budget = g.C.size() + refined.size() + 1;
      for (std::int64_t i = 0; i < g.size.W && budget > 0; ++i)
        for (std::int64_t j = 0; j < g.size.H && budget > 0; ++j)
          for (std::int64_t k = 0; k < g.size.D && budget > 0; ++k, --budget) {
            const Point p{(2 * i + 1) * h0, (2 * j + 1) * h0, (2 * k + 1) * h0};
            if (!g.C.count(p) && !refined.count(p)) return gap(p, 0);
          }
      return violation(layer, "coverage", {}, sum, "§1");  // unreachable when no overlap
    }
  }

  // node-cells: point location at every level.
  for (const Point& n : g.N) {
    PointSet cells;
    for (int l = 0; l <= L; ++l) {
      const std::int64_t h = box.half(l), s = 2 * h;
      for (int d = 0; d < 8; ++d) {
        std::array<std::int64_t, 3> center{};
        bool inside = true;
        for (int a = 0; a < 3 && inside; ++a) {
          const std::int64_t v = coord(n, a);
          if ((d >> a) & 1) {  // the octant above n along axis a
            inside = v < box.extent[static_cast<std::size_t>(a)];
            center[static_cast<std::size_t>(a)] = v / s * s + h;
          } else {
            inside = v > 0;
            center[static_cast<std::size_t>(a)] = (v - 1) / s * s + h;
          }
        }
        if (!inside) continue;
        const Point c = make_point(center);
        const auto it = g.level.find(c);
        if (it != g.level.end() && it->second == l) cells.insert(c);
      }
    }
    const PointSet& listed = g.nbr(n);
    if (cells == listed) continue;
    for (const Point& c : cells)
      if (!listed.count(c))
        return violation(layer, "node-cells", {n, c},
                         "node " + pos(n) + " lies on the closed cube of the leaf " + pos(c) + " but does not list it",
                         "§1");
    for (const Point& c : listed)
      if (!cells.count(c))
        return violation(layer, "node-cells", {n, c},
                         "node " + pos(n) + " lists " + pos(c) + ", whose closed cube does not contain it", "§1");
  }
  return std::nullopt;
}

}  // namespace bccmis::d3::inv
