// Moving-feature adaptivity (src/bccmis/apps/moving_disk.h, apps.h): the checker
// after every frame, history independence, the lattice far from the feature
// back at level 0, the lift back to the initial lattice, both implementations.
// The CLI's outputs (`bccmis animate`) are tested in tests/apps/apps.cmake.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "bccmis/apps/apps.h"
#include "bccmis/apps/moving_disk.h"
#include "bccmis/fast/lattice.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"

namespace bccmis {
namespace {

// Distance, in level-0 cell units, from the square of cell c to (x, y).
double distance_to_cell(const Graph& g, const Point& c, double x, double y) {
  const double S = static_cast<double>(level0_side(g.size));
  const double h = static_cast<double>(cell_side(g.size, g.level_of(c))) / 2 / S;
  const double cx = static_cast<double>(c.x) / S, cy = static_cast<double>(c.y) / S;
  return std::hypot(std::max(std::abs(x - cx) - h, 0.0), std::max(std::abs(y - cy) - h, 0.0));
}

void many_frames(Balance mode) {
  AnimationSettings o;
  o.balance = mode;
  o.radius = 0.3;
  o.path = parse_path("0.5,0.5;5.5,4.5;3,0.2;0,4");
  o.frames = 60;
  const double S = static_cast<double>(level0_side({6, 5, 4}));
  int frames = 0;
  std::size_t operations = 0;
  Graph last = make_lattice({6, 5, 4});
  animate(last, o, [&](const FrameReport& fr, const Graph& g) {
    ++frames;
    operations += fr.refinements + fr.coarsenings;
    ASSERT_TRUE(is_valid(g)) << "frame " << fr.frame << ": " << to_string(*find_violation(g));
    if (mode == Balance::Corner) {
      ASSERT_FALSE(find_corner_imbalance(g)) << "frame " << fr.frame;
    }
    EXPECT_EQ(fr.cells, g.C.size());
    // Refined to the target where the disk is ...
    for (const Point& c : g.C) {
      const double d = distance_to_cell(g, c, fr.x, fr.y);
      if (d <= o.radius) {
        EXPECT_EQ(g.level_of(c), 4) << "frame " << fr.frame;
      }
      // ... and back at the initial lattice far from it (two level-0 cells
      // of balance rings around the disk).
      if (d > o.radius + 2.0) {
        EXPECT_EQ(g.level_of(c), 0) << "frame " << fr.frame << " cell " << c.x << " " << c.y;
      }
    }
    // History independence: a fresh lattice adapted to this disk alone.
    Graph fresh = make_lattice(g.size);
    const Disk d{fr.x * S, fr.y * S, o.radius * S};
    adapt_to_disks(fresh, std::span<const Disk>(&d, 1), 4, mode);
    EXPECT_EQ(canonical_state(fresh), canonical_state(g)) << "frame " << fr.frame;
  });
  EXPECT_EQ(frames, 60);
  EXPECT_GT(operations, 500u);
  EXPECT_GT(last.C.size(), 30u);
}

TEST(Animate, ManyFramesStayValidAndDependOnlyOnTheFeature) { many_frames(Balance::Edge); }

TEST(Animate, CornerBalanceManyFramesStayValidAndDependOnlyOnTheFeature) { many_frames(Balance::Corner); }

TEST(Animate, LiftReturnsToTheInitialLattice) {
  AnimationSettings o;
  o.path = parse_path("1,1;4,4;4,1");
  o.frames = 12;
  o.lift = true;
  Graph g = make_lattice({5, 5, 4});
  const std::vector<FrameReport> reports = animate(g, o);
  ASSERT_EQ(reports.size(), 13u);
  EXPECT_TRUE(reports.back().lifted);
  EXPECT_GT(reports.back().coarsenings, 0u);
  EXPECT_EQ(reports.back().refinements, 0u);
  EXPECT_EQ(g, make_lattice({5, 5, 4}));
}

TEST(Animate, PointFeatureAndTargetLevel) {
  Graph g = make_lattice({2, 2, 5});
  const double S = static_cast<double>(level0_side(g.size));
  // A point on a grid node: the four cells around it reach the target level.
  const Disk p{S, S, 0};
  adapt_to_disks(g, std::span<const Disk>(&p, 1), 3);
  EXPECT_TRUE(is_valid(g));
  int at_target = 0;
  for (const auto& [c, l] : g.level) {
    EXPECT_LE(l, 3);
    if (cell_meets_disk(g.size, c, l, p)) {
      EXPECT_EQ(l, 3);
      ++at_target;
    }
  }
  EXPECT_EQ(at_target, 4);
  // Lowering the target coarsens the cells that are finer than it now.
  adapt_to_disks(g, std::span<const Disk>(&p, 1), 1);
  for (const auto& [c, l] : g.level) EXPECT_LE(l, 1);
  Graph fresh = make_lattice(g.size);
  adapt_to_disks(fresh, std::span<const Disk>(&p, 1), 1);
  EXPECT_EQ(g, fresh);
}

TEST(Animate, PathParsingAndArcLength) {
  const auto path = parse_path(" 0,0 ; 3, 0;3,4 ");
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(point_on_path(path, 0), (std::array<double, 2>{0, 0}));
  EXPECT_EQ(point_on_path(path, 1), (std::array<double, 2>{3, 4}));
  const auto mid = point_on_path(path, 0.5);  // length 7: 3.5 along is (3, 0.5)
  EXPECT_DOUBLE_EQ(mid[0], 3);
  EXPECT_DOUBLE_EQ(mid[1], 0.5);
  EXPECT_EQ(point_on_path(parse_path("2,2"), 0.7), (std::array<double, 2>{2, 2}));
  for (const char* bad : {"", "1,2;", "1;2", "a,1", "1,2x", "1,nan"})
    EXPECT_THROW(parse_path(bad), std::invalid_argument) << bad;
  try {
    parse_path("1,1;2,b");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "path point 2 '2,b': 'b' is not a number");
  }
}

TEST(Animate, FastImplMakesTheSameFramesAndState) {
  // Every frame's report (operations, cells, nodes) and the final state are
  // the reference's; the lattices given to the observer are equal frame by
  // frame. Corner mode too.
  for (const Balance balance : {Balance::Edge, Balance::Corner}) {
    SCOPED_TRACE(std::string(name(balance)));
    AnimationSettings o;
    o.radius = 0.3;
    o.path = parse_path("0.5,0.5;4.5,3.5;1,3");
    o.frames = 12;
    o.lift = true;
    o.balance = balance;
    const LatticeSize size{5, 4, 4};
    std::vector<std::string> states[2];
    std::vector<FrameReport> reports[2];
    Graph finals[2];
    Graph reference = make_lattice(size);
    reports[0] =
        animate(reference, o, [&](const FrameReport&, const Graph& g) { states[0].push_back(canonical_state(g)); });
    finals[0] = reference;
    fast::Lattice lattice(size);
    reports[1] = animate(lattice, o,
                         [&](const FrameReport&, const fast::Lattice& g) { states[1].push_back(canonical_text(g)); });
    finals[1] = lattice.to_graph();
    ASSERT_EQ(reports[0].size(), 13u);
    ASSERT_EQ(reports[1].size(), reports[0].size());
    std::size_t operations = 0;
    for (std::size_t k = 0; k < reports[0].size(); ++k) {
      const FrameReport &a = reports[0][k], &b = reports[1][k];
      EXPECT_EQ(b.refinements, a.refinements) << "frame " << k;
      EXPECT_EQ(b.coarsenings, a.coarsenings) << "frame " << k;
      EXPECT_EQ(b.cells, a.cells) << "frame " << k;
      EXPECT_EQ(b.nodes, a.nodes) << "frame " << k;
      EXPECT_EQ(states[1][k], states[0][k]) << "frame " << k;
      operations += a.refinements + a.coarsenings;
    }
    EXPECT_GT(operations, 100u) << "the feature should move the lattice";
    EXPECT_EQ(finals[1], finals[0]);
    EXPECT_EQ(finals[0], make_lattice({5, 4, 4})) << "lifted: back to the initial lattice";
  }
}

TEST(Animate, BadSettingsThrow) {
  Graph g = make_lattice({8, 8, 5});
  AnimationSettings o;
  o.target_level = 9;
  EXPECT_THROW(animate(g, o), std::invalid_argument);
  o = {};
  o.radius = -1;
  EXPECT_THROW(animate(g, o), std::invalid_argument);
  o = {};
  o.frames = 0;
  EXPECT_THROW(animate(g, o), std::invalid_argument);
  o = {};
  o.path.clear();
  EXPECT_THROW(animate(g, o), std::invalid_argument);
  EXPECT_EQ(g, make_lattice({8, 8, 5})) << "refused settings change nothing";
}

}  // namespace
}  // namespace bccmis
