// bccmis CLI: the command line (CLI11, in cli.cpp only: it is the one
// translation unit that includes <CLI/CLI.hpp>, to keep the build fast).
#pragma once

#include <variant>

#include "commands.h"

namespace bccmis::cli {

/// A subcommand with its options.
using Command = std::variant<ReplayOptions, CheckOptions, DiffOptions, StatsOptions, MeshOptions, StuffOptions,
                             RenderOptions, ViewCommandOptions, ConformanceCommandOptions, ExploreCommandOptions,
                             HeightfieldCommandOptions, AnimateCommandOptions>;

/// The subcommand and its options; or the exit code when the command line
/// itself was the whole run (--help and --version: 0; a usage error, reported
/// on stderr: 2).
std::variant<int, Command> parse_command_line(int argc, char** argv);

}  // namespace bccmis::cli
