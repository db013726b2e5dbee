// The background lattice of isosurface stuffing (spec/stuffing.md S2, S3):
// fit_lattice() places the lattice around the shape, background() and
// background_fast() refine it near the surface (the latter with S3's tests
// on threads, S28c).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bccmis/balance.h"
#include "bccmis/d3/lattice.h"
#include "bccmis/d3/point.h"
#include "bccmis/stuff/detail/parallel_ranges.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff {

Fit fit_lattice(const Bounds& box, const StuffOptions& options) {
  Vec3 extent{};
  for (std::size_t i = 0; i < 3; ++i) {
    extent[i] = box.hi[i] - box.lo[i];
    if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i]) || extent[i] < 0)
      throw ShapeError("the shape's bounding box is empty or not finite");
  }
  const double E = std::max({extent[0], extent[1], extent[2]});
  if (!(E > 0)) throw ShapeError("the shape's bounding box has no extent");
  if (options.cells < 1) throw ShapeError("--cells must be at least 1");
  int L = options.max_level;
  if (options.size) {
    // S2: the smallest L with N 2^L h >= E + 10h.
    const double h = *options.size;
    if (!(h > 0) || !std::isfinite(h)) throw ShapeError("--size must be positive");
    L = 0;
    while (static_cast<double>(options.cells) * std::ldexp(h, L) < E + 10 * h) {
      if (++L > 20) throw ShapeError("--size is too small for the shape: it needs more than 20 levels");
    }
  }
  if (L < 0 || L > 20) throw ShapeError("--max-level must be in [0, 20]");
  if (options.min_level < 0 || options.min_level > L)
    throw ShapeError("--min-level must be in [0, max level " + std::to_string(L) + "]");
  const double n2L = std::ldexp(static_cast<double>(options.cells), L);
  if (n2L <= 10)
    throw ShapeError("--cells x 2^max-level must exceed 10 (the margin of 5 finest cells on each side); it is " +
                     std::to_string(static_cast<long long>(n2L)));
  Fit fit;
  const double S = E / (options.cells - 10.0 / std::ldexp(1.0, L));
  fit.h = std::ldexp(S, -L);
  std::int64_t counts[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const double need = extent[i] + 10 * fit.h;
    counts[i] = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(need / S - 1e-12)));
    fit.origin[i] = 0.5 * (box.lo[i] + box.hi[i]) - 0.5 * static_cast<double>(counts[i]) * S;
  }
  // S2: the fast lattice names its records by 31-bit ids (lattice3d.md).
  constexpr double kLimit = 2147483648.0;  // 2^31
  const double cubes = static_cast<double>(counts[0]) * static_cast<double>(counts[1]) * static_cast<double>(counts[2]);
  const double nodes =
      static_cast<double>(counts[0] + 1) * static_cast<double>(counts[1] + 1) * static_cast<double>(counts[2] + 1);
  if (cubes >= kLimit || nodes >= kLimit)
    throw ShapeError("the initial lattice of " + std::to_string(counts[0]) + " x " + std::to_string(counts[1]) + " x " +
                     std::to_string(counts[2]) +
                     " level-0 cubes has 2^31 or more cubes or nodes, the lattice's limit; use fewer --cells");
  fit.size = d3::LatticeSize{counts[0], counts[1], counts[2], L};
  fit.scale = std::ldexp(S, -(L + 1));
  return fit;
}

bool s3_refines(const Shape& shape, const Fit& fit, const StuffOptions& options, const d3::Point& c, int l) {
  if (l >= fit.size.L) return false;
  if (l < options.min_level) return true;
  const double r = 0.5 * static_cast<double>(d3::cell_side(fit.size, l)) * fit.scale;
  return shape.distance(fit.to_space(c)) <= std::sqrt(3.0) * r + 4 * fit.h;
}

namespace {

/// S3 on the reference lattice, the oracle: the passes as S3 states them
/// (every pass visits the leaves of its start in sorted order, testing each
/// that is still a leaf at its turn).
void refine_near(const Shape& shape, const Fit& fit, const StuffOptions& options, d3::Graph& g) {
  std::vector<d3::Point> snapshot;
  for (bool changed = true; changed;) {
    changed = false;
    {
      const auto& cs = cells(g);  // sorted
      snapshot.assign(cs.begin(), cs.end());
    }
    for (const d3::Point& c : snapshot) {
      if (!is_center(g, c)) continue;  // refined by the cascade earlier in this pass
      if (s3_refines(shape, fit, options, c, level_of(g, c))) {
        d3::refine_balanced(g, c);
        changed = true;
      }
    }
  }
}

/// S3 on the fast lattice, S28c: each pass's tests computed first, over
/// ranges of the leaves on `options.threads` threads (the lattice only read),
/// then the refinements applied in order on this thread. A leaf still a leaf
/// at its turn is the cell, of the level, it was tested at, so the
/// refinements are the serial pass's, in its order: the same lattice, record
/// for record, as the pass above would build.
void refine_near(const Shape& shape, const Fit& fit, const StuffOptions& options, d3::fast::Lattice& g) {
  constexpr std::size_t kLeastPerThread = 256;  // S28c, as S28a
  std::vector<d3::Point> snapshot;
  std::vector<unsigned char> refines;
  for (bool changed = true; changed;) {
    changed = false;
    snapshot = g.cells();  // sorted
    refines.assign(snapshot.size(), 0);
    detail::for_each_range(snapshot.size(), options.threads, kLeastPerThread, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i)
        refines[i] = s3_refines(shape, fit, options, snapshot[i], g.level_of(snapshot[i])) ? 1 : 0;
    });
    for (std::size_t i = 0; i < snapshot.size(); ++i) {
      // Not a leaf any more: refined by the cascade earlier in this pass.
      // A flagged leaf is below level L (S3), so the refinement is applied.
      if (refines[i] && g.is_center(snapshot[i]) && !d3::refine_balanced(g, snapshot[i]).refused) changed = true;
    }
  }
}

}  // namespace

d3::Graph background(const Shape& shape, const Fit& fit, const StuffOptions& options) {
  d3::Graph g = d3::make_lattice(fit.size);
  refine_near(shape, fit, options, g);
  return g;
}

d3::fast::Lattice background_fast(const Shape& shape, const Fit& fit, const StuffOptions& options) {
  d3::fast::Lattice g(fit.size);
  refine_near(shape, fit, options, g);  // S28c
  return g;
}

}  // namespace bccmis::stuff
