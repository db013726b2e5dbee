// What both stuffers share (reference_stuffer.cpp, flat_stuffer.cpp): the
// cut point record of S5, the regularity check of S4 and the phase clock.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "bccmis/d3/mesh.h"
#include "bccmis/d3/point.h"
#include "bccmis/stuff/stopwatch.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::stuff::detail {

inline std::int64_t length2(const d3::Point& p, const d3::Point& q) {
  const std::int64_t dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
  return dx * dx + dy * dy + dz * dz;
}

/// S4: the regular BCC tetrahedron of level L has squared edge lengths 4
/// (two long edges) and 3 (four short ones) in lattice coordinates.
inline void check_regular(const d3::Tet& t, int L) {
  int longs = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const std::int64_t l2 = length2(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>(j)]);
      if (l2 == 4)
        ++longs;
      else if (l2 != 3)
        throw std::logic_error("stuff: a tetrahedron at " + d3::to_string(t[0]) +
                               " with a cut edge or a warped vertex is not a regular BCC tetrahedron of level " +
                               std::to_string(L) + " (spec/stuffing.md S4)");
    }
  if (longs != 2) throw std::logic_error("stuff: a tetrahedron at " + d3::to_string(t[0]) + " is not regular (S4)");
}

/// S5: a cut point on a lattice edge.
struct Cut {
  double t = 0;  ///< from the edge's smaller end
  Vec3 pos{};
  bool removed = false;
};

using stuff::Clock;
using stuff::seconds_since;

/// Times consecutive phases into a PhaseTimes, when one is given.
class PhaseClock {
 public:
  explicit PhaseClock(PhaseTimes* times) : times_(times) {}
  /// The phase since the last lap (or since the clock started) was `phase`.
  void lap(double PhaseTimes::*phase) {
    if (times_) times_->*phase = seconds_since(t0_);
    t0_ = Clock::now();
  }

 private:
  PhaseTimes* times_;
  Clock::time_point t0_ = Clock::now();
};

}  // namespace bccmis::stuff::detail
