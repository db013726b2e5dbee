// Planted-bug copies of refine/coarsen (issue 5, "every test must be able to
// fail"). mutant_ops.cpp is a plain transcription of src/bccmis/refine.cpp and
// coarsen.cpp (direct writes instead of the core's Transaction) in which one
// statement can be broken, selected by a Flaw. With Flaw::None it must behave
// exactly like the core (tests/mutants/mutants_test.cpp checks that too).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bccmis/graph.h"
#include "bccmis/ops.h"

namespace bccmis::mutants {

enum class Flaw {
  None,
  Skip4d,                 ///< refine: old junctions keep c in N(j)            (eq. 4d skipped)
  Skip6d,                 ///< refine: N(y_i) does not get the new junction    (eq. 6d skipped)
  Forget10c,              ///< coarsen: J- stays in N (eq. 10c and its repeat 11d skipped)
  Forget10cOnly,          ///< coarsen: eq. 10c skipped, 11d kept: an EQUIVALENT mutant
  LiteralBoundary6,       ///< refine: junctions only where |N(p_i) ∩ N(p_j)| = 1 (none on the domain boundary)
  WeakCoarsenGuard,       ///< can_coarsen: only n in N and |N(n)| = 4 (the paper's literal test)
  CoarsenDifferentState,  ///< coarsen: also coarsens the first other coarsenable node (valid, but not the inverse)
  CornerBalance,          ///< can_refine: every cell at a corner of c counts, not only edge neighbors (E4's sentence)
  RefusalRefinesNeighbor  ///< refine: refused for a coarser neighbor, but refines that neighbor anyway
};

struct FlawInfo {
  Flaw flaw;
  std::string name;
};

/// Every flaw except None.
const std::vector<FlawInfo>& all_flaws();

std::optional<RefineRefusal> can_refine(const Graph& g, const Point& c, Flaw flaw);
std::optional<CoarsenRefusal> can_coarsen(const Graph& g, const Point& n, Flaw flaw);
RefineResult refine(Graph& g, const Point& c, Flaw flaw);
CoarsenResult coarsen(Graph& g, const Point& n, Flaw flaw);

}  // namespace bccmis::mutants
