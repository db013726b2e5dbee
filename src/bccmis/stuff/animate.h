// bccmis::stuff: a shape moving through a fixed lattice (spec/stuffing.md
// §8): per frame, refine where the surface arrived and coarsen where it
// left, by local lattice operations, then stuff the mesh again.
#pragma once

#include <cstddef>
#include <memory>

#include "bccmis/fast/lattice3.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

/// What one frame did (S15).
struct FrameReport {
  std::size_t refines = 0;   ///< refine operations (the cascade's included)
  std::size_t coarsens = 0;  ///< coarsen operations
  std::size_t leaves = 0;
  double lattice_seconds = 0, stuff_seconds = 0;
};

/// S14: the box a shape covers when translated by t d for t in [0, 1].
Bounds swept_bounds(const Shape& shape, const Vec3& d);

/// S15: the lattice of background() kept up to date under a moving shape,
/// on the fast lattice (fast::Lattice3), stuffed by its flat path.
class MovingLattice {
 public:
  /// The lattice of background_fast(shape at offset 0, fit, options).
  MovingLattice(std::shared_ptr<const Shape> shape, const Fit& fit, const StuffOptions& options);
  /// Moves the shape to `offset` (from its own position): refines the leaves
  /// the surface came near, coarsens the parents it left, and stuffs again.
  FrameReport step(const Vec3& offset);
  const fast::Lattice3& lattice() const { return g_; }
  const Stuffed& stuffed() const { return stuffed_; }
  /// The shape at the current offset.
  const Shape& shape() const { return *moved_; }

 private:
  bool needs(const d3::Point3& c, int level) const;
  std::shared_ptr<const Shape> shape_;
  std::shared_ptr<const Shape> moved_;
  Fit fit_;
  StuffOptions options_;
  fast::Lattice3 g_;
  Stuffed stuffed_;
};

}  // namespace bccmis::stuff
