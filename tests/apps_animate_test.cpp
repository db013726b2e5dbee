// Moving-feature adaptivity (src/bccmis/apps/animate.h, apps.h): the checker
// after every frame, history independence, the lattice far from the feature
// back at level 0, the lift back to the initial lattice, run_animate outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "bccmis/apps/animate.h"
#include "bccmis/apps/apps.h"
#include "bccmis/format.h"
#include "bccmis/invariants/invariants.h"

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
  AnimateOptions o;
  o.balance = std::string(name(mode));
  o.width = 6;
  o.height = 5;
  o.max_level = 4;
  o.radius = 0.3;
  o.path = "0.5,0.5;5.5,4.5;3,0.2;0,4";
  o.frames = 60;
  const double S = static_cast<double>(level0_side({6, 5, 4}));
  int frames = 0;
  std::size_t operations = 0;
  const Graph last = animate(o, [&](const FrameReport& fr, const Graph& g) {
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
  AnimateOptions o;
  o.width = 5;
  o.height = 5;
  o.max_level = 4;
  o.path = "1,1;4,4;4,1";
  o.frames = 12;
  o.lift = true;
  std::vector<FrameReport> reports;
  const Graph g = animate(o, {}, &reports);
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
  for (const char* bad : {"", "1,2;", "1;2", "a,1", "1,2x", "1,nan"}) EXPECT_THROW(parse_path(bad), std::invalid_argument) << bad;
  try {
    parse_path("1,1;2,b");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "path point 2 '2,b': 'b' is not a number");
  }
}

TEST(RunAnimate, WritesFramesStatsAndState) {
  const auto dir = std::filesystem::temp_directory_path() / ("bccmis_apps_run_animate_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  AnimateOptions o;
  o.width = 4;
  o.height = 4;
  o.max_level = 3;
  o.path = "0.5,0.5;3.5,3.5";
  o.frames = 5;
  o.lift = true;
  o.svg_dir = dir.string();
  o.state = (dir / "final.state").string();
  o.check = true;
  std::ostringstream out, err;
  ASSERT_EQ(run_animate(o, out, err), 0) << err.str();
  for (int k = 0; k < 6; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.svg", k);
    std::ifstream in(dir / name);
    std::stringstream svg;
    svg << in.rdbuf();
    EXPECT_EQ(svg.str().rfind("<svg", 0), 0u) << name;
    EXPECT_EQ(svg.str().find("<circle cx") != std::string::npos && svg.str().find("fill=\"#e07020\"") != std::string::npos,
              k < 5)
        << name << ": the feature is drawn in the frames that have it";
  }
  std::ifstream st(o.state);
  std::stringstream state;
  state << st.rdbuf();
  EXPECT_EQ(parse_state(state.str()), make_lattice({4, 4, 3}));
  EXPECT_NE(out.str().find("# frame"), std::string::npos);
  EXPECT_NE(out.str().find(" lifted\n"), std::string::npos);
  EXPECT_NE(out.str().find("total frames 6 "), std::string::npos) << out.str();
  EXPECT_NE(err.str().find("bccmis animate: 6 frames"), std::string::npos);

  o.json = true;
  o.svg_dir.clear();
  o.state.clear();
  out.str("");
  ASSERT_EQ(run_animate(o, out, err), 0);
  EXPECT_EQ(out.str().rfind("{\"lattice\": \"4 4 3\", \"frames\": [", 0), 0u) << out.str();
  EXPECT_NE(out.str().find("\"total\": {\"frames\": 6"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(RunAnimate, FastImplMakesTheSameFramesAndState) {
  // Every frame's report (operations, cells, nodes) and the final state are
  // the reference's; the lattices given to the observer are equal frame by
  // frame. Corner mode too.
  for (const char* balance : {"edge", "corner"}) {
    SCOPED_TRACE(balance);
    AnimateOptions o;
    o.width = 5;
    o.height = 4;
    o.max_level = 4;
    o.radius = 0.3;
    o.path = "0.5,0.5;4.5,3.5;1,3";
    o.frames = 12;
    o.lift = true;
    o.balance = balance;
    std::vector<std::string> states[2];
    std::vector<FrameReport> reports[2];
    Graph finals[2];
    for (int i = 0; i < 2; ++i) {
      o.impl = i == 0 ? "reference" : "fast";
      finals[i] = animate(o, [&](const FrameReport&, const Graph& g) { states[i].push_back(canonical_state(g)); },
                          &reports[i]);
    }
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
  AnimateOptions bad;
  bad.impl = "quick";
  std::ostringstream out, err;
  EXPECT_EQ(run_animate(bad, out, err), 2);
  EXPECT_EQ(err.str(), "bccmis animate: impl 'quick' is unknown: use reference or fast\n");
}

TEST(RunAnimate, BadOptionsExitTwo) {
  std::ostringstream out, err;
  AnimateOptions o;
  o.path = "1,1;oops";
  EXPECT_EQ(run_animate(o, out, err), 2);
  EXPECT_EQ(err.str(), "bccmis animate: path point 2 'oops': expected x,y\n");
  o = {};
  o.target_level = 9;
  err.str("");
  EXPECT_EQ(run_animate(o, out, err), 2);
  EXPECT_EQ(err.str(), "bccmis animate: target level 9 is out of range 0..5 (or -1 for the max level)\n");
  o = {};
  o.svg_dir = "/nonexistent/frames";
  err.str("");
  EXPECT_EQ(run_animate(o, out, err), 2);
  EXPECT_EQ(err.str(), "bccmis animate: /nonexistent/frames: not an existing directory\n");
  o = {};
  o.state = "-";
  err.str("");
  EXPECT_EQ(run_animate(o, out, err), 2);
  o = {};
  o.radius = -1;
  err.str("");
  EXPECT_EQ(run_animate(o, out, err), 2);
  EXPECT_EQ(err.str(), "bccmis animate: radius must be a number >= 0\n");
}

}  // namespace
}  // namespace bccmis
