// bccmis apps: the moving-feature animation of Erleben 2009, §3 (Fig. 6), as
// a library call: typed settings in, one report per frame out. The CLI
// (`bccmis animate`, tools/bccmis/animate.cpp) turns flags into these
// settings and the reports into files; the height-field tessellation's
// building blocks are in heightfield.h (its CLI is tools/bccmis/heightfield.cpp).
// spec/apps.md describes both applications.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/graph.h"

namespace bccmis {

namespace fast {
class Lattice;
}

/// What animate() does: a disk moves along a path at constant speed; every
/// frame refines the cells meeting it to the target level (balanced) and
/// coarsens the cells it has left.
struct AnimationSettings {
  /// target_level: level of the cells meeting the feature (0..L); -1 means L.
  int target_level = -1;
  /// radius: the feature's radius in level-0 cell units (>= 0; 0 is a point).
  double radius = 0.5;
  /// path: the feature's polyline in level-0 cell units (the domain is
  /// [0, W] x [0, H]); at least one point (parse_path reads `x,y;x,y;...`).
  std::vector<std::array<double, 2>> path = {{1, 4}, {4, 7}, {7, 4}, {4, 1}, {1, 4}};
  /// balance: the 2:1 level rule kept (see balance.h).
  Balance balance = Balance::Edge;
  /// frames: number of frames (1..100000); frame k is at fraction k/(frames-1) of the path.
  int frames = 40;
  /// lift: after the last frame, one more frame without the feature (the
  /// lattice returns to the initial one).
  bool lift = false;
};

/// One frame of an animation.
struct FrameReport {
  int frame = 0;        ///< 0-based
  bool lifted = false;  ///< the extra frame without the feature (AnimationSettings::lift)
  double x = 0, y = 0;  ///< feature center, level-0 cell units
  std::size_t refinements = 0;
  std::size_t coarsenings = 0;
  std::size_t cells = 0;
  std::size_t nodes = 0;
  double seconds = 0;  ///< wall time of the frame's adaptation
};

/// Called after every frame with its report and the lattice.
template <class Lattice>
using FrameObserver = std::function<void(const FrameReport& report, const Lattice& g)>;

/// Runs the animation on `g` (usually the initial lattice; the frames only
/// depend on the feature, not on where g started). Throws
/// std::invalid_argument on invalid settings (the message names the
/// setting). Returns one report per frame; `after_frame`, when set, is
/// called after each with the lattice.
std::vector<FrameReport> animate(Graph& g, const AnimationSettings& settings,
                                 const FrameObserver<Graph>& after_frame = {});
/// The same frames on the fast implementation: the same operations, states and reports.
std::vector<FrameReport> animate(fast::Lattice& g, const AnimationSettings& settings,
                                 const FrameObserver<fast::Lattice>& after_frame = {});

}  // namespace bccmis
