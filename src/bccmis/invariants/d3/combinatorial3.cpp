// 3D layer 1, combinatorial (spec/lattice3d.md §1): N and C and the neighbour
// sets form a symmetric bipartite graph over existing vertices, and exactly
// the centers carry a level.
//
// Each check finds its first offender in sorted order, by merge walks over
// the sorted sets and one pass over the edges (O(size log size)); the first
// failing check in this order is reported:
//   lattice-size       W, H, D >= 1; 0 <= L <= 61; W*S, H*S, D*S <= 2^62
//   partition          N ∩ C = ∅
//   neighbor-entry     every v in N ∪ C has an entry in the neighbour map
//   stale-entry        no entry for a position that is not a vertex
//   dangling-neighbor  every listed neighbour is a vertex
//   bipartite          nodes list only centers, centers only nodes
//   symmetry           w ∈ N(v) ⇔ v ∈ N(w)
//   empty-neighbors    no vertex has an empty neighbour set
//   missing-level      every center has a level
//   stray-level        only centers have a level
#include <optional>

#include "bccmis/invariants/d3/lattice3.h"

namespace bccmis::d3::inv3 {

namespace {

const char* kind(bool center) { return center ? "center" : "node"; }

}  // namespace

std::optional<Violation3> check_lattice_size(const LatticeSize3& s) {
  const std::string text = "lattice " + std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.D) +
                           " " + std::to_string(s.L) + " is out of range: ";
  if (s.W < 1 || s.H < 1 || s.D < 1) return violation(1, "lattice-size", {}, text + "W, H and D must be >= 1", "§1");
  if (s.L < 0 || s.L > 61) return violation(1, "lattice-size", {}, text + "L must be in 0..61", "§1");
  const std::int64_t max_cubes = (std::int64_t{1} << 62) >> (s.L + 1);  // W*S <= 2^62
  if (s.W > max_cubes || s.H > max_cubes || s.D > max_cubes)
    return violation(1, "lattice-size", {}, text + "an extent W*2^(L+1), H*2^(L+1) or D*2^(L+1) exceeds 2^62", "§1");
  return std::nullopt;
}

std::optional<Violation3> check_combinatorial(const Graph3& g) {
  constexpr int layer = 1;
  if (auto v = check_lattice_size(g.size)) return v;

  // partition: N ∩ C = ∅ ("a position is never a node and a center at the
  // same time"), by a merge walk.
  {
    auto c = g.C.begin();
    for (const Point3& v : g.N) {
      while (c != g.C.end() && *c < v) ++c;
      if (c != g.C.end() && *c == v)
        return violation(layer, "partition", {v}, pos(v) + " is both a node and a center", "§1");
    }
  }

  // neighbor-entry: every vertex has a neighbour set; centers first.
  for (const bool centers : {true, false}) {
    const PointSet3& set = centers ? g.C : g.N;
    auto e = g.neighbors.begin();
    for (const Point3& v : set) {
      while (e != g.neighbors.end() && e->first < v) ++e;
      if (e == g.neighbors.end() || e->first != v)
        return violation(
            layer, "neighbor-entry", {v},
            std::string(kind(centers)) + " " + pos(v) + " has no neighbor set (no entry in the neighbor map)", "§1");
    }
  }

  // stale-entry: after this and neighbor-entry the keys of the map are
  // exactly N ∪ C.
  {
    auto n = g.N.begin();
    auto c = g.C.begin();
    for (const auto& [v, nbrs] : g.neighbors) {
      while (n != g.N.end() && *n < v) ++n;
      while (c != g.C.end() && *c < v) ++c;
      if ((n == g.N.end() || *n != v) && (c == g.C.end() || *c != v))
        return violation(layer, "stale-entry", {v},
                         pos(v) + " has a neighbor set of " + std::to_string(nbrs.size()) +
                             " but is neither a node nor a center (a deleted vertex left behind?)",
                         "§1");
    }
  }

  // One pass over the edges: the first dangling neighbour is reported at
  // once; the first bipartite, symmetry and empty-set offenders are kept and
  // reported in that order.
  std::optional<Violation3> bipartite, symmetry, empty;
  {
    auto c = g.C.begin();
    for (const auto& [v, nbrs] : g.neighbors) {
      while (c != g.C.end() && *c < v) ++c;
      const bool v_center = c != g.C.end() && *c == v;
      const std::string k = kind(v_center);
      if (nbrs.empty() && !empty)
        empty = violation(layer, "empty-neighbors", {v}, k + " " + pos(v) + " has an empty neighbor set", "§1");
      for (const Point3& w : nbrs) {
        const auto entry = g.neighbors.find(w);
        if (entry == g.neighbors.end())
          return violation(layer, "dangling-neighbor", {v, w},
                           k + " " + pos(v) + " lists " + pos(w) + ", which is neither a node nor a center", "§1");
        if (bipartite && symmetry) continue;  // only danglings can still matter
        const bool w_center = g.C.count(w) != 0;
        if (w_center == v_center) {
          if (!bipartite)
            bipartite = violation(layer, "bipartite", {v, w},
                                  k + " " + pos(v) + " lists " + k + " " + pos(w) + "; a " + k + " may only list " +
                                      (v_center ? "nodes" : "centers"),
                                  "§1");
        } else if (!symmetry && !entry->second.count(v)) {
          symmetry = violation(
              layer, "symmetry", {v, w},
              k + " " + pos(v) + " lists " + kind(w_center) + " " + pos(w) + ", which does not list it", "§1");
        }
      }
    }
  }
  if (bipartite) return bipartite;
  if (symmetry) return symmetry;
  if (empty) return empty;

  // missing-level / stray-level: every center has a level, nodes have none.
  {
    auto l = g.level.begin();
    for (const Point3& c : g.C) {
      while (l != g.level.end() && l->first < c) ++l;
      if (l == g.level.end() || l->first != c)
        return violation(layer, "missing-level", {c}, "center " + pos(c) + " has no level", "§1");
    }
    auto c = g.C.begin();
    for (const auto& [v, lv] : g.level) {
      while (c != g.C.end() && *c < v) ++c;
      if (c == g.C.end() || *c != v)
        return violation(layer, "stray-level", {v},
                         (g.N.count(v) ? "node " + pos(v) : pos(v) + ", which is not a vertex,") + " has a level (" +
                             std::to_string(lv) + "); only centers have levels",
                         "§1");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::d3::inv3
