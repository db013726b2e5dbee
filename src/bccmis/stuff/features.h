// bccmis::stuff::detect_features: the sharp features of a triangle mesh
// (spec/stuffing.md S29): the edges where the surface turns by more than
// the feature angle, the corners where such edges end or meet, and the
// curves that chain the edges from corner to corner.
//
//   const auto f = bccmis::stuff::detect_features(shape.surface_triangles(), 60);
//   // f.edges: 12 for a cube; f.corners: its 8 vertices; f.curves: its 12 edges
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "bccmis/stuff/shape.h"

namespace bccmis::stuff {

/// S29's default feature angle (degrees), CGAL's for detect_features.
inline constexpr double kDefaultFeatureAngle = 60;

/// A feature curve: a polyline through the vertices of its feature edges;
/// a loop repeats its first point at the end.
struct FeatureCurve {
  std::vector<Vec3> points;
  bool closed = false;
  double length() const;
};

/// What S29 found.
struct Features {
  double angle = kDefaultFeatureAngle;  ///< phi, degrees
  std::size_t edges = 0;                ///< the feature edges
  std::vector<Vec3> corners;            ///< in coordinate order
  std::vector<FeatureCurve> curves;     ///< in the order of their first feature edge
};

/// S29 on `triangles` (each oriented; vertices welded by exact equality of
/// their coordinates; a triangle with two equal corners is left out), with
/// the feature angle `angle` in degrees.
Features detect_features(std::span<const std::array<Vec3, 3>> triangles, double angle = kDefaultFeatureAngle);

/// The point of a curve nearest to x: its distance d(x, C), its arc length
/// s(x, C) from the curve's start, and the point itself (S30, S32).
struct CurvePoint {
  double distance = 0;
  double s = 0;
  Vec3 point{};
};
CurvePoint nearest_on_curve(const FeatureCurve& curve, const Vec3& x);
/// The same for the segment [a, b]; s is the parameter t in [0, 1] of the point.
CurvePoint nearest_on_segment(const Vec3& a, const Vec3& b, const Vec3& x);

}  // namespace bccmis::stuff
