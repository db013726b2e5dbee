#include "bccmis/apps/apps.h"

#include <chrono>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "bccmis/apps/moving_disk.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/lattice.h"

namespace bccmis {

namespace {

using Clock = std::chrono::steady_clock;

void validate(const AnimationSettings& s, const LatticeSize& size) {
  if (s.target_level < -1 || s.target_level > size.L)
    throw std::invalid_argument("target level " + std::to_string(s.target_level) + " is out of range 0.." +
                                std::to_string(size.L) + " (or -1 for the max level)");
  if (!std::isfinite(s.radius) || s.radius < 0) throw std::invalid_argument("radius must be a number >= 0");
  if (s.frames < 1 || s.frames > 100000) throw std::invalid_argument("frames must be in 1..100000");
  if (s.path.empty()) throw std::invalid_argument("the path needs at least one point");
}

template <AdaptiveLattice L>
std::vector<FrameReport> run_frames(L& g, const AnimationSettings& s, const FrameObserver<L>& after_frame) {
  const LatticeSize size = size_of(g);
  validate(s, size);
  const int target = s.target_level < 0 ? size.L : s.target_level;
  const double S = static_cast<double>(level0_side(size));
  const int total = s.frames + (s.lift ? 1 : 0);
  std::vector<FrameReport> reports;
  reports.reserve(static_cast<std::size_t>(total));
  for (int k = 0; k < total; ++k) {
    FrameReport fr;
    fr.frame = k;
    fr.lifted = k >= s.frames;
    const auto t0 = Clock::now();
    AdaptReport a;
    if (fr.lifted) {
      a = adapt_to_disks(g, {}, target, s.balance);
    } else {
      const auto p = point_on_path(s.path, s.frames == 1 ? 0.0 : static_cast<double>(k) / (s.frames - 1));
      fr.x = p[0];
      fr.y = p[1];
      const Disk d{p[0] * S, p[1] * S, s.radius * S};
      a = adapt_to_disks(g, std::span<const Disk>(&d, 1), target, s.balance);
    }
    fr.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    fr.refinements = a.refinements;
    fr.coarsenings = a.coarsenings;
    fr.cells = cell_count(g);
    fr.nodes = node_count(g);
    reports.push_back(fr);
    if (after_frame) after_frame(fr, g);
  }
  return reports;
}

}  // namespace

std::vector<FrameReport> animate(Graph& g, const AnimationSettings& s, const FrameObserver<Graph>& after_frame) {
  return run_frames(g, s, after_frame);
}

std::vector<FrameReport> animate(fast::Lattice& g, const AnimationSettings& s,
                                 const FrameObserver<fast::Lattice>& after_frame) {
  return run_frames(g, s, after_frame);
}

}  // namespace bccmis
