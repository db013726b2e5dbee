// bccmis: one interface over both implementations, chosen at run time.
//
// The command-line tool (tools/bccmis, --impl=reference|fast) holds a
// LatticeInterface and apps/apps.cpp reads --impl with parse_impl; every
// other user runs both implementations through the vocabulary of
// bccmis/lattice.h. A LatticeInterface never names an implementation:
//
//   auto g = bccmis::make_lattice(bccmis::Impl::Fast, {6, 6, 5});
//   if (auto r = g->refine({8, 8}); !r.applied()) std::cout << bccmis::code(*r.refused);
//   std::cout << g->canonical_state();
//
// The results are the reference's types (RefineResult, CoarsenResult), so a
// call through the interface allocates; code that wants the fast path without
// allocation uses bccmis::fast::Lattice directly (same member names).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bccmis/format.h"
#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis {

enum class Impl { Reference, Fast };

/// "reference" or "fast"; empty for anything else.
std::optional<Impl> parse_impl(std::string_view name);
std::string_view to_string(Impl impl);

class LatticeInterface {
 public:
  virtual ~LatticeInterface() = default;
  virtual Impl impl() const = 0;
  virtual const LatticeSize& size() const = 0;

  virtual std::optional<RefineRefusal> can_refine(const Point& c) const = 0;
  virtual std::optional<CoarsenRefusal> can_coarsen(const Point& n) const = 0;
  virtual RefineResult refine(const Point& c) = 0;
  virtual CoarsenResult coarsen(const Point& n) = 0;

  virtual std::size_t cell_count() const = 0;
  virtual std::size_t node_count() const = 0;
  virtual bool is_center(const Point& v) const = 0;
  virtual bool is_node(const Point& v) const = 0;
  /// Throws std::out_of_range if c is not a center.
  virtual int level_of(const Point& c) const = 0;
  /// 𝒩(v); empty for a position that is not a vertex.
  virtual PointSet nbr(const Point& v) const = 0;
  /// C and N, sorted by (x, y).
  virtual std::vector<Point> cells() const = 0;
  virtual std::vector<Point> nodes() const = 0;

  /// The state as a reference Graph (for the checker) and as canonical text.
  virtual Graph to_graph() const = 0;
  virtual std::string canonical_state() const = 0;

  virtual std::unique_ptr<LatticeInterface> clone() const = 0;

 protected:
  LatticeInterface() = default;
  LatticeInterface(const LatticeInterface&) = default;
  LatticeInterface& operator=(const LatticeInterface&) = default;
};

/// The initial lattice of `size` in the chosen implementation. Throws
/// LatticeError on an invalid size.
std::unique_ptr<LatticeInterface> make_lattice(Impl impl, const LatticeSize& size);

/// The state of a valid graph (e.g. a parsed canonical state) in the chosen
/// implementation.
std::unique_ptr<LatticeInterface> from_graph(Impl impl, const Graph& g);

/// bccmis::replay for either implementation: the decision log goes to `log`;
/// `after` sees every command and its decision line (empty for `check`).
using InterfaceReplayObserver =
    std::function<void(const TraceCommand&, const LatticeInterface&, std::string_view decision)>;
std::unique_ptr<LatticeInterface> replay(Impl impl, const Trace& trace, std::string& log,
                                         const InterfaceReplayObserver& after = {});

}  // namespace bccmis
