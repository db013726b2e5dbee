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
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "bccmis/checked.h"
#include "bccmis/format.h"
#include "bccmis/invariants.h"
#include "bccmis/ops.h"
#include "fuzz_util.h"

namespace {

using namespace bccmis;

// The checker runs twice per operation (checked_*), so inputs stay small.
constexpr std::size_t kMaxOps = 96;
constexpr std::string_view kTarget = "fuzz_refine_coarsen";

class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  /// An index below `n` (n > 0): one byte, or two when n > 256.
  std::size_t index(std::size_t n) {
    std::size_t k = next();
    if (n > 256) k |= std::size_t{next()} << 8;
    return k % n;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

template <class Set>
typename Set::value_type nth(const Set& s, std::size_t k) {
  return *std::next(s.begin(), static_cast<std::ptrdiff_t>(k));
}

class Run {
 public:
  explicit Run(const LatticeSize& size) : g_(make_lattice(size)) { trace_.size = size; }

  void refine_at(const Vertex& c, bool invert) {
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

  void coarsen_at(const Vertex& n, bool invert) {
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
      std::vector<Vertex> todo;
      for (const Vertex& n : g_.N)
        if (refined_center_level(g_.size, n) == l) todo.push_back(n);
      for (const Vertex& n : todo) {
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
  void record(TraceCommand::Kind kind, const Vertex& at) {
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
  Bytes in(data, size);
  LatticeSize lattice;
  lattice.W = 1 + in.next() % 3;
  lattice.H = 1 + in.next() % 3;
  lattice.L = in.next() % 5;
  Run run(lattice);
  const std::int64_t S = level0_side(lattice);
  for (std::size_t op = 0; op < kMaxOps && !in.empty(); ++op) {
    const std::uint8_t s = in.next();
    const bool invert = (s & 0x80) != 0;
    const Graph& g = run.graph();
    switch (s & 7) {
      case 0:
      case 1:
      case 2:
        run.refine_at(nth(g.C, in.index(g.C.size())), invert);
        break;
      case 3:
      case 4: {
        std::vector<Vertex> refined;
        for (const Vertex& n : g.N)
          if (refined_center_level(g.size, n)) refined.push_back(n);
        if (refined.empty()) break;
        run.coarsen_at(refined[in.index(refined.size())], invert);
        break;
      }
      case 5:
        run.coarsen_at(nth(g.N, in.index(g.N.size())), invert);
        break;
      default: {
        // Raw positions: a little beyond the domain on every side, and an
        // occasional extreme value.
        auto coordinate = [&](std::int64_t extent) -> std::int64_t {
          const std::uint8_t b = in.next();
          if (b == 0xff) return INT64_MAX;
          if (b == 0xfe) return INT64_MIN;
          return static_cast<std::int64_t>(b) % (extent + 3) - 1;
        };
        const Vertex p{coordinate(lattice.W * S), coordinate(lattice.H * S)};
        if ((s & 7) == 6)
          run.refine_at(p, invert);
        else
          run.coarsen_at(p, invert);
        break;
      }
    }
  }
  run.coarsen_everything();
  return 0;
}
