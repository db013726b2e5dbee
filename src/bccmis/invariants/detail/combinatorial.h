// Layer 1 of the checker, combinatorial, for a graph of either dimension
// (Graph, d3::Graph): the sets N and C and the neighbour sets form a
// symmetric bipartite graph over existing vertices, and exactly the centers
// carry a level. The 2D layer (combinatorial.cpp) and the 3D one
// (d3/combinatorial.cpp) check the lattice size themselves, then call this.
//
// Each check finds its first offender in sorted order, by merge walks over the
// sorted sets and one pass over the edges (O(size log size)); the first
// failing check in this order is reported:
//   partition          N ∩ C = ∅
//   neighbor-entry     every v in N ∪ C has an entry in the neighbor map
//   stale-entry        no entry for a position that is not a vertex
//   dangling-neighbor  every listed neighbor is a vertex
//   bipartite          nodes list only centers, centers only nodes
//   symmetry           w ∈ 𝒩(v) ⇔ v ∈ 𝒩(w)
//   empty-neighbors    no vertex has an empty neighbor set
//   missing-level      every center has a level
//   stray-level        only centers have a level
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace bccmis::inv_common {

/// The spec anchors the violations name: the graph's definition, the removal
/// of vertices, and the levels (2D: the paper's §2, §2.2, §2.1 ¶1).
struct CombinatorialSections {
  const char* graph;
  const char* removal;
  const char* levels;
};

/// The first layer-1 violation of g. `violation(layer, code, where, text,
/// section)` makes the checker's violation type (its message starts with
/// the code).
template <class G, class Make>
auto check_combinatorial(const G& g, const CombinatorialSections& sec, const Make& violation)
    -> std::optional<decltype(violation(1, std::string(), std::vector<typename G::point_type>{}, std::string(),
                                        std::string()))> {
  using P = typename G::point_type;
  constexpr int layer = 1;
  auto kind = [](bool center) { return center ? "center" : "node"; };
  auto pos = [](const P& p) { return to_string(p); };

  // partition: N ∩ C = ∅ (two disjoint vertex sets). The first node that is
  // also a center, by a merge walk.
  {
    auto c = g.C.begin();
    for (const P& v : g.N) {
      while (c != g.C.end() && *c < v) ++c;
      if (c != g.C.end() && *c == v)
        return violation(layer, "partition", {v}, pos(v) + " is both a node and a center", sec.graph);
    }
  }

  // neighbor-entry: every vertex has an entry in the neighbor map (a
  // neighbour set is stored for every center and every node). Centers
  // first, then nodes.
  for (const bool centers : {true, false}) {
    const auto& set = centers ? g.C : g.N;
    auto e = g.neighbors.begin();
    for (const P& v : set) {
      while (e != g.neighbors.end() && e->first < v) ++e;
      if (e == g.neighbors.end() || e->first != v)
        return violation(layer, "neighbor-entry", {v},
                         std::string(kind(centers)) + " " + pos(v) +
                             " has no neighbor set (no entry in the neighbor map)",
                         sec.graph);
    }
  }

  // stale-entry: no neighbor-map entry for a position that is not a vertex,
  // e.g. a deleted Y or J- vertex whose entry was left behind. After this
  // and neighbor-entry, the keys of the map are exactly N ∪ C.
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
                         sec.removal);
    }
  }

  // One pass over the edges finds the first violation of each of these, in
  // sorted order; they are reported in this order of priority:
  //   dangling-neighbor: every listed neighbor exists (deleted Y and J-
  //     vertices must be unhooked);
  //   bipartite: edges only join a node and a center (no edge between two
  //     vertices of the same set is stored);
  //   symmetry: n ∈ 𝒩(c) ⇔ c ∈ 𝒩(n);
  //   empty-neighbors: no vertex is isolated (a parsed state never has an
  //     empty entry; the operations must erase, not empty, what they delete).
  decltype(check_combinatorial(g, sec, violation)) bipartite, symmetry, empty;
  {
    auto c = g.C.begin();
    for (const auto& [v, nbrs] : g.neighbors) {
      while (c != g.C.end() && *c < v) ++c;
      const bool v_center = c != g.C.end() && *c == v;
      const std::string k = kind(v_center);
      if (nbrs.empty() && !empty)
        empty = violation(layer, "empty-neighbors", {v}, k + " " + pos(v) + " has an empty neighbor set", sec.graph);
      for (const P& w : nbrs) {
        const auto entry = g.neighbors.find(w);
        if (entry == g.neighbors.end())
          return violation(layer, "dangling-neighbor", {v, w},
                           k + " " + pos(v) + " lists " + pos(w) + ", which is neither a node nor a center",
                           sec.removal);
        if (bipartite && symmetry) continue;  // only danglings can still matter
        const bool w_center = g.C.count(w) != 0;
        if (w_center == v_center) {
          if (!bipartite)
            bipartite = violation(layer, "bipartite", {v, w},
                                  k + " " + pos(v) + " lists " + k + " " + pos(w) + "; a " + k + " may only list " +
                                      (v_center ? "nodes" : "centers"),
                                  sec.graph);
        } else if (!symmetry && !entry->second.count(v)) {
          symmetry = violation(
              layer, "symmetry", {v, w},
              k + " " + pos(v) + " lists " + kind(w_center) + " " + pos(w) + ", which does not list it", sec.graph);
        }
      }
    }
  }
  if (bipartite) return bipartite;
  if (symmetry) return symmetry;
  if (empty) return empty;

  // missing-level / stray-level: the level test reads the level of every
  // center; nodes have none.
  {
    auto l = g.level.begin();
    for (const P& c : g.C) {
      while (l != g.level.end() && l->first < c) ++l;
      if (l == g.level.end() || l->first != c)
        return violation(layer, "missing-level", {c}, "center " + pos(c) + " has no level", sec.levels);
    }
    auto c = g.C.begin();
    for (const auto& [v, lv] : g.level) {
      while (c != g.C.end() && *c < v) ++c;
      if (c == g.C.end() || *c != v)
        return violation(layer, "stray-level", {v},
                         (g.N.count(v) ? "node " + pos(v) : pos(v) + ", which is not a vertex,") + " has a level (" +
                             std::to_string(lv) + "); only centers have levels",
                         sec.levels);
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::inv_common
