// bccmis stats STATE: counts of a state (or of a trace's final state).
#include <iostream>

#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

int run(const StatsOptions& o) {
  std::cout << format_stats(stats(read_state_or_trace(o.state, o.from_trace)), o.json);
  return kExitOk;
}

}  // namespace bccmis::cli
