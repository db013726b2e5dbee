// spec/distributed.md D10, D15: S3's test as p8est's refine and coarsen
// callbacks (internal to bccmis::distributed_mpi).
#pragma once

#include <p8est.h>

#include <exception>

#include "bccmis/p4est/bridge.h"
#include "bccmis/stuff/shape.h"
#include "bccmis/stuff/stuff.h"

namespace bccmis::distributed::detail {

/// What S3's test reads: the shape, the fit and the options, the same on
/// every rank (D10), and the brick's coordinate map; `failed`, the first
/// exception the test threw on this rank (D6). The forest's user_pointer
/// while p8est calls the callbacks.
struct S3Test {
  const p4est_bridge::Brick3* brick;
  const stuff::Shape* shape;
  const stuff::Fit* fit;
  const stuff::StuffOptions* options;
  std::exception_ptr failed;

  /// S3's test at the octant q of `tree`.
  bool passes(p4est_topidx_t tree, const p8est_quadrant_t& q) const;
};

/// p8est_refine's callback: S3's test on the octant's leaf (D10). An
/// exception cannot cross p8est's C code: the first is kept and nothing
/// more is refined (D6: the ranks then agree and every rank throws).
int refine_by_s3(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q);

/// p8est_coarsen's callback: the family's parent fails S3's test (D15,
/// step 1); exceptions as refine_by_s3's.
int coarsen_by_s3(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* family[]);

}  // namespace bccmis::distributed::detail
