// bccmis render STATE -o FILE: a state (or a trace's final state) as SVG.
#include "bccmis/oracle/oracle.h"
#include "commands.h"
#include "io.h"

namespace bccmis::cli {

int run(const RenderOptions& o) {
  const Graph g = read_state_or_trace(o.state, o.from_trace);
  write_atomically(o.output, render_svg(g, display_name(o.state)));
  return kExitOk;
}

}  // namespace bccmis::cli
