// A shape moving through a fixed lattice (spec/stuffing.md S14, S15).
#include "bccmis/stuff/animate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "bccmis/apps/balance3.h"
#include "bccmis/d3/ops.h"

namespace bccmis::stuff {

Bounds swept_bounds(const Shape& shape, const Vec3& d) {
  Bounds b = shape.bounds();
  for (std::size_t i = 0; i < 3; ++i) {
    b.lo[i] = std::min(b.lo[i], b.lo[i] + d[i]);
    b.hi[i] = std::max(b.hi[i], b.hi[i] + d[i]);
  }
  return b;
}

namespace {
StuffOptions with_level(StuffOptions o, int level) {
  o.max_level = level;
  return o;
}
double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

MovingLattice::MovingLattice(std::shared_ptr<const Shape> shape, const Fit& fit, const StuffOptions& options)
    : shape_(std::move(shape)),
      moved_(shape_),
      fit_(fit),
      options_(with_level(options, fit.size.L)),
      g_(background_fast(*moved_, fit_, options_)) {
  stuffed_ = stuff(*moved_, fit_, g_, options_);
}

// S3's test for a cell of `level` centered at c, for the shape where it is now.
bool MovingLattice::needs(const d3::Point3& c, int level) const {
  if (level >= fit_.size.L) return false;
  if (level < options_.min_level) return true;
  const double r = 0.5 * static_cast<double>(d3::cell_side(fit_.size, level)) * fit_.scale;
  return std::abs(moved_->signed_distance(fit_.to_space(c))) <= std::sqrt(3.0) * r + 4 * fit_.h;
}

FrameReport MovingLattice::step(const Vec3& offset) {
  FrameReport report;
  moved_ = translated(shape_, offset);
  const auto t0 = std::chrono::steady_clock::now();
  // S15: refine where the surface arrived, until no leaf passes S3's test.
  for (bool changed = true; changed;) {
    changed = false;
    const std::vector<d3::Point3> cells = g_.cells();
    for (const d3::Point3& c : cells)
      if (g_.is_center(c) && needs(c, g_.level_of(c))) {
        report.refines += d3::refine_balanced(g_, c).refined.size();
        changed = true;
      }
  }
  // Then coarsen every parent the surface left: a node that coarsen accepts
  // (its 8 cells are leaves, siblings, and balance allows) whose parent cell
  // fails S3's test; until none is left.
  for (bool changed = true; changed;) {
    changed = false;
    const std::vector<d3::Point3> nodes = g_.nodes();
    for (const d3::Point3& n : nodes) {
      if (!g_.is_node(n) || g_.can_coarsen(n)) continue;
      const std::optional<int> parent = d3::refined_center_level(g_.size(), n);
      if (!parent || needs(n, *parent)) continue;
      g_.coarsen(n);
      ++report.coarsens;
      changed = true;
    }
  }
  report.lattice_seconds = since(t0);
  report.leaves = g_.cell_count();
  const auto t1 = std::chrono::steady_clock::now();
  stuffed_ = stuff(*moved_, fit_, g_, options_);
  report.stuff_seconds = since(t1);
  return report;
}

}  // namespace bccmis::stuff
