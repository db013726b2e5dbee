// Shared by the p8est bridge tests: random 3D targets (tests/d3/
// cascade_model.h) applied in p8est: refine every octant holding a target
// point until it reaches the target's level, then p8est_balance.
#pragma once

#include <p8est_extended.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "bccmis/p4est/bridge3.h"
#include "d3/cascade_model.h"
#include "p4est/p4est_test_util.h"

namespace bccmis::p4est_bridge::testing {

using Target3 = d3::cascade_model::Target;

struct Target3Context {
  const Brick3* brick;
  const std::vector<Target3>* targets;
};

inline int refine_at_targets3(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q) {
  const auto* ctx = static_cast<const Target3Context*>(forest->user_pointer);
  const Leaf3 leaf = ctx->brick->to_leaf({tree, q->x, q->y, q->z, q->level});
  const std::int64_t h = d3::cell_side(ctx->brick->size(), leaf.level) / 2;
  const d3::Point3& c = leaf.center;
  for (const Target3& t : *ctx->targets) {
    const d3::Point3& p = t.point;
    if (t.level > leaf.level && p.x > c.x - h && p.x < c.x + h && p.y > c.y - h && p.y < c.y + h && p.z > c.z - h &&
        p.z < c.z + h)
      return 1;
  }
  return 0;
}

/// p8est: p8est_refine (recursive) at the targets, then p8est_balance with
/// `connect` unless `balance` is false.
inline Forest3Ptr p8est_targets(const Brick3& brick, const std::vector<Target3>& targets, p8est_connect_type_t connect,
                                bool balance = true) {
  Target3Context ctx{&brick, &targets};
  Forest3Ptr forest(p8est_new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, &ctx));
  p8est_refine_ext(forest.get(), 1, P8EST_QMAXLEVEL, refine_at_targets3, nullptr, nullptr);
  forest->user_pointer = nullptr;
  if (balance) p8est_balance(forest.get(), connect, nullptr);
  return forest;
}

/// The forest's leaves in bccmis coordinates, sorted.
inline std::vector<Leaf3> forest_leaves(const Brick3& brick, const p8est_t* forest) {
  std::vector<Leaf3> out;
  for (const Quadrant3& q : local_quadrants(forest)) out.push_back(brick.to_leaf(q));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace bccmis::p4est_bridge::testing
