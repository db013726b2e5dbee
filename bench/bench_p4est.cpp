// bccmis against p4est (issue 10): the same adapted mesh built in batch, and
// the same one-step move of a feature, at about 10^4, 10^5 and 10^6 leaves.
//
// The mesh: a disk on an 8 x 8 lattice of depth L = 10 (a brick of 8 x 8
// trees); every leaf meeting the disk has level L, and the rest is the
// coarsest face-balanced (bccmis: edge-balanced) mesh around it. The disk
// radius sets the leaf count. The feature: the disk circles the domain
// center (radius 0.3 of the domain side) in 15440 frames per turn, about one
// level-L cell per frame (bench/workloads.h MovingFeature, whose geometry
// P4estFeature below repeats).
//
//   Batch/bccmis_fast/leaves:N   MovingFeature<fast::Lattice>'s constructor: for each
//     level-L cell meeting the disk, refine its leaf down to level L with the
//     balancing cascade (local operations only).
//   Batch/bccmis_fast_reserved/leaves:N  the same after reserve(N) (the leaf
//     count known in advance: the pools and the position table never grow).
//   Batch/p4est/leaves:N         p4est_new, p4est_refine (recursive, cells
//     meeting the disk, to level L), p4est_balance(P4EST_CONNECT_FACE).
//   Step/bccmis_fast/leaves:N    one frame: coarsen near the old disk (finest
//     first, where can_coarsen allows) and refine where the disk arrived.
//   Step/p4est/leaves:N          one frame: p4est_refine (recursive, the new
//     disk), p4est_coarsen (recursive, families whose parent misses the
//     disk), p4est_balance(P4EST_CONNECT_FACE): each pass visits the forest.
//
// Counters: leaves, bytes_per_leaf (bccmis: fast::Lattice::memory_bytes(),
// pools and position table, capacity; p4est: p4est_memory_used +
// p4est_connectivity_memory_used), ops per frame (bccmis).
//
// Flags (before Google Benchmark's own):
//   --bccmis_smoke    a tiny lattice only (ctest bench-smoke)
//   --bccmis_verify   first build both meshes and move both features for a
//                     number of frames, comparing the leaf sets after each,
//                     and import p4est's forest through the bridge (checker
//                     included); exit 1 on a difference
#include <benchmark/benchmark.h>
#include <p4est_bits.h>
#include <p4est_extended.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/p4est/bridge.h"
#include "bench_main.h"
#include "local_feature.h"
#include "workloads.h"

namespace bccmis::bench {
namespace {

bool g_smoke = false;
constexpr int kFramesPerTurn = 15440;

struct Workload {
  std::int64_t leaves;  // the target (nominal) leaf count: the label
  LatticeSize size;
  double radius;  // in lattice units
};

// Radii calibrated so that the batch mesh has about `leaves` leaves.
std::vector<Workload> workloads() {
  if (g_smoke) return {{1000, {4, 4, 5}, 13.0}};
  return {{10'000, {8, 8, 10}, 105.0}, {100'000, {8, 8, 10}, 345.0}, {1'000'000, {8, 8, 10}, 1120.0}};
}

// ---- p4est: the same feature ---------------------------------------------------------------

class P4estFeature {
 public:
  P4estFeature(const p4est_bridge::Brick& brick, double radius, int frames)
      : brick_(brick), radius_(radius), frames_(frames) {
    side_ = static_cast<double>(level0_side(brick.size()));
    disk_ = position(0);
    forest_.reset(p4est_new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, this));
    p4est_refine_ext(forest_.get(), 1, brick.size().L, refine_fn, nullptr, nullptr);
    p4est_balance(forest_.get(), P4EST_CONNECT_FACE, nullptr);
  }

  void frame() {
    frame_ = (frame_ + 1) % frames_;
    disk_ = position(frame_);
    p4est_refine_ext(forest_.get(), 1, brick_.size().L, refine_fn, nullptr, nullptr);
    p4est_coarsen_ext(forest_.get(), 1, 0, coarsen_fn, nullptr, nullptr);
    p4est_balance(forest_.get(), P4EST_CONNECT_FACE, nullptr);
  }

  p4est_t* forest() const { return forest_.get(); }

  std::size_t memory_bytes() const {
    return p4est_memory_used(forest_.get()) + p4est_connectivity_memory_used(brick_.connectivity());
  }

 private:
  struct Disk {
    double x, y;
  };

  // The same formulas as MovingFeature (bench/workloads.h); --bccmis_verify
  // compares the leaf sets frame by frame.
  Disk position(int frame) const {
    const LatticeSize& s = brick_.size();
    const double cx = static_cast<double>(s.W) * side_ / 2, cy = static_cast<double>(s.H) * side_ / 2;
    const double r = 0.3 * std::min(static_cast<double>(s.W), static_cast<double>(s.H)) * side_;
    const double a = 2 * std::numbers::pi * frame / frames_;
    return {cx + r * std::cos(a), cy + r * std::sin(a)};
  }

  bool meets(const p4est_bridge::Leaf& leaf) const {
    const double h = static_cast<double>(cell_side(brick_.size(), leaf.level)) / 2;
    const double dx = std::max(0.0, std::abs(static_cast<double>(leaf.center.x) - disk_.x) - h);
    const double dy = std::max(0.0, std::abs(static_cast<double>(leaf.center.y) - disk_.y) - h);
    return dx * dx + dy * dy <= radius_ * radius_;
  }

  static int refine_fn(p4est_t* forest, p4est_topidx_t tree, p4est_quadrant_t* q) {
    const auto* self = static_cast<const P4estFeature*>(forest->user_pointer);
    return self->meets(self->brick_.to_leaf({tree, q->x, q->y, q->level})) ? 1 : 0;
  }

  static int coarsen_fn(p4est_t* forest, p4est_topidx_t tree, p4est_quadrant_t* children[]) {
    const auto* self = static_cast<const P4estFeature*>(forest->user_pointer);
    p4est_quadrant_t parent;
    p4est_quadrant_parent(children[0], &parent);
    return self->meets(self->brick_.to_leaf({tree, parent.x, parent.y, parent.level})) ? 0 : 1;
  }

  const p4est_bridge::Brick& brick_;
  double radius_;
  int frames_;
  double side_ = 0;
  int frame_ = 0;
  Disk disk_{0, 0};
  p4est_bridge::ForestPtr forest_;
};

std::vector<p4est_bridge::Leaf> leaves_of(const fast::Lattice& g) {
  std::vector<p4est_bridge::Leaf> out;
  out.reserve(g.cell_count());
  g.for_each_cell([&](const Point& c, int level) { out.push_back({c, level}); });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<p4est_bridge::Leaf> leaves_of(const p4est_bridge::Brick& brick, const p4est_t* forest) {
  std::vector<p4est_bridge::Leaf> out;
  for (const p4est_bridge::Quadrant& q : p4est_bridge::local_quadrants(forest)) out.push_back(brick.to_leaf(q));
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
        return Feature(w.size, w.radius, kFramesPerTurn, static_cast<std::size_t>(w.leaves));
      else
        return Feature(w.size, w.radius, kFramesPerTurn);
    }();
    leaves = feature.state().cell_count();
    bytes = feature.state().memory_bytes();
    benchmark::DoNotOptimize(leaves);
  }
  state.counters["leaves"] = static_cast<double>(leaves);
  state.counters["bytes_per_leaf"] = static_cast<double>(bytes) / static_cast<double>(leaves);
}

void batch_p4est(benchmark::State& state, Workload w) {
  const p4est_bridge::Brick brick(w.size);
  std::size_t leaves = 0, bytes = 0;
  for (auto _ : state) {
    P4estFeature feature(brick, w.radius, kFramesPerTurn);
    leaves = static_cast<std::size_t>(feature.forest()->global_num_quadrants);
    bytes = feature.memory_bytes();
    benchmark::DoNotOptimize(leaves);
  }
  state.counters["leaves"] = static_cast<double>(leaves);
  state.counters["bytes_per_leaf"] = static_cast<double>(bytes) / static_cast<double>(leaves);
}

template <class Feature>
void step_bccmis(benchmark::State& state, Workload w) {
  Feature feature(w.size, w.radius, kFramesPerTurn);
  std::size_t ops = 0, frames = 0;
  for (auto _ : state) {
    ops += feature.frame();
    ++frames;
  }
  state.counters["leaves"] = static_cast<double>(feature.state().cell_count());
  state.counters["bytes_per_leaf"] =
      static_cast<double>(feature.state().memory_bytes()) / static_cast<double>(feature.state().cell_count());
  state.counters["ops_per_frame"] = static_cast<double>(ops) / static_cast<double>(frames);
}

void step_p4est(benchmark::State& state, Workload w) {
  const p4est_bridge::Brick brick(w.size);
  P4estFeature feature(brick, w.radius, kFramesPerTurn);
  for (auto _ : state) feature.frame();
  state.counters["leaves"] = static_cast<double>(feature.forest()->global_num_quadrants);
  state.counters["bytes_per_leaf"] =
      static_cast<double>(feature.memory_bytes()) / static_cast<double>(feature.forest()->global_num_quadrants);
}

void register_all() {
  for (const Workload& w : workloads()) {
    const std::string n = "/leaves:" + std::to_string(w.leaves);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast" + n).c_str(), batch_bccmis<LocalFeature<fast::Lattice>>, w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast_reserved" + n).c_str(),
                                 batch_bccmis<LocalFeature<fast::Lattice>, true>, w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/bccmis_fast_pointwise" + n).c_str(),
                                 batch_bccmis<MovingFeature<fast::Lattice>>, w)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Batch/p4est" + n).c_str(), batch_p4est, w)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Step/bccmis_fast" + n).c_str(), step_bccmis<LocalFeature<fast::Lattice>>, w)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Step/bccmis_fast_boxscan" + n).c_str(), step_bccmis<MovingFeature<fast::Lattice>>, w)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("Step/p4est" + n).c_str(), step_p4est, w)->Unit(benchmark::kMicrosecond);
  }
}

// The three features (bccmis local, bccmis box scan, p4est) must describe the
// same mesh after the build and after every frame; p4est's forest must
// import into the same lattice (checker included). Returns the failures.
int verify_one(const Workload& w, int turn, int frames) {
  const p4est_bridge::Brick brick(w.size);
  LocalFeature<fast::Lattice> ours(w.size, w.radius, turn);
  MovingFeature<fast::Lattice> scan(w.size, w.radius, turn);
  P4estFeature theirs(brick, w.radius, turn);
  std::size_t ops = 0, scan_ops = 0;
  for (int f = 0; f <= frames; ++f) {
    if (f > 0) {
      ops += ours.frame();
      scan_ops += scan.frame();
      theirs.frame();
    }
    const std::vector<p4est_bridge::Leaf> mine = leaves_of(ours.state());
    if (mine != leaves_of(brick, theirs.forest()) || mine != leaves_of(scan.state())) {
      std::printf(
          "verify FAILED: leaves:%lld, %d frames a turn, frame %d: bccmis local %zu, bccmis box scan %zu, "
          "p4est %lld leaves (leaf sets differ)\n",
          static_cast<long long>(w.leaves), turn, f, ours.state().cell_count(), scan.state().cell_count(),
          static_cast<long long>(theirs.forest()->global_num_quadrants));
      return 1;
    }
  }
  try {
    if (!(p4est_bridge::import_forest(brick, theirs.forest()) == ours.state().to_graph())) {
      std::printf("verify FAILED: leaves:%lld: the imported p4est forest is not bccmis's lattice\n",
                  static_cast<long long>(w.leaves));
      return 1;
    }
  } catch (const std::exception& e) {
    std::printf("verify FAILED: %s\n", e.what());
    return 1;
  }
  std::printf(
      "verify leaves:%lld, %d frames a turn: %zu leaves, %d frames (%zu / %zu bccmis operations, local / box "
      "scan): same leaf sets in all three\n",
      static_cast<long long>(w.leaves), turn, ours.state().cell_count(), frames, ops, scan_ops);
  return 0;
}

int verify() {
  int failures = 0;
  for (const Workload& w : workloads()) {
    if (w.leaves > 100'000) continue;
    // The benchmarks' turn (about one level-L cell a frame), and a faster
    // one (the disk jumps many cells a frame: many refines and coarsens).
    failures += verify_one(w, kFramesPerTurn, g_smoke ? 60 : 20);
    failures += verify_one(w, 120, g_smoke ? 60 : 12);
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
    return false;
  });
  bccmis::p4est_bridge::Session session(&argc, &argv);
  if (do_verify && verify() != 0) return 1;
  register_all();
  return run_benchmarks(argc, argv);
}
