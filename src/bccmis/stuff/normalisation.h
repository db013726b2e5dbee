// bccmis::stuff::normalisation: the map between a shape's coordinates and
// the well-conditioned coordinates the mesher works in (spec/stuffing.md
// S24): a translation t, applied only to a box far from the origin, and a
// power-of-two scale 2^-k that brings the box's longest extent into [1, 2).
#pragma once

#include <memory>

#include "bccmis/stuff/shape.h"

namespace bccmis::stuff {

/// S24: x' = (x - translation) 2^-exponent, and back x = translation + 2^exponent x'.
struct Normalisation {
  Vec3 translation{};
  int exponent = 0;
  Vec3 to_local(const Vec3& p) const;
  Vec3 to_world(const Vec3& p) const;
  /// True when the map back rounds (a translation by a non-zero t).
  bool translates() const { return translation != Vec3{}; }
  bool operator==(const Normalisation&) const = default;
};

/// S24 for the box of a shape. Throws ShapeError when the box is empty, not
/// finite, or its extent overflows a double.
Normalisation normalisation_of(const Bounds& box);

/// `shape` seen through `n` (S24): distances scaled by 2^-k, points mapped by
/// n.to_local. It evaluates `shape` in its own coordinates, so it is only as
/// well conditioned as they are: the built-in shapes and the triangle meshes
/// override Shape::normalised() with shapes built in local coordinates. The
/// result refers to `shape`, which must outlive it.
std::unique_ptr<Shape> view_normalised(const Shape& shape, const Normalisation& n);

/// The converse: a shape built in local coordinates (`local`, owned),
/// presented in its world coordinates through `n`. Its normalised(n) is
/// `local` itself (through the identity), so the mesher sees the shape as it
/// was built; the triangle meshes are read this way (S24).
std::unique_ptr<Shape> placed(std::unique_ptr<Shape> local, const Normalisation& n);

}  // namespace bccmis::stuff
