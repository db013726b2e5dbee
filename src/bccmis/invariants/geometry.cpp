// Layer 4, lattice geometry (Erleben 2009, §1: nodes of a Cartesian grid plus
// cell centers; refinement replaces a cell by four cells of half size).
//
// In this order:
//   level-range     0 <= level(c) <= L                                        §1 ¶8
//   outside-domain  every vertex lies in [0, W*S] x [0, H*S]                   §1
//   center-position a level-l center has both coordinates odd multiples of
//                   2^(L-l), i.e. it is the center of a level-l cell            §1 ¶7
//   overlap         no cell lies inside another cell                           §1 ¶7
//   coverage        the cells' areas sum to W*H*S^2, so (with no overlap)
//                   they tile the domain                                       §1 ¶7
// Centers lying at the middle of their 4 corners and junctions lying at side
// midpoints are part of layer 2, which derives each square from its center.
//
// Overlap and coverage use the quadtree the cells imply, in O(|C| log |C|):
// the ancestors of every cell (the refined cells) are collected walking up
// until an ancestor already seen; no cell may be an ancestor of another, and
// every child of a refined cell and every level-0 cell must be a cell or
// refined.
#include <optional>
#include <set>
#include <vector>

#include "bccmis/invariants/detail/lattice_geometry.h"
#include "bccmis/invariants/detail/layers.h"

namespace bccmis::inv {

namespace {

bool odd_multiple(std::int64_t v, std::int64_t h) { return v % h == 0 && (v / h) % 2 != 0; }

// The center of the level-k cell containing the (inside, positive) point p.
Point ancestor(const Domain& d, const Point& p, int k) {
  const std::int64_t h = d.half(k), s = 2 * h;
  return {p.x / s * s + h, p.y / s * s + h};
}

}  // namespace

std::optional<Violation> check_geometry(const Graph& g) {
  constexpr int layer = 4;
  const Domain domain(g.size);
  const int L = g.size.L;

  for (const Point& c : g.C) {
    const int l = g.level.at(c);
    if (l < 0 || l > L)
      return violation(layer, "level-range", {c},
                       "center " + pos(c) + " has level " + std::to_string(l) + ", outside 0.." + std::to_string(L) +
                           " (L = " + std::to_string(L) + ")",
                       "§1 ¶8");
  }

  // After layer 1 the keys of the neighbor map are exactly N ∪ C, sorted.
  for (const auto& [v, nbrs] : g.neighbors)
    if (!domain.contains(v))
      return violation(layer, "outside-domain", {v},
                       std::string(g.C.count(v) ? "center " : "node ") + pos(v) + " lies outside the domain [0, " +
                           std::to_string(domain.width) + "] x [0, " + std::to_string(domain.height) + "]",
                       "§1");

  for (const Point& c : g.C) {
    const int l = g.level.at(c);
    const std::int64_t h = domain.half(l);
    if (odd_multiple(c.x, h) && odd_multiple(c.y, h)) continue;
    const std::optional<int> implied = domain.center_level(c);
    std::string text = "center " + pos(c) + " has level " + std::to_string(l) + " but ";
    if (implied)
      text += "its position is the center of a level-" + std::to_string(*implied) + " cell";
    else
      text += "is not the center of any cell: a level-" + std::to_string(l) +
              " center has both coordinates odd multiples of " + std::to_string(h);
    return violation(layer, "center-position", {c}, text, "§1 ¶7");
  }

  // overlap: collect the refined cells (ancestors of cells).
  std::set<Point> refined;
  for (const Point& c : g.C) {
    for (int k = g.level.at(c) - 1; k >= 0; --k) {
      const Point a = ancestor(domain, c, k);
      if (g.C.count(a))
        return violation(layer, "overlap", {a, c},
                         "the level-" + std::to_string(g.level.at(c)) + " cell " +
                             square(c, domain.half(g.level.at(c))) + " of center " + pos(c) +
                             " lies inside the level-" + std::to_string(k) + " cell " + square(a, domain.half(k)) +
                             " of center " + pos(a),
                         "§1 ¶7");
      if (!refined.insert(a).second) break;  // a and its ancestors were walked already
    }
  }

  // coverage: sum of areas, in level-0 cells, by carrying 4 level-(l+1)
  // areas into one level-l area (no overflow: counts are at most |C|).
  std::vector<std::int64_t> count(static_cast<std::size_t>(L) + 1, 0);
  for (const Point& c : g.C) ++count[static_cast<std::size_t>(g.level.at(c))];
  bool whole = true;
  std::int64_t carry = 0;
  for (int l = L; l >= 1; --l) {
    const std::int64_t t = count[static_cast<std::size_t>(l)] + carry;
    if (t % 4 != 0) whole = false;
    carry = t / 4;
  }
  std::int64_t domain_cells = 0;
  const bool fits = !__builtin_mul_overflow(g.size.W, g.size.H, &domain_cells);
  if (whole && fits && count[0] + carry == domain_cells) return std::nullopt;

  // The areas differ; with no overlap some square is covered by no cell.
  const std::string sum = "the cells' areas do not sum to the domain's W*H*S^2 (" + std::to_string(g.size.W) + "*" +
                          std::to_string(g.size.H) + " level-0 cells)";
  auto gap = [&](const Point& p, int k) {
    return violation(layer, "coverage", {p},
                     sum + ": the level-" + std::to_string(k) + " square " + square(p, domain.half(k)) +
                         " centered at " + pos(p) + " contains no cell",
                     "§1 ¶7");
  };
  for (const Point& r : refined) {
    const int k = *domain.center_level(r);
    const std::int64_t q = domain.half(k + 1);
    for (const Point child :
         {Point{r.x - q, r.y - q}, Point{r.x - q, r.y + q}, Point{r.x + q, r.y - q}, Point{r.x + q, r.y + q}})
      if (!g.C.count(child) && !refined.count(child)) return gap(child, k + 1);
  }
  // Every present level-0 cell is a cell or refined, so a missing one turns up
  // within |C| + |refined| + 1 steps even on a huge lattice.
  const std::int64_t h0 = domain.half(0);
  std::size_t budget = g.C.size() + refined.size() + 1;
  for (std::int64_t i = 0; i < g.size.W && budget > 0; ++i)
    for (std::int64_t j = 0; j < g.size.H && budget > 0; ++j, --budget) {
      const Point p{(2 * i + 1) * h0, (2 * j + 1) * h0};
      if (!g.C.count(p) && !refined.count(p)) return gap(p, 0);
    }
  return violation(layer, "coverage", {}, sum, "§1 ¶7");  // unreachable when no overlap
}

}  // namespace bccmis::inv
