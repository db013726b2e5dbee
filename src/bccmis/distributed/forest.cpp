// spec/distributed.md D10: the S3 lattice as a partitioned p8est forest,
// built by every rank at once, and a rank's ghost layer.
#include <algorithm>
#include <exception>
#include <vector>

#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/s3_callbacks.h"

namespace bccmis::distributed {

using namespace p4est_bridge;

Forest::Forest(const stuff::Shape& shape, const stuff::Fit& fit, const stuff::StuffOptions& options, MPI_Comm comm)
    : brick_(fit.size) {
  detail::S3Test test{&brick_, &shape, &fit, &options, nullptr};
  forest_.reset(p8est_new_ext(comm, brick_.connectivity(), 0, 0, 1, 0, nullptr, &test));
  refine_and_balance(test, fit.size.L, true);
  forest_->user_pointer = nullptr;
  build_ghost();
}

void Forest::refine_and_balance(detail::S3Test& test, int L, bool partition) {
  // S3's loop: refine every leaf that passes the test (recursively), then
  // what the edge balance forces, until no leaf passes (D10: the smallest
  // edge-balanced refinement in which no leaf passes the test, S3's lattice).
  forest_->user_pointer = &test;
  for (p4est_gloidx_t before = -1; before != forest_->global_num_quadrants;) {
    before = forest_->global_num_quadrants;
    p8est_refine_ext(forest_.get(), 1, L, detail::refine_by_s3, nullptr, nullptr);
    // D6: one forest on every rank before balance and partition.
    rethrow_on_every_rank(test.failed, "S3's test while the forest was refined", forest_->mpicomm);
    p8est_balance(forest_.get(), P8EST_CONNECT_EDGE, nullptr);
    // Uniform by count (D2), families of sibling leaves kept on one rank (D15).
    if (partition) p8est_partition(forest_.get(), 1, nullptr);
  }
}

void Forest::build_ghost() {
  if (ghost_ != nullptr) p8est_ghost_destroy(ghost_);
  ghost_ = p8est_ghost_new(forest_.get(), P8EST_CONNECT_FULL);
  for (int layer = 1; layer < kGhostLayers; ++layer) expand();
}

std::vector<std::int64_t> Forest::leaves_per_rank() const {
  std::vector<std::int64_t> n(static_cast<std::size_t>(forest_->mpisize));
  for (std::size_t r = 0; r < n.size(); ++r)
    n[r] = forest_->global_first_quadrant[r + 1] - forest_->global_first_quadrant[r];
  return n;
}

Forest::~Forest() {
  if (ghost_ != nullptr) p8est_ghost_destroy(ghost_);
}

std::vector<d3::Point> Forest::own() const {
  std::vector<d3::Point> own;
  for (const Quadrant3& q : local_quadrants(forest_.get())) own.push_back(brick_.to_leaf(q).center);
  return own;
}

std::vector<d3::Point> Forest::known() const {
  std::vector<d3::Point> known = own();
  for (std::size_t k = 0; k < ghost_->ghosts.elem_count; ++k) {
    const p8est_quadrant_t& q = *p8est_quadrant_array_index(&ghost_->ghosts, k);
    known.push_back(brick_.to_leaf(P4<3>::quadrant(q.p.piggy3.which_tree, q)).center);
  }
  std::sort(known.begin(), known.end());
  known.erase(std::unique(known.begin(), known.end()), known.end());
  return known;
}

void Forest::expand() { p8est_ghost_expand(forest_.get(), ghost_); }

std::int64_t Forest::global_leaves() const { return forest_->global_num_quadrants; }

}  // namespace bccmis::distributed
