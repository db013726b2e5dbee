// The streamed output paths against the text they replace: the canonical
// state of both lattices written through TextWriter (write_canonical_state,
// canonical_state, canonical_text) equals the text built line by line with
// std::to_string the way spec/formats.md describes it, on random states of
// lattices whose coordinates take every formatting path (1 to 10 digits, the
// packed and the unpacked sort keys); decision lines equal their
// concatenation; TextWriter's numbers equal std::to_string's.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "bccmis/ops.h"
#include "bccmis/text_writer.h"
#include "bccmis/trace.h"

namespace bccmis {
namespace {

std::string point_words(const Point& p) { return std::to_string(p.x) + " " + std::to_string(p.y); }

// spec/formats.md, "Canonical state", one std::string at a time.
std::string spec_text(const Graph& g) {
  std::string out = "bccmis-state 1\nlattice " + std::to_string(g.size.W) + " " + std::to_string(g.size.H) + " " +
                    std::to_string(g.size.L) + "\n";
  auto neighbors = [&](const Point& v) {
    out += " :";
    for (const Point& w : g.nbr(v)) out += " " + point_words(w);
    out += "\n";
  };
  for (const Point& c : g.C) {
    const auto it = g.level.find(c);
    out += "C " + point_words(c) + " " + (it == g.level.end() ? std::string("?") : std::to_string(it->second));
    neighbors(c);
  }
  for (const Point& n : g.N) {
    out += "N " + point_words(n);
    neighbors(n);
  }
  return out + "end " + std::to_string(g.C.size()) + " " + std::to_string(g.N.size()) + "\n";
}

// Every text the library prints for the pair, against spec_text(reference).
void expect_same_texts(const Graph& reference, const fast::Lattice& lattice) {
  const std::string expected = spec_text(reference);
  EXPECT_EQ(canonical_state(reference), expected);
  EXPECT_EQ(canonical_text(reference), expected);
  EXPECT_EQ(fast::canonical_state(lattice), expected);
  EXPECT_EQ(canonical_text(lattice), expected);
  // After text already in the stream, and twice: nothing is left buffered.
  std::ostringstream out;
  out << "x";
  write_canonical_state(out, lattice);
  write_canonical_state(out, reference);
  EXPECT_EQ(out.str(), "x" + expected + expected);
}

// Random refines and coarsens, applied to both lattices in lock step; the
// texts compared every `every` operations and at the end.
void random_walk(const LatticeSize& size, std::uint32_t seed, int operations, int every) {
  SCOPED_TRACE("lattice " + std::to_string(size.W) + " " + std::to_string(size.H) + " " + std::to_string(size.L) +
               ", seed " + std::to_string(seed));
  Graph reference = make_lattice(size);
  fast::Lattice lattice(size);
  std::mt19937 rng(seed);
  for (int k = 1; k <= operations; ++k) {
    if (rng() % 3 != 0) {
      const std::vector<Point> cs = lattice.cells();
      const Point c = cs[rng() % cs.size()];
      ASSERT_EQ(refine(reference, c).applied(), lattice.refine(c).applied());
    } else {
      const std::vector<Point> ns = lattice.nodes();
      const Point n = ns[rng() % ns.size()];
      ASSERT_EQ(coarsen(reference, n).applied(), lattice.coarsen(n).applied());
    }
    if (k % every == 0) expect_same_texts(reference, lattice);
  }
  expect_same_texts(reference, lattice);
}

TEST(OutputPaths, SmallLatticesRandomStates) {
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    random_walk({1, 1, 3}, seed, 60, 5);
    random_walk({3, 2, 4}, seed, 120, 20);
  }
}

// Coordinates of 5 to 8 digits (the two-halves path) and above 10^8.
TEST(OutputPaths, LongCoordinates) {
  random_walk({5, 3, 12}, 7, 150, 50);  // side 5 * 2^13
  random_walk({2, 2, 26}, 8, 150, 50);  // side 2^28 > 10^8
}

// 1 x 1, L = 28: coordinates below 2^30, so a cell's key (x, y and 4 bits)
// is exactly 64 bits and a node's does not fit (the (position, index)
// sort). L = 30: neither fits.
TEST(OutputPaths, SortKeysAtTheirLimits) {
  random_walk({1, 1, 28}, 9, 120, 40);
  random_walk({1, 1, 30}, 10, 120, 40);
}

// A state of several 64 KiB chunks (about 300 KB): uniform refinement of a
// 16 x 16 lattice to level 2.
TEST(OutputPaths, StateLongerThanTheBuffer) {
  const LatticeSize size{16, 16, 2};
  std::string trace_text = "lattice 16 16 2\n";
  for (int level = 0; level < 2; ++level) {
    const std::int64_t side = cell_side(size, level);
    for (std::int64_t i = 0; i < (16 << level); ++i)
      for (std::int64_t j = 0; j < (16 << level); ++j)
        trace_text += "refine " + point_words({i * side + side / 2, j * side + side / 2}) + "\n";
  }
  const Trace trace = parse_trace(trace_text);
  std::string log_reference, log_fast;
  const Graph reference = replay<Graph>(trace, log_reference);
  const fast::Lattice lattice = replay<fast::Lattice>(trace, log_fast);
  EXPECT_EQ(log_fast, log_reference);
  EXPECT_EQ(reference.C.size(), 16u * 16u * 16u);
  EXPECT_GT(spec_text(reference).size(), 4 * TextWriter::kBufferBytes);
  expect_same_texts(reference, lattice);
}

TEST(OutputPaths, DecisionLinesAndCommandTexts) {
  const std::vector<std::int64_t> values = {0, 7, -7, 10, 99, 100, 12345, -100000000, 4611686018427387904};
  for (const std::int64_t x : values)
    for (const std::int64_t y : values) {
      const TraceCommand refine_cmd{TraceCommand::Kind::Refine, {x, y}, 1};
      const TraceCommand coarsen_cmd{TraceCommand::Kind::Coarsen, {x, y}, 2};
      EXPECT_EQ(command_text(refine_cmd), "refine " + point_words({x, y}));
      EXPECT_EQ(decision_line(refine_cmd, ""), "refine " + point_words({x, y}) + " ok");
      EXPECT_EQ(decision_line(coarsen_cmd, "not-a-refined-center"),
                "coarsen " + point_words({x, y}) + " refused not-a-refined-center");
      std::string log = "before\n";
      append_decision_line(log, coarsen_cmd, "");
      EXPECT_EQ(log, "before\ncoarsen " + point_words({x, y}) + " ok");
    }
  EXPECT_EQ(command_text(TraceCommand{}), "check");
}

TEST(OutputPaths, TextWriterNumbers) {
  std::vector<std::int64_t> values = {std::numeric_limits<std::int64_t>::min(),
                                      std::numeric_limits<std::int64_t>::max(), -1, 0};
  for (int e = 0; e <= 18; ++e) {
    std::int64_t p = 1;
    for (int k = 0; k < e; ++k) p *= 10;
    for (const std::int64_t v : {p - 1, p, p + 1, 2 * p - 1}) {
      values.push_back(v);
      values.push_back(-v);
    }
  }
  std::mt19937_64 rng(11);
  for (int k = 0; k < 2000; ++k) values.push_back(static_cast<std::int64_t>(rng() >> (rng() % 64)));
  std::ostringstream out;
  std::string expected;
  {
    TextWriter w(out);
    for (const std::int64_t v : values) {
      w.put_int(v);
      w.put_point(v, v / -3);
      w.put('\n');
      expected += std::to_string(v) + " " + point_words({v, v / -3}) + "\n";
      const TextWriter::Decimal d(v);
      EXPECT_EQ(std::string(d.text, d.size), std::to_string(v));
    }
    // A piece longer than the buffer, between buffered text.
    const std::string big(TextWriter::kBufferBytes + 17, 'z');
    w.put(big);
    expected += big;
    w.put("tail");
    expected += "tail";
    w.flush();
  }
  EXPECT_EQ(out.str(), expected);
}

}  // namespace
}  // namespace bccmis
