// bccmis::io: the orientation test the tetrahedral mesh readers take.
#pragma once

#include "bccmis/d3/tet_mesh.h"

namespace bccmis::io {

/// The sign (-1, 0 or 1) of det[b - a, c - a, d - a], exactly: the test by
/// which a reader takes a tetrahedron as positively oriented.
using Orientation = int (*)(const d3::Vec3& a, const d3::Vec3& b, const d3::Vec3& c, const d3::Vec3& d);

}  // namespace bccmis::io
