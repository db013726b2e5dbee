// bccmis: refinement (§2.1) and coarsening (§2.2) on the graph of §2.
//
// Both operations are transcriptions of the paper's set equations (2)-(12),
// with the paper's errors fixed as recorded in spec/errata.toml. Each returns
// whether it was applied; a refused call changes nothing.
#pragma once

#include <optional>
#include <string_view>

#include "bccmis/graph.h"

namespace bccmis {

/// Why refine(c) was refused, in the order the preconditions are tested.
enum class RefineRefusal {
  NoSuchCell,       ///< c is not a cell center                     (`no-such-cell`)
  MaxLevel,         ///< level(c) == L                               (`max-level`)
  CoarserNeighbor,  ///< an edge-neighbor cell is coarser than c    (`coarser-neighbor`)
};

/// Why coarsen(n) was refused, in the order the preconditions are tested.
enum class CoarsenRefusal {
  NoSuchNode,         ///< n is not a node                                   (`no-such-node`)
  NotARefinedCenter,  ///< n is a grid node or a side midpoint, not the center
                      ///< of a refined cell                                 (`not-a-refined-center`)
  ChildrenRefined,    ///< a cell around n is finer than n's children        (`children-refined`)
  FinerNeighbor,      ///< a child has a junction: an edge-neighbor two
                      ///< levels finer than the coarse cell would be        (`finer-neighbor`)
};

/// The refusal codes of the trace and decision-log formats (spec/formats.md).
std::string_view code(RefineRefusal r);
std::string_view code(CoarsenRefusal r);

/// What refine(c) did: the decision and the sets it created. `Points` is
/// the set type of the lattice (std::set for the reference, a fixed-size
/// sorted array for the fast lattice); both are sorted by position.
template <class Points>
struct BasicRefineResult {
  std::optional<RefineRefusal> refused;  ///< empty when applied
  Points Y;                              ///< the four new centers (eq. 4a)
  Points J_plus;                         ///< the new junction nodes (eq. 5a, erratum E1)
  bool applied() const { return !refused; }
};

/// What coarsen(n) did: the decision and the sets it deleted.
template <class Points>
struct BasicCoarsenResult {
  std::optional<CoarsenRefusal> refused;  ///< empty when applied
  Points Y;                               ///< the four deleted centers (eq. 8a)
  Points J_minus;                         ///< the deleted junction nodes (eq. 10a, erratum E2)
  bool applied() const { return !refused; }
};

using RefineResult = BasicRefineResult<PointSet>;
using CoarsenResult = BasicCoarsenResult<PointSet>;

/// The exact refine precondition (spec/errata.toml E4 and §2.1): empty when
/// refine(g, c) would be applied, otherwise the first failing reason.
std::optional<RefineRefusal> can_refine(const Graph& g, const Point& c);

/// The exact coarsen precondition (spec/errata.toml E3): empty when
/// coarsen(g, n) would be applied, otherwise the first failing reason.
std::optional<CoarsenRefusal> can_coarsen(const Graph& g, const Point& n);

/// §2.1: split cell c into four cells of the next level.
RefineResult refine(Graph& g, const Point& c);

/// §2.2: merge the four cells around node n into one cell centered at n.
CoarsenResult coarsen(Graph& g, const Point& n);

}  // namespace bccmis
