// bccmis::stuff: the shapes that isosurface stuffing meshes (spec/stuffing.md §1).
//
// A shape is a closed region given by a signed distance: negative inside,
// positive outside, zero on its surface. Stuffing reads it only through this
// interface: the sign at lattice vertices, the crossing point on a lattice
// edge whose ends have opposite signs, the bounding box that the background
// lattice is fitted to, and (for the statistics) its volume and samples of
// its surface.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace bccmis::stuff {

using Vec3 = std::array<double, 3>;
struct SoupReport;     // soup_report.h
struct Normalisation;  // normalisation.h

/// An axis-aligned box, lo <= hi componentwise.
struct Bounds {
  Vec3 lo{}, hi{};
};

/// What S27 compares the mesh's boundary with: the number of connected
/// components of a shape's surface, and the smallest over them of the
/// thinnest extent of the component's bounding box (the size S27's hint
/// names a level for).
struct SurfaceComponents {
  std::size_t count = 0;
  double thinnest = 0;
};

class Shape {
 public:
  virtual ~Shape() = default;
  /// Distance to the surface, negative inside. For a triangle mesh the sign
  /// comes from exact predicates; the magnitude is a double.
  virtual double signed_distance(const Vec3& p) const = 0;
  /// |signed_distance(p)|, for tests that need no sign (S3, S16); shapes
  /// whose sign costs more than their distance compute it without the sign.
  virtual double distance(const Vec3& p) const { return std::abs(signed_distance(p)); }
  /// Whether distance() is 1-Lipschitz, |distance(p) - distance(q)| <=
  /// |p - q| up to rounding (spec/stuffing.md S37, fact 1): the distance to
  /// the surface itself, or a minimum of such. False: only a lower bound.
  virtual bool distance_is_lipschitz() const { return false; }
  /// distance(p), and a point q of the surface that attains it, when the
  /// shape has one (spec/stuffing.md S39): distance(x) <= |x - q| for every
  /// x, up to rounding. The distance is distance(p)'s, bit for bit.
  struct Nearest {
    double distance = 0;
    std::optional<Vec3> point;
  };
  virtual Nearest nearest(const Vec3& p) const { return {distance(p), std::nullopt}; }
  /// The sign of signed_distance(p): -1 inside, 0 on the surface, 1 outside
  /// (S5); shapes whose distance costs more than their sign compute it alone.
  virtual int side(const Vec3& p) const {
    const double f = signed_distance(p);
    return (f > 0) - (f < 0);
  }
  /// For a segment [a, b] whose ends lie on opposite sides (or one on the
  /// surface): a parameter t in [0, 1] with a + t (b - a) on the surface.
  virtual double crossing(const Vec3& a, const Vec3& b) const = 0;
  /// A box holding the whole shape.
  virtual Bounds bounds() const = 0;
  /// The enclosed volume.
  virtual double volume() const = 0;
  /// n points on the surface, spread evenly by area, the same for the same seed.
  virtual std::vector<Vec3> sample_surface(std::size_t n, std::uint64_t seed) const = 0;
  /// What the inspection of a triangle-mesh file read by the default path
  /// found and repaired (spec/stuffing.md S21-S22); nullptr for the other
  /// shapes and for --strict.
  virtual const SoupReport* soup_report() const { return nullptr; }
  /// The same shape in the mesher's coordinates (spec/stuffing.md S24):
  /// x' = (x - t) 2^-k, distances times 2^-k. By default a view that
  /// evaluates this shape in its own coordinates (normalisation.h); shapes
  /// that can, rebuild themselves in the local coordinates, so that no
  /// computation sees a number far outside [2^-60, 2^60]. The result may
  /// refer to this shape, which must outlive it.
  virtual std::unique_ptr<Shape> normalised(const Normalisation& n) const;
  /// The connected components of the surface, when the shape knows them
  /// (S27): the built-in shapes and clean triangle meshes.
  virtual std::optional<SurfaceComponents> surface_components() const { return std::nullopt; }
  /// The triangles of the surface, each oriented outward, when the shape is
  /// a triangle mesh (after S21-S23's repairs; S29 finds its features in
  /// them); empty for the other shapes.
  virtual std::vector<std::array<Vec3, 3>> surface_triangles() const { return {}; }
  /// One line naming the shape for messages and --stats ("sphere r=1", "mesh elephant.off: 2775 triangles").
  virtual std::string describe() const = 0;
};

/// A crossing of [a, b] by bisection on the sign of s.signed_distance: 60
/// halvings bring the bracket below 2^-60 of the segment; 0 when a is on
/// the surface. For shapes without a closed-form crossing.
double bisect_crossing(const Shape& s, const Vec3& a, const Vec3& b);

/// A sphere of radius r (r > 0) around c.
std::unique_ptr<Shape> make_sphere(const Vec3& c, double r);

/// A torus around the z axis through c: tube radius r around a circle of
/// radius R (0 < r < R).
std::unique_ptr<Shape> make_torus(const Vec3& c, double R, double r);

/// Two spheres of radius r around a and b, united (a shape with a neck when
/// they overlap, two components when they do not).
std::unique_ptr<Shape> make_spheres(const Vec3& a, const Vec3& b, double r);

/// The same shape translated by d (its samples, bounds and distances moved).
std::unique_ptr<Shape> translated(std::shared_ptr<const Shape> s, const Vec3& d);

/// A built-in shape by name and parameters (spec/stuffing.md S1):
///   sphere[:r=R]                 radius R (1), centered at the origin
///   torus[:R=A,r=B]              ring radius A (1), tube radius B (0.4), axis z
///   spheres[:r=R,d=D]            two spheres of radius R (0.7) at x = -D/2 and
///                                x = D/2 (D = 1), united
/// Throws ShapeError naming an unknown shape, an unknown or repeated
/// parameter, a value that is not a number, or one out of range.
std::unique_ptr<Shape> make_builtin(const std::string& spec);

/// A refused shape or input file: what is wrong, and where (file:line:col when a file).
class ShapeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bccmis::stuff
