// The independent structural check of a 3D state, used by every test that
// runs operation sequences: the graph must be exactly the geometric graph of
// its own leaf set (tests/d3/leaf_model.h), the leaves must tile the domain
// and be balanced across faces and edges, and the cardinality facts F1-F3 of
// spec/lattice3d.md §3 must hold. Returns the first problem, or "".
#pragma once

#include <string>

#include "bccmis/d3/graph.h"
#include "leaf_model.h"

namespace bccmis::d3::test {

inline model::Leaves leaves_of(const Graph& g) {
  model::Leaves leaves;
  for (const Point& c : g.C) leaves[c] = g.level.count(c) ? g.level.at(c) : -1;
  return leaves;
}

/// F1-F3 on a graph that already matches its geometry.
inline std::string cardinality_problem(const Graph& g) {
  const model::Leaves leaves = leaves_of(g);
  for (const Point& n : g.N) {
    const std::size_t k = g.nbr(n).size();
    bool pure = true;
    for (const Point& c : g.nbr(n)) pure = pure && model::is_corner(model::cube(g.size, c, leaves.at(c)), n);
    const int inside = model::interior_coordinates(g.size, n);
    if (pure) {
      //= bccmis3d#fact-F1 type=test
      if (k != (std::size_t{1} << inside))
        return "pure node " + to_string(n) + " has " + std::to_string(k) + " cells, not 2^" + std::to_string(inside);
    } else {
      //= bccmis3d#fact-F2 type=test
      if (k != 3 && k != 5 && k != 6 && k != 7)
        return "junction " + to_string(n) + " has " + std::to_string(k) + " cells";
      if (k == 3 && inside == 3) return "junction " + to_string(n) + " with 3 cells inside the domain";
    }
  }
  for (const Point& c : g.C) {
    //= bccmis3d#fact-F3 type=test
    const std::size_t k = g.nbr(c).size();
    if (k < 8 || k > 26) return "cell " + to_string(c) + " has " + std::to_string(k) + " nodes";
  }
  return {};
}

inline std::string state_problem(const Graph& g) {
  if (g.level.size() != g.C.size()) return "level map and C differ in size";
  for (const Point& v : g.N)
    if (g.C.count(v)) return to_string(v) + " is a node and a center";
  for (const auto& [v, nbrs] : g.neighbors)
    if (!g.N.count(v) && !g.C.count(v)) return "neighbor set of the deleted vertex " + to_string(v);
  const model::Leaves leaves = leaves_of(g);
  if (std::string why = model::tiling_problem(g.size, leaves); !why.empty()) return "tiling: " + why;
  const model::GeometricGraph geo = model::geometric_graph(g.size, leaves);
  if (geo.N != g.N) return "N is not the set of leaf corners";
  for (const Point& v : g.C)
    if (g.nbr(v) != geo.nbr.at(v)) return "N(" + to_string(v) + ") is not the nodes on its closed cube";
  for (const Point& v : g.N)
    if (g.nbr(v) != geo.nbr.at(v)) return "N(" + to_string(v) + ") is not the cells whose closed cube contains it";
  if (std::string why = model::balance_problem(g.size, leaves, geo); !why.empty()) return "balance: " + why;
  return cardinality_problem(g);
}

}  // namespace bccmis::d3::test
