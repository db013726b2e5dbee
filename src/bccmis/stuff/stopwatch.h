// The clock of the phases' seconds (spec/stuffing.md S13): wall time on the
// steady clock.
#pragma once

#include <chrono>

namespace bccmis::stuff {

using Clock = std::chrono::steady_clock;

/// Seconds from t0 to now.
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace bccmis::stuff
