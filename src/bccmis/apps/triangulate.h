// bccmis apps: the triangle mesh of a lattice (every cell's fan: center +
// boundary nodes in counter-clockwise order, spec/apps.md). Its OBJ, PLY and
// VTK .vtu writers are in bccmis/io/.
#pragma once

#include <functional>

#include "bccmis/graph.h"
#include "bccmis/triangle_mesh.h"

namespace bccmis::fast {
class Lattice;
}

namespace bccmis {

/// The fan triangulation of g (one triangle per stored center-node edge),
/// with z = height(vertex position). The same mesh from either lattice.
TriangleMesh triangulate(const Graph& g, const std::function<double(const Point&)>& height);
TriangleMesh triangulate(const fast::Lattice& g, const std::function<double(const Point&)>& height);

}  // namespace bccmis
