// spec/distributed.md D10, D15: S3's test as p8est's callbacks.
#include "bccmis/distributed/s3_callbacks.h"

#include <p8est_bits.h>

namespace bccmis::distributed::detail {

using namespace p4est_bridge;

bool S3Test::passes(p4est_topidx_t tree, const p8est_quadrant_t& q) const {
  const Leaf3 leaf = brick->to_leaf(P4<3>::quadrant(tree, q));
  return stuff::s3_refines(*shape, *fit, *options, leaf.center, leaf.level);
}

namespace {

/// `decide` on the forest's S3Test; the first exception kept, then 0.
template <class Decide>
int guarded(p8est_t* forest, Decide&& decide) {
  auto* test = static_cast<S3Test*>(forest->user_pointer);
  if (test->failed) return 0;
  try {
    return decide(*test) ? 1 : 0;
  } catch (...) {
    test->failed = std::current_exception();
    return 0;
  }
}

}  // namespace

int refine_by_s3(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q) {
  return guarded(forest, [&](const S3Test& test) { return test.passes(tree, *q); });
}

int coarsen_by_s3(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* family[]) {
  return guarded(forest, [&](const S3Test& test) {
    // D15, step 1: the parent, not a child (a failing child's parent may pass).
    p8est_quadrant_t parent;
    p8est_quadrant_parent(family[0], &parent);
    return !test.passes(tree, parent);
  });
}

}  // namespace bccmis::distributed::detail
