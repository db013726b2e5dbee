#include "testing/twin.h"

#include <exception>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <variant>
#include <vector>

#include "bccmis/lattice.h"
#include "bccmis/ops.h"
#include "bccmis/trace.h"

namespace bccmis::testing {
namespace {

std::string decision(const std::optional<RefineRefusal>& r) { return r ? std::string(code(*r)) : "ok"; }
std::string decision(const std::optional<CoarsenRefusal>& r) { return r ? std::string(code(*r)) : "ok"; }
std::string decision(std::string_view refusal) { return refusal.empty() ? "ok" : std::string(refusal); }

template <class Points>
std::string set_text(const Points& s) {
  std::string out = "{";
  for (const Point& p : s) {
    out += ' ';
    out += to_string(p);
  }
  return out + " }";
}

}  // namespace

Twin::Twin(const LatticeSize& size, Fail fail) : fail_(std::move(fail)), g_(size), lat_(size) {
  trace_.size = size;
  compare_states("initial lattice");
}

void Twin::fail(const std::string& what) const {
  fail_(what + " (at the last command of the trace)", trace_);
  throw std::logic_error("Twin: the Fail callback returned");
}

void Twin::run(TraceCommand::Kind kind, const Point& at, bool batch) {
  const TraceCommand cmd{kind, at, static_cast<int>(trace_.commands.size()) + 2};
  trace_.commands.push_back(cmd);
  // The guards, for both operations, before the operation.
  compare_guards(at);
  const std::string what = command_text(cmd);
  const StepResult<Graph> want = step(g_, cmd);
  auto guarded = [&](const auto& op) {
    try {
      return op();
    } catch (const std::exception& e) {
      fail(what + ": fast threw: " + e.what());
    }
  };
  if (batch) {
    const std::span<const Point> one(&at, 1);
    const std::size_t n =
        guarded([&] { return kind == TraceCommand::Kind::Refine ? lat_.refine_each(one) : lat_.coarsen_each(one); });
    if ((n == 1) != want.applied()) fail(what + ": the batch applied " + std::to_string(n));
  } else {
    const StepResult<fast::Lattice> got = guarded([&] { return step(lat_, cmd); });
    if (got.refusal() != want.refusal())
      fail(what + ": fast says " + decision(got.refusal()) + ", reference " + decision(want.refusal()));
    auto compare = [&](const char* name, const PointSet& w, const auto& g) {
      if (PointSet(g.begin(), g.end()) != w) fail(what + ": " + name + " " + set_text(g) + " != " + set_text(w));
    };
    if (const auto* r = std::get_if<1>(&want.result)) {
      const auto& f = std::get<1>(got.result);
      compare("Y", r->Y, f.Y);
      compare("J+", r->J_plus, f.J_plus);
    } else if (const auto* c = std::get_if<2>(&want.result)) {
      const auto& f = std::get<2>(got.result);
      compare("Y", c->Y, f.Y);
      compare("J-", c->J_minus, f.J_minus);
    }
  }
  applied_ += want.applied();
  compare_states("after " + what);
}

void Twin::reseat(bool from_reference) {
  try {
    if (from_reference) {
      lat_ = fast::Lattice::from_graph(g_);
    } else {
      const fast::Lattice copy = lat_;
      lat_ = copy;
    }
  } catch (const std::exception& e) {
    fail(std::string("fast threw: ") + e.what());
  }
  compare_states(from_reference ? "after from_graph" : "after copying");
}

void Twin::compare_guards(const Point& p) const {
  const std::string at = to_string(p);
  if (decision(can_refine(lat_, p)) != decision(can_refine(g_, p)))
    fail("can_refine " + at + ": fast " + decision(can_refine(lat_, p)) + ", reference " + decision(can_refine(g_, p)));
  if (decision(can_coarsen(lat_, p)) != decision(can_coarsen(g_, p)))
    fail("can_coarsen " + at + ": fast " + decision(can_coarsen(lat_, p)) + ", reference " +
         decision(can_coarsen(g_, p)));
}

void Twin::compare_states(const std::string& when) const {
  if (cell_count(lat_) != cell_count(g_) || node_count(lat_) != node_count(g_))
    fail(when + ": counts differ (fast |C| = " + std::to_string(cell_count(lat_)) +
         ", |N| = " + std::to_string(node_count(lat_)) + ")");
  const std::string want = canonical_text(g_);
  const std::string got = canonical_text(lat_);
  if (got != want) fail(when + ": canonical states differ\n--- reference\n" + want + "--- fast\n" + got);
  if (const auto problem = lat_.audit()) fail(when + ": fast audit: " + *problem);
}

void Twin::compare_queries() const {
  std::vector<Point> at(g_.C.begin(), g_.C.end());
  at.insert(at.end(), g_.N.begin(), g_.N.end());
  const std::int64_t S = level0_side(g_.size);
  for (const Point p : {Point{-1, -1}, Point{0, 0}, Point{g_.size.W * S, g_.size.H * S}, Point{g_.size.W * S + 1, 1},
                        Point{1, 1}, Point{S / 2, 0}})
    at.push_back(p);
  for (const Point& p : at) {
    const auto nbrs = neighbors(lat_, p);
    if (PointSet(nbrs.begin(), nbrs.end()) != neighbors(g_, p)) fail("neighbors " + to_string(p) + " differ");
    if (is_center(lat_, p) != is_center(g_, p)) fail("is_center " + to_string(p) + " differs");
    if (is_node(lat_, p) != is_node(g_, p)) fail("is_node " + to_string(p) + " differs");
    if (is_center(g_, p) && level_of(lat_, p) != level_of(g_, p)) fail("level_of " + to_string(p) + " differs");
    compare_guards(p);
  }
  if (cells(lat_) != std::vector<Point>(g_.C.begin(), g_.C.end())) fail("cells() differs");
  if (nodes(lat_) != std::vector<Point>(g_.N.begin(), g_.N.end())) fail("nodes() differs");
}

}  // namespace bccmis::testing
