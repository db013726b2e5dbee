// The forest of a moving shape on MPI ranks (spec/distributed.md D15,
// bench/RESULTS.md section 44): for each frame k = 1 .. N of `bccmis-mpi
// stuff --animate N`, the CPU seconds (summed over the ranks) of D10's
// forest built from the brick for frame k, against D15's step that moves
// frame k - 1's forest there, with what the step did. Run under mpirun:
//   mpirun -n P forest_step_mpi SHAPE LEVEL FRAMES [THRESHOLD]
#include <mpi.h>
#include <p8est.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>

#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/repartition.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/p4est/bridge.h"
#include "bccmis/stuff/animate_shape.h"

namespace {

using namespace bccmis;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The CPU seconds of `body` on every rank, summed (on rank 0).
template <class Body>
double ranks_cpu(Body&& body) {
  const double start = cpu_seconds();
  body();
  double mine = cpu_seconds() - start, all = 0;
  MPI_Reduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  return all;
}

}  // namespace

int main(int argc, char** argv) {
  const p4est_bridge::Session session(&argc, &argv);
  if (argc < 4) {
    std::fprintf(stderr, "usage: mpirun -n P forest_step_mpi SHAPE LEVEL FRAMES [THRESHOLD]\n");
    return 2;
  }
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::shared_ptr<const stuff::Shape> world = stuff::make_builtin(argv[1]);
  stuff::StuffOptions options;
  options.max_level = std::atoi(argv[2]);
  const int frames = std::atoi(argv[3]);
  const double threshold = argc > 4 ? std::atof(argv[4]) : distributed::kRepartitionThreshold;
  const stuff::Vec3 path = stuff::default_path(*world);
  const stuff::Fit fit = stuff::fit_moving(*world, path, options);
  const auto frame = [&](int k) {
    return distributed::in_world(stuff::translated(world, stuff::frame_offset(path, k, frames)), fit, options,
                                 P8EST_QMAXLEVEL);
  };
  distributed::Replicated first = frame(0);
  distributed::Forest kept(*first.shape, first.fit, first.options, MPI_COMM_WORLD);
  if (rank == 0) {
    std::printf(
        "| frame | leaves | forest from the brick, CPU s | D15's step, CPU s | coarsened | refined | "
        "corrections | imbalance | repartitioned |\n|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  }
  for (int k = 1; k <= frames; ++k) {
    const distributed::Replicated r = frame(k);
    const double scratch =
        ranks_cpu([&] { const distributed::Forest built(*r.shape, r.fit, r.options, MPI_COMM_WORLD); });
    distributed::ForestStep step;
    const double moved = ranks_cpu([&] { step = kept.move_to(*r.shape, r.fit, r.options, threshold); });
    if (rank == 0)
      std::printf("| %d | %lld | %.3f | %.3f | %lld | %lld | %d | %.3f | %s |\n", k,
                  static_cast<long long>(kept.global_leaves()), scratch, moved, static_cast<long long>(step.coarsened),
                  static_cast<long long>(step.refined), step.corrections, step.imbalance,
                  step.repartitioned ? "yes" : "no");
  }
  return 0;
}
