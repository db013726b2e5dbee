// The moving disk of bench/workloads.h (MovingFeature: same disk path, same
// leaf sets after every frame), with work proportional to what changes:
//
//   - batch build, level by level: refine the level-l cells meeting the disk
//     (refine_balanced cascade where a coarser edge-neighbor is in the way),
//     l = 0 .. L-1, enumerating only the cells that meet the disk, row by row;
//   - a frame visits the crescents only: for coarsening, the level-l cells
//     within R + 1.5 s_l of the old disk that do not meet the new disk (finest
//     level first); for refinement, the level-L cells meeting the new disk
//     but not the old one. MovingFeature scans the whole box around the old
//     and new disk instead (every level-L cell of the disk each frame), so
//     its frame costs O(disk area) even when a few cells change.
//
// bench_p4est --bccmis_verify replays both against each other and against
// p4est's refine + coarsen + balance, comparing leaf sets every frame.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "workloads.h"

namespace bccmis::bench {

template <AdaptiveLattice L>
class LocalFeature {
 public:
  /// `reserve_cells` > 0: room for that many cells before the build (the
  /// fast lattice's reserve(); the pools and the position table then never
  /// grow during the build).
  LocalFeature(const LatticeSize& size, double radius, int frames_per_turn, std::size_t reserve_cells = 0)
      : size_(size), g_(size), radius_(radius), frames_(frames_per_turn) {
    if constexpr (requires(L & s) { s.reserve(reserve_cells); })
      if (reserve_cells > 0) g_.reserve(reserve_cells);
    side_ = static_cast<double>(level0_side(size));
    disk_ = position(0);
    for (int l = 0; l < size_.L; ++l)
      for_cells(l, disk_, radius_, nullptr, 0, [&](const Point& c) {
        if (is_center(g_, c) && level_of(g_, c) == l) refine_balanced(c, l);
      });
  }

  /// Moves the disk one frame on and adapts; returns the operations applied.
  std::size_t frame() {
    ops_ = 0;
    const Disk old = disk_;
    frame_ = (frame_ + 1) % frames_;
    disk_ = position(frame_);
    // A refined level-l cell of the balanced mesh around a disk is within
    // D_l < sqrt(2) s_l of it: it contains the disk (l < L), or it touches a
    // refined level-(l+1) cell, so D_l <= D_(l+1) + sqrt(2) s_(l+1), D_(L-1)
    // = 0, and the s_k halve. Cells beyond R + 1.5 s_l of the old disk were
    // not refined and are skipped.
    for (int l = size_.L - 1; l >= 0; --l) {
      const double margin = radius_ + 1.5 * static_cast<double>(cell_side(size_, l));
      for_cells(l, old, margin, &disk_, radius_, [&](const Point& n) {
        if (!can_coarsen(g_, n)) ops_ += coarsen(g_, n).applied();
      });
    }
    for_cells(size_.L, disk_, radius_, &old, radius_, [&](const Point& p) { refine_to(p, size_.L); });
    return ops_;
  }

  const L& state() const { return g_; }

 private:
  struct Disk {
    double x, y;
  };

  Disk position(int frame) const {  // as MovingFeature
    const double cx = static_cast<double>(size_.W) * side_ / 2, cy = static_cast<double>(size_.H) * side_ / 2;
    const double r = 0.3 * std::min(static_cast<double>(size_.W), static_cast<double>(size_.H)) * side_;
    const double a = 2 * std::numbers::pi * frame / frames_;
    return {cx + r * std::cos(a), cy + r * std::sin(a)};
  }

  // The column range [i0, i1] of the level cells (side s) in row j that meet
  // the disk (d, r) (MovingFeature::meets: the closest point of the cell is
  // within r of d); empty when i0 > i1.
  std::pair<std::int64_t, std::int64_t> row_range(std::int64_t j, std::int64_t s, const Disk& d, double r) const {
    const double h = static_cast<double>(s) / 2;
    const double cy = static_cast<double>(j * s) + h;
    const double dy = std::max(0.0, std::abs(cy - d.y) - h);
    if (dy > r) return {1, 0};
    const double w = std::sqrt(r * r - dy * dy);
    // |cx - d.x| - h <= w with cx = i s + h: i s in [d.x - w - 2h, d.x + w].
    auto i0 = static_cast<std::int64_t>(std::ceil((d.x - w) / static_cast<double>(s) - 1));
    auto i1 = static_cast<std::int64_t>(std::floor((d.x + w) / static_cast<double>(s)));
    // Guard the floating-point ends with the exact predicate.
    const auto meets = [&](std::int64_t i) {
      const double dx = std::max(0.0, std::abs(static_cast<double>(i * s) + h - d.x) - h);
      return dx * dx + dy * dy <= r * r;
    };
    while (!meets(i0) && i0 <= i1) ++i0;
    while (meets(i0 - 1)) --i0;
    while (!meets(i1) && i1 >= i0) --i1;
    while (meets(i1 + 1)) ++i1;
    return {i0, i1};
  }

  // Calls f(center) for the level-l cells inside the domain that meet disk
  // (d, r) and, when `minus` is given, do not meet disk (*minus, minus_r);
  // row by row, left to right.
  template <class F>
  void for_cells(int l, const Disk& d, double r, const Disk* minus, double minus_r, F&& f) const {
    const std::int64_t s = cell_side(size_, l);
    const std::int64_t columns = size_.W << l, rows = size_.H << l;
    const auto j0 =
        std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor((d.y - r) / static_cast<double>(s))) - 1);
    const auto j1 =
        std::min<std::int64_t>(rows - 1, static_cast<std::int64_t>(std::floor((d.y + r) / static_cast<double>(s))) + 1);
    for (std::int64_t j = j0; j <= j1; ++j) {
      auto [a0, a1] = row_range(j, s, d, r);
      a0 = std::max<std::int64_t>(a0, 0);
      a1 = std::min<std::int64_t>(a1, columns - 1);
      std::pair<std::int64_t, std::int64_t> b{1, 0};
      if (minus) b = row_range(j, s, *minus, minus_r);
      for (std::int64_t i = a0; i <= a1; ++i) {
        if (b.first <= b.second && i >= b.first && i <= b.second) {
          i = b.second;  // skip the cells meeting `minus`
          continue;
        }
        f(Point{i * s + s / 2, j * s + s / 2});
      }
    }
  }

  // LeafRefiner (workloads.h), locating from level L up: the leaves a frame
  // visits are fine.
  LeafRefiner<L> refiner() { return LeafRefiner<L>(g_, size_, LeafRefiner<L>::Search::FinestFirst, ops_); }
  void refine_to(const Point& p, int target) { refiner().refine_to(p, target); }
  bool refine_balanced(const Point& c, int level) { return refiner().refine_balanced(c, level); }

  LatticeSize size_;
  L g_;
  double radius_;
  int frames_;
  double side_ = 0;
  int frame_ = 0;
  Disk disk_{0, 0};
  std::size_t ops_ = 0;
};

}  // namespace bccmis::bench
