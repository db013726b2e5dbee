// bccmis-mpi stuff: one run on every rank (spec/distributed.md D1, D6).
#pragma once

#include <mpi.h>

#include <optional>

#include "commands.h"

namespace bccmis::cli {

/// The run on this rank, collective over `comm`: the exit code, the same on
/// every rank (D6). `threshold`: --repartition-threshold when given (D15,
/// with --animate only).
int run_mpi(const StuffOptions& o, bool gather, std::optional<double> threshold, MPI_Comm comm);

}  // namespace bccmis::cli
