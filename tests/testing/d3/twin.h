// The 3D reference d3::Graph and bccmis::d3::fast::Lattice driven in lock-step, as
// tests/testing/twin.h does in 2D: the same trace commands through the one
// stepper (bccmis/trace.h) on both. Before every operation both guards
// (can_refine and can_coarsen at the position) must agree; after it the
// decision, Y and J+ / J-, the counts and the canonical state, byte for byte,
// and the fast lattice must pass its own audit. compare_queries() asks every
// query at every vertex and around it.
//
// Used by tests/fast/d3/differential_test.cpp and fuzz/fuzz_differential_3d.cpp.
// A difference is reported through the Fail callback with the trace of the
// commands run so far (readable by `bccmis replay`); the callback must not
// return, and the twin throws std::logic_error if it does.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/d3/lattice.h"
#include "bccmis/fast/d3/lattice.h"
#include "bccmis/io/d3/format.h"
#include "bccmis/io/format.h"
#include "bccmis/trace.h"

namespace bccmis::d3::testing {

class Twin {
 public:
  using Fail = std::function<void(const std::string& what, const d3::Trace& so_far)>;

  Twin(const d3::LatticeSize& size, Fail fail) : fail_(std::move(fail)), g_(size), lat_(size) {
    trace_.size = size;
    compare_states("the initial lattice");
  }

  const d3::Graph& graph() const { return g_; }
  const d3::fast::Lattice& lattice() const { return lat_; }
  const d3::Trace& trace() const { return trace_; }
  std::size_t applied() const { return applied_; }

  /// Runs refine or coarsen at `at` on both (recorded in the trace) and compares.
  void run(CommandKind kind, const d3::Point& at) {
    d3::TraceCommand cmd;
    cmd.kind = kind;
    cmd.at = at;
    cmd.line = static_cast<int>(trace_.commands.size()) + 2;
    trace_.commands.push_back(cmd);
    compare_guards(at);
    const StepResult<d3::Graph> r = step(g_, cmd);
    const StepResult<d3::fast::Lattice> f = step(lat_, cmd);
    std::string log_r, log_f;
    append_decision(log_r, cmd, r);
    append_decision(log_f, cmd, f);
    if (log_r != log_f) fail("decision: reference '" + log_r + "', fast '" + log_f + "'");
    if (kind == CommandKind::Refine) {
      const auto& a = std::get<1>(r.result);
      const auto& b = std::get<1>(f.result);
      compare_points("Y", a.Y, b.Y);
      compare_points("J+", a.J_plus, b.J_plus);
    } else if (kind == CommandKind::Coarsen) {
      const auto& a = std::get<2>(r.result);
      const auto& b = std::get<2>(f.result);
      compare_points("Y", a.Y, b.Y);
      compare_points("J-", a.J_minus, b.J_minus);
    }
    applied_ += r.applied() ? 1 : 0;
    compare_states("after " + log_r.substr(0, log_r.size() - 1));
  }

  /// The fast side goes on from a copy of itself.
  void reseat() {
    const d3::fast::Lattice copy = lat_;
    lat_ = copy;
    compare_states("after a copy");
  }

  /// The counts, the canonical states and the fast audit.
  void compare_states(const std::string& when) const {
    if (cell_count(g_) != cell_count(lat_) || node_count(g_) != node_count(lat_))
      fail("counts " + when + ": reference " + std::to_string(cell_count(g_)) + " cells " +
           std::to_string(node_count(g_)) + " nodes, fast " + std::to_string(cell_count(lat_)) + " cells " +
           std::to_string(node_count(lat_)) + " nodes");
    const std::string a = canonical_text(g_), b = canonical_text(lat_);
    if (a != b) fail("canonical state " + when + " differs:\n--- reference\n" + a + "--- fast\n" + b);
    if (auto problem = lat_.audit()) fail("fast audit " + when + ": " + *problem);
  }

  /// Every query at every vertex and at the positions one unit around it and
  /// at the domain's corners; cells() and nodes(); the conversion to d3::Graph.
  void compare_queries() const {
    if (!std::ranges::equal(cells(g_), cells(lat_))) fail("cells() differ");
    if (!std::ranges::equal(nodes(g_), nodes(lat_))) fail("nodes() differ");
    if (!(lat_.to_graph() == g_)) fail("to_graph() differs from the reference");
    std::vector<d3::Point> at;
    for (const auto* set : {&g_.C, &g_.N})
      for (const d3::Point& v : *set)
        for (std::int64_t d : {-1, 0, 1}) at.push_back({v.x + d, v.y, v.z - d});
    const std::int64_t S = d3::level0_side(g_.size);
    at.push_back({-S, 0, 0});
    at.push_back({g_.size.W * S, g_.size.H * S, g_.size.D * S});
    for (const d3::Point& p : at) {
      compare_guards(p);
      if (is_center(g_, p) != is_center(lat_, p) || is_node(g_, p) != is_node(lat_, p))
        fail("is_center / is_node at " + d3::to_string(p));
      if (is_center(g_, p) && level_of(g_, p) != level_of(lat_, p)) fail("level_of at " + d3::to_string(p));
      if (!std::ranges::equal(neighbors(g_, p), neighbors(lat_, p))) fail("neighbors at " + d3::to_string(p));
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    fail_(what, trace_);
    throw std::logic_error("d3::Twin: the Fail callback returned");
  }

 private:
  void compare_guards(const d3::Point& p) const {
    if (can_refine(g_, p) != can_refine(lat_, p)) fail("can_refine at " + d3::to_string(p));
    if (can_coarsen(g_, p) != can_coarsen(lat_, p)) fail("can_coarsen at " + d3::to_string(p));
  }

  template <class A, class B>
  void compare_points(const char* name, const A& a, const B& b) const {
    if (!std::ranges::equal(a, b)) fail(std::string(name) + " differs");
  }

  Fail fail_;
  d3::Graph g_;
  d3::fast::Lattice lat_;
  d3::Trace trace_;
  std::size_t applied_ = 0;
};

}  // namespace bccmis::d3::testing
