// bccmis::stuff::statistics: what `--stats` reports of a stuffed mesh
// (spec/stuffing.md S13): its quality, its volume against the shape's, and
// the Hausdorff distance between its boundary and the shape's surface.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bccmis/d3/mesh.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

/// S13: the Hausdorff distance, sampled both ways (a lower bound of the exact
/// one), computed only when asked (Settings::hausdorff, --hausdorff).
struct Hausdorff {
  bool computed = false;            ///< false: not asked for, every field below as it starts
  double from_boundary = 0;         ///< max |f| over 7 points of every boundary triangle
  double from_surface = -1;         ///< max distance of 20,000 surface samples to the boundary (-1: not computed)
  std::size_t boundary_points = 0;  ///< the points of the boundary sampled (7 a triangle)
  std::size_t surface_samples = 0;  ///< the surface samples (0: not computed)
  double max() const { return std::max(from_boundary, from_surface); }
};

struct Statistics {
  StuffQuality quality;  ///< volume, dihedral angles, histogram, boundary triangles
  Hausdorff hausdorff;
  double shape_volume = 0;
  std::size_t vertices = 0, tetrahedra = 0;
  /// (volume - shape volume) / shape volume, computed in S24's local
  /// coordinates, where both volumes are representable.
  double relative_volume_error = 0;
  double volume_rel_error() const { return relative_volume_error; }
  /// The fraction of tetrahedra with a dihedral angle below 10 degrees.
  double below10() const {
    return tetrahedra ? static_cast<double>(quality.below10) / static_cast<double>(tetrahedra) : 0;
  }
};

/// S13 on `mesh`, a mesh of `shape` whose boundary is `boundary`; the
/// sampled Hausdorff distance only with `hausdorff`. The distance from the
/// surface needs CGAL's triangle distances: without CGAL in the build it is
/// not computed (from_surface stays -1). The pass over the tetrahedra runs
/// on `threads` threads (0: every core), the same result on any number (S13a).
Statistics statistics(const Shape& shape, const d3::TetMeshF& mesh,
                      const std::vector<std::array<std::uint32_t, 3>>& boundary, bool hausdorff = true,
                      int threads = 0);
/// The same from the pass over the `tetrahedra` tetrahedra on `vertices`
/// already made (`pass`, its boundary count not yet set).
Statistics statistics(const Shape& shape, const StuffQuality& pass, const std::vector<Vec3>& vertices,
                      std::size_t tetrahedra, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                      bool hausdorff);

/// S24: statistics computed in local coordinates, in world units: lengths
/// times 2^k, volumes times 2^3k (infinite when they overflow a double).
Statistics to_world(Statistics s, const Normalisation& n);

}  // namespace bccmis::stuff
