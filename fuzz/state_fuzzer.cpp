// fuzz_state: bytes -> parse_state -> the checker (and, on valid states, the
// operations).
//
// - A parse error must be a clean ParseError (one printable line
//   `file:line:column: message` pointing into the text).
// - parse_state is strict: whatever it accepts must print back (canonical_state)
//   byte-identically, valid graph or not.
// - find_violation must be total on any parsed graph, however broken (no
//   exception, no crash, no sanitizer report); a violation is one line.
//   check_layer on a graph a lower layer rejects may throw (its result is
//   unspecified there) but must not crash.
// - On a state the checker accepts, one refine and one coarsen chosen by the
//   input run through the checked operations, each immediately inverted; the
//   state must come back byte-identically. Failures abort with the state text
//   on stderr (`bccmis check FILE` reads it).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/format.h"
#include "bccmis/geometry.h"
#include "bccmis/invariants/checked.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/ops.h"
#include "fuzz_util.h"

namespace {

using namespace bccmis;

constexpr std::string_view kTarget = "fuzz_state";
constexpr std::string_view kFile = "fuzz.state";

[[noreturn]] void fail_with_state(const std::string& what, std::string_view state) {
  fuzz::fail(kTarget, what + "\n==== state:\n" + std::string(state) + "==== end of state");
}

void check_violation_text(const Violation& v, std::string_view state) {
  const std::string s = to_string(v);
  for (char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    // The message may carry UTF-8 (the paper's section sign); no control bytes.
    if (u < 0x20) fail_with_state("violation text has a control byte: " + s, state);
  }
  if (v.code.empty() || s.empty()) fail_with_state("violation without code or text", state);
}

std::string position(const Point& v) { return std::to_string(v.x) + " " + std::to_string(v.y); }

// Applies op (refine or coarsen at v) and, if applied, its inverse; the state
// must come back.
template <class Op, class Inverse>
void round_trip(Graph g, const Point& v, std::string_view state, const char* name, Op op, Inverse inverse) {
  try {
    if (!op(g, v).applied()) {
      if (canonical_state(g) != state) fail_with_state(std::string("refused ") + name + " changed the state", state);
      return;
    }
    if (!inverse(g, v).applied())
      fail_with_state(std::string("the inverse of ") + name + " " + position(v) + " was refused", state);
  } catch (const std::exception& e) {
    fail_with_state(std::string(name) + " " + position(v) + " threw: " + e.what(), state);
  }
  if (canonical_state(g) != state)
    fail_with_state(std::string(name) + " " + position(v) + " followed by its inverse changed the state", state);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Graph g;
  try {
    g = parse_state(text, kFile);
  } catch (const ParseError& e) {
    fuzz::check_parse_error(kTarget, e, kFile, text);
    return 0;
  }
  if (canonical_state(g) != text)
    fail_with_state("parse_state accepted a text that does not print back byte-identically", text);

  // find_violation must be total: no exception, whatever the graph.
  std::optional<Violation> violation;
  try {
    violation = find_violation(g);
  } catch (const std::exception& e) {
    fail_with_state(std::string("find_violation threw: ") + e.what(), text);
  }
  // A single layer on a graph a lower layer rejects has an unspecified result
  // (invariants.h): an exception is allowed, a crash or undefined behaviour
  // (which the sanitizers report) is not.
  for (int layer = 1; layer <= 4; ++layer) {
    try {
      if (auto v = check_layer(g, layer)) check_violation_text(*v, text);
    } catch (const std::exception&) {
      if (!violation) fail_with_state("check_layer threw on a valid graph", text);
    }
  }
  if (violation) {
    check_violation_text(*violation, text);
    return 0;
  }

  // A valid state: one refine and one coarsen, each inverted at once.
  const std::size_t pick = size * 2654435761u;
  if (!g.C.empty()) {
    const Point c = *std::next(g.C.begin(), static_cast<std::ptrdiff_t>(pick % g.C.size()));
    round_trip(g, c, text, "refine", checked_refine, checked_coarsen);
  }
  std::vector<Point> refined;
  for (const Point& n : g.N)
    if (refined_center_level(g.size, n)) refined.push_back(n);
  if (!refined.empty()) round_trip(g, refined[pick % refined.size()], text, "coarsen", checked_coarsen, checked_refine);
  return 0;
}
