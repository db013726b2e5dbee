#include "bccmis/fast/lattice_interface.h"

#include <utility>

#include "bccmis/fast/lattice.h"

namespace bccmis {

std::optional<Impl> parse_impl(std::string_view name) {
  if (name == "reference") return Impl::Reference;
  if (name == "fast") return Impl::Fast;
  return std::nullopt;
}

std::string_view to_string(Impl impl) { return impl == Impl::Fast ? "fast" : "reference"; }

namespace {

class ReferenceLattice final : public LatticeInterface {
 public:
  explicit ReferenceLattice(Graph g) : g_(std::move(g)) {}
  Impl impl() const override { return Impl::Reference; }
  const LatticeSize& size() const override { return g_.size; }
  std::optional<RefineRefusal> can_refine(const Point& c) const override { return bccmis::can_refine(g_, c); }
  std::optional<CoarsenRefusal> can_coarsen(const Point& n) const override { return bccmis::can_coarsen(g_, n); }
  RefineResult refine(const Point& c) override { return bccmis::refine(g_, c); }
  CoarsenResult coarsen(const Point& n) override { return bccmis::coarsen(g_, n); }
  std::size_t cell_count() const override { return g_.C.size(); }
  std::size_t node_count() const override { return g_.N.size(); }
  bool is_center(const Point& v) const override { return g_.is_center(v); }
  bool is_node(const Point& v) const override { return g_.is_node(v); }
  int level_of(const Point& c) const override { return g_.level_of(c); }
  PointSet nbr(const Point& v) const override { return g_.nbr(v); }
  std::vector<Point> cells() const override { return {g_.C.begin(), g_.C.end()}; }
  std::vector<Point> nodes() const override { return {g_.N.begin(), g_.N.end()}; }
  Graph to_graph() const override { return g_; }
  std::string canonical_state() const override { return bccmis::canonical_state(g_); }
  std::unique_ptr<LatticeInterface> clone() const override { return std::make_unique<ReferenceLattice>(*this); }

 private:
  Graph g_;
};

class FastLattice final : public LatticeInterface {
 public:
  explicit FastLattice(fast::Lattice g) : g_(std::move(g)) {}
  Impl impl() const override { return Impl::Fast; }
  const LatticeSize& size() const override { return g_.size(); }
  std::optional<RefineRefusal> can_refine(const Point& c) const override { return g_.can_refine(c); }
  std::optional<CoarsenRefusal> can_coarsen(const Point& n) const override { return g_.can_coarsen(n); }
  RefineResult refine(const Point& c) override { return fast::to_sets(g_.refine(c)); }
  CoarsenResult coarsen(const Point& n) override { return fast::to_sets(g_.coarsen(n)); }
  std::size_t cell_count() const override { return g_.cell_count(); }
  std::size_t node_count() const override { return g_.node_count(); }
  bool is_center(const Point& v) const override { return g_.is_center(v); }
  bool is_node(const Point& v) const override { return g_.is_node(v); }
  int level_of(const Point& c) const override { return g_.level_of(c); }
  PointSet nbr(const Point& v) const override { return g_.nbr(v).to_set(); }
  std::vector<Point> cells() const override { return g_.cells(); }
  std::vector<Point> nodes() const override { return g_.nodes(); }
  Graph to_graph() const override { return g_.to_graph(); }
  std::string canonical_state() const override { return fast::canonical_state(g_); }
  std::unique_ptr<LatticeInterface> clone() const override { return std::make_unique<FastLattice>(*this); }

 private:
  fast::Lattice g_;
};

}  // namespace

std::unique_ptr<LatticeInterface> make_lattice(Impl impl, const LatticeSize& size) {
  if (impl == Impl::Fast) return std::make_unique<FastLattice>(fast::Lattice(size));
  return std::make_unique<ReferenceLattice>(make_lattice(size));
}

std::unique_ptr<LatticeInterface> from_graph(Impl impl, const Graph& g) {
  if (impl == Impl::Fast) return std::make_unique<FastLattice>(fast::Lattice::from_graph(g));
  return std::make_unique<ReferenceLattice>(g);
}

std::unique_ptr<LatticeInterface> replay(Impl impl, const Trace& trace, std::string& log,
                                         const InterfaceReplayObserver& after) {
  std::unique_ptr<LatticeInterface> g = make_lattice(impl, trace.size);
  for (const TraceCommand& cmd : trace.commands) {
    std::string decision;
    if (cmd.kind == TraceCommand::Kind::Refine) {
      const std::optional<RefineRefusal> r = g->refine(cmd.at).refused;
      decision = decision_line(cmd, r ? code(*r) : std::string_view{});
    } else if (cmd.kind == TraceCommand::Kind::Coarsen) {
      const std::optional<CoarsenRefusal> r = g->coarsen(cmd.at).refused;
      decision = decision_line(cmd, r ? code(*r) : std::string_view{});
    }
    if (!decision.empty()) log += decision + "\n";
    if (after) after(cmd, *g, decision);
  }
  return g;
}

}  // namespace bccmis
