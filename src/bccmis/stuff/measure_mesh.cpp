// S13 and S33 on any mesh of a shape (measure_mesh.h).
#include "bccmis/stuff/measure_mesh.h"

#include <cmath>

#include "bccmis/stuff/conform_features.h"
#include "bccmis/stuff/features.h"
#include "bccmis/stuff/normalisation.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

MeshMeasures measure_mesh(const Shape& world, d3::TetMeshF mesh, std::optional<double> feature_angle) {
  // S24: the shape and the mesh in the local coordinates the statistics are
  // computed in for bccmis's own meshes.
  const Normalisation n = normalisation_of(world.bounds());
  const std::unique_ptr<Shape> local = world.normalised(n);
  for (Vec3& v : mesh.vertices) v = n.to_local(v);
  const auto boundary = boundary_triangles(mesh);
  MeshMeasures m;
  m.statistics = to_world(statistics(*local, mesh, boundary, true), n);
  if (feature_angle) {
    // S29 on the shape's triangles, S33 against the mesh's boundary edges;
    // the grid of S33's search in cubes of the boundary's mean edge length.
    const Features features = detect_features(local->surface_triangles(), *feature_angle);
    double length = 0;
    for (const auto& f : boundary)
      for (std::size_t i = 0; i < 3; ++i) {
        const Vec3 &a = mesh.vertices[f[i]], &b = mesh.vertices[f[(i + 1) % 3]];
        length += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      }
    const double side = boundary.empty() ? 1 : length / static_cast<double>(3 * boundary.size());
    m.feature_curves = features.curves.size();
    m.feature_corners = features.corners.size();
    m.feature_distance = std::ldexp(feature_distance(mesh, boundary, features, side), n.exponent);
  }
  return m;
}

}  // namespace bccmis::stuff
