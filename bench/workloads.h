// Workloads shared by the benchmarks: the operation sequences every
// benchmark replays through both implementations (so every ratio compares
// the same sequence), written once over the lattice vocabulary
// (bccmis/lattice.h) and instantiated for Graph and fast::Lattice.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/graph.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis::bench {

// ---- Geometry helpers --------------------------------------------------------------------

/// The centers of all level-`level` cells of the full lattice, row by row.
inline std::vector<Point> grid_centers(const LatticeSize& size, int level) {
  std::vector<Point> out;
  const std::int64_t s = cell_side(size, level);
  const std::int64_t w = size.W << level, h = size.H << level;
  out.reserve(static_cast<std::size_t>(w * h));
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i) out.push_back({i * s + s / 2, j * s + s / 2});
  return out;
}

/// A square-ish lattice of about `cells` level-0 cells (W = H = round(sqrt)).
inline LatticeSize square_lattice(std::int64_t cells, int L) {
  const auto w = std::max<std::int64_t>(1, std::llround(std::sqrt(static_cast<double>(cells))));
  return LatticeSize{w, w, L};
}

/// The center of the parent of the level-`level` cell centered at c (level >= 1).
inline Point parent_center(const LatticeSize& size, const Point& c, int level) {
  const std::int64_t s = cell_side(size, level - 1);
  return {(c.x / s) * s + s / 2, (c.y / s) * s + s / 2};
}

// ---- A random balanced refine/coarsen mix ------------------------------------------------

struct Op {
  bool refine = true;
  Point at;
};

/// A recorded sequence of applied operations and the state it starts from.
struct Mix {
  LatticeSize size;
  std::vector<Point> warmup;                  ///< the refinements that grew the start state
  fast::Lattice start{LatticeSize{1, 1, 0}};  ///< make_lattice(size) after `warmup`
  std::vector<Op> ops;                        ///< applied operations from `start`
};

/// Grows a W x W lattice (W^2 ~ cells / 4, L = 8) by random refinements to
/// `cells` cells, then records `count` random operations that keep it near
/// that size: refine a random cell (55% below the target size, 45% above) or
/// coarsen the parent of a random cell; only applied operations are kept.
/// Deterministic for a seed. The generator runs the fast lattice; both
/// implementations then replay the same operations.
inline Mix make_mix(std::int64_t cells, std::size_t count, std::uint64_t seed) {
  Mix mix;
  mix.size = square_lattice(std::max<std::int64_t>(1, cells / 4), 8);
  fast::Lattice g(mix.size);
  std::mt19937_64 rng(seed);
  const auto& pool = g.center_pool();
  auto random_cell = [&](Point& c, int& level) {
    for (;;) {
      const auto& rec = pool[std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng)];
      if (!rec.live()) continue;
      c = rec.position();
      level = rec.level(mix.size.L);
      return;
    }
  };
  auto step = [&](bool record) {
    const bool grow = g.cell_count() < static_cast<std::size_t>(cells);
    const bool want_refine = std::bernoulli_distribution(grow ? 0.55 : 0.45)(rng);
    for (int attempt = 0; attempt < 64; ++attempt) {
      Point c;
      int level = 0;
      random_cell(c, level);
      if (want_refine || !record) {
        if (g.refine(c).applied()) {
          if (record)
            mix.ops.push_back({true, c});
          else
            mix.warmup.push_back(c);
          return;
        }
      } else if (level > 0) {
        const Point n = parent_center(mix.size, c, level);
        if (g.coarsen(n).applied()) {
          mix.ops.push_back({false, n});
          return;
        }
      }
    }
  };
  while (g.cell_count() < static_cast<std::size_t>(cells)) step(false);
  mix.start = g;
  while (mix.ops.size() < count) step(true);
  return mix;
}

// ---- Moving feature -----------------------------------------------------------------------

/// A disk moving around a circle; each frame the lattice is adapted so that
/// every cell meeting the disk has the maximum level L, and cells the disk
/// has left are coarsened again (finest first, where the operations allow).
/// Only the neighborhood of the old and new disk is visited, so a frame
/// costs O(ops), not O(lattice). Same semantics as apps/ adapt_to_disks,
/// written once for both implementations.
/// The leaf-locating refinement both moving-feature workloads use (this
/// file's MovingFeature, local_feature.h's LocalFeature): cells are found by
/// position, and a coarser edge-neighbor in the way is refined first.
/// `Search` is the order in which locate tries the levels: from level 0 down
/// (cheap when the leaves are coarse) or from level L up (when they are fine).
template <AdaptiveLattice L>
class LeafRefiner {
 public:
  enum class Search { CoarsestFirst, FinestFirst };

  LeafRefiner(L& g, const LatticeSize& size, Search search, std::size_t& ops)
      : g_(g), size_(size), search_(search), ops_(ops) {}

  /// The leaf cell containing p (strictly inside a level-L cell), and its level.
  Point locate(const Point& p, int& level) const {
    const bool up = search_ == Search::FinestFirst;
    for (int l = up ? size_.L : 0;; l += up ? -1 : 1) {
      const std::int64_t s = cell_side(size_, l);
      const Point c{(p.x / s) * s + s / 2, (p.y / s) * s + s / 2};
      if (is_center(g_, c) || l == (up ? 0 : size_.L)) {
        level = l;
        return c;
      }
    }
  }

  /// Refines the leaves containing p until the one there has level `target`.
  void refine_to(const Point& p, int target) {
    for (;;) {
      int level = 0;
      const Point c = locate(p, level);
      if (level >= target) return;
      if (!refine_balanced(c, level)) return;
    }
  }

  /// Refines c, first refining any coarser edge-neighbor (recursively).
  bool refine_balanced(const Point& c, int level) {
    const auto why = can_refine(g_, c);
    if (why == RefineRefusal::CoarserNeighbor) {
      const std::int64_t h = cell_side(size_, level) / 2;
      const std::int64_t W = size_.W * level0_side(size_), H = size_.H * level0_side(size_);
      for (const Point q :
           {Point{c.x + h + 1, c.y}, Point{c.x - h - 1, c.y}, Point{c.x, c.y + h + 1}, Point{c.x, c.y - h - 1}}) {
        if (q.x < 0 || q.y < 0 || q.x >= W || q.y >= H) continue;
        int nl = 0;
        const Point x = locate(q, nl);
        if (nl < level && is_center(g_, x)) refine_balanced(x, nl);
      }
    } else if (why) {
      return false;
    }
    const bool ok = refine(g_, c).applied();
    ops_ += ok;
    return ok;
  }

 private:
  L& g_;
  LatticeSize size_;
  Search search_;
  std::size_t& ops_;
};

template <AdaptiveLattice L>
class MovingFeature {
 public:
  MovingFeature(const LatticeSize& size, double radius, int frames_per_turn)
      : size_(size), g_(size), radius_(radius), frames_(frames_per_turn) {
    side_ = static_cast<double>(level0_side(size));
    disk_ = position(0);
    for (const Point& p : disk_points(disk_)) refine_to(p, size_.L);
  }

  /// Moves the disk one frame on and adapts; returns the operations applied.
  std::size_t frame() {
    ops_ = 0;
    const Disk old = disk_;
    frame_ = (frame_ + 1) % frames_;
    disk_ = position(frame_);
    // Coarsen where the old disk was, finest first. A level-(l+1) cell
    // exists only within s_l of a disk (the 2:1 grading halves the side at
    // each step), so refined level-l centers lie within R + 2 s_l of it.
    for (int l = size_.L - 1; l >= 0; --l) {
      const std::int64_t s = cell_side(size_, l);
      const double margin = radius_ + 2 * static_cast<double>(s);
      for (const Point& n : centers_in_box(old.x - margin, old.y - margin, old.x + margin, old.y + margin, s)) {
        if (meets(n, l, disk_)) continue;
        if (!can_coarsen(g_, n)) ops_ += coarsen(g_, n).applied();
      }
    }
    // Refine where the disk arrived (cells it already covered are at level L).
    for (const Point& p : disk_points(disk_))
      if (!meets(p, size_.L, old)) refine_to(p, size_.L);
    return ops_;
  }

  const L& state() const { return g_; }

 private:
  struct Disk {
    double x, y;
  };

  Disk position(int frame) const {
    const double cx = static_cast<double>(size_.W) * side_ / 2, cy = static_cast<double>(size_.H) * side_ / 2;
    const double r = 0.3 * std::min(static_cast<double>(size_.W), static_cast<double>(size_.H)) * side_;
    const double a = 2 * std::numbers::pi * frame / frames_;
    return {cx + r * std::cos(a), cy + r * std::sin(a)};
  }

  bool meets(const Point& c, int level, const Disk& d) const {
    const double h = static_cast<double>(cell_side(size_, level)) / 2;
    const double dx = std::max(0.0, std::abs(static_cast<double>(c.x) - d.x) - h);
    const double dy = std::max(0.0, std::abs(static_cast<double>(c.y) - d.y) - h);
    return dx * dx + dy * dy <= radius_ * radius_;
  }

  /// Centers of level cells of side s inside the box, clipped to the domain.
  std::vector<Point> centers_in_box(double x0, double y0, double x1, double y1, std::int64_t s) const {
    std::vector<Point> out;
    const std::int64_t W = size_.W * level0_side(size_), H = size_.H * level0_side(size_);
    const auto lo = [&](double v, std::int64_t max) {
      return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(v / static_cast<double>(s))), 0, max / s);
    };
    for (std::int64_t j = lo(y0, H), j1 = lo(y1, H - 1); j <= j1; ++j)
      for (std::int64_t i = lo(x0, W), i1 = lo(x1, W - 1); i <= i1; ++i)
        if (i * s < W && j * s < H) out.push_back({i * s + s / 2, j * s + s / 2});
    return out;
  }

  /// The centers of the level-L cells that meet the disk.
  std::vector<Point> disk_points(const Disk& d) const {
    std::vector<Point> out;
    for (const Point& c :
         centers_in_box(d.x - radius_, d.y - radius_, d.x + radius_, d.y + radius_, cell_side(size_, size_.L)))
      if (meets(c, size_.L, d)) out.push_back(c);
    return out;
  }

  void refine_to(const Point& p, int target) {
    LeafRefiner<L>(g_, size_, LeafRefiner<L>::Search::CoarsestFirst, ops_).refine_to(p, target);
  }

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
