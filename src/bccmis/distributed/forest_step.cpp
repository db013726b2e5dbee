// spec/distributed.md D15: the forest of the last frame moved to the next
// frame's shape: each rank coarsens and refines its own part, the
// partition corrected where a family to coarsen is split between ranks,
// repartitioned only past the threshold.
#include <p8est_algorithms.h>
#include <p8est_bits.h>
#include <p8est_extended.h>

#include <stdexcept>
#include <vector>

#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/repartition.h"
#include "bccmis/distributed/s3_callbacks.h"

namespace bccmis::distributed {

namespace {

/// D15, step 1: this rank's first own leaf is a later child of a family
/// whose parent fails the test (the family is split between ranks).
bool splits_failing_family(p8est_t& forest, const detail::S3Test& test) {
  if (forest.local_num_quadrants == 0) return false;
  p8est_tree_t* tree = p8est_tree_array_index(forest.trees, forest.first_local_tree);
  const p8est_quadrant_t* q = p8est_quadrant_array_index(&tree->quadrants, 0);
  if (q->level == 0 || p8est_quadrant_child_id(q) == 0) return false;
  p8est_quadrant_t parent;
  p8est_quadrant_parent(q, &parent);
  return !test.passes(forest.first_local_tree, parent);
}

}  // namespace

ForestStep Forest::move_to(const stuff::Shape& shape, const stuff::Fit& fit, const stuff::StuffOptions& options,
                           double threshold) {
  p8est_t* forest = forest_.get();
  const MPI_Comm comm = forest->mpicomm;
  detail::S3Test test{&brick_, &shape, &fit, &options, nullptr};
  forest->user_pointer = &test;
  ForestStep step;
  const p4est_gloidx_t before = forest->global_num_quadrants;
  // 1. Coarsen every family whose parent fails, the partition corrected
  // while such a family is split between ranks.
  for (;;) {
    const p4est_gloidx_t start = forest->global_num_quadrants;
    p8est_coarsen_ext(forest, 1, 0, detail::coarsen_by_s3, nullptr, nullptr);
    if (step.corrections > 0 && forest->global_num_quadrants == start)
      throw std::logic_error("a corrected partition coarsened nothing (spec/distributed.md D15)");
    int split = 0;
    if (!test.failed) try {
        split = splits_failing_family(*forest, test) ? 1 : 0;
      } catch (...) {
        test.failed = std::current_exception();
      }
    rethrow_on_every_rank(test.failed, "S3's test while the forest was coarsened", comm);
    MPI_Allreduce(MPI_IN_PLACE, &split, 1, MPI_INT, MPI_MAX, comm);
    if (split == 0) break;
    std::vector<p4est_locidx_t> counts;
    for (const std::int64_t n : leaves_per_rank()) counts.push_back(static_cast<p4est_locidx_t>(n));
    p8est_partition_for_coarsening(forest, counts.data());
    p8est_partition_given(forest, counts.data());
    ++step.corrections;
  }
  const p4est_gloidx_t coarsened = forest->global_num_quadrants;
  step.coarsened = (before - coarsened) / 7;
  // 2. Refine and balance, as D10's construction, without its partition.
  refine_and_balance(test, fit.size.L, false);
  forest->user_pointer = nullptr;
  step.refined = (forest->global_num_quadrants - coarsened) / 7;
  // 3. Repartition past the threshold.
  const std::vector<std::int64_t> leaves = leaves_per_rank();
  step.imbalance = imbalance(leaves);
  if (repartition_needed(leaves, threshold)) {
    p8est_partition(forest, 1, nullptr);
    step.repartitioned = true;
  }
  // 4. The ghost layer of the moved forest (D10).
  build_ghost();
  return step;
}

}  // namespace bccmis::distributed
