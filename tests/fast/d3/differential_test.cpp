// bccmis::d3::fast::Lattice against the 3D reference (bccmis::d3::Graph):
// random operation sequences on random lattices (1..3 cubes a side, L up to
// 4) run through both in lock-step (tests/testing/d3/twin.h): every guard, every
// decision, Y and J+ / J-, and the canonical state after every step must be
// equal. Seeds are fixed; a failure prints its seed and the trace that
// reproduces it (`bccmis replay FILE`). Then the hand examples of
// spec/examples/d3 through replay<d3::fast::Lattice> against their .expected
// output, byte for byte.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/ops.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/io/format.h"
#include "bccmis/trace.h"
#include "testing/d3/twin.h"

namespace {

using namespace bccmis;

struct Stop {};  // thrown by the Fail callback after it has recorded the failure

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

template <class Set>
d3::Point pick(std::mt19937_64& rng, const Set& set) {
  auto it = set.begin();
  std::advance(it, static_cast<std::ptrdiff_t>(std::uniform_int_distribution<std::size_t>(0, set.size() - 1)(rng)));
  return *it;
}

// One random sequence: mostly refines of live cells, coarsens at refined
// centers, some raw positions (mostly refused) and copies of the fast side.
std::size_t run_sequence(std::uint64_t seed, int operations) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  const d3::LatticeSize size{uniform(1, 3), uniform(1, 3), uniform(1, 3), static_cast<int>(uniform(0, 4))};
  bccmis::d3::testing::Twin twin(size, [seed](const std::string& what, const d3::Trace& so_far) {
    ADD_FAILURE() << "seed " << seed << ": " << what << "\nreproducer (bccmis replay FILE):\n" << format_trace(so_far);
    throw Stop{};
  });
  const std::int64_t S = d3::level0_side(size);
  for (int i = 0; i < operations; ++i) {
    const d3::Graph& g = twin.graph();
    const int choice = static_cast<int>(uniform(0, 19));
    if (choice < 10) {
      twin.run(CommandKind::Refine, pick(rng, g.C));
    } else if (choice < 16) {
      std::vector<d3::Point> refined;
      for (const d3::Point& n : g.N)
        if (d3::refined_center_level(size, n)) refined.push_back(n);
      if (!refined.empty())
        twin.run(CommandKind::Coarsen, pick(rng, refined));
      else
        twin.run(CommandKind::Coarsen, pick(rng, g.N));
    } else if (choice < 19) {
      const d3::Point p{uniform(-1, size.W * S + 1), uniform(-1, size.H * S + 1), uniform(-1, size.D * S + 1)};
      twin.run(choice == 17 ? CommandKind::Refine : CommandKind::Coarsen, p);
    } else {
      twin.reseat();
    }
  }
  twin.compare_queries();
  return twin.applied();
}

TEST(Fast3Differential, RandomSequencesAgreeStepByStep) {
  constexpr std::uint64_t kBaseSeed = 20090303;
  std::size_t applied = 0;
  for (std::uint64_t k = 0; k < 150; ++k) {
    try {
      applied += run_sequence(kBaseSeed + k, 50);
    } catch (const Stop&) {
      return;  // the failure is recorded with its seed
    }
  }
  EXPECT_GT(applied, 150u * 10u);  // the sequences mostly apply, not only refuse
}

TEST(Fast3Differential, UniformRefinementToMaxLevelAndBack) {
  // Every cell refined level by level to L = 3, then every refined center
  // coarsened back, finest first: the largest states the random sequences
  // rarely reach.
  try {
    bccmis::d3::testing::Twin twin({1, 1, 1, 3}, [](const std::string& what, const d3::Trace& so_far) {
      ADD_FAILURE() << what << "\nreproducer:\n" << format_trace(so_far);
      throw Stop{};
    });
    for (int level = 0; level < 3; ++level) {
      const d3::PointSet cells = twin.graph().C;
      for (const d3::Point& c : cells) twin.run(CommandKind::Refine, c);
    }
    EXPECT_EQ(cell_count(twin.lattice()), 512u);
    for (int level = 2; level >= 0; --level) {
      const d3::PointSet nodes = twin.graph().N;
      for (const d3::Point& n : nodes)
        if (d3::refined_center_level(twin.graph().size, n) == level) twin.run(CommandKind::Coarsen, n);
    }
    EXPECT_EQ(cell_count(twin.lattice()), 1u);
    twin.compare_queries();
  } catch (const Stop&) {
  }
}

TEST(Fast3Differential, HandExamplesGiveTheExpectedOutput) {
  const std::filesystem::path dir = std::filesystem::path(BCCMIS_SPEC_EXAMPLES_DIR) / "d3";
  int traces = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".trace") continue;
    ++traces;
    std::filesystem::path expected_path = entry.path();
    expected_path.replace_extension(".expected");
    SCOPED_TRACE(entry.path().string());
    const d3::Trace trace = d3::parse_trace(read_file(entry.path()), entry.path().string());
    std::string log;
    const d3::fast::Lattice g = replay<d3::fast::Lattice>(trace, log);
    EXPECT_EQ(log + canonical_text(g), read_file(expected_path));
  }
  EXPECT_GE(traces, 3);
}

TEST(Fast3Lattice, RefusedOperationsChangeNothingAndInvalidSizesThrow) {
  d3::fast::Lattice g({1, 1, 1, 1});
  const std::string before = canonical_text(g);
  EXPECT_EQ(g.refine({1, 1, 1}).refused, RefineRefusal::NoSuchCell);
  EXPECT_EQ(g.coarsen({2, 2, 2}).refused, CoarsenRefusal::NoSuchNode);
  EXPECT_EQ(canonical_text(g), before);
  EXPECT_THROW(d3::fast::Lattice({0, 1, 1, 1}), LatticeError);
  EXPECT_THROW(d3::fast::Lattice({1, 1, 1, -1}), LatticeError);
  EXPECT_THROW(g.level_of({0, 0, 0}), std::out_of_range);
}

// The reference and the fast lattice after the same `refines` random
// refines (most applied) from the initial lattice of `size`.
std::pair<d3::Graph, d3::fast::Lattice> random_state(std::mt19937_64& rng, const d3::LatticeSize& size, int refines) {
  std::pair<d3::Graph, d3::fast::Lattice> state{d3::Graph(size), d3::fast::Lattice(size)};
  for (int i = 0; i < refines; ++i) {
    const d3::Point c = pick(rng, state.first.C);
    d3::refine(state.first, c);
    state.second.refine(c);
  }
  return state;
}

TEST(Fast3Lattice, LeafBoundaryIsTheReferenceNeighborSet) {
  // spec/lattice3d.md §9.1: the mesh rule's view of a leaf
  // (Lattice::boundary, read from the slots) against N(u) of the reference
  // graph, on the 9 x 9 x 9 points a quarter side apart around every leaf of
  // random states: every node of the cell's boundary is in, every other
  // point (the center, points between slots, points outside the cube) out.
  std::mt19937_64 rng(20261203);
  for (int sequence = 0; sequence < 10; ++sequence) {
    const d3::LatticeSize size{2, 1, 2, 3};
    const auto [g, lat] = random_state(rng, size, 40);
    for (const d3::Point& u : g.C) {
      const auto boundary = leaf_boundary(lat, u);
      const std::int64_t q = d3::cell_side(size, g.level.at(u)) / 4;
      for (std::int64_t i = -4; i <= 4; ++i)
        for (std::int64_t j = -4; j <= 4; ++j)
          for (std::int64_t k = -4; k <= 4; ++k) {
            const d3::Point p{u.x + i * q, u.y + j * q, u.z + k * q};
            ASSERT_EQ(boundary.contains(p), g.nbr(u).contains(p)) << d3::to_string(u) << " " << d3::to_string(p);
          }
    }
  }
  EXPECT_THROW(d3::fast::Lattice({1, 1, 1, 1}).boundary({0, 0, 0}), std::out_of_range);
}

TEST(Fast3Lattice, NodeQueriesAtEveryPointOfTheFinestGrid) {
  // spec/lattice3d.md §9.3: a node that is not a refined center is found from
  // a leaf and a direction, not from the position table. Every integer point
  // of the closed domain (and one layer outside) of random states, against the
  // reference: is_node, is_center, N(p) and the coarsen guard.
  std::mt19937_64 rng(20261204);
  for (int sequence = 0; sequence < 6; ++sequence) {
    const d3::LatticeSize size{2, 1, 1, 3};
    const auto [g, lat] = random_state(rng, size, 30);
    const std::int64_t S = d3::level0_side(size);
    std::size_t nodes = 0;
    for (std::int64_t x = -1; x <= size.W * S + 1; ++x)
      for (std::int64_t y = -1; y <= size.H * S + 1; ++y)
        for (std::int64_t z = -1; z <= size.D * S + 1; ++z) {
          const d3::Point p{x, y, z};
          ASSERT_EQ(lat.is_node(p), g.is_node(p)) << d3::to_string(p);
          ASSERT_EQ(lat.is_center(p), g.is_center(p)) << d3::to_string(p);
          ASSERT_TRUE(std::ranges::equal(lat.nbr(p), g.nbr(p))) << d3::to_string(p);
          ASSERT_EQ(lat.can_coarsen(p), d3::can_coarsen(g, p)) << d3::to_string(p);
          nodes += g.is_node(p);
        }
    EXPECT_EQ(nodes, g.N.size());
  }
}

}  // namespace
