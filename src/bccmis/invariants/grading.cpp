// Layer 3, grading (Erleben 2009, §1 ¶8 and the level test of §2.1):
//   grading   two cells that share a side differ in level by at most 1.
//
// "Share a side" is taken from the graph, as the paper's eq. (3) does: cells a
// and b are edge neighbors iff they have at least two boundary nodes in
// common, |𝒩(a) ∩ 𝒩(b)| >= 2. After layer 2 this is exactly geometric edge
// adjacency (spec/invariants.md): same-level neighbors share two corners, a
// coarse cell and a finer neighbor share a corner and the junction, and cells
// that touch only at a corner share one node. So cells meeting only at a
// corner may differ by 2 levels (never more); that is allowed.
//
// The levels read are the stored ones, which the operations' level test uses;
// layer 4 checks that they agree with the positions.
#include <algorithm>
#include <utility>
#include <vector>

#include "bccmis/invariants/detail/lattice_geometry.h"
#include "bccmis/invariants/detail/layers.h"

namespace bccmis::inv {

std::optional<Violation> check_grading(const Graph& g) {
  constexpr int layer = 3;
  for (const Point& a : g.C) {
    // cell b -> |𝒩(a) ∩ 𝒩(b)|; at most 8 nodes with at most 4 cells each
    // after layer 2, so a small flat table.
    std::vector<std::pair<Point, int>> shared;
    shared.reserve(32);
    for (const Point& n : g.nbr(a))
      for (const Point& b : g.nbr(n)) {
        if (b == a) continue;
        auto it = std::find_if(shared.begin(), shared.end(), [&b](const auto& e) { return e.first == b; });
        if (it == shared.end())
          shared.emplace_back(b, 1);
        else
          ++it->second;
      }
    std::sort(shared.begin(), shared.end());
    const int la = g.level.at(a);
    for (const auto& [b, count] : shared) {
      if (count < 2) continue;
      const int lb = g.level.at(b);
      const long long diff = static_cast<long long>(la) - lb;
      if (diff > 1 || diff < -1)
        return violation(layer, "grading", {a, b},
                         "cells " + pos(a) + " (level " + std::to_string(la) + ") and " + pos(b) + " (level " +
                             std::to_string(lb) + ") share a side but differ by " +
                             std::to_string(diff < 0 ? -diff : diff) + " levels; edge neighbors differ by at most 1",
                         "§1 ¶8");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::inv
