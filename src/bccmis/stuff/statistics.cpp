// S13's statistics (statistics.h).
#include "bccmis/stuff/statistics.h"

#include <cmath>

#if BCCMIS_HAVE_STUFF_SURFACE
#include "bccmis/stuff/surface.h"
#endif

namespace bccmis::stuff {

namespace {

/// S13: the boundary's side of the Hausdorff distance, |f| at the three
/// vertices, three edge midpoints and the centroid of every triangle.
double from_boundary(const Shape& shape, const std::vector<Vec3>& vertices,
                     const std::vector<std::array<std::uint32_t, 3>>& boundary) {
  double d = 0;
  for (const auto& t : boundary) {
    const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const auto mix = [](const Vec3& x, const Vec3& y, const Vec3& z, double u, double v, double w) {
      return Vec3{u * x[0] + v * y[0] + w * z[0], u * x[1] + v * y[1] + w * z[1], u * x[2] + v * y[2] + w * z[2]};
    };
    for (const Vec3& p : {a, b, c, mix(a, b, c, 0.5, 0.5, 0), mix(a, b, c, 0, 0.5, 0.5), mix(a, b, c, 0.5, 0, 0.5),
                          mix(a, b, c, 1.0 / 3, 1.0 / 3, 1.0 / 3)})
      d = std::max(d, std::abs(shape.signed_distance(p)));
  }
  return d;
}

Hausdorff hausdorff(const Shape& shape, const std::vector<Vec3>& vertices,
                    const std::vector<std::array<std::uint32_t, 3>>& boundary) {
  Hausdorff h;
  h.computed = true;
  h.from_boundary = from_boundary(shape, vertices, boundary);
  h.boundary_points = 7 * boundary.size();
#if BCCMIS_HAVE_STUFF_SURFACE
  // S13: the surface's side, 20,000 samples (seed 1) to the boundary triangles.
  if (!boundary.empty()) {
    h.surface_samples = 20000;
    h.from_surface = max_distance_to_triangles(shape.sample_surface(h.surface_samples, 1), vertices, boundary);
  }
#endif
  return h;
}

}  // namespace

Statistics statistics(const Shape& shape, const d3::TetMeshF& mesh,
                      const std::vector<std::array<std::uint32_t, 3>>& boundary, bool with_hausdorff, int threads) {
  return statistics(shape, quality(mesh, std::size_t{0}, threads), mesh.vertices, mesh.tets.size(), boundary,
                    with_hausdorff);
}

Statistics statistics(const Shape& shape, const StuffQuality& pass, const std::vector<Vec3>& vertices,
                      std::size_t tetrahedra, const std::vector<std::array<std::uint32_t, 3>>& boundary,
                      bool with_hausdorff) {
  Statistics s;
  s.quality = pass;
  s.quality.boundary_triangles = boundary.size();
  if (with_hausdorff) s.hausdorff = hausdorff(shape, vertices, boundary);
  s.shape_volume = shape.volume();
  s.vertices = vertices.size();
  s.tetrahedra = tetrahedra;
  s.relative_volume_error = (s.quality.volume - s.shape_volume) / s.shape_volume;
  return s;
}

Statistics to_world(Statistics s, const Normalisation& n) {
  const auto length = [&](double x) { return std::ldexp(x, n.exponent); };
  const auto volume = [&](double x) { return std::ldexp(x, 3 * n.exponent); };
  s.hausdorff.from_boundary = length(s.hausdorff.from_boundary);
  if (s.hausdorff.from_surface >= 0) s.hausdorff.from_surface = length(s.hausdorff.from_surface);
  s.quality.volume = volume(s.quality.volume);
  s.shape_volume = volume(s.shape_volume);
  return s;
}

}  // namespace bccmis::stuff
