// bccmis stats STATE: counts of a state (or of a trace's final state), either
// dimension.
#include <iostream>

#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

int run(const StatsOptions& o) {
  std::cout << std::visit([&](const auto& g) { return format_stats(stats(g), o.json); },
                          read_any_state_or_trace(o.state, o.from_trace));
  return kExitOk;
}

}  // namespace bccmis::cli
