// Uses the installed library the way the README shows: refine, check, coarsen.
#include <iostream>

#include "bccmis/invariants/invariants.h"
#include "bccmis/io/format.h"
#include "bccmis/ops.h"

int main() {
  bccmis::Graph g = bccmis::make_lattice({2, 2, 3});
  const std::string initial = bccmis::canonical_state(g);
  if (!bccmis::refine(g, {8, 8}).applied()) return 1;
  if (!bccmis::is_valid(g)) return 2;
  if (g.C.size() != 7 || g.N.size() != 14) return 3;  // 3 + 4 cells; 9 + 1 + 4 nodes
  if (!bccmis::coarsen(g, {8, 8}).applied()) return 4;
  if (bccmis::canonical_state(g) != initial) return 5;
  std::cout << "consumer ok\n";
  return 0;
}
