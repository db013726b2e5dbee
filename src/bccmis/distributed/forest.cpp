// spec/distributed.md D10: the S3 lattice as a partitioned p8est forest,
// built by every rank at once, and a rank's ghost layer.
#include <algorithm>
#include <exception>
#include <vector>

#include "bccmis/distributed/ranks.h"

namespace bccmis::distributed {

namespace {

using namespace p4est_bridge;

/// What S3's test reads: the shape, the fit and the options, the same on
/// every rank (D10), and the brick's coordinate map; `failed`, the first
/// exception the test threw on this rank (D6).
struct Test {
  const Brick3* brick;
  const stuff::Shape* shape;
  const stuff::Fit* fit;
  const stuff::StuffOptions* options;
  std::exception_ptr failed;
};

/// p8est_refine's callback: S3's test on the octant's leaf. An exception
/// cannot cross p8est's C code: the first is kept and nothing more is
/// refined (D6: the ranks then agree and every rank throws).
int refine_by_s3(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q) {
  auto* test = static_cast<Test*>(forest->user_pointer);
  if (test->failed) return 0;
  try {
    const Leaf3 leaf = test->brick->to_leaf(P4<3>::quadrant(tree, *q));
    return stuff::s3_refines(*test->shape, *test->fit, *test->options, leaf.center, leaf.level) ? 1 : 0;
  } catch (...) {
    test->failed = std::current_exception();
    return 0;
  }
}

}  // namespace

Forest::Forest(const stuff::Shape& shape, const stuff::Fit& fit, const stuff::StuffOptions& options, MPI_Comm comm)
    : brick_(fit.size) {
  Test test{&brick_, &shape, &fit, &options, nullptr};
  forest_.reset(p8est_new_ext(comm, brick_.connectivity(), 0, 0, 1, 0, nullptr, &test));
  // S3's loop: refine every leaf that passes the test (recursively), then
  // what the edge balance forces, until no leaf passes (D10: the smallest
  // edge-balanced refinement in which no leaf passes the test, S3's lattice).
  for (p4est_gloidx_t before = -1; before != forest_->global_num_quadrants;) {
    before = forest_->global_num_quadrants;
    p8est_refine_ext(forest_.get(), 1, fit.size.L, refine_by_s3, nullptr, nullptr);
    // D6: one forest on every rank before balance and partition.
    rethrow_on_every_rank(test.failed, "S3's test while the forest was refined", comm);
    p8est_balance(forest_.get(), P8EST_CONNECT_EDGE, nullptr);
    p8est_partition(forest_.get(), 0, nullptr);  // uniform by count (D2)
  }
  forest_->user_pointer = nullptr;
  ghost_ = p8est_ghost_new(forest_.get(), P8EST_CONNECT_FULL);
  for (int layer = 1; layer < kGhostLayers; ++layer) expand();
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
