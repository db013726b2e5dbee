// bccmis apps: moving-feature adaptivity (Erleben 2009, §3, Fig. 6: a cloth
// mesh refined near contact points). A feature is a disk (a point when the
// radius is 0); the lattice is refined to a target level where cells meet
// the disk and coarsened where merged cells would not (spec/apps.md,
// "Moving-feature adaptivity").
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/graph.h"

namespace bccmis {

/// A disk in lattice coordinates (the units of Point).
struct Disk {
  double x = 0;
  double y = 0;
  double radius = 0;
};

/// Whether the closed square of the level-`level` cell centered at `center`
/// meets the closed disk.
bool cell_meets_disk(const LatticeSize& size, const Point& center, int level, const Disk& d);

/// What adapt_to_disks did.
struct AdaptReport {
  std::size_t refinements = 0;
  std::size_t coarsenings = 0;
};

/// One adaptation step: refines (refine_balanced, repeated until none is
/// left) every cell below `target_level` that meets a disk, then coarsens
/// (coarsen_where) every refined center whose merged cell would not have to
/// be refined again. The result is the coarsest balanced lattice in which
/// every cell meeting a disk has at least the target level, whatever the
/// lattice was before (so it depends only on the disks). With no disks the
/// lattice returns to the initial one. target_level is clamped to [0, L].
/// `balance` is the 2:1 rule kept (corner mode needs a corner-balanced g).
AdaptReport adapt_to_disks(Graph& g, std::span<const Disk> disks, int target_level, Balance balance = Balance::Edge);
/// The same adaptation on the fast implementation (src/bccmis/fast): the same
/// operations in the same order.
AdaptReport adapt_to_disks(fast::Lattice& g, std::span<const Disk> disks, int target_level,
                           Balance balance = Balance::Edge);

/// A polyline in level-0 cell units: `x,y;x,y;...` (at least one point;
/// spaces allowed around numbers). Throws std::invalid_argument naming the
/// offending point.
std::vector<std::array<double, 2>> parse_path(std::string_view text);

/// The point at fraction t in [0, 1] of the polyline's length.
std::array<double, 2> point_on_path(const std::vector<std::array<double, 2>>& path, double t);

}  // namespace bccmis
