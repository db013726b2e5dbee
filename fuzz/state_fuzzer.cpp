// fuzz_state: bytes -> parse_any_state -> the checker (and, on valid states,
// the operations), in either dimension (four numbers on the `lattice` line
// make a 3D state, spec/formats.md "3D extension").
//
// - A parse error must be a clean ParseError (one printable line
//   `file:line:column: message` pointing into the text).
// - The parsers are strict: whatever they accept must print back
//   (canonical_state) byte-identically, valid graph or not.
// - find_violation of the parsed dimension must be total on any parsed graph,
//   however broken (no exception, no crash, no sanitizer report); a violation
//   is one line. check_layer on a graph a lower layer rejects may throw (its
//   result is unspecified there) but must not crash.
// - On a state the checker accepts (in 3D also the mesh layer,
//   check_mesh(g, tetrahedra(g))), one refine and one coarsen chosen by the
//   input run through the checked operations (Checked2, d3::Checked), each
//   immediately inverted; the state must come back byte-identically.
//   Failures abort with the state text on stderr (`bccmis check FILE` reads
//   it).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/d3/lattice.h"
#include "bccmis/geometry.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "d3/checked.h"
#include "fuzz_util.h"
#include "op_run.h"

namespace {

using namespace bccmis;

constexpr std::string_view kTarget = "fuzz_state";
constexpr std::string_view kFile = "fuzz.state";

[[noreturn]] void fail_with_state(const std::string& what, std::string_view state) {
  fuzz::fail(kTarget, what + "\n==== state:\n" + std::string(state) + "==== end of state");
}

template <class V>
void check_violation_text(const V& v, std::string_view state) {
  const std::string s = to_string(v);
  for (char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    // The message may carry UTF-8 (the paper's section sign); no control bytes.
    if (u < 0x20) fail_with_state("violation text has a control byte: " + s, state);
  }
  if (v.code.empty() || s.empty()) fail_with_state("violation without code or text", state);
}

// The mesh layer on a 3D state layers 1-4 accept; nothing more in 2D.
std::optional<std::string> mesh_problem(const Graph&) { return std::nullopt; }
std::optional<std::string> mesh_problem(const d3::Graph& g) { return d3::fuzz::problem(g, true); }

// The checked operations of each dimension.
fuzz::Checked2 checked_ops(const Graph&) { return {}; }
d3::fuzz::Checked checked_ops(const d3::Graph&) { return {}; }

// Applies `op` (refine or coarsen at v, through the checked operations) and,
// if applied, `inverse`; the state must come back byte-identically.
template <AdaptiveLattice L, class Op, class Inverse>
void round_trip(L g, const point_type_t<L>& v, std::string_view state, const char* name, Op op, Inverse inverse) {
  try {
    if (!op(g, v).applied()) {
      if (canonical_text(g) != state) fail_with_state(std::string("refused ") + name + " changed the state", state);
      return;
    }
    if (!inverse(g, v).applied())
      fail_with_state(std::string("the inverse of ") + name + " " + to_string(v) + " was refused", state);
  } catch (const std::exception& e) {
    fail_with_state(std::string(name) + " " + to_string(v) + " threw: " + e.what(), state);
  }
  if (canonical_text(g) != state)
    fail_with_state(std::string(name) + " " + to_string(v) + " followed by its inverse changed the state", state);
}

template <AdaptiveLattice L>
void run(const L& g, std::string_view text) {
  if (canonical_text(g) != text)
    fail_with_state("the parser accepted a text that does not print back byte-identically", text);

  // find_violation must be total: no exception, whatever the graph.
  std::optional<std::string> violation;
  try {
    if (auto v = find_violation(g)) {
      check_violation_text(*v, text);
      violation = to_string(*v);
    }
  } catch (const std::exception& e) {
    fail_with_state(std::string("find_violation threw: ") + e.what(), text);
  }
  // A single layer on a graph a lower layer rejects has an unspecified result
  // (invariants.h, invariants.h): an exception is allowed, a crash or
  // undefined behaviour (which the sanitizers report) is not.
  for (int layer = 1; layer <= 4; ++layer) {
    try {
      if (auto v = check_layer(g, layer)) check_violation_text(*v, text);
    } catch (const std::exception&) {
      if (!violation) fail_with_state("check_layer threw on a valid graph", text);
    }
  }
  if (violation) return;
  if (auto p = mesh_problem(g)) fail_with_state("the mesh of a state layers 1-4 accept: " + *p, text);

  // A valid state: one refine and one coarsen, each inverted at once.
  const std::size_t pick = text.size() * 2654435761u;
  auto ops = checked_ops(g);
  auto refine_op = [&](L& h, const point_type_t<L>& p) { return ops.refine(h, p); };
  auto coarsen_op = [&](L& h, const point_type_t<L>& p) { return ops.coarsen(h, p); };
  if (cell_count(g) != 0) {
    const auto c = *std::next(std::ranges::begin(cells(g)), static_cast<std::ptrdiff_t>(pick % cell_count(g)));
    round_trip(g, c, text, "refine", refine_op, coarsen_op);
  }
  std::vector<point_type_t<L>> refined;
  for (const auto& n : nodes(g))
    if (refined_center_level(size_of(g), n)) refined.push_back(n);
  if (!refined.empty()) round_trip(g, refined[pick % refined.size()], text, "coarsen", coarsen_op, refine_op);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  AnyState g;
  try {
    g = parse_any_state(text, kFile);
  } catch (const ParseError& e) {
    fuzz::check_parse_error(kTarget, e, kFile, text);
    return 0;
  }
  std::visit([&](const auto& state) { run(state, text); }, g);
  return 0;
}
