// Layer 6 of the 3D checker: CGAL as an external referee of a tetrahedral
// mesh of a 3D lattice (spec/invariants.md, "3D layer 6").
//
// The tets are read with CGAL's exact predicates (Epeck; every int64
// coordinate is converted exactly). Then, in this order:
//   cgal-orientation  CGAL::orientation of some tet (in list order) is not
//                     POSITIVE
//   cgal-invalid      the tets, loaded into a CGAL Triangulation_3 by CGAL's
//                     tet-soup loader (CGAL/Mesh_3/tet_soup_to_c3t3.h,
//                     build_triangulation), do not make a valid triangulation
//                     (a triangle of three or more tets, an invalid data
//                     structure, a badly oriented cell, or a cell count that
//                     differs from the list)
//   cgal-delaunay     on a uniform lattice (every leaf of the same level), a
//                     tet with no hull vertex is not a cell of CGAL's
//                     Delaunay_triangulation_3 of N ∪ C
// Layer 5 (check_mesh) is the authority; the caller runs this after it passed,
// but it is safe on any graph and any list of tets.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>

#include "bccmis/invariants/d3/invariants.h"

namespace bccmis::d3 {

/// The first layer-6 problem of `tets` as a mesh of g, or nothing.
std::optional<Violation> find_tetrahedralization_violation(const Graph& g, std::span<const Tet> tets);

/// Loads `tets` into a CGAL Triangulation_3 with the loader of cgal-invalid
/// (exact kernel, Epeck) and calls held(finite cells) while the triangulation
/// is alive and every temporary of the load is freed, so that a caller can
/// measure what the triangulation holds (d3_bench_memory). Returns the finite
/// cell count, or nothing when the loader refuses the tets.
std::optional<std::size_t> hold_triangulation(std::span<const Tet> tets, const std::function<void(std::size_t)>& held);

}  // namespace bccmis::d3
