// bccmis: the command-line oracle (spec/cli.md). main parses the command
// line (cli.cpp) and runs the chosen subcommand (one file each: replay.cpp,
// check.cpp, diff.cpp, stats.cpp, mesh.cpp, stuff.cpp, render.cpp, view.cpp,
// conformance.cpp, explore.cpp, heightfield.cpp, animate.cpp); io.h owns
// reading, writing and the exit codes: 0 success; 1 an invariant is violated
// (or states differ, or implementations disagree); 2 bad input (usage, parse
// error, unreadable file, unwritable output); 3 internal error.
#include <variant>

#include "cli.h"
#include "io.h"

int main(int argc, char** argv) {
  using namespace bccmis::cli;
  const std::variant<int, Command> parsed = parse_command_line(argc, argv);
  if (const int* exit_code = std::get_if<int>(&parsed)) return *exit_code;
  return guarded("bccmis", [&] {
    const int code = std::visit([](const auto& options) { return run(options); }, std::get<Command>(parsed));
    flush_stdout();
    return code;
  });
}
