// bccmis against p8est (issue "3D at scale"): the same adapted 3D mesh built in
// batch, and the same one-step move of a ball, at about 10^4, 10^5 and 10^6
// leaves. The 3D analogue of bench_p4est.cpp.
//
// The mesh: a ball in a 4 x 2 x 2 lattice of depth L = 8 (p8est: the
// 4 x 2 x 2 brick); every leaf meeting the ball has level L, and the rest is
// the coarsest edge-balanced mesh around it (p8est: P8EST_CONNECT_EDGE). The
// ball radius sets the leaf count. The feature: the ball crosses the box
// along x and back, one level-L cell side a frame (bench/local_feature3.h,
// whose geometry P8estFeature below shares).
//
//   Batch/bccmis_fast/leaves:N           LocalFeature3<fast::Lattice3>'s constructor:
//     level by level, refine the cells meeting the ball with the balance
//     cascade (local operations only).
//   Batch/bccmis_fast_reserved/leaves:N  the same after reserve(N).
//   Batch/p8est/leaves:N                 p8est_new_ext, p8est_refine_ext (recursive,
//     cells meeting the ball, to level L), p8est_balance(P8EST_CONNECT_EDGE).
//   Step/bccmis_fast/leaves:N            one frame: coarsen near the old ball
//     (finest first, where can_coarsen allows), refine where the ball arrived.
//   Step/p8est/leaves:N                  one frame: p8est_refine_ext (recursive,
//     the new ball), p8est_coarsen_ext (recursive, families whose parent misses
//     the ball), p8est_balance(P8EST_CONNECT_EDGE): each visits the forest.
//
// Counters: leaves, bytes_per_leaf (bccmis: fast::Lattice3::memory_bytes();
// p8est: p8est_memory_used + p8est_connectivity_memory_used), ops per frame.
//
// Flags (before Google Benchmark's own):
//   --bccmis_smoke    a tiny lattice only (ctest bench-smoke)
//   --bccmis_verify   first build both meshes and move both balls for a number
//                     of frames, comparing the leaf sets after each, and import
//                     p8est's forest through the bridge (checker included);
//                     exit 1 on a difference
//   --bccmis_verify_large  also verify the 10^6-leaf workload (leaf sets
//                     every frame; the import only up to 10^5 leaves)
//   --bccmis_verify_steps  after each Step benchmark's timed loop (untimed),
//                     replay the frames it timed on a bccmis and a p8est
//                     feature, comparing leaf sets after every frame and the
//                     last with the measured one; exit 1 on a difference
#include <benchmark/benchmark.h>
#include <p8est_bits.h>
#include <p8est_extended.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bccmis/fast/lattice3.h"
#include "bccmis/p4est/bridge3.h"
#include "bench_main.h"
#include "local_feature3.h"

namespace bccmis::bench {
namespace {

using p4est_bridge::Leaf3;

bool g_smoke = false;
bool g_verify_large = false;
bool g_verify_steps = false;
bool g_failures = false;
std::size_t g_verified_frames = 0;

struct Workload {
  std::int64_t leaves;  // the target (nominal) leaf count: the label
  d3::LatticeSize3 size;
  double radius;  // in lattice units (a level-L cell has side 2)
};

// Radii calibrated so that the batch mesh has about `leaves` leaves.
std::vector<Workload> workloads() {
  if (g_smoke) return {{1000, {2, 1, 1, 4}, 5.0}};
  return {{10'000, {4, 2, 2, 8}, 22.0}, {100'000, {4, 2, 2, 8}, 50.0}, {1'000'000, {4, 2, 2, 8}, 110.0}};
}

// ---- p8est: the same feature ----------------------------------------------------------------

class P8estFeature {
 public:
  P8estFeature(const p4est_bridge::Brick3& brick, double radius, int speed)
      : brick_(brick), radius_(radius), speed_(speed) {
    ball_ = ball_position(brick.size(), 0, speed_);
    forest_.reset(p8est_new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, this));
    p8est_refine_ext(forest_.get(), 1, brick.size().L, refine_fn, nullptr, nullptr);
    p8est_balance(forest_.get(), P8EST_CONNECT_EDGE, nullptr);
  }

  void frame() {
    ball_ = ball_position(brick_.size(), ++frame_, speed_);
    p8est_refine_ext(forest_.get(), 1, brick_.size().L, refine_fn, nullptr, nullptr);
    p8est_coarsen_ext(forest_.get(), 1, 0, coarsen_fn, nullptr, nullptr);
    p8est_balance(forest_.get(), P8EST_CONNECT_EDGE, nullptr);
  }

  p8est_t* forest() const { return forest_.get(); }

  std::size_t memory_bytes() const {
    return p8est_memory_used(forest_.get()) + p8est_connectivity_memory_used(brick_.connectivity());
  }

 private:
  bool meets(const Leaf3& leaf) const {
    const double h = static_cast<double>(d3::cell_side(brick_.size(), leaf.level)) / 2;
    return cube_meets(leaf.center, h, ball_, radius_);
  }

  static int refine_fn(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* q) {
    const auto* self = static_cast<const P8estFeature*>(forest->user_pointer);
    return self->meets(self->brick_.to_leaf({tree, q->x, q->y, q->z, q->level})) ? 1 : 0;
  }

  static int coarsen_fn(p8est_t* forest, p4est_topidx_t tree, p8est_quadrant_t* children[]) {
    const auto* self = static_cast<const P8estFeature*>(forest->user_pointer);
    p8est_quadrant_t parent;
    p8est_quadrant_parent(children[0], &parent);
    return self->meets(self->brick_.to_leaf({tree, parent.x, parent.y, parent.z, parent.level})) ? 0 : 1;
  }

  const p4est_bridge::Brick3& brick_;
  double radius_;
  int speed_;
  int frame_ = 0;
  Ball3 ball_;
  p4est_bridge::Forest3Ptr forest_;
};

std::vector<Leaf3> leaves_of(const fast::Lattice3& g) {
  std::vector<Leaf3> out;
  out.reserve(g.cell_count());
  for (const d3::Point3& c : g.cells()) out.push_back({c, g.level_of(c)});
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Leaf3> leaves_of(const p4est_bridge::Brick3& brick, const p8est_t* forest) {
  std::vector<Leaf3> out;
  for (const p4est_bridge::Quadrant3& q : p4est_bridge::local_quadrants(forest)) out.push_back(brick.to_leaf(q));
  std::sort(out.begin(), out.end());
  return out;
}

// ---- Benchmarks ---------------------------------------------------------------------------------

template <bool kReserve>
void batch_bccmis(benchmark::State& state, Workload w) {
  std::size_t leaves = 0, bytes = 0, ops = 0;
  for (auto _ : state) {
    LocalFeature3<fast::Lattice3> feature(w.size, w.radius, 1, kReserve ? static_cast<std::size_t>(w.leaves) : 0);
    leaves = feature.state().cell_count();
    bytes = feature.state().memory_bytes();
    ops = (leaves - static_cast<std::size_t>(w.size.W * w.size.H * w.size.D)) / 7;
    benchmark::DoNotOptimize(leaves);
  }
  state.counters["leaves"] = static_cast<double>(leaves);
  state.counters["bytes_per_leaf"] = static_cast<double>(bytes) / static_cast<double>(leaves);
  state.counters["refines"] = static_cast<double>(ops);
}

void batch_p8est(benchmark::State& state, Workload w) {
  const p4est_bridge::Brick3 brick(w.size);
  std::size_t leaves = 0, bytes = 0;
  for (auto _ : state) {
    P8estFeature feature(brick, w.radius, 1);
    leaves = static_cast<std::size_t>(feature.forest()->global_num_quadrants);
    bytes = feature.memory_bytes();
    benchmark::DoNotOptimize(leaves);
  }
  state.counters["leaves"] = static_cast<double>(leaves);
  state.counters["bytes_per_leaf"] = static_cast<double>(bytes) / static_cast<double>(leaves);
}

// --bccmis_verify_steps, after a Step benchmark's timed loop: a bccmis and
// a p8est feature replay the `frames` frames it timed, their leaf sets
// compared after each; the last must be the measured feature's leaf set.
void check_frames(benchmark::State& state, const Workload& w, int frames, const std::vector<Leaf3>& measured) {
  if (!g_verify_steps) return;
  const p4est_bridge::Brick3 brick(w.size);
  LocalFeature3<fast::Lattice3> ours(w.size, w.radius, 1);
  P8estFeature theirs(brick, w.radius, 1);
  for (int f = 1; f <= frames; ++f) {
    ours.frame();
    theirs.frame();
    if (leaves_of(ours.state()) != leaves_of(brick, theirs.forest())) {
      std::printf("verify FAILED: leaves:%lld, frame %d of %d timed: the leaf sets differ\n",
                  static_cast<long long>(w.leaves), f, frames);
      g_failures = true;
      state.SkipWithError("leaf sets differ");
      return;
    }
  }
  if (leaves_of(ours.state()) != measured) {
    std::printf("verify FAILED: leaves:%lld: the measured feature's last frame differs\n",
                static_cast<long long>(w.leaves));
    g_failures = true;
    state.SkipWithError("leaf sets differ");
    return;
  }
  g_verified_frames += static_cast<std::size_t>(frames);
}

void step_bccmis(benchmark::State& state, Workload w) {
  LocalFeature3<fast::Lattice3> feature(w.size, w.radius, 1);
  std::size_t ops = 0, frames = 0;
  for (auto _ : state) {
    ops += feature.frame();
    ++frames;
  }
  check_frames(state, w, static_cast<int>(frames), leaves_of(feature.state()));
  const auto& g = feature.state();
  state.counters["leaves"] = static_cast<double>(g.cell_count());
  state.counters["bytes_per_leaf"] = static_cast<double>(g.memory_bytes()) / static_cast<double>(g.cell_count());
  state.counters["ops_per_frame"] = static_cast<double>(ops) / static_cast<double>(frames);
}

void step_p8est(benchmark::State& state, Workload w) {
  const p4est_bridge::Brick3 brick(w.size);
  P8estFeature feature(brick, w.radius, 1);
  int frames = 0;
  for (auto _ : state) {
    feature.frame();
    ++frames;
  }
  check_frames(state, w, frames, leaves_of(brick, feature.forest()));
  const auto leaves = static_cast<double>(feature.forest()->global_num_quadrants);
  state.counters["leaves"] = leaves;
  state.counters["bytes_per_leaf"] = static_cast<double>(feature.memory_bytes()) / leaves;
}

void register_all() {
  for (const Workload& w : workloads()) {
    const std::string n = "/leaves:" + std::to_string(w.leaves);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast" + n).c_str(), batch_bccmis<false>, w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast_reserved" + n).c_str(), batch_bccmis<true>, w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/p8est" + n).c_str(), batch_p8est, w)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Step/bccmis_fast" + n).c_str(), step_bccmis, w)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Step/p8est" + n).c_str(), step_p8est, w)->Unit(benchmark::kMicrosecond);
  }
}

// Both features must describe the same mesh after the build and after every
// frame; p8est's final forest must import into the same lattice (checker
// included). Returns the failures.
int verify_one(const Workload& w, int speed, int frames) {
  const p4est_bridge::Brick3 brick(w.size);
  LocalFeature3<fast::Lattice3> ours(w.size, w.radius, speed);
  P8estFeature theirs(brick, w.radius, speed);
  std::size_t ops = 0;
  for (int f = 0; f <= frames; ++f) {
    if (f > 0) {
      ops += ours.frame();
      theirs.frame();
    }
    if (leaves_of(ours.state()) != leaves_of(brick, theirs.forest())) {
      std::printf("verify FAILED: leaves:%lld, speed %d, frame %d: bccmis %zu, p8est %lld leaves (leaf sets differ)\n",
                  static_cast<long long>(w.leaves), speed, f, ours.state().cell_count(),
                  static_cast<long long>(theirs.forest()->global_num_quadrants));
      return 1;
    }
  }
  // The import builds the reference graph (std::set, about 2 ms a refine):
  // up to 10^5 leaves.
  if (w.leaves > 100'000) {
    std::printf(
        "verify leaves:%lld, speed %d: %zu leaves, %d frames, %zu bccmis operations: same leaf sets (no import)\n",
        static_cast<long long>(w.leaves), speed, ours.state().cell_count(), frames, ops);
    std::fflush(stdout);
    return 0;
  }
  try {
    if (!(p4est_bridge::import_forest(brick, theirs.forest()) == ours.state().to_graph())) {
      std::printf("verify FAILED: leaves:%lld: the imported p8est forest is not bccmis's lattice\n",
                  static_cast<long long>(w.leaves));
      return 1;
    }
  } catch (const std::exception& e) {
    std::printf("verify FAILED: %s\n", e.what());
    return 1;
  }
  std::printf("verify leaves:%lld, speed %d: %zu leaves, %d frames, %zu bccmis operations: same leaf sets\n",
              static_cast<long long>(w.leaves), speed, ours.state().cell_count(), frames, ops);
  std::fflush(stdout);
  return 0;
}

int verify() {
  int failures = 0;
  for (const Workload& w : workloads()) {
    if (w.leaves > 100'000 && !g_verify_large) continue;
    // The benchmarks' speed (one level-L cell a frame), and a faster one
    // (the ball jumps several cells a frame: many refines and coarsens); the
    // smoke lattice's pass is 8 frames, so 40 frames turn around 5 times.
    failures += verify_one(w, 1, g_smoke ? 40 : 20);
    failures += verify_one(w, 5, g_smoke ? 12 : 12);
  }
  return failures;
}

}  // namespace
}  // namespace bccmis::bench

int main(int argc, char** argv) {
  using namespace bccmis::bench;
  bool do_verify = false;
  take_flags(argc, argv, [&](std::string_view a) {
    if (a == "--bccmis_smoke") return g_smoke = true;
    if (a == "--bccmis_verify") return do_verify = true;
    if (a == "--bccmis_verify_large") return do_verify = g_verify_large = true;
    if (a == "--bccmis_verify_steps") return g_verify_steps = true;
    return false;
  });
  bccmis::p4est_bridge::Session session(&argc, &argv);
  if (do_verify && verify() != 0) return 1;
  register_all();
  const int status = run_benchmarks(argc, argv);
  if (g_verify_steps)
    std::printf("verify steps: %s, %zu timed frames replayed by both\n",
                g_failures ? "FAILED" : "same leaf sets after every frame", g_verified_frames);
  return g_failures ? 1 : status;
}
