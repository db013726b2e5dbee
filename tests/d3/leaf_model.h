// An independent model of the 3D lattice for the tests: a set of octree
// leaves (center -> level) and the graph spec/lattice3d.md §1 derives from
// it by geometry alone. Nothing here calls refine or coarsen or shares their
// code; it uses only the data types Point3 and LatticeSize3.
//
//   N     = every corner of every leaf cube
//   N(n)  = the leaves whose closed cube contains n: for each level and each
//           of the 8 octant directions at n, the cube of that level holding
//           the octant, if it is a leaf
//   N(c)  = the nodes n with c in N(n)
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bccmis/d3/graph.h"

namespace bccmis::d3::model {

using Leaves = std::map<Point3, int>;  // center -> level

struct Box {
  std::int64_t lo[3], hi[3];
};

inline std::int64_t side(const LatticeSize3& size, int level) { return std::int64_t{1} << (size.L + 1 - level); }

inline Box cube(const LatticeSize3& size, const Point3& c, int level) {
  const std::int64_t h = side(size, level) / 2;
  return {{c.x - h, c.y - h, c.z - h}, {c.x + h, c.y + h, c.z + h}};
}

inline std::int64_t coord(const Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

inline std::int64_t extent(const LatticeSize3& size, int axis) {
  const std::int64_t S = side(size, 0);
  return (axis == 0 ? size.W : axis == 1 ? size.H : size.D) * S;
}

/// The number of axes in which two closed boxes overlap with positive length,
/// or -1 if they are disjoint. For two leaves: 0 = corner contact,
/// 1 = an edge segment, 2 = a face patch.
inline int contact_dimension(const Box& a, const Box& b) {
  int dim = 0;
  for (int k = 0; k < 3; ++k) {
    const std::int64_t overlap = std::min(a.hi[k], b.hi[k]) - std::max(a.lo[k], b.lo[k]);
    if (overlap < 0) return -1;
    dim += overlap > 0;
  }
  return dim;
}

inline bool is_corner(const Box& b, const Point3& p) {
  for (int k = 0; k < 3; ++k)
    if (coord(p, k) != b.lo[k] && coord(p, k) != b.hi[k]) return false;
  return true;
}

/// How many coordinates of p lie strictly inside the domain.
inline int interior_coordinates(const LatticeSize3& size, const Point3& p) {
  int k = 0;
  for (int a = 0; a < 3; ++a) k += coord(p, a) > 0 && coord(p, a) < extent(size, a);
  return k;
}

struct GeometricGraph {
  std::set<Point3> N;
  std::map<Point3, std::set<Point3>> nbr;
};

/// The graph of spec/lattice3d.md §1 recomputed from the leaves.
inline GeometricGraph geometric_graph(const LatticeSize3& size, const Leaves& leaves) {
  GeometricGraph g;
  for (const auto& [c, l] : leaves) {
    const Box b = cube(size, c, l);
    for (int i = 0; i < 8; ++i)
      g.N.insert({(i & 4) ? b.hi[0] : b.lo[0], (i & 2) ? b.hi[1] : b.lo[1], (i & 1) ? b.hi[2] : b.lo[2]});
  }
  for (const Point3& n : g.N) {
    for (int l = 0; l <= size.L; ++l) {
      const std::int64_t s = side(size, l);
      for (int d = 0; d < 8; ++d) {
        std::int64_t center[3];
        bool inside = true;
        for (int k = 0; k < 3; ++k) {
          const bool up = (d >> k) & 1;
          const std::int64_t v = coord(n, k);
          // The index of the level-l cube holding n + eps in direction d.
          const std::int64_t index = up ? v / s : (v - 1 >= 0 ? (v - 1) / s : -1);
          if (index < 0 || (index + 1) * s > extent(size, k)) inside = false;
          center[k] = index * s + s / 2;
        }
        if (!inside) continue;
        const Point3 c{center[0], center[1], center[2]};
        auto it = leaves.find(c);
        if (it != leaves.end() && it->second == l) {
          g.nbr[n].insert(c);
          g.nbr[c].insert(n);
        }
      }
    }
  }
  return g;
}

/// Empty if the leaves tile the domain as octree leaves; else why not.
inline std::string tiling_problem(const LatticeSize3& size, const Leaves& leaves) {
  std::uint64_t volume = 0;  // in level-L cubes
  for (const auto& [c, l] : leaves) {
    if (l < 0 || l > size.L) return "leaf " + to_string(c) + " has level " + std::to_string(l);
    const std::int64_t s = side(size, l);
    for (int k = 0; k < 3; ++k) {
      const std::int64_t v = coord(c, k);
      if (v < s / 2 || v > extent(size, k) - s / 2 || (v - s / 2) % s != 0)
        return "leaf " + to_string(c) + " is not a level-" + std::to_string(l) + " center";
    }
    for (int a = 0; a < l; ++a) {  // no ancestor is a leaf too
      const std::int64_t t = side(size, a);
      const Point3 up{c.x / t * t + t / 2, c.y / t * t + t / 2, c.z / t * t + t / 2};
      auto it = leaves.find(up);
      if (it != leaves.end() && it->second == a) return "leaf " + to_string(c) + " lies inside leaf " + to_string(up);
    }
    const std::uint64_t edge = std::uint64_t{1} << (size.L - l);
    volume += edge * edge * edge;
  }
  const std::uint64_t cubes = static_cast<std::uint64_t>(size.W * size.H * size.D);
  if (volume != cubes << (3 * size.L)) return "the leaves do not cover the domain";
  return {};
}

/// Empty if face-or-edge neighbours differ by at most one level; else the pair.
inline std::string balance_problem(const LatticeSize3& size, const Leaves& leaves, const GeometricGraph& g) {
  for (const Point3& n : g.N) {
    const auto& cells = g.nbr.at(n);
    for (const Point3& a : cells)
      for (const Point3& b : cells) {
        const int la = leaves.at(a), lb = leaves.at(b);
        if (la - lb <= 1) continue;
        if (contact_dimension(cube(size, a, la), cube(size, b, lb)) >= 1)
          return to_string(a) + " (level " + std::to_string(la) + ") and " + to_string(b) + " (level " +
                 std::to_string(lb) + ") share an edge or face";
      }
  }
  return {};
}

/// Every octree leaf set of the lattice (balanced or not), by recursion over
/// the cubes: a cube is a leaf, or (below level L) the union of its 8
/// children's leaf sets.
inline std::vector<Leaves> all_leaf_sets(const LatticeSize3& size) {
  std::function<std::vector<Leaves>(const Point3&, int)> options = [&](const Point3& c, int l) {
    std::vector<Leaves> out{Leaves{{c, l}}};
    if (l == size.L) return out;
    const std::int64_t q = side(size, l) / 4;
    std::vector<Leaves> refined{Leaves{}};
    for (int i = 0; i < 8; ++i) {
      const Point3 child{c.x + ((i & 4) ? q : -q), c.y + ((i & 2) ? q : -q), c.z + ((i & 1) ? q : -q)};
      std::vector<Leaves> next;
      for (const Leaves& partial : refined)
        for (const Leaves& sub : options(child, l + 1)) {
          Leaves u = partial;
          u.insert(sub.begin(), sub.end());
          next.push_back(std::move(u));
        }
      refined = std::move(next);
    }
    out.insert(out.end(), refined.begin(), refined.end());
    return out;
  };
  const std::int64_t S = side(size, 0);
  std::vector<Leaves> sets{Leaves{}};
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t k = 0; k < size.D; ++k) {
        std::vector<Leaves> next;
        for (const Leaves& partial : sets)
          for (const Leaves& sub : options({i * S + S / 2, j * S + S / 2, k * S + S / 2}, 0)) {
            Leaves u = partial;
            u.insert(sub.begin(), sub.end());
            next.push_back(std::move(u));
          }
        sets = std::move(next);
      }
  return sets;
}

}  // namespace bccmis::d3::model
