// bccmis-mpi stuff: the stages of one run on every rank and the agreement
// after each (spec/distributed.md D6); the library does the work
// (bccmis/distributed/): the fit, the partitioned forest and each rank's
// lattice (D2, D10), the pieces (D3, D4), their gathering (D5), the
// features and --check on the gathered mesh (D12) and its statistics and
// warnings (D13).
#include "stuff_mpi.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bccmis/distributed/gathered.h"
#include "bccmis/distributed/leaf_piece.h"
#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/replicated.h"
#include "bccmis/io/pvtu.h"
#include "bccmis/io/regions.h"
#include "bccmis/io/vtu.h"
#include "bccmis/p4est/bridge.h"
#include "bccmis/stuff/mesh_shape.h"
#include "io.h"
#include "stuff_input.h"
#include "stuff_stats.h"

namespace bccmis::cli {

namespace {

constexpr const char* kTool = "bccmis-mpi stuff";

/// Ends the run on every rank with the agreed exit code.
struct Stop {
  int code;
};

/// D6: runs `body` on this rank (a failure prints one line, naming the
/// rank; a collective step that failed on another rank, RankFailed, is that
/// rank's to report), then the ranks agree; throws Stop on every rank when
/// one failed.
template <class Body>
void stage(MPI_Comm comm, Body&& body) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::string tool = std::string(kTool) + ": rank " + std::to_string(rank);
  const int code = guarded(tool.c_str(), [&] {
    try {
      body();
    } catch (const distributed::RankFailed&) {
      return kExitOk;  // the failing rank reports, and the agreement gives its code
    } catch (const stuff::ShapeError& e) {
      throw InputError(e.what());
    } catch (const stuff::CheckError& e) {
      throw CheckFailure(e.what());
    }
    return kExitOk;
  });
  const distributed::Agreement a = distributed::agree(code, comm);
  if (!a.ok()) throw Stop{a.code};
}

/// D1: the options this slice does not split yet, the ones that need the
/// gathered mesh (D12), and the one output (or none, with --stats).
void check_options(const StuffOptions& o, bool gather) {
  const auto refuse = [](const std::string& what) {
    throw InputError(what + " is not supported on several ranks yet (spec/distributed.md D1)");
  };
  if (o.hausdorff) refuse("--hausdorff");
  if (o.animate > 0 || !o.path.empty() || o.compare) refuse("--animate");
  if (o.impl != "fast") refuse("--impl " + o.impl);
  if (o.memory_limit_gb > 0) refuse("--memory-limit");
  if (o.crease_cuts > 0) refuse("--crease-cuts");  // S35.7 places cut points inside each piece's stuffing
  const bool features = o.features_on();
  if ((features || o.check) && !gather)
    throw InputError(
        std::string(features ? "the features of a triangle-mesh INPUT (on by default, S29-S35)" : "--check") +
        " run on the mesh gathered on rank 0: add --gather" + (features ? ", or --no-features" : "") +
        " (spec/distributed.md D12)");
  if (o.outputs.empty() && o.stats) return;  // D11: the statistics alone
  if (o.outputs.size() != 1)
    throw InputError("give one output: -o FILE.pvtu (a piece per rank), or --gather -o FILE (.vtu, .msh, .mesh)");
  const std::string& path = o.outputs[0];
  if (gather && !ends_with(path, ".vtu") && !ends_with(path, ".msh") && !ends_with(path, ".mesh"))
    throw InputError("output '" + path + "': --gather writes .vtu, .msh or .mesh");
  if (!gather && !ends_with(path, ".pvtu"))
    throw InputError("output '" + path + "': without --gather the output is a .pvtu (its pieces beside it)");
}

/// The piece of rank r beside FILE.pvtu: FILE_RRRR.vtu.
std::string piece_path(const std::string& pvtu, int r) {
  char suffix[24];
  std::snprintf(suffix, sizeof suffix, "_%04d.vtu", r);
  return pvtu.substr(0, pvtu.size() - 5) + suffix;
}

std::string file_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

}  // namespace

int run_mpi(const StuffOptions& o, bool gather, MPI_Comm comm) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  OutputSet pieces, index;  // index: rank 0's .pvtu or --gather file, renamed last
  std::shared_ptr<const stuff::Shape> shape;
  std::optional<distributed::Replicated> lattice;
  distributed::LeafPiece piece;
  const std::string& out = o.outputs.empty() ? std::string() : o.outputs[0];
  const bool write = !o.outputs.empty();  // else --stats alone (D11)
  // D12: the features and --check run on the whole mesh, gathered in local
  // coordinates (check_options: only with --gather).
  const bool whole = o.features_on() || o.check;
  stuff::PhaseSeconds seconds;  // D11: rank 0's wall seconds of the stages
  auto t = stuff::Clock::now();
  const auto phase = [&](const char* name) {
    seconds.emplace_back(name, stuff::seconds_since(t));
    t = stuff::Clock::now();
  };
  try {
    // (1) the options, the outputs' temporaries, the shape, the lattice.
    stage(comm, [&] {
      check_options(o, gather);
      if (write && !gather) pieces.open(piece_path(out, rank));
      if (write && rank == 0) index.open(out);
      shape = load_shape(o);
      stuff::StuffOptions so;
      so.max_level = o.max_level;
      so.min_level = o.min_level;
      so.cells = o.cells;
      if (o.size > 0) so.size = o.size;
      so.threads = o.threads;
      lattice.emplace(distributed::fitted(*shape, so, P8EST_QMAXLEVEL));
    });
    phase("input");
    // (2) the partitioned forest (D10), then this rank's piece on its own
    // lattice (the library widens the ghost layers while some rank's leaves
    // reach beyond the leaves it knows).
    std::unique_ptr<distributed::Forest> forest;
    stage(comm, [&] {
      forest = std::make_unique<distributed::Forest>(*lattice->shape, lattice->fit, lattice->options, comm);
    });
    phase("forest");
    stuff::StuffQuality quality;  // D11: the piece's, in local coordinates
    stage(comm,
          [&] { piece = distributed::stuff_own_piece(*lattice, *forest, comm, o.stats ? &quality : nullptr, !whole); });
    phase("pieces");
    const std::int64_t leaves = forest->global_leaves();
    forest.reset();
    // D7: the pieces' global vertex numbers (collective on every rank).
    std::vector<std::int64_t> ids;
    std::vector<std::uint8_t> owned;
    stage(comm, [&] {
      if ((write && !gather) || o.stats) ids = distributed::global_ids(piece, comm, &owned);
    });
    // (3) the outputs, into their temporaries.
    // Every rank's tetrahedra: a rank whose leaves make none writes no piece (D1).
    const std::uint64_t mine = piece.mesh.tets.size();
    std::vector<std::uint64_t> counts(static_cast<std::size_t>(size));
    MPI_Allgather(&mine, 1, MPI_UINT64_T, counts.data(), 1, MPI_UINT64_T, comm);
    std::uint64_t tetrahedra = 0, vertices = 0;
    for (const std::uint64_t n : counts) tetrahedra += n;
    stage(comm, [&] {
      if (rank == 0 && tetrahedra == 0) {  // S21 or S26, as bccmis stuff
        stuff::Fit world = lattice->fit;
        world.h = std::ldexp(world.h, lattice->normalisation.exponent);
        throw InputError(stuff::empty_mesh_message(*shape, world));
      }
    });
    // D11: S13's statistics reduced on rank 0 (a lost component refused, S27).
    stuff::Meshed meshed;
    bool warned = o.stats;  // D13: rank 0 holds S27's comparison and its warnings
    stage(comm, [&] {
      if (o.stats) meshed = distributed::rank_statistics(*shape, *lattice, piece, quality, ids, owned, leaves, comm);
    });
    phase("statistics");
    std::vector<std::vector<std::byte>> bytes;
    d3::TetMeshF mesh;  // --gather: the whole mesh on rank 0, until it is written
    io::Regions regions;
    stage(comm, [&] {
      if ((write && gather) || whole) bytes = distributed::gather_bytes(distributed::to_bytes(piece), 0, comm);
    });
    stage(comm, [&] {
      if (!write && !whole) return;
      if (!gather) {
        if (mine > 0)
          pieces.add(piece_path(out, rank),
                     [&](std::ostream& s) { io::write_vtu_piece(s, piece.mesh, ids, encoding(o)); });
        if (rank == 0) {
          std::vector<std::string> names;
          for (int r = 0; r < size; ++r)
            if (counts[static_cast<std::size_t>(r)] > 0) names.push_back(file_name(piece_path(out, r)));
          index.add(out, [&](std::ostream& s) { io::write_pvtu(s, names); });
        }
      } else if (rank == 0) {
        std::vector<distributed::LeafPiece> all;
        for (const auto& b : bytes) all.push_back(distributed::from_bytes(b));
        mesh = distributed::gather_pieces(all);
        all = {};
        bytes = {};  // the whole mesh alone on rank 0 from here (D12's memory)
        // D12: the feature step and --check, then S24's map (the pieces stayed local);
        // D13: S27's warnings and, with the features, the statistics of the conformed mesh.
        if (whole) {
          stuff::FeatureSettings features;
          features.on = o.features_on();
          if (o.feature_angle >= 0) features.angle = o.feature_angle;
          distributed::Finished f =
              distributed::finish_gathered(*shape, *lattice, mesh, features, o.check, o.stats && features.on);
          regions = std::move(f.regions);
          meshed.topology = f.topology;
          meshed.warnings = std::move(f.warnings);
          if (f.statistics) {
            meshed.statistics = f.statistics;
            meshed.features = f.features;
          }
          warned = true;
        } else {
          regions = io::regions_of(mesh.tets);
        }
        vertices = mesh.vertices.size();
        if (write) add_tetrahedra_output(index, out, mesh, regions, encoding(o));
      }
    });
    // (4) the pieces renamed into place on every rank, then the index.
    stage(comm, [&] {
      if (mine > 0) pieces.commit();  // an empty piece's temporary goes with `pieces`
    });
    stage(comm, [&] {
      if (rank == 0) index.commit();
    });
    phase("write");
    if (rank == 0 && warned && !o.quiet)  // D13, as bccmis stuff prints them
      for (const std::string& warning : meshed.warnings) std::cerr << kTool << ": warning: " << warning << "\n";
    if (rank == 0 && o.stats) std::cout << stats_text(shape->describe(), meshed, seconds, o.json) << std::flush;
    if (rank == 0 && !o.quiet && write)
      std::cerr << kTool << ": " << tetrahedra << " tetrahedra"
                << (gather ? ", " + std::to_string(vertices) + " vertices,"
                           : " in " +
                                 std::to_string(std::count_if(counts.begin(), counts.end(),
                                                              [](std::uint64_t n) { return n > 0; })) +
                                 " pieces")
                << " from " << size << " rank" << (size == 1 ? "" : "s") << " written to " << out << "\n";
  } catch (const Stop& stop) {
    return stop.code;
  }
  return kExitOk;
}

}  // namespace bccmis::cli
