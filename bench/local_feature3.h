// Forwarding header kept for bench/bench_p8est.cpp until it is renamed: the 3D
// local-feature workload is bench/d3/local_feature.h.
// TODO remove when the p4est code is renamed.
#pragma once

#include "d3/local_feature.h"

namespace bccmis::bench {
using Ball3 = d3::bench::Ball;   // TODO remove when the p4est code is renamed
using d3::bench::ball_position;  // TODO remove when the p4est code is renamed
template <class L>
using LocalFeature3 = d3::bench::LocalFeature<L>;  // TODO remove when the p4est code is renamed
}  // namespace bccmis::bench
