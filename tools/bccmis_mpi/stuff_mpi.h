// bccmis-mpi stuff: one run on every rank (spec/distributed.md D1, D6).
#pragma once

#include <mpi.h>

#include "commands.h"

namespace bccmis::cli {

/// The run on this rank, collective over `comm`: the exit code, the same on
/// every rank (D6).
int run_mpi(const StuffOptions& o, bool gather, MPI_Comm comm);

}  // namespace bccmis::cli
