// Planted-bug copies of the core's refine (§2.1) and coarsen (§2.2); see
// mutant_ops.h. The equation numbers are given in plain comments on purpose:
// these are not implementations the spec coverage check should count.

#include "mutants/mutant_ops.h"

#include <array>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "bccmis/geometry.h"
#include "bccmis/set_ops.h"

namespace bccmis::mutants {

const std::vector<FlawInfo>& all_flaws() {
  static const std::vector<FlawInfo> flaws = {
      {Flaw::Skip4d, "Skip4d"},
      {Flaw::Skip6d, "Skip6d"},
      {Flaw::Forget10c, "Forget10c"},
      {Flaw::Forget10cOnly, "Forget10cOnly"},
      {Flaw::LiteralBoundary6, "LiteralBoundary6"},
      {Flaw::WeakCoarsenGuard, "WeakCoarsenGuard"},
      {Flaw::CoarsenDifferentState, "CoarsenDifferentState"},
      {Flaw::CornerBalance, "CornerBalance"},
      {Flaw::RefusalRefinesNeighbor, "RefusalRefinesNeighbor"},
  };
  return flaws;
}

namespace {

struct Neighborhood {
  PointSet B, J, P, X;
};

// (2a)-(3).
Neighborhood neighborhood(const Graph& g, const Point& c) {
  Neighborhood s;
  s.B = g.nbr(c);
  for (const Point& b : s.B)
    if (g.nbr(b).size() == 3) s.J.insert(b);
  s.P = minus(s.B, s.J);
  for (auto bi = s.B.begin(); bi != s.B.end(); ++bi)
    for (auto bj = std::next(bi); bj != s.B.end(); ++bj) s.X = unite(s.X, intersect(g.nbr(*bi), g.nbr(*bj)));
  s.X = minus(s.X, PointSet{c});
  return s;
}

}  // namespace

std::optional<RefineRefusal> can_refine(const Graph& g, const Point& c, Flaw flaw) {
  if (!g.is_center(c)) return RefineRefusal::NoSuchCell;
  if (g.level_of(c) >= g.size.L) return RefineRefusal::MaxLevel;
  const Neighborhood s = neighborhood(g, c);
  PointSet X = s.X;
  if (flaw == Flaw::CornerBalance) {
    // The sentence before (3): every cell at a pure corner of c.
    for (const Point& p : s.P) X = unite(X, g.nbr(p));
    X = minus(X, PointSet{c});
  }
  for (const Point& x : X)
    if (g.is_center(x) && g.level_of(x) < g.level_of(c)) return RefineRefusal::CoarserNeighbor;
  return std::nullopt;
}

RefineResult refine(Graph& g, const Point& c, Flaw flaw) {
  RefineResult result;
  result.refused = can_refine(g, c, flaw);
  if (result.refused) {
    if (flaw == Flaw::RefusalRefinesNeighbor && *result.refused == RefineRefusal::CoarserNeighbor) {
      for (const Point& x : neighborhood(g, c).X)
        if (g.level_of(x) < g.level_of(c)) {
          refine(g, x, Flaw::None);
          break;
        }
    }
    return result;
  }

  auto nb = [&g](const Point& v) -> PointSet& { return g.neighbors[v]; };
  const int l = g.level_of(c);
  const auto [B, J, P, X] = neighborhood(g, c);
  if (P.size() != 4) throw std::logic_error("mutant refine: ||P|| != 4");
  const std::vector<Point> p(P.begin(), P.end());

  struct Side {
    std::size_t i, j;
    Point j_plus;
  };
  std::vector<Side> sides;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j) {
      if (!are_side_adjacent(p[i], p[j])) continue;
      const Point mid = midpoint(p[i], p[j]);
      if (J.count(mid) != 0) continue;
      sides.push_back({i, j, mid});
    }

  // (4a)-(4h)
  std::array<Point, 4> y;
  for (std::size_t i = 0; i < 4; ++i) y[i] = midpoint(c, p[i]);
  const PointSet Y(y.begin(), y.end());
  g.C = unite(g.C, Y);
  for (const Point& yi : Y) g.level[yi] = l + 1;
  nb(c) = Y;
  if (flaw != Flaw::Skip4d)
    for (const Point& ji : J) nb(ji) = minus(nb(ji), PointSet{c});
  for (std::size_t i = 0; i < 4; ++i) nb(p[i]) = minus(unite(nb(p[i]), PointSet{y[i]}), PointSet{c});
  for (std::size_t i = 0; i < 4; ++i) nb(y[i]) = PointSet{p[i], c};
  g.C = minus(g.C, PointSet{c});
  g.level.erase(c);
  g.N = unite(g.N, PointSet{c});

  // (5a)-(6e)
  PointSet J_plus;
  for (const Side& s : sides) J_plus.insert(s.j_plus);
  g.N = unite(g.N, J_plus);
  for (const Side& s : sides) {
    const Point& j_k = s.j_plus;
    const Point &p_i = p[s.i], &p_j = p[s.j], &y_i = y[s.i], &y_j = y[s.j];
    const PointSet x_k = intersect(nb(p_i), nb(p_j));
    if (flaw == Flaw::LiteralBoundary6 && x_k.size() != 1) continue;  // the paper's condition, read literally
    for (const Point& x : x_k) nb(x) = unite(nb(x), PointSet{j_k});
    nb(j_k) = unite(x_k, PointSet{y_i, y_j});
    if (flaw != Flaw::Skip6d) nb(y_i) = unite(nb(y_i), PointSet{j_k});
    nb(y_j) = unite(nb(y_j), PointSet{j_k});
  }

  // (7a)-(7b)
  for (const Point& j_k : J)
    for (std::size_t i = 0; i < 4; ++i) {
      if (intersect(nb(j_k), nb(p[i])).size() != 1) continue;
      nb(j_k) = unite(nb(j_k), PointSet{y[i]});
      nb(y[i]) = unite(nb(y[i]), PointSet{j_k});
    }

  result.Y = Y;
  result.J_plus = J_plus;
  return result;
}

std::optional<CoarsenRefusal> can_coarsen(const Graph& g, const Point& n, Flaw flaw) {
  if (!g.is_node(n)) return CoarsenRefusal::NoSuchNode;
  if (flaw == Flaw::WeakCoarsenGuard) {
    if (g.nbr(n).size() != 4) return CoarsenRefusal::NotARefinedCenter;
    return std::nullopt;
  }
  const std::optional<int> l = refined_center_level(g.size, n);
  if (!l) return CoarsenRefusal::NotARefinedCenter;
  if (g.nbr(n).size() != 4) return CoarsenRefusal::NotARefinedCenter;
  for (const Point& y : g.nbr(n))
    if (!g.is_center(y) || g.level_of(y) != *l + 1) return CoarsenRefusal::ChildrenRefined;
  for (const Point& y : g.nbr(n))
    if (g.nbr(y).size() != 4) return CoarsenRefusal::FinerNeighbor;
  return std::nullopt;
}

CoarsenResult coarsen(Graph& g, const Point& n, Flaw flaw) {
  CoarsenResult result;
  result.refused = can_coarsen(g, n, flaw);
  if (result.refused) return result;

  auto nb = [&g](const Point& v) -> PointSet& { return g.neighbors[v]; };
  int l = 0;
  if (const auto from_position = refined_center_level(g.size, n)) {
    l = *from_position;
  } else {  // only reachable through WeakCoarsenGuard: take the children's level - 1
    const Point& y0 = *g.nbr(n).begin();
    l = g.is_center(y0) ? g.level_of(y0) - 1 : 0;
  }

  // (8a)-(8b)
  const PointSet Y = nb(n);
  PointSet B;
  for (const Point& y_i : Y) B = unite(B, nb(y_i));
  B = minus(B, PointSet{n});
  PointSet side_midpoints;
  for (const Point& b_i : B)
    if (intersect(nb(b_i), Y).size() == 2) side_midpoints.insert(b_i);

  // (9a)-(9f)
  for (const Point& b_i : B) nb(b_i) = minus(nb(b_i), Y);
  for (const Point& y_i : Y) nb(y_i).clear();
  nb(n).clear();
  g.N = minus(g.N, PointSet{n});
  g.C = unite(g.C, PointSet{n});
  g.level[n] = l;
  g.C = minus(g.C, Y);
  for (const Point& y_i : Y) {
    g.neighbors.erase(y_i);
    g.level.erase(y_i);
  }

  // (10a)-(11d)
  PointSet J_minus;
  for (const Point& b_i : side_midpoints)
    if (nb(b_i).size() <= 1) J_minus.insert(b_i);
  B = minus(B, J_minus);
  if (flaw != Flaw::Forget10c && flaw != Flaw::Forget10cOnly) g.N = minus(g.N, J_minus);  // (10c)
  for (const Point& j_i : J_minus) {
    const PointSet x_i = nb(j_i);
    for (const Point& x : x_i) nb(x) = minus(nb(x), PointSet{j_i});
    nb(j_i).clear();
    g.neighbors.erase(j_i);
  }
  if (flaw != Flaw::Forget10c) g.N = minus(g.N, J_minus);  // (11d), repeats (10c)

  // (12a)-(12b)
  nb(n) = B;
  for (const Point& b_i : B) nb(b_i) = unite(nb(b_i), PointSet{n});

  result.Y = Y;
  result.J_minus = J_minus;

  if (flaw == Flaw::CoarsenDifferentState) {
    // A second, valid coarsen somewhere else: the state stays a valid lattice.
    for (const Point& m : PointSet(g.N))
      if (m != n && !bccmis::can_coarsen(g, m)) {
        bccmis::coarsen(g, m);
        break;
      }
  }
  return result;
}

}  // namespace bccmis::mutants
