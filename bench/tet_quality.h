// Quality measures of a tetrahedral mesh, computed in long double from the
// vertex positions alone, so that every mesher's output is measured the same
// way: the six dihedral angles of a tetrahedron, its signed volume, and a
// mesh summary (min/max dihedral angle, fraction of tetrahedra with an angle
// below 10 degrees, volume, inverted tetrahedra). Also the enclosed volume of
// a closed triangulated surface. Used by stuff_peers (bench/RESULTS.md,
// "Peers for isosurface stuffing").
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace bccmis::bench {

using Vec3L = std::array<long double, 3>;

inline Vec3L sub(const Vec3L& a, const Vec3L& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3L cross(const Vec3L& a, const Vec3L& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline long double dot(const Vec3L& a, const Vec3L& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline long double norm(const Vec3L& a) { return std::sqrt(dot(a, a)); }

// Six times the signed volume: det(p1 - p0, p2 - p0, p3 - p0). Positive when
// p3 lies on the side of the plane (p0, p1, p2) that its normal
// (p1 - p0) x (p2 - p0) points to: the positive orientation.
inline long double orient6(const Vec3L& p0, const Vec3L& p1, const Vec3L& p2, const Vec3L& p3) {
  return dot(cross(sub(p1, p0), sub(p2, p0)), sub(p3, p0));
}

// The interior dihedral angles (degrees) of the tetrahedron p, one per edge in
// the order (0,1) (0,2) (0,3) (1,2) (1,3) (2,3). At edge (i, j) with the other
// two vertices k, l: the normals of the faces (i, j, k) and (i, j, l) taken as
// e x (pk - pi) and e x (pl - pi), e = pj - pi, are the projections of the two
// faces onto the plane orthogonal to e turned by the same quarter turn about
// e, so the angle between them is the dihedral angle; atan2 of |n1 x n2| and
// n1 . n2 keeps it accurate near 0 and 180 degrees. A degenerate face gives 0.
inline std::array<long double, 6> dihedral_angles(const std::array<Vec3L, 4>& p) {
  static constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                       {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  const long double rad_to_deg = 180.0L / 3.141592653589793238462643383279502884L;
  std::array<long double, 6> out{};
  for (int e = 0; e < 6; ++e) {
    const Vec3L& pi = p[static_cast<std::size_t>(kEdges[e][0])];
    const Vec3L edge = sub(p[static_cast<std::size_t>(kEdges[e][1])], pi);
    const Vec3L n1 = cross(edge, sub(p[static_cast<std::size_t>(kEdges[e][2])], pi));
    const Vec3L n2 = cross(edge, sub(p[static_cast<std::size_t>(kEdges[e][3])], pi));
    out[static_cast<std::size_t>(e)] = std::atan2(norm(cross(n1, n2)), dot(n1, n2)) * rad_to_deg;
  }
  return out;
}

struct MeshQuality {
  std::size_t tetrahedra = 0;
  long double min_dihedral = 0;  // degrees, over all tetrahedra
  long double max_dihedral = 0;
  std::size_t below10 = 0;   // tetrahedra with some dihedral angle < 10 degrees
  std::size_t inverted = 0;  // tetrahedra with orient6 <= 0
  long double volume = 0;    // sum of signed volumes
};

// Summary of tetrahedra given as indices into points.
inline MeshQuality measure(const std::vector<Vec3L>& points, const std::vector<std::array<std::size_t, 4>>& tets) {
  MeshQuality q;
  q.tetrahedra = tets.size();
  q.min_dihedral = tets.empty() ? 0 : 180;
  for (const auto& t : tets) {
    const std::array<Vec3L, 4> p{points[t[0]], points[t[1]], points[t[2]], points[t[3]]};
    const long double o = orient6(p[0], p[1], p[2], p[3]);
    if (o <= 0) ++q.inverted;
    q.volume += o / 6;
    bool below = false;
    for (const long double a : dihedral_angles(p)) {
      if (a < q.min_dihedral) q.min_dihedral = a;
      if (a > q.max_dihedral) q.max_dihedral = a;
      if (a < 10) below = true;
    }
    if (below) ++q.below10;
  }
  return q;
}

// The volume enclosed by a closed, outward-oriented triangulated surface:
// the signed volumes of the tetrahedra (origin, a, b, c) summed.
inline long double enclosed_volume(const std::vector<Vec3L>& points,
                                   const std::vector<std::array<std::size_t, 3>>& tris) {
  long double v = 0;
  for (const auto& t : tris) v += dot(points[t[0]], cross(points[t[1]], points[t[2]]));
  return v / 6;
}

}  // namespace bccmis::bench
