// Layer 1, combinatorial (Erleben 2009, §2 and §2.2): the sets N and C and the
// neighbor sets form a symmetric bipartite graph over existing vertices, and
// exactly the centers carry a level.
//
// Each check finds its first offender in sorted order, by merge walks over the
// sorted sets and one pass over the edges (O(size log size)); the first
// failing check in this order is reported:
//   lattice-size       1 <= W, H; 0 <= L <= 61; W*S, H*S <= 2^62         §1
//   partition          N ∩ C = ∅                                         §2
//   neighbor-entry     every v in N ∪ C has an entry in the neighbor map  §2
//   stale-entry        no entry for a position that is not a vertex       §2.2
//   dangling-neighbor  every listed neighbor is a vertex                 §2.2
//   bipartite          nodes list only centers, centers only nodes        §2
//   symmetry           w ∈ 𝒩(v) ⇔ v ∈ 𝒩(w)                               §2
//   empty-neighbors    no vertex has an empty neighbor set               §2
//   missing-level      every center has a level                           §2.1 ¶1
//   stray-level        only centers have a level                          §2.1 ¶1
#include <optional>

#include "bccmis/invariants/detail/lattice.h"
#include "bccmis/invariants/detail/layers.h"

namespace bccmis::inv {

namespace {

const char* kind(bool center) { return center ? "center" : "node"; }

}  // namespace

std::optional<Violation> check_combinatorial(const Graph& g) {
  constexpr int layer = 1;

  // lattice-size: the coordinates of spec/formats.md exist (every later
  // layer computes 2^(L+1) and W*S).
  {
    const LatticeSize& s = g.size;
    const std::string text =
        "lattice " + std::to_string(s.W) + " " + std::to_string(s.H) + " " + std::to_string(s.L) + " is out of range: ";
    if (s.W < 1 || s.H < 1) return violation(layer, "lattice-size", {}, text + "W and H must be >= 1", "§1");
    if (s.L < 0 || s.L > 61) return violation(layer, "lattice-size", {}, text + "L must be in 0..61", "§1");
    const std::int64_t max_cells = (std::int64_t{1} << 62) >> (s.L + 1);  // W*S <= 2^62
    if (s.W > max_cells || s.H > max_cells)
      return violation(layer, "lattice-size", {}, text + "the domain side W*2^(L+1) or H*2^(L+1) exceeds 2^62", "§1");
  }

  // partition: N ∩ C = ∅ (§2 "two disjoint vertex sets"). The first node
  // that is also a center, by a merge walk.
  {
    auto c = g.C.begin();
    for (const Point& v : g.N) {
      while (c != g.C.end() && *c < v) ++c;
      if (c != g.C.end() && *c == v)
        return violation(layer, "partition", {v}, pos(v) + " is both a node and a center", "§2");
    }
  }

  // neighbor-entry: every vertex has an entry in the neighbor map (§2 "for
  // each c in C we store a neighbor set"; likewise for each node). Centers
  // first, then nodes.
  for (const bool centers : {true, false}) {
    const PointSet& set = centers ? g.C : g.N;
    auto e = g.neighbors.begin();
    for (const Point& v : set) {
      while (e != g.neighbors.end() && e->first < v) ++e;
      if (e == g.neighbors.end() || e->first != v)
        return violation(
            layer, "neighbor-entry", {v},
            std::string(kind(centers)) + " " + pos(v) + " has no neighbor set (no entry in the neighbor map)", "§2");
    }
  }

  // stale-entry: no neighbor-map entry for a position that is not a vertex,
  // e.g. a deleted Y or J- vertex whose entry was left behind (§2.2). After
  // this and neighbor-entry, the keys of the map are exactly N ∪ C.
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
                         "§2.2");
    }
  }

  // One pass over the edges finds the first violation of each of these, in
  // sorted order; they are reported in this order of priority:
  //   dangling-neighbor: every listed neighbor exists (§2.2: deleted Y and
  //     J- vertices must be unhooked, eq. 9a and 11b);
  //   bipartite: edges only join a node and a center (§2 "we do not store
  //     edges where v_i and v_j both belong to the same vertex-set");
  //   symmetry: n ∈ 𝒩(c) ⇔ c ∈ 𝒩(n) (§2 "then v_i ∈ 𝒩(v_j) and v_j ∈ 𝒩(v_i)");
  //   empty-neighbors: no vertex is isolated (a parsed state never has an
  //     empty entry; the operations must erase, not empty, what they delete).
  std::optional<Violation> bipartite, symmetry, empty;
  {
    auto c = g.C.begin();
    for (const auto& [v, nbrs] : g.neighbors) {
      while (c != g.C.end() && *c < v) ++c;
      const bool v_center = c != g.C.end() && *c == v;
      const std::string k = kind(v_center);
      if (nbrs.empty() && !empty)
        empty = violation(layer, "empty-neighbors", {v}, k + " " + pos(v) + " has an empty neighbor set", "§2");
      for (const Point& w : nbrs) {
        const auto entry = g.neighbors.find(w);
        if (entry == g.neighbors.end())
          return violation(layer, "dangling-neighbor", {v, w},
                           k + " " + pos(v) + " lists " + pos(w) + ", which is neither a node nor a center", "§2.2");
        if (bipartite && symmetry) continue;  // only danglings can still matter
        const bool w_center = g.C.count(w) != 0;
        if (w_center == v_center) {
          if (!bipartite)
            bipartite = violation(layer, "bipartite", {v, w},
                                  k + " " + pos(v) + " lists " + k + " " + pos(w) + "; a " + k + " may only list " +
                                      (v_center ? "nodes" : "centers"),
                                  "§2");
        } else if (!symmetry && !entry->second.count(v)) {
          symmetry = violation(
              layer, "symmetry", {v, w},
              k + " " + pos(v) + " lists " + kind(w_center) + " " + pos(w) + ", which does not list it", "§2");
        }
      }
    }
  }
  if (bipartite) return bipartite;
  if (symmetry) return symmetry;
  if (empty) return empty;

  // missing-level / stray-level: the level test of §2.1 ¶1 reads the level of
  // every center; nodes have none.
  {
    auto l = g.level.begin();
    for (const Point& c : g.C) {
      while (l != g.level.end() && l->first < c) ++l;
      if (l == g.level.end() || l->first != c)
        return violation(layer, "missing-level", {c}, "center " + pos(c) + " has no level", "§2.1 ¶1");
    }
    auto c = g.C.begin();
    for (const auto& [v, lv] : g.level) {
      while (c != g.C.end() && *c < v) ++c;
      if (c == g.C.end() || *c != v)
        return violation(layer, "stray-level", {v},
                         (g.N.count(v) ? "node " + pos(v) : pos(v) + ", which is not a vertex,") + " has a level (" +
                             std::to_string(lv) + "); only centers have levels",
                         "§2.1 ¶1");
    }
  }
  return std::nullopt;
}

}  // namespace bccmis::inv
