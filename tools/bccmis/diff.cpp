// bccmis diff A B: the semantic difference of two canonical states (either
// dimension; states of different dimensions differ in that).
#include <iostream>

#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

int run(const DiffOptions& o) {
  const std::string hint =
      "'bccmis diff' compares two states; replay the trace with 'bccmis replay TRACE --state FILE' first";
  const AnyState a = read_any_state(o.a, hint);
  const AnyState b = read_any_state(o.b, hint);
  std::vector<std::string> d;
  if (a.index() != b.index()) {
    auto dimension = [](const AnyState& s) { return s.index() == 0 ? "a 2D state" : "a 3D state"; };
    d.push_back(std::string("dimension: A is ") + dimension(a) + ", B is " + dimension(b));
  } else if (a.index() == 0) {
    d = diff_states(std::get<0>(a), std::get<0>(b));
  } else {
    d = diff_states(std::get<1>(a), std::get<1>(b));
  }
  if (!o.quiet)
    for (const std::string& line : d) std::cout << line << "\n";
  return d.empty() ? kExitOk : kExitViolation;
}

}  // namespace bccmis::cli
