// fuzz_differential: the reference core and bccmis::fast::Lattice driven by
// the same operations; every observable must agree (issue 9).
//
// Input layout (every byte string is a valid program):
//   byte 0..2   W = 1 + b0 % 4, H = 1 + b1 % 4, L = b2 % 6
//   then ops    selector byte s, then operands:
//     s & 7 == 0,1,2  refine the k-th live center of the reference  (k: 1 byte, 2 if |C| > 256)
//     s & 7 == 3,4    coarsen the k-th node at a refined cell's center (mostly legal)
//     s & 7 == 5      coarsen the k-th node of N (mostly refused)
//     s & 7 == 6      refine at a raw position (x, y)                (2 bytes; mostly refused)
//     s & 7 == 7      coarsen at a raw position (x, y)               (2 bytes; mostly refused)
//     s & 0x40        afterwards, the fast side goes on with a copy of itself
//                     (s & 0x20 clear) or with Lattice::from_graph of the
//                     reference state (s & 0x20 set)
//     s & 0x80        the operation goes through refine_each / coarsen_each
//   At most kMaxOps operations are decoded.
//
// After every operation: can_refine and can_coarsen at the position (both
// operations, before it ran), the decision, Y and J+/J-, the counts, the
// canonical state byte for byte, and the fast lattice's own audit. At the end:
// nbr, is_center, is_node and level_of at every vertex and at the positions
// around the domain. Any difference aborts with the equivalent text trace on
// stderr, so `bccmis replay` (reference) reproduces the run.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bccmis/fast/lattice.h"
#include "bccmis/format.h"
#include "bccmis/ops.h"
#include "fuzz_util.h"

namespace {

using namespace bccmis;

constexpr std::size_t kMaxOps = 128;
constexpr std::string_view kTarget = "fuzz_differential";

using fuzz::Bytes;

std::string decision(const std::optional<RefineRefusal>& r) { return r ? std::string(code(*r)) : "ok"; }
std::string decision(const std::optional<CoarsenRefusal>& r) { return r ? std::string(code(*r)) : "ok"; }

std::string text(const Point& p) { return bccmis::to_string(p); }

class Twin {
 public:
  explicit Twin(const LatticeSize& size) : g_(make_lattice(size)), lat_(size) {
    trace_.size = size;
    compare_states("initial lattice");
  }

  const Graph& graph() const { return g_; }

  void refine(const Point& c, bool batch) {
    record(TraceCommand::Kind::Refine, c);
    compare_guards(c);
    const RefineResult want = bccmis::refine(g_, c);
    const std::string what = "refine " + text(c);
    if (batch) {
      const std::size_t applied = guarded([&] { return lat_.refine_each(std::span<const Point>(&c, 1)); });
      if ((applied == 1) != want.applied()) fail(what + ": refine_each applied " + std::to_string(applied));
    } else {
      const fast::RefineResult got = guarded([&] { return lat_.refine(c); });
      if (decision(got.refused) != decision(want.refused))
        fail(what + ": fast says " + decision(got.refused) + ", reference " + decision(want.refused));
      if (got.Y.to_set() != want.Y) fail(what + ": Y differs");
      if (got.J_plus.to_set() != want.J_plus) fail(what + ": J+ differs");
    }
    compare_states("after " + what);
  }

  void coarsen(const Point& n, bool batch) {
    record(TraceCommand::Kind::Coarsen, n);
    compare_guards(n);
    const CoarsenResult want = bccmis::coarsen(g_, n);
    const std::string what = "coarsen " + text(n);
    if (batch) {
      const std::size_t applied = guarded([&] { return lat_.coarsen_each(std::span<const Point>(&n, 1)); });
      if ((applied == 1) != want.applied()) fail(what + ": coarsen_each applied " + std::to_string(applied));
    } else {
      const fast::CoarsenResult got = guarded([&] { return lat_.coarsen(n); });
      if (decision(got.refused) != decision(want.refused))
        fail(what + ": fast says " + decision(got.refused) + ", reference " + decision(want.refused));
      if (got.Y.to_set() != want.Y) fail(what + ": Y differs");
      if (got.J_minus.to_set() != want.J_minus) fail(what + ": J- differs");
    }
    compare_states("after " + what);
  }

  /// The fast side goes on from a copy of itself or from the reference state.
  void reseat(bool from_reference) {
    if (from_reference) {
      lat_ = guarded([&] { return fast::Lattice::from_graph(g_); });
    } else {
      const fast::Lattice copy = lat_;
      lat_ = copy;
    }
    compare_states(from_reference ? "after from_graph" : "after copying");
  }

  /// Every query at every vertex and around the domain.
  void compare_queries() {
    std::vector<Point> at(g_.C.begin(), g_.C.end());
    at.insert(at.end(), g_.N.begin(), g_.N.end());
    const std::int64_t S = level0_side(g_.size);
    for (const Point p : {Point{-1, -1}, Point{0, 0}, Point{g_.size.W * S, g_.size.H * S},
                          Point{g_.size.W * S + 1, 1}, Point{1, 1}, Point{S / 2, 0}})
      at.push_back(p);
    for (const Point& p : at) {
      if (lat_.nbr(p).to_set() != g_.nbr(p)) fail("nbr " + text(p) + " differs");
      if (lat_.is_center(p) != g_.is_center(p)) fail("is_center " + text(p) + " differs");
      if (lat_.is_node(p) != g_.is_node(p)) fail("is_node " + text(p) + " differs");
      if (g_.is_center(p) && lat_.level_of(p) != g_.level_of(p)) fail("level_of " + text(p) + " differs");
      compare_guards(p);
    }
    if (lat_.cells() != std::vector<Point>(g_.C.begin(), g_.C.end())) fail("cells() differs");
    if (lat_.nodes() != std::vector<Point>(g_.N.begin(), g_.N.end())) fail("nodes() differs");
  }

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

  template <class Op>
  auto guarded(Op op) -> decltype(op()) {
    try {
      return op();
    } catch (const std::exception& e) {
      fail(std::string("fast threw: ") + e.what());
    }
  }

  void compare_guards(const Point& p) const {
    if (decision(lat_.can_refine(p)) != decision(can_refine(g_, p)))
      fail("can_refine " + text(p) + ": fast " + decision(lat_.can_refine(p)) + ", reference " +
           decision(can_refine(g_, p)));
    if (decision(lat_.can_coarsen(p)) != decision(can_coarsen(g_, p)))
      fail("can_coarsen " + text(p) + ": fast " + decision(lat_.can_coarsen(p)) + ", reference " +
           decision(can_coarsen(g_, p)));
  }

  void compare_states(const std::string& when) const {
    if (lat_.cell_count() != g_.C.size() || lat_.node_count() != g_.N.size()) fail(when + ": counts differ");
    if (fast::canonical_state(lat_) != canonical_state(g_)) fail(when + ": canonical states differ");
    if (const auto problem = lat_.audit()) fail(when + ": fast audit: " + *problem);
  }

  Graph g_;
  fast::Lattice lat_;
  Trace trace_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  Bytes in(data, size);
  Twin twin(fuzz::decode_lattice(in, 4, 6));
  for (std::size_t op = 0; op < kMaxOps && !in.empty(); ++op) {
    const std::uint8_t s = in.next();
    const bool batch = (s & 0x80) != 0;
    fuzz::decode_operation(
        in, s, twin.graph(), [&](const Point& c) { twin.refine(c, batch); },
        [&](const Point& n) { twin.coarsen(n, batch); });
    if (s & 0x40) twin.reseat((s & 0x20) != 0);
  }
  twin.compare_queries();
  return 0;
}
