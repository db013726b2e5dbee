// bccmis against p4est (issue 10): the same adapted mesh built in batch, and
// the same one-step move of a feature, at about 10^4, 10^5 and 10^6 leaves;
// compiled with BCCMIS_P4_TO_P8 defined (bench_p8est; as p4est compiles
// p8est.c from p4est.c), the 3D analogue against p8est (issue "3D at
// scale"). One source for both (issue 26): the block "The names that differ
// between the dimensions" below is the only dimension-specific part, besides
// the 2D-only box-scan feature.
//
// 2D, the mesh: a disk on an 8 x 8 lattice of depth L = 10 (a brick of 8 x 8
// trees); every leaf meeting the disk has level L, and the rest is the
// coarsest face-balanced (bccmis: edge-balanced) mesh around it. The disk
// radius sets the leaf count. The feature: the disk circles the domain
// center (radius 0.3 of the domain side) in 15440 frames per turn, about one
// level-L cell per frame (bench/workloads.h MovingFeature, whose geometry
// the 2D disk_at below repeats).
//
// 3D, the mesh: a ball in a 4 x 2 x 2 lattice of depth L = 8 (p8est: the
// 4 x 2 x 2 brick); every leaf meeting the ball has level L, and the rest is
// the coarsest edge-balanced mesh around it (p8est: P8EST_CONNECT_EDGE). The
// ball radius sets the leaf count. The feature: the ball crosses the box
// along x and back, one level-L cell side a frame (bench/d3/local_feature.h,
// whose geometry ForestFeature below shares).
//
//   Batch/bccmis_fast/leaves:N   LocalFeature<fast::Lattice>'s (3D:
//     d3::bench::LocalFeature<d3::fast::Lattice>'s) constructor: for each level-L cell
//     meeting the feature (3D: level by level), refine it down to level L
//     with the balancing cascade (local operations only).
//   Batch/bccmis_fast_reserved/leaves:N  the same after reserve(N) (the leaf
//     count known in advance: the pools and the position table never grow).
//   Batch/bccmis_fast_pointwise/leaves:N (2D) MovingFeature<fast::Lattice>'s
//     constructor.
//   Batch/p4est/leaves:N         p4est_new_ext, p4est_refine_ext (recursive,
//     cells meeting the feature, to level L), p4est_balance(P4EST_CONNECT_FACE);
//     Batch/p8est: the same with p8est and P8EST_CONNECT_EDGE.
//   Step/bccmis_fast/leaves:N    one frame: coarsen near the old feature
//     (finest first, where can_coarsen allows) and refine where it arrived.
//   Step/bccmis_fast_boxscan/leaves:N (2D) the same with MovingFeature.
//   Step/p4est/leaves:N          one frame: p4est_refine_ext (recursive, the
//     new feature), p4est_coarsen_ext (recursive, families whose parent
//     misses the feature), p4est_balance: each pass visits the forest
//     (Step/p8est: the same with p8est).
//
// Counters: leaves, bytes_per_leaf (bccmis: fast::Lattice::memory_bytes(),
// pools and position table, capacity; p4est: p4est_memory_used +
// p4est_connectivity_memory_used), ops per frame (bccmis); 3D also refines
// (the batch's refines).
//
// Flags (before Google Benchmark's own):
//   --bccmis_smoke    a tiny lattice only (ctest bench-smoke)
//   --bccmis_verify   first build both meshes and move both features for a
//                     number of frames, comparing the leaf sets after each,
//                     and import p4est's forest through the bridge (checker
//                     included); exit 1 on a difference
// and in 3D (bench_p8est) only:
//   --bccmis_verify_large  also verify the 10^6-leaf workload (leaf sets
//                     every frame; the import only up to 10^5 leaves)
//   --bccmis_verify_steps  after each Step benchmark's timed loop (untimed),
//                     replay the frames it timed on a bccmis and a p8est
//                     feature, comparing leaf sets after every frame and the
//                     last with the measured one; exit 1 on a difference
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/p4est/bridge.h"
#include "bench_main.h"
#ifndef BCCMIS_P4_TO_P8
#include <p4est_bits.h>

#include "bccmis/fast/lattice.h"
#include "local_feature.h"
#include "workloads.h"
#else
#include <p8est_bits.h>

#include "bccmis/fast/d3/lattice.h"
#include "d3/local_feature.h"
#endif

namespace bccmis::bench {
namespace {

bool g_smoke = false;
bool g_verify_large = false;
bool g_verify_steps = false;
bool g_failures = false;
std::size_t g_verified_frames = 0;

template <class Size>
struct WorkloadOf {
  std::int64_t leaves;  // the target (nominal) leaf count: the label
  Size size;
  double radius;  // in lattice units (a level-L cell has side 2)
};

// ---- The names that differ between the dimensions ---------------------------------------------

#ifndef BCCMIS_P4_TO_P8
constexpr int kDim = 2;
using Size = LatticeSize;
using Ours = LocalFeature<fast::Lattice>;   // the bccmis feature
using Scan = MovingFeature<fast::Lattice>;  // the box-scan feature, compared in 2D only
constexpr bool kScan = true;
constexpr auto quadrant_parent = &p4est_quadrant_parent;

// Every feature moves by `motion`: in 2D the frames of a turn of the disk.
constexpr int kFramesPerTurn = 15440;
constexpr int kMotion = kFramesPerTurn;

// Radii calibrated so that the batch mesh has about `leaves` leaves.
using Workload = WorkloadOf<Size>;
std::vector<Workload> workloads() {
  if (g_smoke) return {{1000, {4, 4, 5}, 13.0}};
  return {{10'000, {8, 8, 10}, 105.0}, {100'000, {8, 8, 10}, 345.0}, {1'000'000, {8, 8, 10}, 1120.0}};
}

struct Shape {
  double x, y;
};

// The same formulas as MovingFeature (bench/workloads.h); --bccmis_verify
// compares the leaf sets frame by frame.
Shape shape_at(const Size& s, int frame, int frames) {
  frame %= frames;
  const double side = static_cast<double>(level0_side(s));
  const double cx = static_cast<double>(s.W) * side / 2, cy = static_cast<double>(s.H) * side / 2;
  const double r = 0.3 * std::min(static_cast<double>(s.W), static_cast<double>(s.H)) * side;
  const double a = 2 * std::numbers::pi * frame / frames;
  return {cx + r * std::cos(a), cy + r * std::sin(a)};
}

bool meets(const Point& c, double h, const Shape& disk, double radius) {
  const double dx = std::max(0.0, std::abs(static_cast<double>(c.x) - disk.x) - h);
  const double dy = std::max(0.0, std::abs(static_cast<double>(c.y) - disk.y) - h);
  return dx * dx + dy * dy <= radius * radius;
}

std::vector<p4est_bridge::Leaf> leaves_of(const fast::Lattice& g) {
  std::vector<p4est_bridge::Leaf> out;
  out.reserve(g.cell_count());
  g.for_each_cell([&](const Point& c, int level) { out.push_back({c, level}); });
  std::sort(out.begin(), out.end());
  return out;
}

// --bccmis_verify: the features' motions and frames (smoke, full): the
// benchmarks' turn (about one level-L cell a frame), and a faster one (the
// disk jumps many cells a frame: many refines and coarsens).
struct VerifyRun {
  int motion, smoke_frames, frames;
};
constexpr std::array<VerifyRun, 2> kVerifyRuns{{{kFramesPerTurn, 60, 20}, {120, 60, 12}}};
std::string motion_name(int frames) { return std::to_string(frames) + " frames a turn"; }
#else
constexpr int kDim = 3;
using Size = d3::LatticeSize;
using Ours = d3::bench::LocalFeature<d3::fast::Lattice>;
using Scan = Ours;  // none in 3D
constexpr bool kScan = false;
constexpr auto quadrant_parent = &p8est_quadrant_parent;

// In 3D the ball's speed: level-L cell sides a frame.
constexpr int kMotion = 1;

using Workload = WorkloadOf<Size>;
std::vector<Workload> workloads() {
  if (g_smoke) return {{1000, {2, 1, 1, 4}, 5.0}};
  return {{10'000, {4, 2, 2, 8}, 22.0}, {100'000, {4, 2, 2, 8}, 50.0}, {1'000'000, {4, 2, 2, 8}, 110.0}};
}

using Shape = d3::bench::Ball;
Shape shape_at(const Size& s, int frame, int speed) { return d3::bench::ball_position(s, frame, speed); }
bool meets(const d3::Point& c, double h, const Shape& ball, double radius) { return cube_meets(c, h, ball, radius); }

std::vector<p4est_bridge::Leaf3> leaves_of(const d3::fast::Lattice& g) {
  std::vector<p4est_bridge::Leaf3> out;
  out.reserve(g.cell_count());
  for (const d3::Point& c : g.cells()) out.push_back({c, g.level_of(c)});
  std::sort(out.begin(), out.end());
  return out;
}

// The benchmarks' speed (one level-L cell a frame), and a faster one (the
// ball jumps several cells a frame: many refines and coarsens); the smoke
// lattice's pass is 8 frames, so 40 frames turn around 5 times.
struct VerifyRun {
  int motion, smoke_frames, frames;
};
constexpr std::array<VerifyRun, 2> kVerifyRuns{{{1, 40, 20}, {5, 12, 12}}};
std::string motion_name(int speed) { return "speed " + std::to_string(speed); }
#endif

using P4 = p4est_bridge::P4<kDim>;
using Leaf = p4est_bridge::LeafOf<kDim>;
using Quadrant = p4est_bridge::QuadrantOf<kDim>;
using Brick = p4est_bridge::BrickOf<kDim>;
const char* const kP4est = P4::kP4est;

// ---- p4est (p8est): the same feature --------------------------------------------------------

class ForestFeature {
 public:
  ForestFeature(const Brick& brick, double radius, int motion) : brick_(brick), radius_(radius), motion_(motion) {
    shape_ = shape_at(brick.size(), 0, motion_);
    forest_.reset(P4::new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, this));
    P4::refine_ext(forest_.get(), 1, brick.size().L, refine_fn, nullptr, nullptr);
    P4::balance(forest_.get(), P4::kConnectCore, nullptr);
  }

  void frame() {
    shape_ = shape_at(brick_.size(), ++frame_, motion_);
    P4::refine_ext(forest_.get(), 1, brick_.size().L, refine_fn, nullptr, nullptr);
    P4::coarsen_ext(forest_.get(), 1, 0, coarsen_fn, nullptr, nullptr);
    P4::balance(forest_.get(), P4::kConnectCore, nullptr);
  }

  P4::forest_t* forest() const { return forest_.get(); }

  std::size_t memory_bytes() const {
    return P4::memory_used(forest_.get()) + P4::connectivity_memory_used(brick_.connectivity());
  }

 private:
  bool meets_leaf(const Leaf& leaf) const {
    const double h = static_cast<double>(cell_side(brick_.size(), leaf.level)) / 2;
    return meets(leaf.center, h, shape_, radius_);
  }

  static int refine_fn(P4::forest_t* forest, p4est_topidx_t tree, P4::quadrant_t* q) {
    const auto* self = static_cast<const ForestFeature*>(forest->user_pointer);
    return self->meets_leaf(self->brick_.to_leaf(P4::quadrant(tree, *q))) ? 1 : 0;
  }

  static int coarsen_fn(P4::forest_t* forest, p4est_topidx_t tree, P4::quadrant_t* children[]) {
    const auto* self = static_cast<const ForestFeature*>(forest->user_pointer);
    P4::quadrant_t parent;
    quadrant_parent(children[0], &parent);
    return self->meets_leaf(self->brick_.to_leaf(P4::quadrant(tree, parent))) ? 0 : 1;
  }

  const Brick& brick_;
  double radius_;
  int motion_;
  int frame_ = 0;
  Shape shape_{};
  p4est_bridge::ForestPtrOf<kDim> forest_;
};

std::vector<Leaf> leaves_of(const Brick& brick, const P4::forest_t* forest) {
  std::vector<Leaf> out;
  for (const Quadrant& q : p4est_bridge::local_quadrants(forest)) out.push_back(brick.to_leaf(q));
  std::sort(out.begin(), out.end());
  return out;
}

// ---- Benchmarks ---------------------------------------------------------------------------------

template <class Feature, bool kReserve = false>
void batch_bccmis(benchmark::State& state, Workload w) {
  std::size_t leaves = 0, bytes = 0;
  for (auto _ : state) {
    Feature feature = [&] {
      if constexpr (kReserve)
        return Feature(w.size, w.radius, kMotion, static_cast<std::size_t>(w.leaves));
      else
        return Feature(w.size, w.radius, kMotion);
    }();
    leaves = feature.state().cell_count();
    bytes = feature.state().memory_bytes();
    benchmark::DoNotOptimize(leaves);
  }
  state.counters["leaves"] = static_cast<double>(leaves);
  state.counters["bytes_per_leaf"] = static_cast<double>(bytes) / static_cast<double>(leaves);
  if (kDim == 3) {  // every refine adds 2^3 - 1 leaves
    std::int64_t trees = 1;
    for (const std::int64_t n : P4::cells(w.size)) trees *= n;
    state.counters["refines"] = static_cast<double>((leaves - static_cast<std::size_t>(trees)) / 7);
  }
}

void batch_p4est(benchmark::State& state, Workload w) {
  const Brick brick(w.size);
  std::size_t leaves = 0, bytes = 0;
  for (auto _ : state) {
    ForestFeature feature(brick, w.radius, kMotion);
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
void check_frames(benchmark::State& state, const Workload& w, int frames, const std::vector<Leaf>& measured) {
  const Brick brick(w.size);
  Ours ours(w.size, w.radius, kMotion);
  ForestFeature theirs(brick, w.radius, kMotion);
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

template <class Feature>
void step_bccmis(benchmark::State& state, Workload w) {
  Feature feature(w.size, w.radius, kMotion);
  std::size_t ops = 0, frames = 0;
  for (auto _ : state) {
    ops += feature.frame();
    ++frames;
  }
  if (g_verify_steps) check_frames(state, w, static_cast<int>(frames), leaves_of(feature.state()));
  const auto& g = feature.state();
  state.counters["leaves"] = static_cast<double>(g.cell_count());
  state.counters["bytes_per_leaf"] = static_cast<double>(g.memory_bytes()) / static_cast<double>(g.cell_count());
  state.counters["ops_per_frame"] = static_cast<double>(ops) / static_cast<double>(frames);
}

void step_p4est(benchmark::State& state, Workload w) {
  const Brick brick(w.size);
  ForestFeature feature(brick, w.radius, kMotion);
  int frames = 0;
  for (auto _ : state) {
    feature.frame();
    ++frames;
  }
  if (g_verify_steps) check_frames(state, w, frames, leaves_of(brick, feature.forest()));
  const auto leaves = static_cast<double>(feature.forest()->global_num_quadrants);
  state.counters["leaves"] = leaves;
  state.counters["bytes_per_leaf"] = static_cast<double>(feature.memory_bytes()) / leaves;
}

void register_all() {
  const std::string p4est = kP4est;
  for (const Workload& w : workloads()) {
    const std::string n = "/leaves:" + std::to_string(w.leaves);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast" + n).c_str(), batch_bccmis<Ours>, w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast_reserved" + n).c_str(), batch_bccmis<Ours, true>, w)
        ->Unit(benchmark::kMillisecond);
    if (kScan)
      benchmark::RegisterBenchmark(("Batch/bccmis_fast_pointwise" + n).c_str(), batch_bccmis<Scan>, w)
          ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/" + p4est + n).c_str(), batch_p4est, w)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Step/bccmis_fast" + n).c_str(), step_bccmis<Ours>, w)->Unit(benchmark::kMicrosecond);
    if (kScan)
      benchmark::RegisterBenchmark(("Step/bccmis_fast_boxscan" + n).c_str(), step_bccmis<Scan>, w)
          ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Step/" + p4est + n).c_str(), step_p4est, w)->Unit(benchmark::kMicrosecond);
  }
}

// The features (bccmis local, in 2D bccmis box scan, p4est) must describe
// the same mesh after the build and after every frame; p4est's forest must
// import into the same lattice (checker included). Returns the failures.
int verify_one(const Workload& w, int motion, int frames) {
  const Brick brick(w.size);
  Ours ours(w.size, w.radius, motion);
  std::optional<Scan> scan;
  if (kScan) scan.emplace(w.size, w.radius, motion);
  ForestFeature theirs(brick, w.radius, motion);
  std::size_t ops = 0, scan_ops = 0;
  const std::string head = "leaves:" + std::to_string(w.leaves) + ", " + motion_name(motion);
  for (int f = 0; f <= frames; ++f) {
    if (f > 0) {
      ops += ours.frame();
      if (kScan) scan_ops += scan->frame();
      theirs.frame();
    }
    const std::vector<Leaf> mine = leaves_of(ours.state());
    if (mine != leaves_of(brick, theirs.forest()) || (kScan && mine != leaves_of(scan->state()))) {
      const std::string counts = kScan ? "bccmis local " + std::to_string(ours.state().cell_count()) +
                                             ", bccmis box scan " + std::to_string(scan->state().cell_count())
                                       : "bccmis " + std::to_string(ours.state().cell_count());
      std::printf("verify FAILED: %s, frame %d: %s, %s %lld leaves (leaf sets differ)\n", head.c_str(), f,
                  counts.c_str(), kP4est, static_cast<long long>(theirs.forest()->global_num_quadrants));
      return 1;
    }
  }
  const std::string done =
      std::to_string(ours.state().cell_count()) + " leaves, " + std::to_string(frames) + " frames" +
      (kScan ? " (" + std::to_string(ops) + " / " + std::to_string(scan_ops) + " bccmis operations, local / box scan)"
             : ", " + std::to_string(ops) + " bccmis operations");
  // The import builds the reference graph (std::set, about 2 ms a refine):
  // up to 10^5 leaves.
  if (w.leaves > 100'000) {
    std::printf("verify %s: %s: same leaf sets (no import)\n", head.c_str(), done.c_str());
    std::fflush(stdout);
    return 0;
  }
  try {
    if (!(p4est_bridge::import_forest(brick, theirs.forest()) == ours.state().to_graph())) {
      std::printf("verify FAILED: leaves:%lld: the imported %s forest is not bccmis's lattice\n",
                  static_cast<long long>(w.leaves), kP4est);
      return 1;
    }
  } catch (const std::exception& e) {
    std::printf("verify FAILED: %s\n", e.what());
    return 1;
  }
  std::printf("verify %s: %s: same leaf sets%s\n", head.c_str(), done.c_str(), kScan ? " in all three" : "");
  std::fflush(stdout);
  return 0;
}

int verify() {
  int failures = 0;
  for (const Workload& w : workloads()) {
    if (w.leaves > 100'000 && !g_verify_large) continue;
    for (const VerifyRun& run : kVerifyRuns)
      failures += verify_one(w, run.motion, g_smoke ? run.smoke_frames : run.frames);
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
    if (kDim == 3 && a == "--bccmis_verify_large") return do_verify = g_verify_large = true;
    if (kDim == 3 && a == "--bccmis_verify_steps") return g_verify_steps = true;
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
