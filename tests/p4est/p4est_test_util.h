// Shared by the p4est and p8est bridge tests: one MPI/p4est session per test
// process, and random refinement targets (2D here, 3D from tests/d3/
// cascade_model.h) applied in both bccmis and p4est (p8est): refine every
// quadrant (octant) holding a target point until it reaches the target's
// level, then p4est_balance (p8est_balance). Written once over the dimension
// with the bridge's traits P4<Dim>.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bccmis/apps/balance.h"
#include "bccmis/invariants/d3/invariants.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/p4est/bridge.h"
#include "d3/cascade_model.h"

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

using Target3 = d3::cascade_model::Target;

template <int Dim, class T>
struct TargetContext {
  const BrickOf<Dim>* brick;
  const std::vector<T>* targets;
};

/// Refine a quadrant (octant) holding a target point of a finer level.
template <int Dim, class T>
int refine_at_targets(typename P4<Dim>::forest_t* forest, p4est_topidx_t tree, typename P4<Dim>::quadrant_t* q) {
  const auto* ctx = static_cast<const TargetContext<Dim, T>*>(forest->user_pointer);
  const LeafOf<Dim> leaf = ctx->brick->to_leaf(P4<Dim>::quadrant(tree, *q));
  const std::int64_t h = cell_side(ctx->brick->size(), leaf.level) / 2;
  const std::array<std::int64_t, Dim> c = P4<Dim>::axes(leaf.center);
  for (const T& t : *ctx->targets) {
    const std::array<std::int64_t, Dim> p = P4<Dim>::axes(t.point);
    bool inside = t.level > leaf.level;
    for (std::size_t a = 0; a < Dim; ++a) inside = inside && p[a] > c[a] - h && p[a] < c[a] + h;
    if (inside) return 1;
  }
  return 0;
}

/// p4est (p8est): refine (recursive) at the targets, then balance with
/// `connect` unless `balance` is false.
template <int Dim, class T>
ForestPtrOf<Dim> forest_at_targets(const BrickOf<Dim>& brick, const std::vector<T>& targets,
                                   typename P4<Dim>::connect_type_t connect, bool balance) {
  using P = P4<Dim>;
  TargetContext<Dim, T> ctx{&brick, &targets};
  ForestPtrOf<Dim> forest(P::new_ext(sc_MPI_COMM_WORLD, brick.connectivity(), 0, 0, 1, 0, nullptr, &ctx));
  P::refine_ext(forest.get(), 1, P::kQMaxLevel, refine_at_targets<Dim, T>, nullptr, nullptr);
  forest->user_pointer = nullptr;
  if (balance) P::balance(forest.get(), connect, nullptr);
  return forest;
}

inline ForestPtr p4est_targets(const Brick& brick, const std::vector<Target>& targets, p4est_connect_type_t connect,
                               bool balance = true) {
  return forest_at_targets(brick, targets, connect, balance);
}

inline Forest3Ptr p8est_targets(const Brick3& brick, const std::vector<Target3>& targets, p8est_connect_type_t connect,
                                bool balance = true) {
  return forest_at_targets(brick, targets, connect, balance);
}

/// The forest's leaves in bccmis coordinates, sorted.
template <int Dim>
std::vector<LeafOf<Dim>> forest_leaves(const BrickOf<Dim>& brick, const typename P4<Dim>::forest_t* forest) {
  std::vector<LeafOf<Dim>> out;
  for (const QuadrantOf<Dim>& q : local_quadrants(forest)) out.push_back(brick.to_leaf(q));
  std::sort(out.begin(), out.end());
  return out;
}

/// What import_quadrants says about `qs`: its ImportError's what(), or
/// "accepted".
template <int Dim>
std::string import_error(const BrickOf<Dim>& brick, const std::vector<QuadrantOf<Dim>>& qs) {
  try {
    import_quadrants(brick, qs);
  } catch (const ImportError& e) {
    return e.what();
  }
  return "accepted";
}

/// The forest exported from g is balanced as the core is (P4EST_CONNECT_FACE,
/// P8EST_CONNECT_EDGE) and holds exactly the quadrants of g's leaves.
template <int Dim>
void expect_quadrants_of(const BrickOf<Dim>& brick, const typename P4<Dim>::Graph& g,
                         typename P4<Dim>::forest_t* forest) {
  EXPECT_EQ(P4<Dim>::is_balanced(forest, P4<Dim>::kConnectCore), 1);
  std::vector<QuadrantOf<Dim>> expected;
  for (const LeafOf<Dim>& leaf : leaves(g)) expected.push_back(brick.to_quadrant(leaf));
  std::vector<QuadrantOf<Dim>> got = local_quadrants(forest);
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
}

/// The forest imports, passes the checker, and exports to the same
/// quadrants in the same order.
template <int Dim>
void expect_round_trip(const BrickOf<Dim>& brick, const typename P4<Dim>::forest_t* forest) {
  const typename P4<Dim>::Graph g = import_forest(brick, forest);
  EXPECT_EQ(find_violation(g), std::nullopt);
  EXPECT_EQ(static_cast<std::int64_t>(g.C.size()), static_cast<std::int64_t>(forest->global_num_quadrants));
  const ForestPtrOf<Dim> again = export_forest(brick, g, sc_MPI_COMM_WORLD);
  EXPECT_EQ(local_quadrants(again.get()), local_quadrants(forest));
}

/// g's leaves are the forest's, and the forest imports to g, to the last
/// node (fatal failures: call under ASSERT_NO_FATAL_FAILURE).
template <int Dim>
void expect_same_lattice(const typename P4<Dim>::Graph& g, const BrickOf<Dim>& brick,
                         const typename P4<Dim>::forest_t* forest) {
  const std::vector<LeafOf<Dim>> expected = forest_leaves(brick, forest);
  const std::vector<LeafOf<Dim>> got = leaves(g);
  ASSERT_EQ(got.size(), expected.size());
  ASSERT_EQ(got, expected);
  ASSERT_EQ(import_forest(brick, forest), g);
}

/// The tests' main: Google Test with one Session for the whole program.
inline int run_tests(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::AddGlobalTestEnvironment(new SessionEnvironment);
  return RUN_ALL_TESTS();
}

}  // namespace bccmis::p4est_bridge::testing
