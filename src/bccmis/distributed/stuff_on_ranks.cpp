// spec/distributed.md D1-D13: the stages of one bccmis-mpi stuff run on
// every rank, each ending with the ranks' agreement (D6).
#include "bccmis/distributed/stuff_on_ranks.h"

#include <p8est.h>

#include <cmath>
#include <cstddef>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/distributed/gathered.h"
#include "bccmis/distributed/rank_memory.h"
#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/stuff/memory_estimate.h"

namespace bccmis::distributed {

RankRun stuff_on_ranks(const stuff::Shape& world, const RankSettings& s, MPI_Comm comm,
                       stuff::Clock::time_point start) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // D16: without a limit, a rank may take its node's memory available over the ranks sharing the node.
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
  int on_node = 1;
  MPI_Comm_size(node, &on_node);
  MPI_Comm_free(&node);
  // S24, S2: the fit every rank makes alike; D16: each rank's estimate against its limit.
  std::optional<Replicated> lattice;
  on_every_rank(comm, "fitting the lattice", [&] {
    lattice.emplace(fitted(world, s.lattice, P8EST_QMAXLEVEL));
    std::optional<double> limit = s.memory_limit;
    if (!limit)
      if (const auto available = stuff::available_memory()) limit = *available / on_node;
    const RankRole role{rank, size, s.gather || s.features.on || s.check || s.hausdorff,
                        s.features.on && s.features.crease_cuts > 0};
    if (limit) refuse_what_will_not_fit_on_rank(*lattice->shape, lattice->options, *limit, role);
  });
  const double input = stuff::seconds_since(start);
  const auto t = stuff::Clock::now();
  // D10: the partitioned forest.
  std::unique_ptr<Forest> forest;
  on_every_rank(comm, "building the forest",
                [&] { forest = std::make_unique<Forest>(*lattice->shape, lattice->fit, lattice->options, comm); });
  RankRun run = stuff_on_ranks(world, *lattice, *forest, s, comm, t);
  run.seconds.insert(run.seconds.begin(), std::pair<std::string, double>("input", input));
  return run;
}

RankRun stuff_on_ranks(const stuff::Shape& world, Replicated& lattice, Forest& forest, const RankSettings& s,
                       MPI_Comm comm, stuff::Clock::time_point start) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  RankRun run;
  // D12: the features, --check and --hausdorff run on the whole mesh, gathered in local coordinates.
  const bool whole = s.features.on || s.check || s.hausdorff;
  auto t = start;
  const auto phase = [&](const char* name) {
    run.seconds.emplace_back(name, stuff::seconds_since(t));
    t = stuff::Clock::now();
  };
  phase("forest");
  // D10: this rank's piece on its own lattice.
  stuff::StuffQuality quality;  // D11: the piece's, in local coordinates
  on_every_rank(comm, "stuffing its piece",
                [&] { run.piece = stuff_own_piece(lattice, forest, comm, s.statistics ? &quality : nullptr, !whole); });
  phase("pieces");
  const std::int64_t leaves = forest.global_leaves();
  // D7: the pieces' global vertex numbers.
  std::vector<std::uint8_t> owned;
  on_every_rank(comm, "numbering the vertices", [&] {
    if (s.pieces || s.statistics) run.ids = global_ids(run.piece, comm, &owned);
  });
  // Every rank's tetrahedra; an empty mesh refused on their sum (S21, S26).
  const std::uint64_t mine = run.piece.mesh.tets.size();
  run.tetrahedra.resize(static_cast<std::size_t>(size));
  MPI_Allgather(&mine, 1, MPI_UINT64_T, run.tetrahedra.data(), 1, MPI_UINT64_T, comm);
  std::uint64_t tetrahedra = 0;
  for (const std::uint64_t n : run.tetrahedra) tetrahedra += n;
  on_every_rank(comm, "counting the tetrahedra", [&] {
    if (rank == 0 && tetrahedra == 0) {
      stuff::Fit fit = lattice.fit;
      fit.h = std::ldexp(fit.h, lattice.normalisation.exponent);
      throw stuff::ShapeError(s.empty_message ? *s.empty_message : stuff::empty_mesh_message(world, fit));
    }
  });
  // D11: S13's statistics reduced on rank 0 (a lost component refused, S27).
  on_every_rank(comm, "reducing the statistics", [&] {
    if (s.statistics) run.report = rank_statistics(world, lattice, run.piece, quality, run.ids, owned, leaves, comm);
  });
  run.warned = s.statistics;
  phase("statistics");
  run.since = t;
  // D5: the pieces on rank 0; D12, D13: the whole mesh finished there.
  std::vector<std::vector<std::byte>> bytes;
  on_every_rank(comm, "gathering the pieces", [&] {
    if (s.gather || whole) bytes = gather_bytes(to_bytes(run.piece), 0, comm);
  });
  on_every_rank(comm, "finishing the gathered mesh", [&] {
    if (rank != 0 || !(s.gather || whole)) return;
    std::vector<LeafPiece> all;
    for (const auto& b : bytes) all.push_back(from_bytes(b));
    run.mesh = gather_pieces(all);
    all = {};
    bytes = {};  // the whole mesh alone on rank 0 from here (D12's memory)
    if (!whole) {
      run.regions = io::regions_of(run.mesh.tets, &run.boundary);
      return;
    }
    // D13: rank 0's statistics of the whole mesh with the features or the distance.
    const bool own = s.statistics && (s.features.on || s.hausdorff);
    Finished f = finish_gathered(world, lattice, run.mesh, s.features, s.check, own, s.hausdorff);
    run.regions = std::move(f.regions);
    run.boundary = std::move(f.boundary);
    run.report.topology = f.topology;
    run.report.warnings = std::move(f.warnings);
    if (f.statistics) {
      run.report.statistics = f.statistics;
      run.report.features = f.features;
      if (f.cut_points) run.report.stuffed.cut_points = *f.cut_points;  // D16: B's or C's, as the serial run counts
    }
    run.warned = true;
  });
  return run;
}

}  // namespace bccmis::distributed
