// bccmis apps, internal: the balance modes, the coarsening sweep, the
// moving-feature adaptation and the height-field tessellation written once
// over the lattice type, so that the reference Graph and bccmis::fast::Lattice
// run the same application code; the balance cascade itself, written over
// every dimension, is the core's bccmis/balance.h.
//
// balance.cpp, animate.cpp and heightfield.cpp instantiate the templates for
// Graph and for fast::Lattice (the overloads in balance.h, animate.h and
// heightfield.h). A lattice is reached only through the vocabulary of
// bccmis/lattice.h and the geometry of bccmis/geometry.h: the same queries
// and operations, with the same (x, y)-sorted neighbor order, so both
// instantiations make the same decisions in the same order
// (tests/apps/fast_test.cpp and RunAnimate.FastImplMakesTheSameFramesAndState
// compare states and reports).
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/apps/heightfield.h"
#include "bccmis/apps/moving_disk.h"
#include "bccmis/balance.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/geometry.h"
#include "bccmis/graph.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"

namespace bccmis::detail {

// ---- balance (balance.h) ------------------------------------------------------------

template <AdaptiveLattice Lat>
std::optional<CoarsenRefusal> can_coarsen_under(const Lat& g, const Point& n, Balance b) {
  const std::optional<CoarsenRefusal> why = can_coarsen(g, n);
  if (why || b == Balance::Edge) return why;
  // The merged cell has the children's level minus one; a cell touching it
  // may be at most one level finer, i.e. at most the children's level.
  const auto& Y = neighbors(g, n);
  for (const Point& y : Y) {
    const int child = level_of(g, y);
    for (const Point& p : neighbors(g, y)) {
      if (p == n) continue;
      for (const Point& x : neighbors(g, p))
        if (!contains(Y, x) && level_of(g, x) > child) return CoarsenRefusal::FinerNeighbor;
    }
  }
  return std::nullopt;
}

/// coarsen_sweep of balance.h; `allow(g, n)` decides each candidate.
template <AdaptiveLattice Lat, class Allow>
std::size_t coarsen_sweep(Lat& g, const Allow& allow, Balance b) {
  // Only refined centers can be coarsened; the position test is cheap and
  // keeps the pass from calling the predicate on grid nodes and midpoints.
  // Finest first: merging the children of a cell can make the cell itself
  // (one level up) or a neighbor blocked by a finer junction mergeable, so
  // one pass usually reaches the fixpoint.
  std::vector<std::pair<int, Point>> candidates;
  for (const Point& n : nodes(g))
    if (const std::optional<int> l = refined_center_level(size_of(g), n)) candidates.push_back({-*l, n});
  std::sort(candidates.begin(), candidates.end());
  std::size_t done = 0;
  for (const auto& [minus_level, n] : candidates) {
    if (can_coarsen_under(g, n, b) || !allow(g, n)) continue;
    if (coarsen(g, n).applied()) ++done;
  }
  return done;
}

/// coarsen_where of balance.h.
template <AdaptiveLattice Lat, class Allow>
std::size_t coarsen_where(Lat& g, const Allow& allow, Balance b) {
  std::size_t total = 0;
  while (const std::size_t done = coarsen_sweep(g, allow, b)) total += done;
  return total;
}

template <AdaptiveLattice Lat>
PointSet boundary_after_coarsen(const Lat& g, const Point& n) {
  const auto& Y = neighbors(g, n);
  const int child_level = Y.empty() ? 0 : level_of(g, *Y.begin());
  const std::int64_t half = cell_side(size_of(g), child_level);  // half the merged cell's side
  PointSet B;
  for (const Point& y : Y)
    for (const Point& p : neighbors(g, y)) {
      if (p == n || B.count(p) != 0) continue;
      const bool corner = (p.x == n.x - half || p.x == n.x + half) && (p.y == n.y - half || p.y == n.y + half);
      std::size_t outside = 0;
      for (const Point& x : neighbors(g, p)) outside += contains(Y, x) ? 0 : 1;
      if (corner || outside >= 2) B.insert(p);
    }
  return B;
}

// ---- moving feature (animate.h) --------------------------------------------------------

/// adapt_to_disks of animate.h.
template <AdaptiveLattice Lat>
AdaptReport adapt_to_disks(Lat& g, std::span<const Disk> disks, int target_level, Balance balance) {
  const LatticeSize size = size_of(g);
  const int target = std::clamp(target_level, 0, size.L);
  auto needs_refinement = [&](const Point& c, int level) {
    if (level >= target) return false;
    for (const Disk& d : disks)
      if (cell_meets_disk(size, c, level, d)) return true;
    return false;
  };
  AdaptReport report;
  for (;;) {
    std::vector<Point> marked;
    for (const Point& c : cells(g))
      if (needs_refinement(c, level_of(g, c))) marked.push_back(c);
    if (marked.empty()) break;
    for (const Point& c : marked)
      if (is_center(g, c)) report.refinements += refine_balanced(g, c, balance).refined.size();
  }
  report.coarsenings = coarsen_where(
      g,
      [&](const Lat& now, const Point& n) {
        const int merged_level = level_of(now, *neighbors(now, n).begin()) - 1;
        return !needs_refinement(n, merged_level);
      },
      balance);
  return report;
}

// ---- height field (heightfield.h) ------------------------------------------------------

template <AdaptiveLattice Lat>
CellFan cell_fan(const Lat& g, const Point& c, const HeightSampler& s) {
  return CellFan(c, level_of(g, c), boundary_in_angular_order(g, c), s);
}

/// tessellate() of heightfield.h; `observer(sweep, g, operations)` after
/// every sweep that changed something.
template <AdaptiveLattice Lat, class Observer>
TessellateReport tessellate(Lat& g, const HeightSampler& s, const TessellateSettings& t, const Observer& observer) {
  TessellateReport report;
  // Errors within rounding of the height scale count as zero, so a plane
  // needs no refinement even at tolerance 0.
  const double limit = t.tolerance + kRoundingSlack * s.vertical_scale();
  auto budget_left = [&] { return t.max_sweeps <= 0 || report.sweeps < t.max_sweeps; };

  if (t.coarsen) {
    // Merge four cells when the merged cell, with the boundary it would have,
    // interpolates the field within tolerance.
    const auto within = [&](const Lat& now, const Point& n) {
      const int level = level_of(now, *neighbors(now, n).begin()) - 1;
      return cell_error(CellFan(n, level, in_angular_order(n, boundary_after_coarsen(now, n)), s), s, t.error) <= limit;
    };
    while (budget_left()) {
      const std::size_t done = coarsen_sweep(g, within, t.balance);
      if (done == 0) break;
      report.coarsenings += done;
      ++report.sweeps;
      if (observer) observer(report.sweeps, g, done);
    }
  }

  report.converged = false;
  while (budget_left()) {
    std::vector<Point> marked;
    for (const Point& c : cells(g))
      if (level_of(g, c) < size_of(g).L && cell_error(cell_fan(g, c, s), s, t.error) > limit) marked.push_back(c);
    if (marked.empty()) {
      report.converged = true;
      break;
    }
    std::size_t done = 0;
    for (const Point& c : marked) {
      // A cascade earlier in this sweep may have refined c already; its
      // children are measured in the next sweep.
      if (!is_center(g, c)) continue;
      done += refine_balanced(g, c, t.balance).refined.size();
    }
    report.refinements += done;
    ++report.sweeps;
    if (observer) observer(report.sweeps, g, done);
  }
  return report;
}

}  // namespace bccmis::detail
