// spec/lattice3d.md §5, coarsening in 3D: equations K1a-K4b of
// spec/equations3d.toml, with the choices Q4, V3, V4 and V6 of
// spec/choices3d.toml.
//
// The configuration, with the names used below. Node n is the center of a
// refined level-l cube; its 8 children Y (level l+1) are merged back. B is
// every node on the children's boundaries except n: the 8 corners of the
// coarse cube, the 12 midpoints of its edges and the 6 centers of its faces.
// M is those midpoints and centers, told from the corners by how many
// children contain them (2 or 4, a corner 1). A node of M that no remaining
// cell has as a corner is no longer needed (J-); one with a level-(l+1) cell
// beyond it stays, as a junction (j on the right face below).
//
//     before: the front face (z = max)             after
//
//        b ------ j- ------ b ---+                b ----------------- b ---+
//        |   y_4   |   y_8   | x |                |                   | x  |
//        |         |         |---|                |                   |----|
//       j- ------- j- ------ j   |      ==>       |         n         j    |
//        |   y_2   |   y_6   |---|                |                   |----|
//        |         |         | x |                |                   | x  |
//        b ------ j- ------ b ---+                b ----------------- b ---+
//
//   (n, the node where the 8 children meet, lies behind the face center;
//    after coarsening it is the center of the merged cube.)
//
// Each statement carries two comment lines: the spec id and the equation as
// text. A choice of the 3D spec is marked `type=choice` and explained in
// spec/choices3d.toml.

#include <bit>
#include <stdexcept>

#include "bccmis/d3/geometry.h"
#include "bccmis/d3/ops.h"
#include "bccmis/set_ops.h"
#include "bccmis/transaction.h"

namespace bccmis::d3 {

std::optional<int> refined_center_level(const LatticeSize& size, const Point& p) {
  const std::int64_t S = level0_side(size);
  // Strictly inside the domain; the extents are at most 2^62, so no overflow.
  if (p.x <= 0 || p.y <= 0 || p.z <= 0 || p.x >= size.W * S || p.y >= size.H * S || p.z >= size.D * S)
    return std::nullopt;
  // A level-l center has all coordinates odd multiples of 2^(L-l).
  const int tx = std::countr_zero(static_cast<std::uint64_t>(p.x));
  const int ty = std::countr_zero(static_cast<std::uint64_t>(p.y));
  const int tz = std::countr_zero(static_cast<std::uint64_t>(p.z));
  if (tx != ty || tx != tz) return std::nullopt;
  const int l = size.L - tx;
  if (l < 0 || l >= size.L) return std::nullopt;  // a grid node (l < 0) or a level-L center
  return l;
}

std::optional<CoarsenRefusal> can_coarsen(const Graph& g, const Point& n) {
  //= bccmis3d#pre-coarsen-node
  //# n in N
  if (!g.is_node(n)) return CoarsenRefusal::NoSuchNode;
  //= bccmis3d#pre-coarsen-refined-center
  //= type=choice
  //= reason=Q4: whether n is a refined center, and its level, come from its position
  //# n is the center of a level-l cube, l < L: all coordinates odd multiples of 2^(L-l), strictly inside the domain
  const std::optional<int> l = refined_center_level(g.size, n);
  if (!l) return CoarsenRefusal::NotARefinedCenter;
  //= bccmis3d#pre-coarsen-eight-cells
  //= type=choice
  //= reason=V6: implied by the position test on a valid graph; kept as 2D keeps |N(n)| = 4
  //# |N(n)| = 8
  if (g.nbr(n).size() != 8) return CoarsenRefusal::NotARefinedCenter;
  //= bccmis3d#pre-coarsen-children-leaves
  //# for all y in N(n): level(y) = l + 1
  for (const Point& y : g.nbr(n))
    if (!g.is_center(y) || g.level_of(y) != *l + 1) return CoarsenRefusal::ChildrenRefined;
  //= bccmis3d#pre-coarsen-balance
  //# for all y in N(n): |N(y)| = 8
  for (const Point& y : g.nbr(n))
    if (g.nbr(y).size() != 8) return CoarsenRefusal::FinerNeighbor;
  return std::nullopt;
}

CoarsenResult coarsen(Graph& g, const Point& n) {
  CoarsenResult result;
  result.refused = can_coarsen(g, n);
  if (result.refused) return result;

  // Every change is staged in tx and applied at the end, all or nothing.
  BasicTransaction<Graph> tx(g);
  auto nb = [&tx](const Point& v) -> PointSet& { return tx.nb(v); };
  const int l = *refined_center_level(g.size, n);

  // 1. The children and the boundary of the coarse cube: K1a-K1c.
  //= bccmis3d#eq-K1a
  //# Y = N(n)
  const PointSet Y = nb(n);
  //= bccmis3d#eq-K1b
  //# B = ( union over y_i in Y of N(y_i) ) \ {n}
  PointSet B;
  for (const Point& y_i : Y) B = unite(B, nb(y_i));
  B = minus(B, PointSet{n});
  //= bccmis3d#eq-K1c
  //= type=choice
  //= reason=V4: a corner of the coarse cube is in 1 child, an edge midpoint in 2, a face center in 4
  //# M = { b in B : |N(b) ∩ Y| in {2, 4} }
  PointSet M;
  for (const Point& b : B) {
    const std::size_t k = intersect(nb(b), Y).size();
    if (k == 2 || k == 4) M.insert(b);
  }
  if (B.size() != 26 || M.size() != 18)
    throw std::logic_error(
        "coarsen: the children's boundary is not 8 corners, 12 edge midpoints and "
        "6 face centers; the graph is not a valid lattice");

  // 2. Unhook and delete the children: K2a-K2f.
  //= bccmis3d#eq-K2a
  //# N(b) = N(b) \ Y  for all b in B
  for (const Point& b : B) nb(b) = minus(nb(b), Y);
  //= bccmis3d#eq-K2b
  //# N(y_i) = ∅  for all y_i in Y
  for (const Point& y_i : Y) nb(y_i).clear();
  //= bccmis3d#eq-K2c
  //# N(n) = ∅
  nb(n).clear();
  //= bccmis3d#eq-K2d
  //# N = N \ {n}
  tx.remove_node(n);
  //= bccmis3d#eq-K2e
  //= type=choice
  //= reason=Q4: the merged cell's level l comes from n's position
  //# C = C ∪ {n}
  tx.add_center(n, l);
  //= bccmis3d#eq-K2f
  //# C = C \ Y
  for (const Point& y_i : Y) {
    tx.remove_center(y_i);
    tx.remove_vertex(y_i);  // the Y vertices are deleted
  }

  // 3. Delete the nodes the coarse cube no longer needs: K3a-K3e. A cell left
  //    at a node of M has level l (the node is inside its edge or face) or
  //    l + 1 (the node is its corner).
  //= bccmis3d#eq-K3a
  //= type=choice
  //= reason=V3: no threshold on |N(b)| works in 3D; delete b when no remaining cell has it as a corner
  //# J- = { b in M : level(x) <= l for all x in N(b) }
  PointSet J_minus;
  for (const Point& b : M) {
    bool corner_of_a_cell = false;
    for (const Point& x : nb(b)) corner_of_a_cell = corner_of_a_cell || g.level_of(x) > l;
    if (!corner_of_a_cell) J_minus.insert(b);
  }
  //= bccmis3d#eq-K3b
  //# B = B \ J-
  B = minus(B, J_minus);
  //= bccmis3d#eq-K3c
  //# N = N \ J-
  for (const Point& j : J_minus) tx.remove_node(j);
  for (const Point& j : J_minus) {
    //= bccmis3d#eq-K3d
    //# N(x) = N(x) \ {j}  for all x in N(j), j in J-
    for (const Point& x : nb(j)) nb(x) = minus(nb(x), PointSet{j});
    //= bccmis3d#eq-K3e
    //# N(j) = ∅  for all j in J-
    nb(j).clear();
    tx.remove_vertex(j);  // the J- vertices are deleted
  }

  // 4. Connect the coarse cell to its boundary: K4a-K4b.
  //= bccmis3d#eq-K4a
  //# N(n) = B
  nb(n) = B;
  //= bccmis3d#eq-K4b
  //# N(b) = N(b) ∪ {n}  for all b in B
  for (const Point& b : B) nb(b) = unite(nb(b), PointSet{n});

  result.Y = Y;
  result.J_minus = J_minus;
  tx.commit();
  return result;
}

}  // namespace bccmis::d3
