// bccmis-mpi: `mpirun -n P bccmis-mpi stuff ...`, isosurface stuffing with
// its leaves split among MPI ranks (spec/distributed.md). main starts MPI
// (through the p4est bridge's Session), parses the options of `bccmis stuff`
// (the same option code, stuff_command_line.h) plus --gather, and runs
// stuff.cpp. Exit codes as bccmis's (spec/cli.md), the same on every rank.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

#include "bccmis/p4est/bridge.h"
#include "io.h"
#include "stuff_command_line.h"
#include "stuff_mpi.h"

int main(int argc, char** argv) {
  using namespace bccmis::cli;
  const bccmis::p4est_bridge::Session session(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  CLI::App app{
      "bccmis-mpi: tetrahedral meshes of shapes by isosurface stuffing, the leaves split among MPI ranks "
      "(spec/distributed.md). Run under mpirun -n P."};
  app.require_subcommand(1);
  StuffOptions o;
  bool gather = false;
  CLI::App* cmd = add_stuff(app, o);
  cmd->add_flag("--gather", gather,
                "Gather the mesh on rank 0 and write one file (.vtu, .msh, .mesh), the bytes bccmis stuff writes; "
                "a triangle mesh's features and --check run there and need it; "
                "without it, -o names a .pvtu and every rank writes its .vtu piece beside it");
  double threshold = 0;
  CLI::Option* repartition =
      cmd->add_option("--repartition-threshold", threshold,
                      "With --animate: repartition the forest after a frame's step when the largest rank's leaf "
                      "count exceeds T times the mean (T >= 1; default 1.1; spec/distributed.md D15)")
          ->type_name("T")
          ->check([](const std::string& value) -> std::string {
            char* end = nullptr;
            const double t = std::strtod(value.c_str(), &end);
            if (end == value.c_str() || *end != '\0' || !std::isfinite(t) || t < 1)
              return "'" + value + "' is not a finite number >= 1 (spec/distributed.md D15)";
            return {};
          });
  cmd->footer("Example:\n  mpirun -n 2 bccmis-mpi stuff --shape torus -L 4 -o torus.pvtu");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = e.get_exit_code() == 0 ? kExitOk : kExitInput;
    if (rank == 0) {
      if (code == kExitOk) return app.exit(e);
      std::cerr << "bccmis-mpi: " << e.what() << "\nRun 'bccmis-mpi stuff --help' for usage.\n";
    }
    return code;
  }
  if (const std::string why = finish_stuff_options(*cmd, o); !why.empty()) {
    if (rank == 0) std::cerr << "bccmis-mpi: " << why << "\nRun 'bccmis-mpi stuff --help' for usage.\n";
    return kExitInput;
  }
  return run_mpi(o, gather, repartition->count() > 0 ? std::optional<double>(threshold) : std::nullopt, MPI_COMM_WORLD);
}
