// bccmis::distributed::repartition_needed: whether a step of a moving
// shape repartitions the forest (spec/distributed.md D15, step 3).
#pragma once

#include <cstdint>
#include <span>

namespace bccmis::distributed {

/// D15: the default of --repartition-threshold.
inline constexpr double kRepartitionThreshold = 1.1;

/// D15: the imbalance of leaves n_r per rank, max_r n_r / (N / P) (N their
/// sum, P their number); 1 when N is 0.
double imbalance(std::span<const std::int64_t> leaves);

/// D15: true when max_r n_r P > threshold N, so not when the imbalance
/// equals the threshold.
bool repartition_needed(std::span<const std::int64_t> leaves, double threshold);

}  // namespace bccmis::distributed
