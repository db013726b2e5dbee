// A moving sphere on a 3D lattice (bench_p8est): every leaf meeting the ball
// has level L, the rest is the coarsest edge-balanced mesh around it. The
// ball crosses the box along x and back (a triangle wave), `speed` level-L
// cube sides a frame.
//
//   - batch build, level by level: refine the level-l cells meeting the ball
//     (with the balance cascade where a coarser face- or edge-neighbor is in
//     the way), l = 0 .. L-1, enumerating only the cells that meet the ball,
//     row by row;
//   - a frame (spec/lattice3d.md §9.11) coarsens, finest level first, from
//     the level-(L-1) cubes the ball left, then tries only the coarser cubes
//     touching a cube it coarsened (C1, C2); then refines to level L the
//     level-(L-1) cubes the ball reached. Between frames it keeps nothing
//     but the lattice: no table of the leaves near the ball to update.
//
// bench_p8est --bccmis_verify compares the leaf sets with p8est's refine +
// coarsen + balance(P8EST_CONNECT_EDGE) after every frame.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "bccmis/d3/point.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis::d3::bench {

/// The ball's path and the predicate both sides share.
struct Ball {
  double x = 0, y = 0, z = 0;
};

/// The ball center at `frame` for a box of the given size: y and z at the
/// box center, x a triangle wave between a quarter and three quarters of the
/// box's width, `speed` level-L cell sides a frame.
inline Ball ball_position(const d3::LatticeSize& size, int frame, int speed) {
  const double S = static_cast<double>(d3::level0_side(size));
  const double x0 = 0.25 * static_cast<double>(size.W) * S, x1 = 0.75 * static_cast<double>(size.W) * S;
  const double step = static_cast<double>(d3::cell_side(size, size.L)) * speed;
  const auto frames = static_cast<std::int64_t>(std::llround((x1 - x0) / step));  // one pass
  const std::int64_t t = frame % (2 * frames);
  const std::int64_t u = t <= frames ? t : 2 * frames - t;
  return {x0 + static_cast<double>(u) * step, static_cast<double>(size.H) * S / 2, static_cast<double>(size.D) * S / 2};
}

/// Whether the cube centered at c with half side h meets the ball (b, r):
/// its closest point is within r of b.
inline bool cube_meets(const d3::Point& c, double h, const Ball& b, double r) {
  const double dx = std::max(0.0, std::abs(static_cast<double>(c.x) - b.x) - h);
  const double dy = std::max(0.0, std::abs(static_cast<double>(c.y) - b.y) - h);
  const double dz = std::max(0.0, std::abs(static_cast<double>(c.z) - b.z) - h);
  return dx * dx + dy * dy + dz * dz <= r * r;
}

template <AdaptiveLattice L>
class LocalFeature {
 public:
  /// `reserve_cells` > 0: room for that many cells before the build.
  LocalFeature(const d3::LatticeSize& size, double radius, int speed, std::size_t reserve_cells = 0)
      : size_(size), g_(size), radius_(radius), speed_(speed) {
    if constexpr (requires(L & s) { s.reserve(reserve_cells); })
      if (reserve_cells > 0) g_.reserve(reserve_cells);
    ball_ = ball_position(size_, 0, speed_);
    for (int l = 0; l < size_.L; ++l)
      for_cells(l, ball_, radius_, nullptr, 0, [&](const d3::Point& c) {
        if (is_center(g_, c) && level_of(g_, c) == l) refine_balanced(c, l);
      });
  }

  /// Moves the ball one frame on and adapts; returns the operations applied.
  /// spec/lattice3d.md §9.11: the coarsenings start at the level-(L-1)
  /// cubes the ball left and spread only from a cube just coarsened to the
  /// coarser cubes touching it (S1); the refinements start at the
  /// level-(L-1) cubes the ball reached.
  std::size_t frame() {
    ops_ = 0;
    const Ball old = ball_;
    ball_ = ball_position(size_, ++frame_, speed_);
    const int finest = size_.L - 1;
    if (finest < 0) return 0;  // depth 0: no operation applies
    // §9.11 C1: the level-(L-1) cubes meeting the old ball, not the new one.
    todo_.clear();
    for_cells(finest, old, radius_, &ball_, radius_, [&](const d3::Point& n) { todo_.push_back(n); });
    // In a list, with the lattice's look-ahead (§9.12); every seed spreads
    // (§9.11 C2: a seed refused adds candidates that are refused too).
    ops_ += coarsen_each(g_, todo_);
    next_.clear();
    if (finest > 0)
      for (const d3::Point& n : todo_) push_touching(n, finest, next_);
    std::swap(todo_, next_);
    for (int l = finest - 1; l >= 0 && !todo_.empty(); --l) {
      // §9.11 S1: a level in any order; a candidate may repeat. Layer by
      // layer, row by row (the order the build allocated the records in).
      std::sort(todo_.begin(), todo_.end(), row_order);
      todo_.erase(std::unique(todo_.begin(), todo_.end()), todo_.end());
      next_.clear();
      for (const d3::Point& n : todo_) {
        // A leaf is no refined center: is_center reads the table line
        // can_coarsen reads next (can_coarsen would search for the node).
        if (is_center(g_, n) || can_coarsen(g_, n) || !coarsen(g_, n).applied()) continue;
        ++ops_;
        if (l > 0) push_touching(n, l, next_);  // §9.11 C2
      }
      std::swap(todo_, next_);
    }
    // §9.11, the refine pass: the level-(L-1) cubes meeting the new ball, not the old one.
    for_cells(finest, ball_, radius_, &old, radius_, [&](const d3::Point& p) {
      if (is_center(g_, p))
        refine_balanced(p, finest);
      else if (!is_node(g_, p))  // inside a coarser leaf (not refined already)
        refine_to(p, size_.L);
    });
    return ops_;
  }

  const L& state() const { return g_; }
  const Ball& ball() const { return ball_; }
  int frame_number() const { return frame_; }

 private:
  // The column range [i0, i1] of the level cells (side s) in row (j, k) that
  // meet the ball (b, r); empty when i0 > i1.
  std::pair<std::int64_t, std::int64_t> row_range(std::int64_t j, std::int64_t k, std::int64_t s, const Ball& b,
                                                  double r) const {
    const double h = static_cast<double>(s) / 2;
    const double dy = std::max(0.0, std::abs(static_cast<double>(j * s) + h - b.y) - h);
    const double dz = std::max(0.0, std::abs(static_cast<double>(k * s) + h - b.z) - h);
    const double rest = r * r - dy * dy - dz * dz;
    if (rest < 0) return {1, 0};
    const double w = std::sqrt(rest);
    auto i0 = static_cast<std::int64_t>(std::ceil((b.x - w) / static_cast<double>(s) - 1));
    auto i1 = static_cast<std::int64_t>(std::floor((b.x + w) / static_cast<double>(s)));
    // Guard the floating-point ends with the exact predicate.
    const auto meets = [&](std::int64_t i) {
      return cube_meets(d3::Point{i * s + s / 2, j * s + s / 2, k * s + s / 2}, h, b, r);
    };
    while (i0 <= i1 && !meets(i0)) ++i0;
    while (meets(i0 - 1)) --i0;
    while (i1 >= i0 && !meets(i1)) --i1;
    while (i1 >= i0 && meets(i1 + 1)) ++i1;
    return {i0, i1};
  }

  // Calls f(center) for the level-l cells inside the domain that meet ball
  // (b, r) and, when `minus` is given, do not meet ball (*minus, minus_r).
  template <class F>
  void for_cells(int l, const Ball& b, double r, const Ball* minus, double minus_r, F&& f) const {
    const std::int64_t s = d3::cell_side(size_, l);
    const double sd = static_cast<double>(s);
    const std::int64_t columns = size_.W << l, rows = size_.H << l, layers = size_.D << l;
    const auto lo = [&](double v) {
      return std::max<std::int64_t>(0, static_cast<std::int64_t>(std::floor(v / sd)) - 1);
    };
    const auto hi = [&](double v, std::int64_t n) {
      return std::min<std::int64_t>(n - 1, static_cast<std::int64_t>(std::floor(v / sd)) + 1);
    };
    const std::int64_t k0 = lo(b.z - r), k1 = hi(b.z + r, layers);
    const std::int64_t j0 = lo(b.y - r), j1 = hi(b.y + r, rows);
    for (std::int64_t k = k0; k <= k1; ++k)
      for (std::int64_t j = j0; j <= j1; ++j) {
        auto [a0, a1] = row_range(j, k, s, b, r);
        a0 = std::max<std::int64_t>(a0, 0);
        a1 = std::min<std::int64_t>(a1, columns - 1);
        std::pair<std::int64_t, std::int64_t> m{1, 0};
        if (minus) m = row_range(j, k, s, *minus, minus_r);
        for (std::int64_t i = a0; i <= a1; ++i) {
          if (m.first <= m.second && i >= m.first && i <= m.second) {
            i = m.second;  // skip the cells meeting `minus`
            continue;
          }
          f(d3::Point{i * s + s / 2, j * s + s / 2, k * s + s / 2});
        }
      }
  }

  static bool row_order(const d3::Point& a, const d3::Point& b) {
    return a.z != b.z ? a.z < b.z : a.y != b.y ? a.y < b.y : a.x < b.x;
  }

  // §9.11 C2: appends the level-(l-1) cubes touching the closed level-l cube
  // centred at n that do not meet the ball. On each axis n's cube touches
  // its parent's and, across the parent's side it lies on, the next one
  // (none beyond the domain): at most 2 x 2 x 2 cubes, all distinct.
  void push_touching(const d3::Point& n, int l, std::vector<d3::Point>& out) const {
    const std::int64_t s = d3::cell_side(size_, l - 1);
    const std::int64_t S = d3::level0_side(size_);
    const std::int64_t extent[3] = {size_.W * S, size_.H * S, size_.D * S};
    const std::int64_t at[3] = {n.x, n.y, n.z};
    std::int64_t c[3][2];
    int count[3];
    for (int a = 0; a < 3; ++a) {
      const std::int64_t parent = (at[a] / s) * s + s / 2;
      const std::int64_t beyond = at[a] < parent ? parent - s : parent + s;
      c[a][0] = parent;
      count[a] = beyond > 0 && beyond < extent[a] ? 2 : 1;
      c[a][1] = beyond;
    }
    const double h = static_cast<double>(s) / 2;
    for (int i = 0; i < count[0]; ++i)
      for (int j = 0; j < count[1]; ++j)
        for (int k = 0; k < count[2]; ++k) {
          const d3::Point q{c[0][i], c[1][j], c[2][k]};
          if (!cube_meets(q, h, ball_, radius_)) out.push_back(q);
        }
  }

  // The leaf cell containing p (strictly inside a level-L cell), searching
  // from level L up: the leaves a frame visits are fine.
  d3::Point locate(const d3::Point& p, int& level) const {
    for (int l = size_.L;; --l) {
      const std::int64_t s = d3::cell_side(size_, l);
      const d3::Point c{(p.x / s) * s + s / 2, (p.y / s) * s + s / 2, (p.z / s) * s + s / 2};
      if (l == 0 || is_center(g_, c)) {
        level = l;
        return c;
      }
    }
  }

  // The lattice's coarsen_each where it has one, else one coarsen a node.
  static std::size_t coarsen_each(L& g, const std::vector<d3::Point>& nodes) {
    if constexpr (requires { g.coarsen_each(std::span<const d3::Point>(nodes)); }) {
      return g.coarsen_each(std::span<const d3::Point>(nodes));
    } else {
      std::size_t applied = 0;
      for (const d3::Point& n : nodes) applied += coarsen(g, n).applied();
      return applied;
    }
  }

  // Refines the leaves containing p until the one there has level `target`.
  void refine_to(const d3::Point& p, int target) {
    for (;;) {
      int level = 0;
      const d3::Point c = locate(p, level);
      if (level >= target || !refine_balanced(c, level)) return;
    }
  }

  // Refines c, first refining every coarser face- or edge-neighbor
  // (recursively): the leaves just outside c's 6 faces and 12 edges.
  // Precondition: c is a leaf of level `level`.
  bool refine_balanced(const d3::Point& c, int level) {
    const auto why = can_refine(g_, c);
    if (why == RefineRefusal::CoarserNeighbor) {
      const std::int64_t h = d3::cell_side(size_, level) / 2 + 1;
      const std::int64_t S = d3::level0_side(size_);
      const std::int64_t X = size_.W * S, Y = size_.H * S, Z = size_.D * S;
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const int nonzero = (dx != 0) + (dy != 0) + (dz != 0);
            if (nonzero == 0 || nonzero == 3) continue;  // c itself, a corner
            const d3::Point q{c.x + dx * h, c.y + dy * h, c.z + dz * h};
            if (q.x < 0 || q.y < 0 || q.z < 0 || q.x >= X || q.y >= Y || q.z >= Z) continue;
            // The leaf at q is a face-or-edge neighbour of c, so of level
            // level - 1 or finer (§2): coarser only when it is the level-
            // (level-1) cube there, one lookup (§9.11).
            const std::int64_t s = d3::cell_side(size_, level - 1);
            const d3::Point x{(q.x / s) * s + s / 2, (q.y / s) * s + s / 2, (q.z / s) * s + s / 2};
            if (is_center(g_, x)) refine_balanced(x, level - 1);
          }
    } else if (why) {
      return false;
    }
    const bool ok = refine(g_, c).applied();
    ops_ += ok;
    return ok;
  }

  d3::LatticeSize size_;
  L g_;
  double radius_;
  int speed_;
  int frame_ = 0;
  Ball ball_;
  std::size_t ops_ = 0;
  std::vector<d3::Point> todo_, next_;  // a frame's candidates, kept for their capacity
};

}  // namespace bccmis::d3::bench
