// §2.1 The refinement operation: equations (2a)-(7b), with errata E1, E4, E5 and E10.
//
// The paper's Fig. 2 configuration, with the names used below. Cell c (level l)
// has corners p_1..p_4 (the pure nodes P) and one old junction j_1 (J) on its
// right side, where two level-(l+1) cells already sit. X holds the cells that
// share a side with c. Refinement turns c into a node, makes the four children
// y_i (the child y_i holds corner p_i), creates a junction j+_k on each side of
// c that had none (J+), and hooks the old junction to the two children beside it.
//
//        before                                after
//   p_3 ---------- p_4 ---+              p_3 ---- j+ ---- p_4 ---+
//    |              |  x  |               | y_3   |   y_4  |  x  |
//    |              |-----|               |       |        |-----|
//    |      c      j_1    |     ==>      j+ ----- c ----- j_1    |
//    |              |-----|               | y_1   |   y_2  |-----|
//    |              |  x  |               |       |        |  x  |
//   p_1 ---------- p_2 ---+              p_1 ---- j+ ---- p_2 ---+
//
// Only the diagonal edges (node-center) are stored; the horizontal and vertical
// edges drawn here are the hull edges of eq. (1).
//
// Each statement carries two comment lines: the spec id (spec/equations.toml)
// and the equation's text from there, verbatim (tests/spec_coverage.py compares
// them). Deviations from the paper are marked `type=deviation` and explained in
// spec/errata.toml.

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bccmis/geometry.h"
#include "bccmis/ops.h"
#include "bccmis/set_ops.h"
#include "bccmis/transaction.h"

namespace bccmis {

std::string_view code(RefineRefusal r) {
  switch (r) {
    case RefineRefusal::NoSuchCell: return "no-such-cell";
    case RefineRefusal::MaxLevel: return "max-level";
    case RefineRefusal::CoarserNeighbor: return "coarser-neighbor";
  }
  return "?";
}

namespace {

// The neighborhood sets of c computed by (2a)-(3), before anything changes.
struct Neighborhood {
  PointSet B, J, P, X;
};

Neighborhood neighborhood(const Graph& g, const Point& c) {
  Neighborhood s;
  //= erleben2009#eq-2a
  //# B = N(c)
  s.B = g.nbr(c);
  //= erleben2009#eq-2b
  //# J = { b_i in B : |N(b_i)| = 3 }
  for (const Point& b : s.B)
    if (g.nbr(b).size() == 3) s.J.insert(b);
  //= erleben2009#eq-2c
  //# P = B \ J
  s.P = minus(s.B, s.J);
  //= erleben2009#eq-3
  //= type=deviation
  //= reason=E4: the formula (edge neighbors) is implemented, not the sentence (all neighbors)
  //# X = ( union over b_i, b_j in B, i != j, of N(b_i) ∩ N(b_j) ) \ {c}
  for (auto bi = s.B.begin(); bi != s.B.end(); ++bi)
    for (auto bj = std::next(bi); bj != s.B.end(); ++bj) s.X = unite(s.X, intersect(g.nbr(*bi), g.nbr(*bj)));
  s.X = minus(s.X, PointSet{c});
  return s;
}

}  // namespace

std::optional<RefineRefusal> can_refine(const Graph& g, const Point& c) {
  //= erleben2009#pre-refine-cell
  //# c in C
  if (!g.is_center(c)) return RefineRefusal::NoSuchCell;
  //= erleben2009#pre-refine-max-level
  //= type=deviation
  //= reason=E10: the integer lattice bounds the level; the paper has no maximum
  //# level(c) < L
  if (g.level_of(c) >= g.size.L) return RefineRefusal::MaxLevel;
  //= erleben2009#pre-refine-level
  //# level(x) >= level(c)  for all x in X
  const Neighborhood s = neighborhood(g, c);
  for (const Point& x : s.X)
    if (g.level_of(x) < g.level_of(c)) return RefineRefusal::CoarserNeighbor;
  return std::nullopt;
}

RefineResult refine(Graph& g, const Point& c) {
  RefineResult result;
  result.refused = can_refine(g, c);
  if (result.refused) return result;

  // Every change is staged in tx and applied at the end, all or nothing.
  Transaction tx(g);
  auto nb = [&tx](const Point& v) -> PointSet& { return tx.nb(v); };
  const int l = g.level_of(c);

  // 1. The neighborhood of c (Fig. 2a): eq. (2a)-(3).
  const auto [B, J, P, X] = neighborhood(g, c);
  //= erleben2009#claim-P-has-4
  //# ||P|| = 4 and ||Y|| = 4
  // (Y is made below with one child per p_i, so ||P|| = 4 gives ||Y|| = 4.)
  if (P.size() != 4)
    throw std::logic_error(
        "refine: ||P|| != 4 although no edge-neighbor is coarser; "
        "the graph is not a valid lattice (run the checker)");

  const std::vector<Point> p(P.begin(), P.end());  // p[0..3] = p_1..p_4

  // The sides of c that need a new junction in step 3, found before anything
  // changes. Erratum E1: the paper makes a junction only where
  // |N(p_i) ∩ N(p_j)| = 1, i.e. on sides with a same-level neighbor, so a side
  // on the domain boundary got none. We take the four sides of c instead
  // (adjacent corners: a position use) and give every side without an old
  // junction a new midpoint node.
  struct Side {
    std::size_t i, j;  // indices into p / y
    Point j_plus;
  };
  std::vector<Side> sides;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) {
      if (!are_side_adjacent(p[i], p[j])) continue;  // a diagonal of c, not a side
      const Point mid = midpoint(p[i], p[j]);
      if (J.count(mid) != 0) continue;  // the side already has its junction: step 4
      sides.push_back({i, j, mid});
    }

  if (sides.size() != 4 - J.size())
    throw std::logic_error(
        "refine: an old junction is not a side midpoint of c; "
        "the graph is not a valid lattice (run the checker)");

  // 2. Subdivide c (Fig. 2b): eq. (4a)-(4h). The paper pairs each p_i with one
  //    y_i without saying how; y_i is the child cell that has p_i as a corner,
  //    centred halfway between c and p_i (erratum E5, position use P1).
  std::array<Point, 4> y;  // y[i] pairs with p[i]
  for (std::size_t i = 0; i < 4; ++i) y[i] = midpoint(c, p[i]);

  //= erleben2009#eq-4a
  //# Y = { y_1, ..., y_4 }
  const PointSet Y(y.begin(), y.end());
  //= erleben2009#eq-4b
  //# C = C ∪ Y
  for (const Point& y_i : Y) tx.add_center(y_i, l + 1);
  //= erleben2009#eq-4c
  //# N(c) = Y
  nb(c) = Y;
  //= erleben2009#eq-4d
  //# N(j_i) = N(j_i) \ {c}  for all j_i in J
  for (const Point& ji : J) nb(ji) = minus(nb(ji), PointSet{c});
  //= erleben2009#eq-4e
  //# N(p_i) = N(p_i) ∪ {y_i} \ {c}  for all p_i in P
  for (std::size_t i = 0; i < 4; ++i) nb(p[i]) = minus(unite(nb(p[i]), PointSet{y[i]}), PointSet{c});
  //= erleben2009#eq-4f
  //# N(y_i) = {p_i, c}  for all y_i in Y
  for (std::size_t i = 0; i < 4; ++i) nb(y[i]) = PointSet{p[i], c};
  //= erleben2009#eq-4g
  //# C = C \ {c}
  tx.remove_center(c);
  //= erleben2009#eq-4h
  //# N = N ∪ {c}
  tx.add_node(c);

  // 3. New junctions (Fig. 2c): eq. (5a)-(6e), over the sides found above.
  //= erleben2009#eq-5a
  //= type=deviation
  //= reason=E1: one new junction per side of c without an old junction (4 - ||J|| of them)
  //# J+ = { j+_1, ..., j+_(4 - ||J||) }
  PointSet J_plus;
  for (const Side& s : sides) J_plus.insert(s.j_plus);
  //= erleben2009#eq-5b
  //# N = N ∪ J+
  for (const Point& j : J_plus) tx.add_node(j);

  for (const Side& s : sides) {
    const Point& j_k = s.j_plus;
    const Point &p_i = p[s.i], &p_j = p[s.j], &y_i = y[s.i], &y_j = y[s.j];
    //= erleben2009#eq-6a
    //= type=deviation
    //= reason=E1: x_k is the set N(p_i) ∩ N(p_j): one cell across the side, or none on the boundary
    //# x_k = N(p_i) ∩ N(p_j)  (for p_i, p_j in P, i != j, |N(p_i) ∩ N(p_j)| = 1)
    const PointSet x_k = intersect(nb(p_i), nb(p_j));
    //= erleben2009#eq-6b
    //# N(x_k) = N(x_k) ∪ {j+_k}
    for (const Point& x : x_k) nb(x) = unite(nb(x), PointSet{j_k});
    //= erleben2009#eq-6c
    //# N(j+_k) = {x_k, y_i, y_j}
    nb(j_k) = unite(x_k, PointSet{y_i, y_j});
    //= erleben2009#eq-6d
    //# N(y_i) = N(y_i) ∪ {j+_k}
    nb(y_i) = unite(nb(y_i), PointSet{j_k});
    //= erleben2009#eq-6e
    //# N(y_j) = N(y_j) ∪ {j+_k}
    nb(y_j) = unite(nb(y_j), PointSet{j_k});
  }

  // 4. Old junctions (Fig. 2d): eq. (7a)-(7b). The condition is evaluated for
  //    every pair (j_k, p_i) on the graph as left by steps 2-3; adding y_i to
  //    N(j_k) cannot change the condition for another corner p_m, because y_i
  //    touches no corner but p_i.
  for (const Point& j_k : J)
    for (std::size_t i = 0; i < 4; ++i) {
      //= erleben2009#eq-7-condition
      //# |N(j_k) ∩ N(p_i)| = 1 for j_k in J, p_i in P
      if (intersect(nb(j_k), nb(p[i])).size() != 1) continue;
      //= erleben2009#eq-7a
      //# N(j_k) = N(j_k) ∪ {y_i}
      nb(j_k) = unite(nb(j_k), PointSet{y[i]});
      //= erleben2009#eq-7b
      //# N(y_i) = N(y_i) ∪ {j_k}
      nb(y[i]) = unite(nb(y[i]), PointSet{j_k});
    }

  result.Y = Y;
  result.J_plus = J_plus;
  tx.commit();
  return result;
}

}  // namespace bccmis
