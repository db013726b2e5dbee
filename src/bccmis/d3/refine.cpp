// spec/lattice3d.md §4, refinement in 3D: equations R1a-R4b of
// spec/equations3d.toml, with the choices Q1-Q3, V1, V2, V5 and V7 of
// spec/choices3d.toml.
//
// The configuration, with the names used below. Cell c (level l) has corners
// p_1..p_8 (the pure nodes P, sorted by position: x first, then y, then z).
// X holds the cells that share a face patch or an edge segment with c. Here
// the cells to the right of c are already finer, so the right face of c holds
// an old face center and the right edges old midpoints (the junctions J).
// Refinement turns c into a node, makes the 8 children y_i (the child y_i
// holds corner p_i), creates a node j+ at every edge midpoint and face center
// of c that had none (J+), and links the old junctions to the children beside
// them.
//
//       before: c and its corners            after: the front face of c (z = max)
//
//            p_3 -------------- p_7             p_4 ------ j+ ------ p_8
//            /|                 /|               |   y_4    |   y_8    |
//           / |                / |               |          |          |
//        p_4 -------------- p_8  |              j+ ------- j+ ------- j_1
//         |   |              |   |   ==>         |   y_2    |   y_6    |
//         |  p_1 ------------|- p_5              |          |          |
//         |  /       c       |  /               p_2 ------ j+ ------ p_6
//         | /                | /
//        p_2 -------------- p_6               y            j_1: an old edge midpoint
//                                             |            (finer cells to the right);
//                                             +--- x       c is now the node where
//                                            /             all 8 children meet
//                                           z
//
// Only the node-center incidences are stored; the cube edges drawn here are
// not edges of the graph.
//
// Each statement carries two comment lines: the spec id and the equation as
// text. A choice of the 3D spec is marked `type=choice` and explained in
// spec/choices3d.toml.

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bccmis/d3/geometry.h"
#include "bccmis/d3/ops.h"
#include "bccmis/set_ops.h"
#include "bccmis/transaction.h"

namespace bccmis::d3 {

namespace {

// The neighborhood sets of c computed by R1a-R1d, before anything changes.
struct Neighborhood {
  PointSet B, J, P, X;
};

// A junction's cardinality (spec/lattice3d.md §3, F2): 3, 5, 6 or 7.
bool is_junction_cardinality(std::size_t k) { return k == 3 || k == 5 || k == 6 || k == 7; }

Neighborhood neighborhood(const Graph& g, const Point& c) {
  Neighborhood s;
  //= bccmis3d#eq-R1a
  //# B = N(c)
  s.B = g.nbr(c);
  //= bccmis3d#eq-R1b
  //= type=choice
  //= reason=V2: in 3D junctions have 3, 5, 6 or 7 cells and pure nodes 1, 2, 4 or 8
  //# J = { b in B : |N(b)| in {3, 5, 6, 7} }
  for (const Point& b : s.B)
    if (is_junction_cardinality(g.nbr(b).size())) s.J.insert(b);
  //= bccmis3d#eq-R1c
  //# P = B \ J
  s.P = minus(s.B, s.J);
  //= bccmis3d#eq-R1d
  //= type=choice
  //= reason=V1: the cells sharing a face patch or an edge segment with c (2:1 face and edge balance)
  //# X = ( union over b_i != b_j in B of N(b_i) ∩ N(b_j) ) \ {c}
  for (auto bi = s.B.begin(); bi != s.B.end(); ++bi)
    for (auto bj = std::next(bi); bj != s.B.end(); ++bj) s.X = unite(s.X, intersect(g.nbr(*bi), g.nbr(*bj)));
  s.X = minus(s.X, PointSet{c});
  return s;
}

}  // namespace

std::optional<RefineRefusal> can_refine(const Graph& g, const Point& c) {
  //= bccmis3d#pre-refine-cell
  //# c in C
  if (!g.is_center(c)) return RefineRefusal::NoSuchCell;
  //= bccmis3d#pre-refine-max-level
  //= type=choice
  //= reason=V5: the integer lattice bounds the level
  //# level(c) < L
  if (g.level_of(c) >= g.size.L) return RefineRefusal::MaxLevel;
  //= bccmis3d#pre-refine-level
  //# for all x in X: level(x) >= level(c)
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
  BasicTransaction<Graph> tx(g);
  auto nb = [&tx](const Point& v) -> PointSet& { return tx.nb(v); };
  const int l = g.level_of(c);
  const std::int64_t half = cell_side(g.size, l) / 2;

  // 1. The neighborhood of c: R1a-R1f.
  const auto [B, J, P, X] = neighborhood(g, c);
  //= bccmis3d#claim-P-has-8
  //# |P| = 8: P is exactly the 8 corners of c
  std::array<Point, 8> p{};  // p[0..7] = p_1..p_8, sorted by position
  {
    std::size_t i = 0;
    for (std::int64_t dx : {-half, half})
      for (std::int64_t dy : {-half, half})
        for (std::int64_t dz : {-half, half}) p[i++] = {c.x + dx, c.y + dy, c.z + dz};
  }
  if (P != PointSet(p.begin(), p.end()))
    throw std::logic_error(
        "refine: P is not the 8 corners of c although no face or edge neighbour is "
        "coarser; the graph is not a valid lattice");

  // The edges and faces of c (choice Q2), each with its midpoint m and, when
  // m is not an old junction, the cells around it other than c (R1e, R1f),
  // all found before anything changes.
  struct Edge {
    CubeEdge e;
    Point m;
    bool old;      // m is an old junction (step 4), else a new node (step 3)
    PointSet X_e;  // the cells around the edge other than c (new nodes only)
  };
  struct Face {
    CubeFace f;
    Point m;
    bool old;
    PointSet X_f;  // the cell across the face, if any (new nodes only)
  };
  std::vector<Edge> edges;
  for (const CubeEdge& e : cube_edges(p)) {
    const Point m = midpoint(p[e.i], p[e.j]);
    if (J.count(m) != 0) {
      edges.push_back({e, m, true, {}});
      continue;
    }
    //= bccmis3d#eq-R1e
    //= type=choice
    //= reason=V7: 0 to 3 cells, none where the edge lies on the domain boundary's edge
    //# X_e = ( N(p_i) ∩ N(p_j) ) \ {c}  for each edge e = {p_i, p_j} of c with m(e) not in J
    PointSet X_e = minus(intersect(g.nbr(p[e.i]), g.nbr(p[e.j])), PointSet{c});
    edges.push_back({e, m, false, std::move(X_e)});
  }
  std::vector<Face> faces;
  for (const CubeFace& f : cube_faces(p)) {
    const auto& [i, j, k, m4] = f.corners;
    const Point m = midpoint(p[i], p[m4]);  // opposite corners of the face
    if (J.count(m) != 0) {
      faces.push_back({f, m, true, {}});
      continue;
    }
    //= bccmis3d#eq-R1f
    //= type=choice
    //= reason=V7: 0 or 1 cell, none on the domain boundary
    //# X_f = ( N(p_i) ∩ N(p_j) ∩ N(p_k) ∩ N(p_m) ) \ {c}  for each face f of c with m(f) not in J
    PointSet X_f =
        minus(intersect(intersect(g.nbr(p[i]), g.nbr(p[j])), intersect(g.nbr(p[k]), g.nbr(p[m4]))), PointSet{c});
    faces.push_back({f, m, false, std::move(X_f)});
  }
  //= bccmis3d#claim-J-on-edges-and-faces
  //# every j in J is the midpoint m(e) of one edge or the center m(f) of one face of c
  std::size_t old_junctions = 0;
  for (const Edge& e : edges) old_junctions += e.old;
  for (const Face& f : faces) old_junctions += f.old;
  if (old_junctions != J.size())
    throw std::logic_error(
        "refine: a junction of c is not an edge midpoint or face center of c; "
        "the graph is not a valid lattice");

  // 2. Subdivide c: R2a-R2h. y_i is the child whose cube has corner p_i,
  //    centred halfway between c and p_i (choice Q1, a position use).
  std::array<Point, 8> y{};  // y[i] pairs with p[i]
  for (std::size_t i = 0; i < 8; ++i) y[i] = midpoint(c, p[i]);

  //= bccmis3d#eq-R2a
  //= type=choice
  //= reason=Q1: y_i is named by its position, the midpoint of c and p_i
  //# Y = { y_1, ..., y_8 }
  const PointSet Y(y.begin(), y.end());
  //= bccmis3d#eq-R2b
  //# C = C ∪ Y
  for (const Point& y_i : Y) tx.add_center(y_i, l + 1);
  //= bccmis3d#eq-R2c
  //# N(c) = Y
  nb(c) = Y;
  //= bccmis3d#eq-R2d
  //# N(j) = N(j) \ {c}  for all j in J
  for (const Point& j : J) nb(j) = minus(nb(j), PointSet{c});
  //= bccmis3d#eq-R2e
  //# N(p_i) = ( N(p_i) ∪ {y_i} ) \ {c}  for all p_i in P
  for (std::size_t i = 0; i < 8; ++i) nb(p[i]) = minus(unite(nb(p[i]), PointSet{y[i]}), PointSet{c});
  //= bccmis3d#eq-R2f
  //# N(y_i) = {p_i, c}  for all y_i in Y
  for (std::size_t i = 0; i < 8; ++i) nb(y[i]) = PointSet{p[i], c};
  //= bccmis3d#eq-R2g
  //# C = C \ {c}
  tx.remove_center(c);
  //= bccmis3d#eq-R2h
  //# N = N ∪ {c}
  tx.add_node(c);

  // 3. New nodes on the edges and faces of c that had none: R3a-R3h.
  //= bccmis3d#eq-R3a
  //= type=choice
  //= reason=Q2: the edges and faces of c, and whether each has its node, come from positions
  //# J+ = { m(e) : e an edge of c, m(e) not in J } ∪ { m(f) : f a face of c, m(f) not in J }
  PointSet J_plus;
  for (const Edge& e : edges)
    if (!e.old) J_plus.insert(e.m);
  for (const Face& f : faces)
    if (!f.old) J_plus.insert(f.m);
  //= bccmis3d#eq-R3b
  //# N = N ∪ J+
  for (const Point& j : J_plus) tx.add_node(j);

  for (const Edge& e : edges) {
    if (e.old) continue;
    const Point& j_plus = e.m;
    const PointSet y_e{y[e.e.i], y[e.e.j]};
    //= bccmis3d#eq-R3c
    //# N(x) = N(x) ∪ {j+}  for all x in X_e
    for (const Point& x : e.X_e) nb(x) = unite(nb(x), PointSet{j_plus});
    //= bccmis3d#eq-R3d
    //# N(j+) = X_e ∪ {y_i, y_j}
    nb(j_plus) = unite(e.X_e, y_e);
    //= bccmis3d#eq-R3e
    //# N(y) = N(y) ∪ {j+}  for y in {y_i, y_j}
    for (const Point& y_i : y_e) nb(y_i) = unite(nb(y_i), PointSet{j_plus});
  }
  for (const Face& f : faces) {
    if (f.old) continue;
    const Point& j_plus = f.m;
    PointSet y_f;
    for (std::size_t i : f.f.corners) y_f.insert(y[i]);
    //= bccmis3d#eq-R3f
    //# N(x) = N(x) ∪ {j+}  for all x in X_f
    for (const Point& x : f.X_f) nb(x) = unite(nb(x), PointSet{j_plus});
    //= bccmis3d#eq-R3g
    //# N(j+) = X_f ∪ {y_i, y_j, y_k, y_m}
    nb(j_plus) = unite(f.X_f, y_f);
    //= bccmis3d#eq-R3h
    //# N(y) = N(y) ∪ {j+}  for y in {y_i, y_j, y_k, y_m}
    for (const Point& y_i : y_f) nb(y_i) = unite(nb(y_i), PointSet{j_plus});
  }

  // 4. Old junctions join the children beside them: R4a-R4b. An old edge
  //    midpoint joins the 2 children at the ends of its edge, an old face
  //    center the 4 children of its face (choice Q3: which edge or face comes
  //    from the position, found in step 1).
  for (const Edge& e : edges) {
    if (!e.old) continue;
    const Point& j = e.m;
    for (std::size_t i : {e.e.i, e.e.j}) {
      //= bccmis3d#eq-R4a
      //= type=choice
      //= reason=Q3: the children beside an old junction are those of its edge's corners
      //# N(j) = N(j) ∪ { y_i : p_i in e }  for all j in J, e the edge or face with m(e) = j
      nb(j) = unite(nb(j), PointSet{y[i]});
      //= bccmis3d#eq-R4b
      //# N(y_i) = N(y_i) ∪ {j}  for all j in J and p_i in the edge or face of j
      nb(y[i]) = unite(nb(y[i]), PointSet{j});
    }
  }
  for (const Face& f : faces) {
    if (!f.old) continue;
    const Point& j = f.m;
    for (std::size_t i : f.f.corners) {
      //= bccmis3d#eq-R4a
      //= type=choice
      //= reason=Q3: the children beside an old junction are those of its face's corners
      //# N(j) = N(j) ∪ { y_i : p_i in e }  for all j in J, e the edge or face with m(e) = j
      nb(j) = unite(nb(j), PointSet{y[i]});
      //= bccmis3d#eq-R4b
      //# N(y_i) = N(y_i) ∪ {j}  for all j in J and p_i in the edge or face of j
      nb(y[i]) = unite(nb(y[i]), PointSet{j});
    }
  }

  result.Y = Y;
  result.J_plus = J_plus;
  tx.commit();
  return result;
}

}  // namespace bccmis::d3
