// Unit tests of bccmis::fast::Lattice against the reference core (issue 9):
// the initial lattice, every project trace replayed through both with the
// decision log and the canonical state compared after every command, the
// queries, conversions, extreme positions and sizes, and the lattice
// vocabulary (bccmis/lattice.h) answering alike on both.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"
#include "bccmis/trace.h"

namespace bccmis::fast {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string text(const Point& p) { return to_string(p); }

/// Both printers of the fast lattice agree with the reference's printer of g.
void expect_same_state(const Graph& g, const Lattice& lat, const std::string& where) {
  const std::string want = bccmis::canonical_state(g);
  ASSERT_EQ(canonical_state(lat), want) << where;
  ASSERT_EQ(bccmis::canonical_state(lat.to_graph()), want) << where;
  ASSERT_TRUE(lat.to_graph() == g) << where;
  const auto problem = lat.audit();
  ASSERT_FALSE(problem) << where << ": " << *problem;
}

// ---- Initial lattice ------------------------------------------------------------

TEST(FastLattice, InitialLatticeEqualsTheReference) {
  for (const LatticeSize size : {LatticeSize{1, 1, 0}, LatticeSize{1, 1, 1}, LatticeSize{3, 1, 1}, LatticeSize{2, 5, 3},
                                 LatticeSize{6, 6, 5}, LatticeSize{1, 1, 61}, LatticeSize{7, 3, 0}}) {
    expect_same_state(bccmis::make_lattice(size), Lattice(size),
                      "lattice " + std::to_string(size.W) + " " + std::to_string(size.H) + " " +
                          std::to_string(size.L));
  }
}

TEST(FastLattice, InvalidSizesThrowTheReferenceError) {
  EXPECT_THROW(Lattice(LatticeSize{0, 1, 1}), LatticeError);
  EXPECT_THROW(Lattice(LatticeSize{1, -3, 1}), LatticeError);
  EXPECT_THROW(Lattice(LatticeSize{1, 1, -1}), LatticeError);
  EXPECT_THROW(Lattice(LatticeSize{1, 1, 62}), LatticeError);
  EXPECT_THROW(Lattice(LatticeSize{std::int64_t{1} << 61, 1, 1}), LatticeError);  // W*S > 2^62
}

TEST(FastLattice, LatticesBeyondTheIndexRangeThrowLengthError) {
  // Valid for the format (W*S <= 2^62) but 2^26 or more vertices of one kind.
  EXPECT_THROW(Lattice(LatticeSize{std::int64_t{1} << 20, std::int64_t{1} << 20, 0}), std::length_error);
}

// ---- Replays: every trace of the project through both -------------------------------

struct ReplayRun {
  std::string log;
  std::vector<std::string> states;  // canonical state after every command
  std::string final_state;
};

ReplayRun run_reference(const Trace& t) {
  ReplayRun r;
  const Graph g = replay<Graph>(t, r.log, [&](const TraceCommand&, const Graph& gr, std::string_view) {
    r.states.push_back(bccmis::canonical_state(gr));
  });
  r.final_state = bccmis::canonical_state(g);
  return r;
}

ReplayRun run_fast(const Trace& t) {
  ReplayRun r;
  const Lattice g = replay<Lattice>(t, r.log, [&](const TraceCommand&, const Lattice& lat, std::string_view) {
    r.states.push_back(canonical_state(lat));
    const auto problem = lat.audit();
    if (problem) ADD_FAILURE() << "audit: " << *problem;
  });
  r.final_state = canonical_state(g);
  return r;
}

std::vector<fs::path> project_traces() {
  std::vector<fs::path> out;
  const fs::path root = BCCMIS_SOURCE_DIR;
  for (const char* dir : {"spec/examples", "tests/regressions", "fuzz/corpus/fuzz_trace"}) {
    for (const auto& e : fs::directory_iterator(root / dir))
      if (e.path().extension() == ".trace") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(FastReplay, EveryProjectTraceGivesTheSameLogAndStatesAfterEveryCommand) {
  int replayed = 0;
  for (const fs::path& p : project_traces()) {
    SCOPED_TRACE(p.string());
    const std::string src = read_file(p);
    Trace t;
    try {
      t = parse_trace(src, p.string());
    } catch (const ParseError&) {
      continue;  // a parse error belongs to the shared parser, not to an implementation
    }
    const ReplayRun want = run_reference(t);
    const ReplayRun got = run_fast(t);
    ASSERT_EQ(got.log, want.log);
    ASSERT_EQ(got.states.size(), want.states.size());
    for (std::size_t i = 0; i < want.states.size(); ++i)
      ASSERT_EQ(got.states[i], want.states[i]) << "after command " << i + 1;
    ASSERT_EQ(got.final_state, want.final_state);
    ++replayed;
  }
  EXPECT_GE(replayed, 4);
}

TEST(FastReplay, SpecExamplesMatchTheirExpectedFiles) {
  const fs::path dir = fs::path(BCCMIS_SOURCE_DIR) / "spec/examples";
  int compared = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".trace") continue;
    fs::path expected = e.path();
    expected.replace_extension(".expected");
    if (!fs::exists(expected)) continue;
    SCOPED_TRACE(e.path().string());
    const ReplayRun got = run_fast(parse_trace(read_file(e.path()), e.path().string()));
    EXPECT_EQ(got.log + got.final_state, read_file(expected));
    ++compared;
  }
  EXPECT_GE(compared, 3);  // fig2, fig3, refusals
}

TEST(FastReplay, RefusalsTraceGivesEveryCodeInOrder) {
  const fs::path p = fs::path(BCCMIS_SOURCE_DIR) / "spec/examples/refusals.trace";
  const ReplayRun got = run_fast(parse_trace(read_file(p), p.string()));
  for (const char* code : {"no-such-cell", "no-such-node", "coarser-neighbor", "not-a-refined-center", "finer-neighbor",
                           "max-level", "children-refined"})
    EXPECT_NE(got.log.find(code), std::string::npos) << code;
}

// ---- Results of applied operations ------------------------------------------------------

TEST(FastLattice, Fig2RefineAndFig3CoarsenReturnTheReferenceSets) {
  Graph g = bccmis::make_lattice({3, 1, 1});
  Lattice lat({3, 1, 1});
  for (const Point c : {Point{10, 2}, Point{6, 2}}) {
    const bccmis::RefineResult want = bccmis::refine(g, c);
    const RefineResult got = lat.refine(c);
    ASSERT_TRUE(got.applied());
    EXPECT_EQ(got.Y.to_set(), want.Y);
    EXPECT_EQ(got.J_plus.to_set(), want.J_plus);
    EXPECT_TRUE(std::is_sorted(got.Y.begin(), got.Y.end()));
    EXPECT_TRUE(std::is_sorted(got.J_plus.begin(), got.J_plus.end()));
  }
  // (6,2) has an old junction (8,2): J+ has the three other midpoints.
  EXPECT_EQ(lat.refine({6, 6}).refused, RefineRefusal::NoSuchCell);
  const bccmis::CoarsenResult want = bccmis::coarsen(g, {6, 2});
  const CoarsenResult got = lat.coarsen({6, 2});
  ASSERT_TRUE(got.applied());
  EXPECT_EQ(got.Y.to_set(), want.Y);
  EXPECT_EQ(got.J_minus.to_set(), want.J_minus);
  EXPECT_EQ(fast::to_sets(got).J_minus, want.J_minus);
  expect_same_state(g, lat, "after fig3");
}

TEST(FastLattice, RefusedOperationsChangeNothing) {
  Lattice lat({2, 1, 2});
  lat.refine({4, 4});
  const std::string before = canonical_state(lat);
  EXPECT_EQ(lat.refine({6, 2}).refused, RefineRefusal::CoarserNeighbor);
  EXPECT_EQ(lat.coarsen({8, 0}).refused, CoarsenRefusal::NotARefinedCenter);
  EXPECT_EQ(lat.coarsen({12, 4}).refused, CoarsenRefusal::NoSuchNode);
  EXPECT_EQ(lat.refine({4, 4}).refused, RefineRefusal::NoSuchCell);
  EXPECT_EQ(canonical_state(lat), before);
}

TEST(FastLattice, ExtremePositionsAreRefusedNotCrashed) {
  Lattice lat({2, 2, 3});
  Graph g = bccmis::make_lattice({2, 2, 3});
  for (const std::int64_t a : {INT64_MIN, std::int64_t{-1}, std::int64_t{0}, std::int64_t{8}, INT64_MAX})
    for (const std::int64_t b : {INT64_MIN, std::int64_t{0}, std::int64_t{8}, std::int64_t{24}, INT64_MAX}) {
      const Point p{a, b};
      EXPECT_EQ(lat.can_refine(p), bccmis::can_refine(g, p)) << text(p);
      EXPECT_EQ(lat.can_coarsen(p), bccmis::can_coarsen(g, p)) << text(p);
      EXPECT_EQ(lat.refine(p).refused, bccmis::refine(g, p).refused) << text(p);
      EXPECT_EQ(lat.coarsen(p).refused, bccmis::coarsen(g, p).refused) << text(p);
    }
  expect_same_state(g, lat, "after extreme positions");
}

TEST(FastLattice, DeepestLevelWithPositionsNear2To62) {
  // lattice 1 1 61: the domain side is 2^62. Refine the cell at the far
  // corner down to level 61, then coarsen back; compare every step.
  const LatticeSize size{1, 1, 61};
  Graph g = bccmis::make_lattice(size);
  Lattice lat(size);
  const std::int64_t side = level0_side(size);
  std::vector<Point> refined;
  Point c{side / 2, side / 2};
  for (int l = 0; l < 61; ++l) {
    ASSERT_EQ(lat.refine(c).refused, bccmis::refine(g, c).refused) << "level " << l;
    refined.push_back(c);
    const std::int64_t h = cell_side(size, l + 1) / 2;
    c = Point{c.x + h, c.y + h};  // the north-east child
  }
  EXPECT_EQ(lat.refine(c).refused, RefineRefusal::MaxLevel);
  EXPECT_EQ(lat.level_of(c), 61);
  expect_same_state(g, lat, "at level 61");
  for (auto it = refined.rbegin(); it != refined.rend(); ++it) {
    ASSERT_TRUE(lat.coarsen(*it).applied()) << text(*it);
    ASSERT_TRUE(bccmis::coarsen(g, *it).applied());
  }
  expect_same_state(g, lat, "after coarsening back");
  expect_same_state(bccmis::make_lattice(size), lat, "initial again");
}

// ---- Queries and conversions -------------------------------------------------------------

/// A lattice with junctions on every kind of side, in both implementations.
struct Mixed {
  Graph g = bccmis::make_lattice({3, 2, 3});
  Lattice lat{LatticeSize{3, 2, 3}};
  Mixed() {
    for (const Point c : {Point{8, 8}, Point{24, 8}, Point{28, 4}, Point{30, 6}, Point{12, 12}, Point{8, 24}}) {
      bccmis::refine(g, c);
      lat.refine(c);
    }
  }
};

TEST(FastLattice, QueriesAgreeWithTheReferenceGraph) {
  const Mixed m;
  expect_same_state(m.g, m.lat, "mixed");
  EXPECT_EQ(m.lat.cell_count(), m.g.C.size());
  EXPECT_EQ(m.lat.node_count(), m.g.N.size());
  EXPECT_EQ(m.lat.cells(), std::vector<Point>(m.g.C.begin(), m.g.C.end()));
  EXPECT_EQ(m.lat.nodes(), std::vector<Point>(m.g.N.begin(), m.g.N.end()));
  std::size_t visited = 0;
  m.lat.for_each_cell([&](const Point& c, int level) {
    ++visited;
    EXPECT_EQ(m.g.level_of(c), level);
  });
  EXPECT_EQ(visited, m.g.C.size());
  const std::int64_t side = level0_side(m.g.size);
  for (std::int64_t x = -1; x <= 3 * side + 1; ++x)
    for (std::int64_t y = -1; y <= 2 * side + 1; ++y) {
      const Point p{x, y};
      ASSERT_EQ(m.lat.is_center(p), m.g.is_center(p)) << text(p);
      ASSERT_EQ(m.lat.is_node(p), m.g.is_node(p)) << text(p);
      ASSERT_EQ(m.lat.nbr(p).to_set(), m.g.nbr(p)) << text(p);
      if (m.g.is_center(p)) {
        ASSERT_EQ(m.lat.level_of(p), m.g.level_of(p)) << text(p);
      } else {
        ASSERT_THROW(m.lat.level_of(p), std::out_of_range) << text(p);
      }
      ASSERT_EQ(m.lat.can_refine(p), bccmis::can_refine(m.g, p)) << text(p);
      ASSERT_EQ(m.lat.can_coarsen(p), bccmis::can_coarsen(m.g, p)) << text(p);
    }
}

TEST(FastLattice, FromGraphRoundTripsAndKeepsGoing) {
  Mixed m;
  Lattice copy = Lattice::from_graph(m.g);
  expect_same_state(m.g, copy, "from_graph");
  // Both go on identically from the converted state.
  for (const Point p : {Point{6, 6}, Point{10, 10}, Point{8, 8}, Point{28, 4}, Point{24, 8}, Point{4, 4}}) {
    const auto want = bccmis::refine(m.g, p).refused;
    ASSERT_EQ(copy.refine(p).refused, want) << text(p);
    const auto want_c = bccmis::coarsen(m.g, p).refused;
    ASSERT_EQ(copy.coarsen(p).refused, want_c) << text(p);
  }
  expect_same_state(m.g, copy, "after ops on the converted state");
  // A parsed canonical state converts too.
  const Graph parsed = parse_state(bccmis::canonical_state(m.g));
  expect_same_state(m.g, Lattice::from_graph(parsed), "from a parsed state");
}

TEST(FastLattice, FromGraphRejectsANeighborThatIsNoCornerOrMidpoint) {
  Graph g = bccmis::make_lattice({1, 1, 1});
  g.neighbors[{2, 2}].insert({1, 0});
  g.N.insert({1, 0});
  g.neighbors[{1, 0}].insert({2, 2});
  EXPECT_THROW(Lattice::from_graph(g), std::invalid_argument);
}

TEST(FastLattice, CopiesAreIndependent) {
  Mixed m;
  Lattice copy = m.lat;
  copy.refine({4, 4});
  expect_same_state(m.g, m.lat, "original after the copy changed");
  Graph g2 = m.g;
  bccmis::refine(g2, {4, 4});
  expect_same_state(g2, copy, "copy");
}

TEST(FastLattice, ReserveAndShrinkKeepTheState) {
  Mixed m;
  const std::size_t before = m.lat.memory_bytes();
  m.lat.reserve(10000);
  EXPECT_GT(m.lat.memory_bytes(), before);
  expect_same_state(m.g, m.lat, "after reserve");
  m.lat.shrink_to_fit();
  expect_same_state(m.g, m.lat, "after shrink_to_fit");
  EXPECT_EQ(m.lat.refine({4, 4}).refused, bccmis::refine(m.g, {4, 4}).refused);
  expect_same_state(m.g, m.lat, "after an op");
}

TEST(FastLattice, RecordsAreCompact) {
  EXPECT_EQ(sizeof(Lattice::Center), 48u);
  EXPECT_EQ(sizeof(Lattice::Node), 16u);
}

// ---- The implementation names and the vocabulary ---------------------------------------------------------------

TEST(Vocabulary, BothImplementationsAnswerAlike) {
  const LatticeSize size{3, 2, 3};
  Graph ref(size);
  Lattice fst(size);
  EXPECT_EQ(size_of(fst), size);
  for (const Point c :
       {Point{8, 8}, Point{24, 8}, Point{28, 4}, Point{30, 6}, Point{12, 12}, Point{8, 24}, Point{6, 6}}) {
    const bccmis::RefineResult a = refine(ref, c);
    const bccmis::RefineResult b = to_sets(refine(fst, c));
    EXPECT_EQ(a.refused, b.refused);
    EXPECT_EQ(a.Y, b.Y);
    EXPECT_EQ(a.J_plus, b.J_plus);
  }
  const bccmis::CoarsenResult a = coarsen(ref, {28, 4});
  const bccmis::CoarsenResult b = to_sets(coarsen(fst, {28, 4}));
  EXPECT_EQ(a.refused, b.refused);
  EXPECT_EQ(a.J_minus, b.J_minus);
  EXPECT_EQ(canonical_text(fst), canonical_text(ref));
  EXPECT_TRUE(fst.to_graph() == ref);
  EXPECT_EQ(cells(fst), std::vector<Point>(cells(ref).begin(), cells(ref).end()));
  EXPECT_EQ(nodes(fst), std::vector<Point>(nodes(ref).begin(), nodes(ref).end()));
  EXPECT_EQ(cell_count(fst), cell_count(ref));
  EXPECT_EQ(node_count(fst), node_count(ref));
  for (const Point p : {Point{8, 8}, Point{6, 6}, Point{16, 8}, Point{5, 5}}) {
    EXPECT_EQ(neighbors(fst, p).to_set(), neighbors(ref, p));
    EXPECT_EQ(is_center(fst, p), is_center(ref, p));
    EXPECT_EQ(is_node(fst, p), is_node(ref, p));
    EXPECT_EQ(can_refine(fst, p), can_refine(ref, p));
    EXPECT_EQ(can_coarsen(fst, p), can_coarsen(ref, p));
  }
  EXPECT_EQ(level_of(fst, {4, 4}), level_of(ref, {4, 4}));
  EXPECT_THROW(level_of(fst, {8, 8}), std::out_of_range);
  EXPECT_THROW(level_of(ref, {8, 8}), std::out_of_range);
  const Lattice copy = fst;
  refine(fst, {4, 4});
  EXPECT_EQ(canonical_text(copy), canonical_text(ref));
  const Lattice back = Lattice::from_graph(ref);
  EXPECT_EQ(canonical_text(back), canonical_text(ref));
}

Graph as_graph(const Graph& g) { return g; }
Graph as_graph(const Lattice& g) { return g.to_graph(); }

/// replay<L> of `t`: its decision log and final canonical state; the
/// checker passes at every `check`, and there is exactly one.
template <AdaptiveLattice L>
void expect_replay_output(const Trace& t, const std::string& want_log, const std::string& want_state) {
  std::string log;
  int checks = 0;
  const L g = replay<L>(t, log, [&](const TraceCommand& cmd, const L& lat, std::string_view) {
    if (cmd.kind == TraceCommand::Kind::Check) {
      ++checks;
      EXPECT_FALSE(find_violation(as_graph(lat)));
    }
  });
  EXPECT_EQ(log, want_log);
  EXPECT_EQ(canonical_text(g), want_state);
  EXPECT_EQ(checks, 1);
}

TEST(Vocabulary, ReplayGivesTheReferenceOutputForEitherImplementation) {
  const fs::path p = fs::path(BCCMIS_SOURCE_DIR) / "spec/examples/refusals.trace";
  const Trace t = parse_trace(read_file(p), p.string());
  std::string want_log;
  const Graph want = replay<Graph>(t, want_log);
  {
    SCOPED_TRACE("reference");
    expect_replay_output<Graph>(t, want_log, bccmis::canonical_state(want));
  }
  {
    SCOPED_TRACE("fast");
    expect_replay_output<Lattice>(t, want_log, bccmis::canonical_state(want));
  }
}

}  // namespace
}  // namespace bccmis::fast
