// bccmis::d3 invariants, the feature layer (spec/invariants.md, "3D layer 8";
// spec/stuffing.md S32): a stuffed mesh holds the sharp features the mesher
// says it conformed: a mesh vertex at every corner, and every curve covered
// by boundary edges lying on it.
//
// Written from the spec only, like the stuffed-mesh layer: it finds the
// boundary itself (the triangles of exactly one tetrahedron) and measures
// distances along the curves with its own arithmetic (long double). The checks:
//   feature-corner     a mesh vertex within `tolerance` of each corner
//   feature-uncovered  for each curve of length Len, the arc-length intervals
//                      [s(u), s(w)] of the boundary edges uw lying on it
//                      cover [0, Len] (to `tolerance`); uw lies on the curve
//                      when u and w are within `tolerance` of it at different
//                      arc lengths and every curve vertex between them is
//                      within `chord` of the segment uw
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "bccmis/invariants/d3/invariants.h"

namespace bccmis::d3 {

/// What the mesher claims to have conformed (S30), and the tolerances of S32.
struct FeatureClaims {
  std::vector<std::array<double, 3>> corners;
  std::vector<std::vector<std::array<double, 3>>> curves;  ///< polylines
  double tolerance = 0;                                    ///< 1e-9 h
  double chord = 0;                                        ///< h / 4
};

/// The first corner without a vertex, or the first point of a curve that no
/// boundary edge covers, as a Violation of layer 8 naming the corner or the
/// curve (by index) and the point; empty when there is none.
std::optional<Violation> check_feature_conformity(std::span<const std::array<double, 3>> vertices,
                                                  std::span<const std::array<std::uint32_t, 4>> tets,
                                                  const FeatureClaims& claims);

}  // namespace bccmis::d3
