// bccmis CLI: the options of `bccmis stuff` (spec/cli.md), declared once for
// every tool that stuffs (bccmis stuff, bccmis-mpi stuff).
#pragma once

#include <string>

#include "commands.h"

namespace CLI {
class App;
}

namespace bccmis::cli {

/// The subcommand "stuff" of `app`, its options stored in `o`.
CLI::App* add_stuff(CLI::App& app, StuffOptions& o);

/// After parsing: the rules across options (spec/cli.md, stuff). A usage
/// error's message, or empty (and `o` completed: --json and --hausdorff set
/// --stats).
std::string finish_stuff_options(const CLI::App& cmd, StuffOptions& o);

}  // namespace bccmis::cli
