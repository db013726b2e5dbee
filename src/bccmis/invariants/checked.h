// Checked operations: refine/coarsen with the checker run before and after,
// and the exact changes of N and C that the equations imply (p4est-style
// count checks). Tests, fuzzers and the CLI use these.
//
// checked_refine(g, c) throws ViolationError when
//   - g is invalid before the call (context "before refine (x, y)"),
//   - refine was refused but changed g (code "refused-changed"),
//   - refine was applied and g is invalid after it (context "after refine (x, y)"),
//   - the sets changed other than by eq. (4b), (4g), (4h), (5b): C loses c and
//     gains exactly the four new centers Y; N gains exactly c and J+ and loses
//     nothing; |Y| = 4, |J+| <= 4 (code "refine-count").
// checked_coarsen(g, n) likewise, with eq. (9d)-(9f), (10c): C loses exactly Y
// (|Y| = 4) and gains n; N loses exactly n and J- and gains nothing
// (code "coarsen-count"). These violations have layer 0.
// Otherwise they return what refine/coarsen returned.
#pragma once

#include "bccmis/invariants/invariants.h"
#include "bccmis/ops.h"

namespace bccmis {

RefineResult checked_refine(Graph& g, const Point& c);
CoarsenResult checked_coarsen(Graph& g, const Point& n);

}  // namespace bccmis
