// The version-1 formats of spec/formats.md: canonical state, trace, decision
// log, and their error messages (file:line:column).
#include <gtest/gtest.h>

#include "test_util.h"

namespace bccmis {
namespace {

// Written by hand from spec/formats.md: lattice 1 1 0 has S = 2.
constexpr const char* kLattice110 =
    "bccmis-state 1\n"
    "lattice 1 1 0\n"
    "C 1 1 0 : 0 0 0 2 2 0 2 2\n"
    "N 0 0 : 1 1\n"
    "N 0 2 : 1 1\n"
    "N 2 0 : 1 1\n"
    "N 2 2 : 1 1\n"
    "end 1 4\n";

TEST(CanonicalState, InitialLatticeMatchesHandWrittenText) {
  EXPECT_EQ(canonical_state(make_lattice({1, 1, 0})), kLattice110);
}

TEST(CanonicalState, ParsesBackToTheSameGraph) {
  const Graph g = parse_state(kLattice110);
  EXPECT_EQ(g, make_lattice({1, 1, 0}));
  const Graph h = test::build("lattice 3 1 1\nrefine 10 2\nrefine 6 2\n");
  const std::string text = canonical_state(h);
  EXPECT_EQ(parse_state(text), h);
  EXPECT_EQ(canonical_state(parse_state(text)), text);
}

TEST(CanonicalState, RefinedRootByHand) {
  // lattice 1 1 1 (S = 4) after refining the root: derived from (4)-(6) with E1.
  const char* expected =
      "bccmis-state 1\n"
      "lattice 1 1 1\n"
      "C 1 1 1 : 0 0 0 2 2 0 2 2\n"
      "C 1 3 1 : 0 2 0 4 2 2 2 4\n"
      "C 3 1 1 : 2 0 2 2 4 0 4 2\n"
      "C 3 3 1 : 2 2 2 4 4 2 4 4\n"
      "N 0 0 : 1 1\n"
      "N 0 2 : 1 1 1 3\n"
      "N 0 4 : 1 3\n"
      "N 2 0 : 1 1 3 1\n"
      "N 2 2 : 1 1 1 3 3 1 3 3\n"
      "N 2 4 : 1 3 3 3\n"
      "N 4 0 : 3 1\n"
      "N 4 2 : 3 1 3 3\n"
      "N 4 4 : 3 3\n"
      "end 4 9\n";
  EXPECT_EQ(canonical_state(test::build("lattice 1 1 1\nrefine 2 2\n")), expected);
}

// An input a parser must reject, and where and why.
struct BadInput {
  const char* name;
  std::string text;
  int line, column;
  const char* message_part;
};

// parse(b.text, file) must throw a ParseError that names the file, b's line
// and column and a message containing b.message_part, and whose what() starts
// with "file:line:column: ".
template <class Parse>
void expect_parse_error(const BadInput& b, const std::string& file, Parse parse) {
  try {
    parse(b.text, file);
    FAIL() << "parsed: " << b.name;
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file, file);
    EXPECT_EQ(e.line, b.line) << e.what();
    EXPECT_EQ(e.column, b.column) << e.what();
    EXPECT_NE(e.message.find(b.message_part), std::string::npos) << e.what();
    EXPECT_EQ(
        std::string(e.what()).rfind(file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": ", 0),
        0u);
  }
}

// A test's name: the input's name, '_' for every character not a letter or digit.
std::string test_name(const testing::TestParamInfo<BadInput>& p) {
  std::string n = p.param.name;
  for (char& ch : n)
    if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

class StateErrors : public testing::TestWithParam<BadInput> {};

TEST_P(StateErrors, NamesLineColumnAndProblem) {
  expect_parse_error(GetParam(), "s.txt",
                     [](const std::string& text, const std::string& file) { parse_state(text, file); });
}

std::string with(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

INSTANTIATE_TEST_SUITE_P(
    Format, StateErrors,
    testing::Values(
        BadInput{"empty", "", 1, 1, "empty file"},
        BadInput{"magic", with(kLattice110, "bccmis-state 1", "bccmis-stat 1"), 1, 1, "expected 'bccmis-state 1'"},
        BadInput{"version", with(kLattice110, "bccmis-state 1", "bccmis-state 2"), 1, 14, "version"},
        BadInput{"double space", with(kLattice110, "C 1 1 0 :", "C 1  1 0 :"), 3, 5, "single space"},
        BadInput{"trailing space", with(kLattice110, "N 0 0 : 1 1\n", "N 0 0 : 1 1 \n"), 4, 12, "trailing space"},
        BadInput{"bad int", with(kLattice110, "N 0 2 : 1 1", "N 0 2 : 1 x"), 5, 11, "expected y coordinate"},
        BadInput{"leading zero", with(kLattice110, "N 0 2 : 1 1", "N 0 02 : 1 1"), 5, 5, "expected y coordinate"},
        BadInput{"unsorted", with(kLattice110, "N 0 2 : 1 1\nN 2 0", "N 2 0 : 1 1\nN 0 2"), 6, 3, "sorted"},
        BadInput{"count", with(kLattice110, "end 1 4", "end 1 5"), 8, 7, "node count 5"},
        BadInput{"no end", "bccmis-state 1\nlattice 1 1 0\n", 3, 1, "unexpected end of file"},
        BadInput{"no newline", with(kLattice110, "end 1 4\n", "end 1 4"), 8, 8, "missing newline"},
        BadInput{"after end", std::string(kLattice110) + "x\n", 9, 1, "after the 'end' line"},
        BadInput{"bad lattice", with(kLattice110, "lattice 1 1 0", "lattice 0 1 0"), 2, 9, "W must be >= 1"},
        BadInput{"huge int", with(kLattice110, "N 0 0 : 1 1", "N 0 0 : 1 99999999999999999999"), 4, 11, "out of range"},
        BadInput{"crlf", with(kLattice110, "end 1 4\n", "end 1 4\r\n"), 8, 8, "carriage return"},
        BadInput{"both kinds", with(kLattice110, "N 0 0 : 1 1", "N 1 1 : 1 1"), 4, 3, "both as a center and as a node"},
        BadInput{"odd neighbors", with(kLattice110, "N 0 0 : 1 1", "N 0 0 : 1 1 2"), 4, 13, "odd number"},
        BadInput{"no colon", with(kLattice110, "N 0 0 : 1 1", "N 0 0 1 1"), 4, 7, "expected 'N x y : neighbors'"}),
    test_name);

// ---- Traces ------------------------------------------------------------------

TEST(Trace, ParsesCommandsCommentsAndBlankLines) {
  const Trace t =
      parse_trace("# a comment\n\nlattice 2 1 1   # trailing comment\n\trefine 2 2\ncoarsen 2 2\ncheck\r\n");
  EXPECT_EQ(t.size, (LatticeSize{2, 1, 1}));
  EXPECT_EQ(t.lattice_line, 3);
  ASSERT_EQ(t.commands.size(), 3u);
  EXPECT_EQ(t.commands[0].kind, TraceCommand::Kind::Refine);
  EXPECT_EQ(t.commands[0].at, (Point{2, 2}));
  EXPECT_EQ(t.commands[0].line, 4);
  EXPECT_EQ(t.commands[1].kind, TraceCommand::Kind::Coarsen);
  EXPECT_EQ(t.commands[2].kind, TraceCommand::Kind::Check);
  EXPECT_EQ(format_trace(t), "lattice 2 1 1\nrefine 2 2\ncoarsen 2 2\ncheck\n");
}

TEST(Trace, DecisionLogSaysOkOrRefusedWithCode) {
  EXPECT_EQ(test::decisions("lattice 2 1 1\nrefine 2 2\nrefine 3 1\ncoarsen 4 2\ncoarsen 2 2\nrefine 0 0\n"),
            "refine 2 2 ok\n"
            "refine 3 1 refused max-level\n"
            "coarsen 4 2 refused not-a-refined-center\n"
            "coarsen 2 2 ok\n"
            "refine 0 0 refused no-such-cell\n");
}

class TraceErrors : public testing::TestWithParam<BadInput> {};

TEST_P(TraceErrors, NamesLineColumnAndProblem) {
  expect_parse_error(GetParam(), "t.trace",
                     [](const std::string& text, const std::string& file) { parse_trace(text, file); });
}

INSTANTIATE_TEST_SUITE_P(
    Format, TraceErrors,
    testing::Values(BadInput{"unknown", "lattice 1 1 1\nsplit 2 2\n", 2, 1, "unknown command 'split'"},
                    BadInput{"no lattice", "# nothing\nrefine 2 2\n", 2, 1, "before the 'lattice W H L' command"},
                    BadInput{"empty", "", 1, 1, "no 'lattice W H L' command"},
                    BadInput{"two lattices", "lattice 1 1 1\nlattice 1 1 1\n", 2, 1, "second 'lattice'"},
                    BadInput{"few args", "lattice 1 1 1\nrefine 2\n", 2, 9, "too few arguments"},
                    BadInput{"many args", "lattice 1 1 1\n  refine 2 2 2\n", 2, 14, "too many arguments"},
                    BadInput{"not int", "lattice 1 1 1\nrefine 2 two\n", 2, 10, "expected y coordinate"},
                    BadInput{"overflow", "lattice 1 1 1\ncoarsen 9223372036854775808 0\n", 2, 9, "out of range"},
                    BadInput{"zero width", "lattice 0 1 1\n", 1, 9, "W must be >= 1"},
                    BadInput{"negative L", "lattice 1 1 -1\n", 1, 13, "L must be >= 0"},
                    BadInput{"huge L", "lattice 1 1 62\n", 1, 13, "above 61"},
                    BadInput{"domain too big", "lattice 3 1 60\n", 1, 1, "exceed 2^62"},
                    BadInput{"too many cells", "lattice 3000 3000 0\n", 1, 1, "exceeds the limit"},
                    BadInput{"binary", "lattice 1 1 1\nrefine \x01 2\n", 2, 8, "unexpected byte '\\x01'"}),
    test_name);

TEST(Lattice, RejectsSizesOutOfRange) {
  EXPECT_THROW(make_lattice({0, 1, 0}), LatticeError);
  EXPECT_THROW(make_lattice({1, 0, 0}), LatticeError);
  EXPECT_THROW(make_lattice({1, 1, -1}), LatticeError);
  EXPECT_THROW(validate_lattice_size({2, 1, 61}), LatticeError);  // 2 * 2^62 > 2^62
  EXPECT_NO_THROW(validate_lattice_size({1, 1, 61}));             // exactly 2^62
  EXPECT_NO_THROW(validate_lattice_size({std::int64_t{1} << 61, 1, 0}));
  EXPECT_THROW(validate_lattice_size({(std::int64_t{1} << 61) + 1, 1, 0}), LatticeError);
}

// Expected literals written by hand from RFC 8259 §7.
TEST(Json, StringLiteralEscapesWhatJsonRequires) {
  EXPECT_EQ(json_string(""), "\"\"");
  EXPECT_EQ(json_string("plain é"), "\"plain é\"");
  EXPECT_EQ(json_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json_string("l1\nl2\tx\ry"), "\"l1\\nl2\\tx\\ry\"");
  EXPECT_EQ(json_string(std::string_view("\x01\x1f\0", 3)), "\"\\u0001\\u001f\\u0000\"");
  EXPECT_EQ(json_string("</script>&"), "\"</script>&\"");
  EXPECT_EQ(json_string("</script>&", true), "\"\\u003c/script\\u003e\\u0026\"");
}

}  // namespace
}  // namespace bccmis
