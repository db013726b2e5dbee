// Shared by the 3D cascade tests (tests/d3/balance_test.cpp and the p8est
// differential): random refinement targets, their application through
// refine_balanced, and an independent geometric closure on octree cubes that
// says which leaf set a set of targets must reach.
//
// The closure works on cubes (center, level) alone and never builds a graph:
// a target (p, l) splits the cubes of levels 0..l-1 holding p; a split cube
// q of level k forces its parent (k > 0) and, for every same-level cube q'
// meeting q across a face or an edge (corner mode: at a corner point too),
// the parent of q' (q's children, of level k+1, meet q' there, so the leaf
// covering q' must have level k or more). The leaves are the children of
// split cubes that are not split, and the level-0 cubes that are not split.
#pragma once

#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/balance.h"
#include "bccmis/d3/graph.h"
#include "bccmis/d3/lattice.h"

namespace bccmis::d3::cascade_model {

/// A target: the leaf containing `point` must reach at least `level`.
struct Target {
  Point point;  ///< strictly inside a level-L cube: odd coordinates
  int level = 0;
};

inline std::string describe(const LatticeSize& size, const std::vector<Target>& targets) {
  std::string s = "lattice " + std::to_string(size.W) + " " + std::to_string(size.H) + " " + std::to_string(size.D) +
                  " " + std::to_string(size.L) + "; targets (x y z level):";
  for (const Target& t : targets)
    s += " (" + std::to_string(t.point.x) + " " + std::to_string(t.point.y) + " " + std::to_string(t.point.z) + " " +
         std::to_string(t.level) + ")";
  return s;
}

inline std::vector<Target> random_targets(const LatticeSize& size, std::mt19937_64& rng, int count) {
  const std::int64_t S = level0_side(size);
  auto odd = [&](std::int64_t n) { return 2 * std::uniform_int_distribution<std::int64_t>(0, n * S / 2 - 1)(rng) + 1; };
  std::vector<Target> out;
  for (int k = 0; k < count; ++k) {
    const std::int64_t x = odd(size.W), y = odd(size.H), z = odd(size.D);
    out.push_back({{x, y, z}, std::uniform_int_distribution<int>(1, size.L)(rng)});
  }
  return out;
}

/// The center of the level-l cube containing p (p strictly inside a level-L cube).
inline Point cube_at(const LatticeSize& size, const Point& p, int l) {
  const std::int64_t s = cell_side(size, l);
  return {(p.x / s) * s + s / 2, (p.y / s) * s + s / 2, (p.z / s) * s + s / 2};
}

/// bccmis: refine_balanced the leaf containing each target until it reaches
/// the target level, targets in the given order. Adds the number of cells the
/// cascades refined besides the requested ones to `*extra` when given.
inline Graph refine_targets(const LatticeSize& size, const std::vector<Target>& targets, Balance b,
                            std::size_t* extra = nullptr) {
  Graph g(size);
  for (const Target& t : targets)
    for (int l = 0; l < t.level; ++l) {
      const Point c = cube_at(size, t.point, l);
      if (!g.is_center(c)) continue;
      const BalancedRefineResult r = refine_balanced(g, c, b);
      if (!r.applied()) throw std::logic_error("refine_balanced refused " + to_string(c));
      if (extra) *extra += r.refined.size() - 1;
    }
  return g;
}

/// The leaves (center -> level) the closure of the targets reaches.
inline std::map<Point, int> closure_leaves(const LatticeSize& size, const std::vector<Target>& targets, Balance b) {
  using Cube = std::pair<int, Point>;  // level, center
  const std::int64_t S = level0_side(size);
  const std::int64_t extent[3] = {size.W * S, size.H * S, size.D * S};
  std::set<Cube> split;
  std::vector<Cube> work;
  auto add = [&](const Cube& q) {
    if (split.insert(q).second) work.push_back(q);
  };
  for (const Target& t : targets)
    for (int l = 0; l < t.level; ++l) add({l, cube_at(size, t.point, l)});
  while (!work.empty()) {
    const auto [k, c] = work.back();
    work.pop_back();
    if (k == 0) continue;  // level-0 cubes have no parent to force
    const std::int64_t s = cell_side(size, k);
    add({k - 1, cube_at(size, c, k - 1)});
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const int moved = (dx != 0) + (dy != 0) + (dz != 0);
          if (moved == 0 || (moved == 3 && b == Balance::Edge)) continue;
          const Point n{c.x + dx * s, c.y + dy * s, c.z + dz * s};
          if (n.x <= 0 || n.y <= 0 || n.z <= 0 || n.x >= extent[0] || n.y >= extent[1] || n.z >= extent[2]) continue;
          add({k - 1, cube_at(size, n, k - 1)});
        }
  }
  std::map<Point, int> leaves;
  auto emit = [&](const Point& c, int l) {
    if (!split.count({l, c})) leaves[c] = l;
  };
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t k = 0; k < size.D; ++k) emit({i * S + S / 2, j * S + S / 2, k * S + S / 2}, 0);
  for (const auto& [l, c] : split) {
    const std::int64_t q = cell_side(size, l) / 4;
    for (int i = 0; i < 8; ++i)
      emit({c.x + ((i & 4) ? q : -q), c.y + ((i & 2) ? q : -q), c.z + ((i & 1) ? q : -q)}, l + 1);
  }
  return leaves;
}

}  // namespace bccmis::d3::cascade_model
