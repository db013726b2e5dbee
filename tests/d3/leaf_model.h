// An independent model of the 3D lattice for the tests: a set of octree
// leaves (center -> level) and the graph spec/lattice3d.md §1 derives from
// it by geometry alone. Nothing here calls refine or coarsen or shares their
// code; it uses only the data types Point and LatticeSize.
//
//   N     = every corner of every leaf cube
//   N(n)  = the leaves whose closed cube contains n: for each level and each
//           of the 8 octant directions at n, the cube of that level holding
//           the octant, if it is a leaf
//   N(c)  = the nodes n with c in N(n)
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bccmis/d3/graph.h"

namespace bccmis::d3::model {

using Leaves = std::map<Point, int>;  // center -> level

struct Box {
  std::int64_t lo[3], hi[3];
};

inline std::int64_t side(const LatticeSize& size, int level) { return std::int64_t{1} << (size.L + 1 - level); }

inline Box cube(const LatticeSize& size, const Point& c, int level) {
  const std::int64_t h = side(size, level) / 2;
  return {{c.x - h, c.y - h, c.z - h}, {c.x + h, c.y + h, c.z + h}};
}

inline std::int64_t coord(const Point& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

inline std::int64_t extent(const LatticeSize& size, int axis) {
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

inline bool is_corner(const Box& b, const Point& p) {
  for (int k = 0; k < 3; ++k)
    if (coord(p, k) != b.lo[k] && coord(p, k) != b.hi[k]) return false;
  return true;
}

/// How many coordinates of p lie strictly inside the domain.
inline int interior_coordinates(const LatticeSize& size, const Point& p) {
  int k = 0;
  for (int a = 0; a < 3; ++a) k += coord(p, a) > 0 && coord(p, a) < extent(size, a);
  return k;
}

struct GeometricGraph {
  std::set<Point> N;
  std::map<Point, std::set<Point>> nbr;
};

/// The graph of spec/lattice3d.md §1 recomputed from the leaves.
inline GeometricGraph geometric_graph(const LatticeSize& size, const Leaves& leaves) {
  GeometricGraph g;
  for (const auto& [c, l] : leaves) {
    const Box b = cube(size, c, l);
    for (int i = 0; i < 8; ++i)
      g.N.insert({(i & 4) ? b.hi[0] : b.lo[0], (i & 2) ? b.hi[1] : b.lo[1], (i & 1) ? b.hi[2] : b.lo[2]});
  }
  for (const Point& n : g.N) {
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
        const Point c{center[0], center[1], center[2]};
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
inline std::string tiling_problem(const LatticeSize& size, const Leaves& leaves) {
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
      const Point up{c.x / t * t + t / 2, c.y / t * t + t / 2, c.z / t * t + t / 2};
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
inline std::string balance_problem(const LatticeSize& size, const Leaves& leaves, const GeometricGraph& g) {
  for (const Point& n : g.N) {
    const auto& cells = g.nbr.at(n);
    for (const Point& a : cells)
      for (const Point& b : cells) {
        const int la = leaves.at(a), lb = leaves.at(b);
        if (la - lb <= 1) continue;
        if (contact_dimension(cube(size, a, la), cube(size, b, lb)) >= 1)
          return to_string(a) + " (level " + std::to_string(la) + ") and " + to_string(b) + " (level " +
                 std::to_string(lb) + ") share an edge or face";
      }
  }
  return {};
}

/// The 8 children (level l + 1) of the level-l cube centred at c.
inline std::array<Point, 8> children(const LatticeSize& size, const Point& c, int l) {
  const std::int64_t q = side(size, l) / 4;
  std::array<Point, 8> out;
  for (int i = 0; i < 8; ++i)
    out[static_cast<std::size_t>(i)] = {c.x + ((i & 4) ? q : -q), c.y + ((i & 2) ? q : -q), c.z + ((i & 1) ? q : -q)};
  return out;
}

/// Every leaf set of the level-l cube centred at c: the cube itself, or
/// (below level L) the union of its 8 children's leaf sets.
inline std::vector<Leaves> cube_leaf_sets(const LatticeSize& size, const Point& c, int l) {
  std::vector<Leaves> out{Leaves{{c, l}}};
  if (l == size.L) return out;
  std::vector<Leaves> refined{Leaves{}};
  for (const Point& child : children(size, c, l)) {
    std::vector<Leaves> next;
    for (const Leaves& partial : refined)
      for (const Leaves& sub : cube_leaf_sets(size, child, l + 1)) {
        Leaves u = partial;
        u.insert(sub.begin(), sub.end());
        next.push_back(std::move(u));
      }
    refined = std::move(next);
  }
  out.insert(out.end(), refined.begin(), refined.end());
  return out;
}

/// Calls fn on every octree leaf set of the lattice (balanced or not), one at
/// a time: every combination of one leaf set per level-0 cube.
inline void for_each_leaf_set(const LatticeSize& size, const std::function<void(const Leaves&)>& fn) {
  const std::int64_t S = side(size, 0);
  std::vector<std::vector<Leaves>> roots;
  for (std::int64_t i = 0; i < size.W; ++i)
    for (std::int64_t j = 0; j < size.H; ++j)
      for (std::int64_t k = 0; k < size.D; ++k)
        roots.push_back(cube_leaf_sets(size, {i * S + S / 2, j * S + S / 2, k * S + S / 2}, 0));
  Leaves current;
  std::function<void(std::size_t)> product = [&](std::size_t r) {
    if (r == roots.size()) return fn(current);
    for (const Leaves& sub : roots[r]) {
      current.insert(sub.begin(), sub.end());
      product(r + 1);
      for (const auto& [c, l] : sub) current.erase(c);
    }
  };
  product(0);
}

/// Every octree leaf set of the lattice (balanced or not).
inline std::vector<Leaves> all_leaf_sets(const LatticeSize& size) {
  std::vector<Leaves> sets;
  for_each_leaf_set(size, [&sets](const Leaves& leaves) { sets.push_back(leaves); });
  return sets;
}

/// Two leaves that break the 2:1 rule: levels two or more apart and in
/// contact along an edge segment or a face patch.
inline bool unbalanced_pair(const LatticeSize& size, const Point& a, int la, const Point& b, int lb) {
  return (la - lb > 1 || lb - la > 1) && contact_dimension(cube(size, a, la), cube(size, b, lb)) >= 1;
}

// ---- The operations, decided from the leaves alone ----------------------------
//
// refine(p) replaces the leaf p by its 8 children; coarsen(p) replaces the 8
// children of the cube centred at p by that cube. Each is refused, with the
// code of spec/formats.md, when its result would not be a balanced leaf set
// of the lattice; the codes are told apart in the order of spec/lattice3d.md
// §4 and §5.

/// "ok" or the refusal code of refine(p).
inline std::string refine_decision(const LatticeSize& size, const Leaves& leaves, const Point& p) {
  const auto it = leaves.find(p);
  if (it == leaves.end()) return "no-such-cell";
  const int l = it->second;
  if (l >= size.L) return "max-level";
  for (const Point& child : children(size, p, l))
    for (const auto& [o, lo] : leaves)
      if (o != p && unbalanced_pair(size, child, l + 1, o, lo)) return "coarser-neighbor";
  return "ok";
}

/// The level l < L of the cube centred at p, if p is the center of one.
inline std::optional<int> cube_level_at(const LatticeSize& size, const Point& p) {
  for (int l = 0; l < size.L; ++l) {
    const std::int64_t s = side(size, l);
    bool center = true;
    for (int k = 0; k < 3; ++k) {
      const std::int64_t v = coord(p, k);
      center = center && v >= s / 2 && v <= extent(size, k) - s / 2 && (v - s / 2) % s == 0;
    }
    if (center) return l;
  }
  return std::nullopt;
}

/// "ok" or the refusal code of coarsen(p).
inline std::string coarsen_decision(const LatticeSize& size, const Leaves& leaves, const Point& p) {
  bool corner = false;
  for (const auto& [c, l] : leaves) corner = corner || is_corner(cube(size, c, l), p);
  if (!corner) return "no-such-node";
  const std::optional<int> l = cube_level_at(size, p);
  if (!l) return "not-a-refined-center";
  const std::array<Point, 8> kids = children(size, p, *l);
  for (const Point& k : kids) {
    const auto it = leaves.find(k);
    if (it == leaves.end() || it->second != *l + 1) return "children-refined";
  }
  for (const auto& [o, lo] : leaves)
    if (std::find(kids.begin(), kids.end(), o) == kids.end() && unbalanced_pair(size, p, *l, o, lo))
      return "finer-neighbor";
  return "ok";
}

/// Applies refine(p), which refine_decision accepts.
inline void apply_refine(const LatticeSize& size, Leaves& leaves, const Point& p) {
  const int l = leaves.at(p);
  leaves.erase(p);
  for (const Point& child : children(size, p, l)) leaves[child] = l + 1;
}

/// Applies coarsen(p), which coarsen_decision accepts.
inline void apply_coarsen(const LatticeSize& size, Leaves& leaves, const Point& p) {
  const int l = *cube_level_at(size, p);
  for (const Point& child : children(size, p, l)) leaves.erase(child);
  leaves[p] = l;
}

}  // namespace bccmis::d3::model
