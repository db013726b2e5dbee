// A graph the checkers must reject, built by hand: the state an unguarded
// refine would make next to a coarser cell.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis::test {

/// lattice 2 1 2, the right cell refined, then its child (10, 2) = [8, 12] x
/// [0, 4] split by hand into four level-2 cells, as the paper's equations
/// do: the level-0 cell (4, 4) is next to cells two levels finer along
/// (8, 0)-(8, 4). The new junctions (12, 2) and (10, 4) are linked as (6b)
/// links them; `coarse_lists_quarter` says whether (4, 4) was handed the
/// quarter point (8, 2) as (6b) would.
inline Graph two_level_jump(bool coarse_lists_quarter) {
  auto link = [](Graph& g, const Point& a, const Point& b) {
    g.neighbors[a].insert(b);
    g.neighbors[b].insert(a);
  };
  Graph g = make_lattice({2, 1, 2});
  EXPECT_TRUE(refine(g, {12, 4}).applied());
  const Point c{10, 2};
  for (const Point p : PointSet(g.nbr(c))) g.neighbors[p].erase(c);
  g.neighbors[c].clear();
  g.C.erase(c);
  g.level.erase(c);
  g.N.insert(c);
  for (const Point yi : {Point{9, 1}, Point{9, 3}, Point{11, 1}, Point{11, 3}}) {
    g.C.insert(yi);
    g.level[yi] = 2;
    for (const std::int64_t dx : {-1, 1})
      for (const std::int64_t dy : {-1, 1}) {
        const Point p{yi.x + dx, yi.y + dy};
        g.N.insert(p);
        link(g, yi, p);
      }
  }
  link(g, {14, 2}, {12, 2});
  link(g, {10, 6}, {10, 4});
  if (coarse_lists_quarter) link(g, {4, 4}, {8, 2});
  return g;
}

}  // namespace bccmis::test
