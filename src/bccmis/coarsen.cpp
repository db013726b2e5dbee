// §2.2 The coarsening operation: equations (8a)-(12b), with errata E2, E3, E7 and E9.
//
// The paper's Fig. 3 configuration, with the names used below. Node n is the
// center of a refined level-l cell; its four children Y (level l+1) are merged
// back. B is every node on the children's boundaries except n: the 4 corners
// of the coarse cell and the 4 midpoints of its sides. A side midpoint with a
// same-level (l) cell or the domain boundary beyond it is no longer needed
// (J-); one with two level-(l+1) cells beyond it stays, as a junction.
//
//        before                                after
//   b ------ j- ------ b ---+              b --------------- b ---+
//   | y_3    |    y_4  |  x |              |                 |  x |
//   |        |         |----|              |                 |----|
//   b ------ n ------- b    |     ==>      |        n        b    |
//   | y_1    |    y_2  |----|              |                 |----|
//   |        |         |  x |              |                 |  x |
//   b ------ j- ------ b ---+              b --------------- b ---+
//
// Each statement carries two comment lines: the spec id (spec/equations.toml)
// and the equation's text from there, verbatim (tests/spec_coverage.py compares
// them). Deviations from the paper are marked `type=deviation` and explained in
// spec/errata.toml.

#include <stdexcept>

#include "bccmis/geometry.h"
#include "bccmis/ops.h"
#include "bccmis/set_ops.h"
#include "bccmis/transaction.h"

namespace bccmis {

std::string_view code(CoarsenRefusal r) {
  switch (r) {
    case CoarsenRefusal::NoSuchNode: return "no-such-node";
    case CoarsenRefusal::NotARefinedCenter: return "not-a-refined-center";
    case CoarsenRefusal::ChildrenRefined: return "children-refined";
    case CoarsenRefusal::FinerNeighbor: return "finer-neighbor";
  }
  return "?";
}

std::optional<CoarsenRefusal> can_coarsen(const Graph& g, const Point& n) {
  //= erleben2009#pre-coarsen-node
  //# n in N
  if (!g.is_node(n)) return CoarsenRefusal::NoSuchNode;
  //= erleben2009#pre-coarsen-refined-center
  //= type=deviation
  //= reason=E3: |N(n)| = 4 also holds at grid nodes and at midpoints between refined cells
  //# n is the center of a refined level-l cell
  // From n's position (erratum E7): l = L - log2(lowest set bit of n.x and n.y).
  const std::optional<int> l = refined_center_level(g.size, n);
  if (!l) return CoarsenRefusal::NotARefinedCenter;
  //= erleben2009#pre-coarsen-not-junction
  //# |N(n)| = 4
  if (g.nbr(n).size() != 4) return CoarsenRefusal::NotARefinedCenter;
  //= erleben2009#pre-coarsen-children-leaves
  //= type=deviation
  //= reason=E3: a refined child would leave overlapping cells
  //# level(y) = l + 1  for all y in N(n)
  for (const Point& y : g.nbr(n))
    if (!g.is_center(y) || g.level_of(y) != *l + 1) return CoarsenRefusal::ChildrenRefined;
  //= erleben2009#pre-coarsen-balance
  //= type=deviation
  //= reason=E3: a junction on a child means an edge-neighbor of level l+2
  //# |N(y)| = 4  for all y in N(n)
  for (const Point& y : g.nbr(n))
    if (g.nbr(y).size() != 4) return CoarsenRefusal::FinerNeighbor;
  return std::nullopt;
}

CoarsenResult coarsen(Graph& g, const Point& n) {
  CoarsenResult result;
  result.refused = can_coarsen(g, n);
  if (result.refused) return result;

  // Every change is staged in tx and applied at the end, all or nothing.
  Transaction tx(g);
  auto nb = [&tx](const Point& v) -> PointSet& { return tx.nb(v); };
  const int l = *refined_center_level(g.size, n);

  // 1. The children and the boundary of the coarse cell: eq. (8a)-(8b).
  //= erleben2009#eq-8a
  //# Y = N(n)
  const PointSet Y = nb(n);
  //= erleben2009#eq-8b
  //# B = ( union over y_i in Y of N(y_i) ) \ {n}
  PointSet B;
  for (const Point& y_i : Y) B = unite(B, nb(y_i));
  B = minus(B, PointSet{n});

  // Erratum E2: the side midpoints of the coarse cell are the b shared by two
  // children; they are found before (9a) removes the children.
  PointSet side_midpoints;
  for (const Point& b_i : B)
    if (intersect(nb(b_i), Y).size() == 2) side_midpoints.insert(b_i);

  // 2. Unhook and delete the children (Fig. 3a): eq. (9a)-(9f).
  //= erleben2009#eq-9a
  //# N(b_i) = N(b_i) \ Y  for all b_i in B
  for (const Point& b_i : B) nb(b_i) = minus(nb(b_i), Y);
  //= erleben2009#eq-9b
  //# N(y_i) = ∅  for all y_i in Y
  for (const Point& y_i : Y) nb(y_i).clear();
  //= erleben2009#eq-9c
  //# N(n) = ∅
  nb(n).clear();
  //= erleben2009#eq-9d
  //# N = N \ {n}
  tx.remove_node(n);
  //= erleben2009#eq-9e
  //# C = C ∪ {n}
  tx.add_center(n, l);
  //= erleben2009#eq-9f
  //# C = C \ Y
  for (const Point& y_i : Y) {
    tx.remove_center(y_i);
    tx.remove_vertex(y_i);  // the Y-vertices are deleted
  }

  // 3. Delete the junctions the coarse cell no longer needs (Fig. 3b):
  //    eq. (10a)-(11d).
  //= erleben2009#eq-10a
  //= type=deviation
  //= reason=E2: |N(b)| = 1 alone deletes boundary corners and keeps boundary side midpoints
  //# J- = { b_i in B : |N(b_i)| = 1 }
  // Implemented: J- = { b in B : b is a side midpoint of the coarse cell and |N(b)| <= 1 }.
  PointSet J_minus;
  for (const Point& b_i : side_midpoints)
    if (nb(b_i).size() <= 1) J_minus.insert(b_i);
  //= erleben2009#eq-10b
  //# B = B \ J-
  B = minus(B, J_minus);
  //= erleben2009#eq-10c
  //# N = N \ J-
  for (const Point& j_i : J_minus) tx.remove_node(j_i);
  for (const Point& j_i : J_minus) {
    //= erleben2009#eq-11a
    //= type=deviation
    //= reason=E2: x_i is a set of 0 or 1 cells (none on the domain boundary)
    //# x_i = N(j-_i)
    const PointSet x_i = nb(j_i);
    //= erleben2009#eq-11b
    //# N(x_i) = N(x_i) \ {j-_i}
    for (const Point& x : x_i) nb(x) = minus(nb(x), PointSet{j_i});
    //= erleben2009#eq-11c
    //# N(j-_i) = ∅
    nb(j_i).clear();
    tx.remove_vertex(j_i);  // the J- vertices are deleted
  }
  //= erleben2009#eq-11d
  //# N = N \ J-
  // This repeats (10c), harmless (erratum E9).
  for (const Point& j_i : J_minus) tx.remove_node(j_i);

  // 4. Connect the coarse cell to its boundary (Fig. 3c): eq. (12a)-(12b).
  //= erleben2009#eq-12a
  //# N(n) = B
  nb(n) = B;
  //= erleben2009#eq-12b
  //# N(b_i) = N(b_i) ∪ {n}  for all b_i in B
  for (const Point& b_i : B) nb(b_i) = unite(nb(b_i), PointSet{n});

  result.Y = Y;
  result.J_minus = J_minus;
  tx.commit();
  return result;
}

}  // namespace bccmis
