// fuzz_refine_coarsen: random operation sequences on a small lattice.
//
// Input layout (GEOS/fmt style: every byte string is a valid program):
//   byte 0..2   W = 1 + b0 % 3, H = 1 + b1 % 3, L = b2 % 5
//   then ops    selector byte s, then operands:
//     s & 7 == 0,1,2  refine the k-th live center            (k: 1 byte, 2 if |C| > 256)
//     s & 7 == 3,4    coarsen the k-th node that sits at a refined cell's
//                     center (mostly legal; may be refused)  (k: 1 or 2 bytes)
//     s & 7 == 5      coarsen the k-th node of N (mostly refused)
//     s & 7 == 6      refine at a raw position (x, y)        (2 bytes; mostly refused)
//     s & 7 == 7      coarsen at a raw position (x, y)       (2 bytes; mostly refused)
//     s & 0x80        if the operation was applied, invert it at once
//                     (refine c <-> coarsen c) and compare canonical states
//   At most kMaxOps operations are decoded.
//
// Every decoded operation runs through checked_refine/checked_coarsen (the
// checker before and after, the exact set changes, and a refused operation
// must leave the graph unchanged). The immediate inverses and
// the final teardown use the plain operations, because the byte comparison of
// canonical states that follows them is stronger than the checker: an
// inverse must restore the state before the operation, and coarsening every
// refined cell, finest level first, must succeed each time and give the
// initial lattice. Any failure aborts with the equivalent text trace on stderr, so
// `bccmis replay` reproduces it.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/format.h"
#include "bccmis/geometry.h"
#include "bccmis/invariants/checked.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/ops.h"
#include "fuzz_util.h"
#include "testing/byte_program.h"

namespace {

using namespace bccmis;

// The checker runs twice per operation (checked_*), so inputs stay small.
constexpr std::size_t kMaxOps = 96;
constexpr std::string_view kTarget = "fuzz_refine_coarsen";

class Run {
 public:
  explicit Run(const LatticeSize& size) : g_(make_lattice(size)) { trace_.size = size; }

  void refine_at(const Point& c, bool invert) {
    // checked_* already rejects a refusal that changes the graph; the copy is
    // only needed to compare after an inversion.
    std::optional<Graph> before;
    if (invert) before = g_;
    record(TraceCommand::Kind::Refine, c);
    const RefineResult r = guarded([&] { return checked_refine(g_, c); });
    if (!r.applied() || !invert) return;
    record(TraceCommand::Kind::Coarsen, c);
    const CoarsenResult back = guarded([&] { return coarsen(g_, c); });
    if (!back.applied())
      fail("coarsen right after refine at the same position was refused (" + std::string(code(*back.refused)) + ")");
    expect_state(*before, "coarsen(refine(g, c), c) != g (paper §3)");
  }

  void coarsen_at(const Point& n, bool invert) {
    // checked_* already rejects a refusal that changes the graph; the copy is
    // only needed to compare after an inversion.
    std::optional<Graph> before;
    if (invert) before = g_;
    record(TraceCommand::Kind::Coarsen, n);
    const CoarsenResult r = guarded([&] { return checked_coarsen(g_, n); });
    if (!r.applied() || !invert) return;
    record(TraceCommand::Kind::Refine, n);
    const RefineResult back = guarded([&] { return refine(g_, n); });
    if (!back.applied())
      fail("refine right after coarsen at the same position was refused (" + std::string(code(*back.refused)) + ")");
    expect_state(*before, "refine(coarsen(g, n), n) != g");
  }

  /// Coarsens every refined cell, finest first; each must be applied. Then the
  /// graph must be the initial lattice.
  void coarsen_everything() {
    for (int l = g_.size.L - 1; l >= 0; --l) {
      std::vector<Point> todo;
      for (const Point& n : g_.N)
        if (refined_center_level(g_.size, n) == l) todo.push_back(n);
      for (const Point& n : todo) {
        record(TraceCommand::Kind::Coarsen, n);
        const CoarsenResult r = guarded([&] { return coarsen(g_, n); });
        if (!r.applied())
          fail("coarsening everything, finest level first: coarsen refused (" + std::string(code(*r.refused)) + ")");
      }
    }
    expect_state(make_lattice(g_.size), "coarsening everything did not give the initial lattice");
  }

  const Graph& graph() const { return g_; }

 private:
  void record(TraceCommand::Kind kind, const Point& at) {
    TraceCommand c;
    c.kind = kind;
    c.at = at;
    c.line = static_cast<int>(trace_.commands.size()) + 2;
    trace_.commands.push_back(c);
  }

  [[noreturn]] void fail(const std::string& what) const {
    fuzz::fail(kTarget, what + " (at the last command of the trace)", &trace_);
  }

  // Graph equality is equality of the canonical texts (format.h); the texts
  // are only built for the message.
  void expect_state(const Graph& expected, const std::string& what) const {
    if (g_ == expected) return;
    const std::string want = canonical_state(expected), got = canonical_state(g_);
    std::size_t line = 1, i = 0;
    for (; i < want.size() && i < got.size() && want[i] == got[i]; ++i) line += want[i] == '\n';
    fail(what + "; the canonical states differ first on line " + std::to_string(line) +
         (want == got ? " (but the graphs differ: a bug in canonical_state or operator==)" : ""));
  }

  template <class Op>
  auto guarded(Op op) -> decltype(op()) {
    try {
      return op();
    } catch (const ViolationError& e) {
      fail(std::string("invariant violated: ") + e.what());
    } catch (const std::exception& e) {
      fail(std::string("exception: ") + e.what());
    }
  }

  Graph g_;
  Trace trace_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  testing::Bytes in(data, size);
  Run run(testing::decode_lattice(in, 3, 5));
  testing::run_program(
      in, kMaxOps, run.graph(), [&](const Point& c, std::uint8_t s) { run.refine_at(c, (s & 0x80) != 0); },
      [&](const Point& n, std::uint8_t s) { run.coarsen_at(n, (s & 0x80) != 0); }, [](std::uint8_t) {});
  run.coarsen_everything();
  return 0;
}
