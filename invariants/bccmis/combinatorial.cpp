// Layer 1, combinatorial (Erleben 2009, §2 and §2.2): the sets N and C and the
// neighbour sets form a symmetric bipartite graph over existing vertices, and
// exactly the centers carry a level.
//
// Each check is one pass over the vertices in sorted order, in this order:
//   lattice-size       1 <= W, H; 0 <= L <= 61; W*S, H*S <= 2^62         §1
//   partition          N ∩ C = ∅                                         §2
//   neighbor-entry     every v in N ∪ C has an entry in the neighbour map  §2
//   stale-entry        no entry for a position that is not a vertex       §2.2
//   dangling-neighbor  every listed neighbour is a vertex                 §2.2
//   bipartite          nodes list only centers, centers only nodes        §2
//   symmetry           w ∈ 𝒩(v) ⇔ v ∈ 𝒩(w)                               §2
//   empty-neighbors    no vertex has an empty neighbour set               §2
//   missing-level      every center has a level                           §2.1 ¶1
//   stray-level        only centers have a level                          §2.1 ¶1
#include "bccmis/detail/lattice.h"
#include "bccmis/detail/layers.h"

namespace bccmis::inv {

namespace {

const char* kind(const Graph& g, const Point& v) { return g.C.count(v) ? "center" : "node"; }

}  // namespace

std::optional<Violation> check_combinatorial(const Graph& g) {
  constexpr int layer = 1;
  auto is_vertex = [&g](const Point& v) { return g.N.count(v) != 0 || g.C.count(v) != 0; };

  // lattice-size: the coordinates of spec/formats.md exist (every later
  // layer computes 2^(L+1) and W*S).
  {
    const LatticeSize& s = g.size;
    const std::string text = "lattice " + std::to_string(s.W) + " " + std::to_string(s.H) + " " +
                             std::to_string(s.L) + " is out of range: ";
    if (s.W < 1 || s.H < 1) return violation(layer, "lattice-size", {}, text + "W and H must be >= 1", "§1");
    if (s.L < 0 || s.L > 61) return violation(layer, "lattice-size", {}, text + "L must be in 0..61", "§1");
    const std::int64_t max_cells = (std::int64_t{1} << 62) >> (s.L + 1);  // W*S <= 2^62
    if (s.W > max_cells || s.H > max_cells)
      return violation(layer, "lattice-size", {}, text + "the domain side W*2^(L+1) or H*2^(L+1) exceeds 2^62",
                       "§1");
  }

  // partition: N ∩ C = ∅ (§2 "two disjoint vertex sets").
  for (const Point& v : g.N)
    if (g.C.count(v))
      return violation(layer, "partition", {v}, pos(v) + " is both a node and a center", "§2");

  // neighbor-entry: every vertex has an entry in the neighbour map (§2 "for
  // each c in C we store a neighbor set"; likewise for each node).
  for (const VertexSet* set : {&g.C, &g.N})
    for (const Point& v : *set)
      if (!g.neighbors.count(v))
        return violation(layer, "neighbor-entry", {v},
                         std::string(kind(g, v)) + " " + pos(v) + " has no neighbour set (no entry in the neighbour map)",
                         "§2");

  // stale-entry: no neighbour-map entry for a position that is not a vertex,
  // e.g. a deleted Y or J- vertex whose entry was left behind (§2.2).
  for (const auto& [v, nbrs] : g.neighbors)
    if (!is_vertex(v))
      return violation(layer, "stale-entry", {v},
                       pos(v) + " has a neighbour set of " + std::to_string(nbrs.size()) +
                           " but is neither a node nor a center (a deleted vertex left behind?)",
                       "§2.2");

  // dangling-neighbor: every listed neighbour exists (§2.2: deleted Y and J-
  // vertices must be unhooked, eq. 9a and 11b).
  for (const auto& [v, nbrs] : g.neighbors)
    for (const Point& w : nbrs)
      if (!is_vertex(w))
        return violation(layer, "dangling-neighbor", {v, w},
                         std::string(kind(g, v)) + " " + pos(v) + " lists " + pos(w) +
                             ", which is neither a node nor a center",
                         "§2.2");

  // bipartite: edges only join a node and a center (§2 "we do not store edges
  // where v_i and v_j both belong to the same vertex-set").
  for (const auto& [v, nbrs] : g.neighbors)
    for (const Point& w : nbrs)
      if (g.C.count(v) == g.C.count(w)) {
        const std::string k = kind(g, v);
        return violation(layer, "bipartite", {v, w},
                         k + " " + pos(v) + " lists " + k + " " + pos(w) + "; a " + k + " may only list " +
                             (k == "node" ? "centers" : "nodes"),
                         "§2");
      }

  // symmetry: n ∈ 𝒩(c) ⇔ c ∈ 𝒩(n) (§2 "then v_i ∈ 𝒩(v_j) and v_j ∈ 𝒩(v_i)").
  for (const auto& [v, nbrs] : g.neighbors)
    for (const Point& w : nbrs)
      if (!g.nbr(w).count(v))
        return violation(layer, "symmetry", {v, w},
                         std::string(kind(g, v)) + " " + pos(v) + " lists " + kind(g, w) + " " + pos(w) +
                             ", which does not list it",
                         "§2");

  // empty-neighbors: no vertex is isolated. (A parsed state never has an
  // empty entry; the operations must erase, not empty, what they delete.)
  for (const auto& [v, nbrs] : g.neighbors)
    if (nbrs.empty())
      return violation(layer, "empty-neighbors", {v},
                       std::string(kind(g, v)) + " " + pos(v) + " has an empty neighbour set", "§2");

  // missing-level / stray-level: the level test of §2.1 ¶1 reads the level of
  // every center; nodes have none.
  for (const Point& c : g.C)
    if (!g.level.count(c))
      return violation(layer, "missing-level", {c}, "center " + pos(c) + " has no level", "§2.1 ¶1");
  for (const auto& [v, l] : g.level)
    if (!g.C.count(v))
      return violation(layer, "stray-level", {v},
                       (g.N.count(v) ? "node " + pos(v) : pos(v) + ", which is not a vertex,") + " has a level (" +
                           std::to_string(l) + "); only centers have levels",
                       "§2.1 ¶1");
  return std::nullopt;
}

}  // namespace bccmis::inv
