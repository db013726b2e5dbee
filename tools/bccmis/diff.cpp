// bccmis diff A B: the semantic difference of two canonical states.
#include <iostream>

#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

int run(const DiffOptions& o) {
  const std::string hint =
      "'bccmis diff' compares two states; replay the trace with 'bccmis replay TRACE --state FILE' first";
  const Graph a = read_state(o.a, hint);
  const Graph b = read_state(o.b, hint);
  const std::vector<std::string> d = diff_states(a, b);
  if (!o.quiet)
    for (const std::string& line : d) std::cout << line << "\n";
  return d.empty() ? kExitOk : kExitViolation;
}

}  // namespace bccmis::cli
