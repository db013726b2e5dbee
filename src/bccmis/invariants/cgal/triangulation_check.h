// Layer 5 of the checker: CGAL's exact constrained Delaunay triangulation as an
// external referee (Erleben 2009, §1 ¶6 "the triangulation is the Delaunay
// complex of the interlaced grid nodes" and §2 eq. (1)).
//
// All vertices N ∪ C are inserted into a CGAL constrained Delaunay
// triangulation over Epeck (exact), with every graph edge (c, n) and every
// hull edge of eq. (1) (consecutive boundary nodes of each cell, in angular
// order around its center) as a constraint. Then, in this order:
//   constraint-crossing  two constraints cross (CGAL had to add a vertex)
//   missing-edge         a graph or hull edge is not an edge of CGAL's
//                        triangulation (a vertex lies on it)
//   extra-edge           CGAL's triangulation has an edge that is neither
//   hull-domain          the triangulated region (the vertices' convex hull)
//                        is not the domain rectangle (checked first for
//                        vertices outside the domain)
//   triangle-count       the triangle count differs from Σ|𝒩(c)| (one star
//                        triangle per cell boundary edge) or from Euler's
//                        formula 2V - h - 2 (h vertices on the hull)
//   not-delaunay         an edge is not locally Delaunay by the exact
//                        side_of_oriented_circle test (cocircular is allowed)
// The caller runs this only after layers 1-4 passed (find_violation(g, 4)),
// but it is safe on any graph whose lattice size is valid.
#pragma once

#include <optional>

#include "bccmis/invariants/invariants.h"

namespace bccmis {

std::optional<Violation> find_triangulation_violation(const Graph& g);

}  // namespace bccmis
