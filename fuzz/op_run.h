// The operation-sequence harness of fuzz_refine_coarsen and
// fuzz_refine_coarsen_3d, written once for every lattice (bccmis/lattice.h).
//
// OpRun<L, Checked> keeps a lattice and the text trace of every command it
// ran. Each decoded operation runs through the target's checked operations
// (Checked::refine / Checked::coarsen: the checker before and after, the
// exact set changes, and a refused operation must leave the lattice
// unchanged; they throw on a violation). The immediate inverses and the
// final teardown use the plain operations, because the byte comparison of
// canonical states that follows them is stronger than the checker: an
// inverse must restore the state before the operation, and coarsening every
// refined cell, finest level first, must succeed each time and give the
// initial lattice. Any failure aborts with the equivalent text trace on
// stderr (fuzz_util.h), so `bccmis replay` reproduces it.
#pragma once

#include <cstddef>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bccmis/invariants/checked.h"
#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/lattice.h"
#include "bccmis/trace.h"
#include "fuzz_util.h"

namespace bccmis::fuzz {

/// What a target's own checked operations throw when the checker rejects a
/// state (the 2D checked_refine/checked_coarsen throw ViolationError).
struct InvariantFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The checked operations of the 2D Graph (invariants/checked.h); the 3D ones
/// are d3::Checked (d3/checked.h).
struct Checked2 {
  RefineResult refine(Graph& g, const Point& c) const { return checked_refine(g, c); }
  CoarsenResult coarsen(Graph& g, const Point& n) const { return checked_coarsen(g, n); }
};

template <AdaptiveLattice L, class Checked>
class OpRun {
 public:
  using P = point_type_t<L>;

  /// `max_cells`: a refine that could take the lattice past this many cells
  /// (2^dimension - 1 more) is skipped, not run and not recorded.
  OpRun(std::string_view target, const typename L::size_type& size, Checked checked = {},
        std::size_t max_cells = std::numeric_limits<std::size_t>::max())
      : target_(target), g_(size), checked_(std::move(checked)), max_cells_(max_cells) {
    trace_.size = size;
  }

  void refine_at(const P& c, bool invert) {
    if (cell_count(g_) + (std::size_t{1} << L::dimension) - 1 > max_cells_) return;
    run_and_invert(
        CommandKind::Refine, CommandKind::Coarsen, c, invert, [&] { return checked_.refine(g_, c); },
        [&] { return coarsen(g_, c); }, "coarsen right after refine at the same position was refused (",
        "coarsen(refine(g, c), c) != g (paper §3)");
  }

  void coarsen_at(const P& n, bool invert) {
    run_and_invert(
        CommandKind::Coarsen, CommandKind::Refine, n, invert, [&] { return checked_.coarsen(g_, n); },
        [&] { return refine(g_, n); }, "refine right after coarsen at the same position was refused (",
        "refine(coarsen(g, n), n) != g");
  }

  /// Coarsens every refined cell, finest first; each must be applied. Then the
  /// lattice must be the initial one.
  void coarsen_everything() {
    const auto& size = size_of(g_);
    for (int l = size.L - 1; l >= 0; --l) {
      std::vector<P> todo;
      for (const P& n : nodes(g_))
        if (refined_center_level(size, n) == l) todo.push_back(n);
      for (const P& n : todo) {
        record(CommandKind::Coarsen, n);
        const auto r = guarded([&] { return coarsen(g_, n); });
        if (!r.applied())
          fail("coarsening everything, finest level first: coarsen refused (" + std::string(code(*r.refused)) + ")");
      }
    }
    expect_state(L(size), "coarsening everything did not give the initial lattice");
  }

  /// Runs f(lattice) under the same guard as the operations: an exception
  /// fails with the trace.
  template <class F>
  void check(const F& f) {
    guarded([&] {
      f(static_cast<const L&>(g_));
      return 0;
    });
  }

  const L& graph() const { return g_; }

  [[noreturn]] void fail(const std::string& what) const {
    fuzz::fail(target_, what + " (at the last command of the trace)", &trace_);
  }

 private:
  void record(CommandKind kind, const P& at) {
    trace_command_t<L> c;
    c.kind = kind;
    c.at = at;
    c.line = static_cast<int>(trace_.commands.size()) + 2;
    trace_.commands.push_back(c);
  }

  // Records and runs `op` (checked); when it is applied and `invert` is
  // set, records and runs `inverse` at the same position, which must be
  // applied (else: `refused` and the refusal's code) and give back the
  // lattice before (else: `differs`).
  template <class Op, class Inverse>
  void run_and_invert(CommandKind kind, CommandKind inverse_kind, const P& at, bool invert, Op op, Inverse inverse,
                      const std::string& refused, const std::string& differs) {
    // The checked operation already rejects a refusal that changes the
    // lattice; the copy is only needed to compare after an inversion.
    std::optional<L> before;
    if (invert) before = g_;
    record(kind, at);
    const auto r = guarded(op);
    if (!r.applied() || !invert) return;
    record(inverse_kind, at);
    const auto back = guarded(inverse);
    if (!back.applied()) fail(refused + std::string(code(*back.refused)) + ")");
    expect_state(*before, differs);
  }

  // The canonical texts (spec/formats.md) must be byte-identical, and the
  // lattices equal.
  void expect_state(const L& expected, const std::string& what) const {
    const std::string want = canonical_text(expected), got = canonical_text(g_);
    if (want == got && g_ == expected) return;
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
    } catch (const InvariantFailure& e) {
      fail(std::string("invariant violated: ") + e.what());
    } catch (const std::exception& e) {
      fail(std::string("exception: ") + e.what());
    }
  }

  std::string_view target_;
  L g_;
  Checked checked_;
  std::size_t max_cells_;
  trace_t<L> trace_;
};

}  // namespace bccmis::fuzz
