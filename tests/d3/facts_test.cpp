// The facts of spec/lattice3d.md §2-§3 in every state of randomized operation
// sequences, the independent structural check (tests/d3/check.h) after every
// step, and the refine/coarsen round trips. The random sequences use fixed
// seeds, printed on failure.
#include <gtest/gtest.h>

#include <iterator>
#include <random>
#include <set>
#include <vector>

#include "check.h"
#include "util.h"

namespace bccmis::d3 {
namespace {

using test::vs;

template <class Set>
Point pick(const Set& s, std::mt19937_64& rng) {
  auto it = s.begin();
  std::advance(it, static_cast<long>(std::uniform_int_distribution<std::size_t>(0, s.size() - 1)(rng)));
  return *it;
}

struct Walk {
  std::string trace;  // the operations so far, as a 3D trace
  std::size_t applied = 0;
};

// Runs `steps` random operations on g (refine a random cell, or coarsen a
// random node: refusals included), calling check(g, walk) after each one.
template <class Check>
Walk random_walk(Graph& g, std::uint64_t seed, int steps, Check check) {
  std::mt19937_64 rng(seed);
  Walk walk;
  for (int step = 0; step < steps; ++step) {
    const bool do_refine = std::uniform_int_distribution<int>(0, 99)(rng) < 55;
    if (do_refine) {
      const Point c = pick(g.C, rng);
      walk.trace += "refine " + std::to_string(c.x) + ' ' + std::to_string(c.y) + ' ' + std::to_string(c.z) + '\n';
      walk.applied += refine(g, c).applied();
    } else {
      // Half of the coarsen targets are nodes at refined-center positions, so
      // that coarsening is often possible; the others are any node.
      std::vector<Point> centers;
      for (const Point& v : g.N)
        if (refined_center_level(g.size, v)) centers.push_back(v);
      const bool any = centers.empty() || std::uniform_int_distribution<int>(0, 1)(rng) == 0;
      const Point n = any ? pick(g.N, rng) : pick(centers, rng);
      walk.trace += "coarsen " + std::to_string(n.x) + ' ' + std::to_string(n.y) + ' ' + std::to_string(n.z) + '\n';
      walk.applied += coarsen(g, n).applied();
    }
    if (!check(g, walk)) break;
  }
  return walk;
}

struct Case {
  LatticeSize size;
  int steps;
};

const Case kCases[] = {
    {{1, 1, 1, 3}, 120}, {{2, 1, 1, 2}, 120}, {{2, 2, 1, 2}, 100}, {{2, 2, 2, 1}, 60}, {{3, 1, 2, 2}, 80}};
constexpr std::uint64_t kSeeds[] = {20090303, 2};

std::string lattice_line(const LatticeSize& s) {
  return "lattice " + std::to_string(s.W) + ' ' + std::to_string(s.H) + ' ' + std::to_string(s.D) + ' ' +
         std::to_string(s.L) + '\n';
}

TEST(D3Facts, CardinalitiesInRandomStates) {
  //= bccmis3d#fact-F1 type=test
  //= bccmis3d#fact-F2 type=test
  //= bccmis3d#fact-F3 type=test
  //= bccmis3d#claim-P-has-8 type=test
  //= bccmis3d#claim-J-on-edges-and-faces type=test
  //= bccmis3d#claim-children-have-8 type=test
  std::set<std::size_t> junction_counts, pure_counts, cell_counts;
  for (const Case& k : kCases)
    for (const std::uint64_t seed : kSeeds) {
      Graph g(k.size);
      std::size_t states = 0;
      const Walk walk = random_walk(g, seed, k.steps, [&](const Graph& h, const Walk& w) {
        ++states;
        const model::Leaves leaves = test::leaves_of(h);
        for (const Point& n : h.N) {
          bool pure = true;
          for (const Point& c : h.nbr(n)) pure = pure && model::is_corner(model::cube(h.size, c, leaves.at(c)), n);
          (pure ? pure_counts : junction_counts).insert(h.nbr(n).size());
        }
        for (const Point& c : h.C) cell_counts.insert(h.nbr(c).size());
        const std::string why = test::state_problem(h);
        EXPECT_EQ(why, "") << "seed " << seed << ", after:\n" << lattice_line(k.size) << w.trace;
        return why.empty();
      });
      EXPECT_GT(walk.applied, static_cast<std::size_t>(k.steps / 5)) << "seed " << seed << ": the walk stalls";
      EXPECT_EQ(states, static_cast<std::size_t>(k.steps));
    }
  // The walks reach every cardinality the facts allow (so the check is not vacuous).
  EXPECT_EQ(junction_counts, (std::set<std::size_t>{3, 5, 6, 7}));
  EXPECT_EQ(pure_counts, (std::set<std::size_t>{1, 2, 4, 8}));
  EXPECT_EQ(*cell_counts.begin(), 8u);
  EXPECT_GE(*cell_counts.rbegin(), 16u);
}

TEST(D3Facts, XIsExactlyTheFaceAndEdgeNeighbours) {
  //= bccmis3d#fact-balance type=test
  //= bccmis3d#eq-R1d type=test
  // In random states of lattice 2 2 1 2, X computed by the set formula R1d
  // equals the leaves whose closed cube meets c's in a segment or a patch.
  Graph g(LatticeSize{2, 2, 1, 2});
  std::size_t compared = 0;
  random_walk(g, 20090303, 120, [&](const Graph& h, const Walk&) {
    const model::Leaves leaves = test::leaves_of(h);
    for (const Point& c : h.C) {
      const PointSet& B = h.nbr(c);
      PointSet X;
      for (auto bi = B.begin(); bi != B.end(); ++bi)
        for (auto bj = std::next(bi); bj != B.end(); ++bj)
          for (const Point& x : h.nbr(*bi))
            if (x != c && h.nbr(*bj).count(x)) X.insert(x);
      PointSet geometric;
      for (const auto& [x, lx] : leaves)
        if (x != c && model::contact_dimension(model::cube(h.size, c, leaves.at(c)), model::cube(h.size, x, lx)) >= 1)
          geometric.insert(x);
      EXPECT_EQ(X, geometric) << to_string(c);
      ++compared;
    }
    return !testing::Test::HasFailure();
  });
  EXPECT_GT(compared, 1000u);
}

TEST(D3Facts, RandomRefusalsLeaveTheStateUnchanged) {
  // Any refused operation in a random walk leaves the canonical text as it was.
  Graph g(LatticeSize{2, 1, 1, 2});
  std::mt19937_64 rng(20090303);
  std::size_t refusals = 0;
  for (int step = 0; step < 300; ++step) {
    const std::string before = canonical_state(g);
    const bool do_refine = step % 2 == 0;
    const Point v = do_refine ? pick(g.C, rng) : pick(g.N, rng);
    const bool applied = do_refine ? refine(g, v).applied() : coarsen(g, v).applied();
    if (!applied) {
      ++refusals;
      ASSERT_EQ(canonical_state(g), before) << (do_refine ? "refine " : "coarsen ") << to_string(v);
    }
  }
  EXPECT_GT(refusals, 50u);
}

TEST(D3Facts, RefineThenCoarsenIsTheIdentityOnInteriorFaceEdgeAndCornerCells) {
  //= bccmis3d#claim-inverse type=test
  // lattice 3 3 3 1 (S = 4): corner (2,2,2), edge (6,2,2), face (6,6,2),
  // interior (6,6,6); first on the initial lattice, then with finer
  // neighbours around them so that old junctions are involved.
  const std::vector<std::string> setups = {"", "refine 10 6 6\nrefine 6 10 2\nrefine 2 6 2\nrefine 6 2 6\n"};
  for (const std::string& setup : setups) {
    const Graph start = test::build("lattice 3 3 3 1\n" + setup);
    for (const Point c : {Point{2, 2, 2}, Point{6, 2, 2}, Point{6, 6, 2}, Point{6, 6, 6}}) {
      Graph g = start;
      ASSERT_TRUE(refine(g, c).applied()) << to_string(c);
      EXPECT_EQ(test::state_problem(g), "");
      ASSERT_TRUE(coarsen(g, c).applied()) << to_string(c);
      EXPECT_EQ(canonical_state(g), canonical_state(start)) << to_string(c) << " after\n" << setup;
    }
  }
}

TEST(D3Facts, CoarsenThenRefineIsTheIdentity) {
  //= bccmis3d#claim-inverse type=test
  // In random states, every coarsenable node coarsened and refined back.
  Graph g(LatticeSize{2, 2, 1, 2});
  std::size_t round_trips = 0;
  random_walk(g, 7, 150, [&](const Graph& h, const Walk& w) {
    for (const Point& n : h.N) {
      if (can_coarsen(h, n)) continue;
      Graph k = h;
      if (!coarsen(k, n).applied()) continue;
      EXPECT_TRUE(refine(k, n).applied());
      EXPECT_EQ(k, h) << to_string(n) << " after\n" << w.trace;
      ++round_trips;
    }
    return !testing::Test::HasFailure();
  });
  EXPECT_GT(round_trips, 50u);
}

TEST(D3Facts, UniformLevelTwoAndBack) {
  //= bccmis3d#claim-inverse type=test
  // lattice 2 2 1 2 (S = 8): refine every cell to level 2 (64 cubes of side 2
  // per level-0 cube: 256 leaves), then coarsen all of it back.
  const LatticeSize size{2, 2, 1, 2};
  Graph g(size);
  const Graph initial = g;
  std::vector<PointSet> refined_at(2);
  for (int level = 0; level < 2; ++level) {
    const PointSet cells = g.C;
    for (const Point& c : cells) {
      ASSERT_TRUE(refine(g, c).applied()) << to_string(c);
      refined_at[level].insert(c);
    }
  }
  EXPECT_EQ(g.C.size(), 4u * 64u);
  EXPECT_EQ(g.N.size(), 9u * 9u * 5u);  // the level-2 grid points of [0,16] x [0,16] x [0,8]
  EXPECT_EQ(test::state_problem(g), "");
  for (int level = 1; level >= 0; --level)
    for (const Point& n : refined_at[level]) ASSERT_TRUE(coarsen(g, n).applied()) << to_string(n);
  EXPECT_EQ(canonical_state(g), canonical_state(initial));
}

TEST(D3Facts, MaximalCellHasTwentySixNodes) {
  //= bccmis3d#fact-F3 type=test
  // lattice 3 3 3 1: the middle cube with all 26 others refined.
  std::string trace = "lattice 3 3 3 1\n";
  for (int i : {2, 6, 10})
    for (int j : {2, 6, 10})
      for (int k : {2, 6, 10})
        if (!(i == 6 && j == 6 && k == 6))
          trace += "refine " + std::to_string(i) + ' ' + std::to_string(j) + ' ' + std::to_string(k) + '\n';
  const Graph g = test::build(trace);
  EXPECT_EQ(g.nbr({6, 6, 6}).size(), 26u);
  EXPECT_EQ(test::state_problem(g), "");
}

}  // namespace
}  // namespace bccmis::d3
