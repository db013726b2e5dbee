// 3D layer 3, grading (spec/lattice3d.md §2): face-or-edge neighbours differ
// by at most one level.
//
//   grading  |N(a) ∩ N(b)| >= 2 implies |level(a) - level(b)| <= 1      §2
//
// Face-or-edge neighbours are read from the graph, as §2 reads eq. (3): two
// cells are neighbours iff they share at least two nodes (after layer 2, iff
// their closed cubes meet in an edge segment or a face patch). For each cell
// a in sorted order, the cells of its nodes are counted; the first neighbour
// b (in sorted order) whose stored level is too far from a's is reported.
// O(|C| * 26 * 8 * log).
#include <cstdlib>
#include <map>
#include <optional>

#include "bccmis/invariants/d3/detail/lattice_geometry.h"

namespace bccmis::d3::inv {

std::optional<Violation> check_grading(const Graph& g) {
  constexpr int layer = 3;
  for (const Point& a : g.C) {
    const int la = g.level.at(a);
    std::map<Point, int> shared;  // cell -> number of a's nodes it lists
    for (const Point& n : g.nbr(a))
      for (const Point& b : g.nbr(n))
        if (b != a) ++shared[b];
    for (const auto& [b, count] : shared) {
      if (count < 2) continue;
      const int lb = g.level.at(b);
      if (std::abs(static_cast<long long>(la) - lb) > 1)
        return violation(layer, "grading", {a, b},
                         "cells " + pos(a) + " (level " + std::to_string(la) + ") and " + pos(b) + " (level " +
                             std::to_string(lb) + ") share " + std::to_string(count) +
                             " nodes (an edge segment or a face patch) but differ by more than one level",
                         "§2");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::d3::inv
