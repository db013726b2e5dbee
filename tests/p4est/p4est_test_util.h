// Shared by the p4est bridge tests: one MPI/p4est session per test process,
// and random refinement targets applied in both bccmis and p4est.
#pragma once

#include <gtest/gtest.h>
#include <p4est_extended.h>

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/p4est/bridge.h"

namespace bccmis::p4est_bridge::testing {

/// MPI (singleton), libsc and p4est, set up once for the whole test program.
class SessionEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { session_ = std::make_unique<Session>(); }
  void TearDown() override { session_.reset(); }

 private:
  std::unique_ptr<Session> session_;
};

/// A target: the leaf containing `point` must reach at least `level`.
struct Target {
  Point point;  ///< strictly inside a level-L cell: odd coordinates
  int level = 0;
};

inline std::string describe(const LatticeSize& size, const std::vector<Target>& targets) {
  std::string s = "lattice " + std::to_string(size.W) + " " + std::to_string(size.H) + " " + std::to_string(size.L) +
                  "; targets (x y level):";
  for (const Target& t : targets)
    s += " (" + std::to_string(t.point.x) + " " + std::to_string(t.point.y) + " " + std::to_string(t.level) + ")";
  return s;
}

inline std::vector<Target> random_targets(const LatticeSize& size, std::mt19937_64& rng, int count) {
  const std::int64_t S = level0_side(size);
  std::vector<Target> out;
  for (int k = 0; k < count; ++k) {
    // A level-L cell center: odd coordinates 1, 3, ..., W S - 1.
    const std::int64_t x = 2 * std::uniform_int_distribution<std::int64_t>(0, size.W * S / 2 - 1)(rng) + 1;
    const std::int64_t y = 2 * std::uniform_int_distribution<std::int64_t>(0, size.H * S / 2 - 1)(rng) + 1;
    out.push_back({{x, y}, std::uniform_int_distribution<int>(1, size.L)(rng)});
  }
  return out;
}

/// The cell of level l containing p (p strictly inside a level-L cell).
inline Point cell_at(const LatticeSize& size, const Point& p, int l) {
  const std::int64_t s = cell_side(size, l);
  return {(p.x / s) * s + s / 2, (p.y / s) * s + s / 2};
}

/// bccmis: refine_balanced the leaf containing each target until it reaches
/// the target level, targets in order.
inline Graph refine_targets(const LatticeSize& size, const std::vector<Target>& targets, Balance b) {
  Graph g = make_lattice(size);
  for (const Target& t : targets)
    for (int l = 0; l < t.level; ++l) {
      const Point c = cell_at(size, t.point, l);
      if (g.is_center(c) && !refine_balanced(g, c, b).applied()) ADD_FAILURE() << "refine_balanced refused";
    }
  return g;
}

struct TargetContext {
  const Brick* brick;
  const std::vector<Target>* targets;
};

inline int refine_at_targets(p4est_t* forest, p4est_topidx_t tree, p4est_quadrant_t* q) {
  const auto* ctx = static_cast<const TargetContext*>(forest->user_pointer);
  const Leaf leaf = ctx->brick->to_leaf({tree, q->x, q->y, q->level});
  const std::int64_t h = cell_side(ctx->brick->size(), leaf.level) / 2;
  for (const Target& t : *ctx->targets)
    if (t.level > leaf.level && t.point.x > leaf.center.x - h && t.point.x < leaf.center.x + h &&
        t.point.y > leaf.center.y - h && t.point.y < leaf.center.y + h)
      return 1;
  return 0;
}

/// p4est: p4est_refine (recursive) at the targets, then p4est_balance.
inline ForestPtr p4est_targets(const Brick& brick, const std::vector<Target>& targets, p4est_connect_type_t connect,
                               bool balance = true) {
  TargetContext ctx{&brick, &targets};
  ForestPtr forest(p4est_new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, &ctx));
  p4est_refine_ext(forest.get(), 1, P4EST_QMAXLEVEL, refine_at_targets, nullptr, nullptr);
  forest->user_pointer = nullptr;
  if (balance) p4est_balance(forest.get(), connect, nullptr);
  return forest;
}

/// The forest's leaves in bccmis coordinates, sorted.
inline std::vector<Leaf> forest_leaves(const Brick& brick, const p4est_t* forest) {
  std::vector<Leaf> out;
  for (const Quadrant& q : local_quadrants(forest)) out.push_back(brick.to_leaf(q));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace bccmis::p4est_bridge::testing
