// bccmis::d3: the 3D lattice in the vocabulary every lattice speaks
// (bccmis/lattice.h). Graph3 models AdaptiveLattice with Point3 as its point
// type and dimension 3; these free functions are found by argument-dependent
// lookup, so the stepper and every tool written against the concept run on
// the 3D lattice unchanged.
#pragma once

#include <cstddef>

#include "bccmis/d3/format.h"
#include "bccmis/d3/graph.h"
#include "bccmis/d3/ops.h"
#include "bccmis/lattice.h"

namespace bccmis::d3 {

inline const LatticeSize3& size_of(const Graph3& g) { return g.size; }
inline bool is_center(const Graph3& g, const Point3& v) { return g.is_center(v); }
inline bool is_node(const Graph3& g, const Point3& v) { return g.is_node(v); }
/// Throws std::out_of_range if c is not a center.
inline int level_of(const Graph3& g, const Point3& c) { return g.level_of(c); }
inline const PointSet3& neighbors(const Graph3& g, const Point3& v) { return g.nbr(v); }
inline const PointSet3& cells(const Graph3& g) { return g.C; }
inline const PointSet3& nodes(const Graph3& g) { return g.N; }
inline std::size_t cell_count(const Graph3& g) { return g.C.size(); }
inline std::size_t node_count(const Graph3& g) { return g.N.size(); }

static_assert(AdaptiveLattice<Graph3>);
static_assert(Graph3::dimension == 3);

}  // namespace bccmis::d3
