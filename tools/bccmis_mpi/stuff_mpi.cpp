// bccmis-mpi stuff: the options checked, the shape read, the run on every
// rank as one library call (distributed::stuff_on_ranks, spec/distributed.md
// D1-D13; distributed::animate_on_ranks with --animate, D14, D15, D17), the outputs written and the report printed, the
// ranks agreeing after each stage (D6).
#include "stuff_mpi.h"

#include <algorithm>
#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "animate_report.h"
#include "bccmis/distributed/animate_on_ranks.h"
#include "bccmis/distributed/ranks.h"
#include "bccmis/distributed/stuff_on_ranks.h"
#include "bccmis/io/pvd.h"
#include "bccmis/io/pvtu.h"
#include "bccmis/io/vtu.h"
#include "bccmis/p4est/bridge.h"
#include "bccmis/stuff/animate_shape.h"
#include "bccmis/stuff/mesh_shape.h"
#include "io.h"
#include "staging_directory.h"
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

/// D1: the option this slice does not split yet, the ones that need the
/// gathered mesh (D12: the features, --check, --hausdorff), and the one output (or none, with --stats).
void check_options(const StuffOptions& o, bool gather, bool threshold) {
  const auto refuse = [](const std::string& what) {
    throw InputError(what + " is not supported on several ranks yet (spec/distributed.md D1)");
  };
  if (!o.path.empty() || o.compare) throw InputError("--path and --compare apply with --animate");
  if (threshold) throw InputError("--repartition-threshold applies with --animate (spec/distributed.md D15)");
  if (o.impl != "fast") refuse("--impl " + o.impl);
  const bool features = o.features_on();
  if ((features || o.check || o.hausdorff) && !gather)
    throw InputError(std::string(features  ? "the features of a triangle-mesh INPUT (on by default, S29-S35)"
                                 : o.check ? "--check"
                                           : "--hausdorff") +
                     " run on the mesh gathered on rank 0: add --gather" + (features ? ", or --no-features" : "") +
                     " (spec/distributed.md D12)");
  if (o.outputs.empty() && o.stats) return;  // D11: the statistics alone
  if (gather && !o.outputs.empty()) {        // D1: the whole mesh on rank 0, as bccmis stuff writes it
    for (const std::string& path : o.outputs)
      if (!ends_with(path, ".vtu") && !ends_with(path, ".msh") && !ends_with(path, ".mesh") &&
          !ends_with(path, ".off") && !ends_with(path, ".obj"))
        throw InputError("output '" + path + "': --gather writes .vtu, .msh, .mesh, .off or .obj");
    return;
  }
  if (o.outputs.size() != 1)
    throw InputError(
        "give one output: -o FILE.pvtu (a piece per rank), or --gather -o FILE (.vtu, .msh, .mesh, "
        ".off, .obj; several)");
  const std::string& path = o.outputs[0];
  if (!gather && !ends_with(path, ".pvtu"))
    throw InputError("output '" + path + "': without --gather the output is a .pvtu (its pieces beside it)");
}

/// The piece of rank r beside FILE.pvtu: FILE_RRRR.vtu.
std::string piece_path(const std::string& pvtu, int r) { return numbered(pvtu.substr(0, pvtu.size() - 5), r, ".vtu"); }

std::string file_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

/// D14: what --animate on ranks refuses, and its one output (none with
/// --stats alone, D17).
void check_animate_options(const StuffOptions& o, bool gather) {
  const auto refuse = [](const std::string& what) {
    throw InputError(what + " is not supported with --animate on several ranks (spec/distributed.md D14)");
  };
  if (o.hausdorff) refuse("--hausdorff");
  if (o.features || o.feature_angle >= 0 || o.crease_cuts > 0) refuse("the features");
  if (o.impl != "fast") refuse("--impl " + o.impl);
  if (o.memory_limit_gb > 0) refuse("--memory-limit");  // the serial animation does not estimate (S25) either
  if (o.check && !gather)                               // D17: D12's check of each gathered frame
    throw InputError("--check runs on the mesh gathered on rank 0: add --gather (spec/distributed.md D12, D17)");
  if (o.outputs.empty() && o.stats) return;  // D17: the report alone
  const std::string extension = gather ? ".vtu" : ".pvtu";
  if (o.outputs.size() != 1 || !ends_with(o.outputs[0], extension))
    throw InputError(std::string("--animate writes a frame a file and their .pvd beside them: give ") +
                     (gather ? "--gather -o FILE.vtu (frames FILE_KKKK.vtu)"
                             : "-o FILE.pvtu (frames FILE_KKKK.pvtu, pieces FILE_KKKK_RRRR.vtu)") +
                     " (spec/distributed.md D14)");
}

/// D18: rank 0's staging directory's path on every rank.
std::string broadcast(std::string path, MPI_Comm comm) {
  unsigned long long length = path.size();
  MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, comm);
  path.resize(length);
  MPI_Bcast(path.data(), static_cast<int>(length), MPI_CHAR, 0, comm);
  return path;
}

/// D14: --animate N on every rank: every frame's files staged as its
/// meshes come, in D18's staging directory, renamed once every frame
/// succeeded on every rank (D6); D17's report printed by rank 0 after the
/// last frame.
int run_animate(const StuffOptions& o, bool gather, double threshold, MPI_Comm comm) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const bool write = !o.outputs.empty();  // else --stats alone (D17)
  const std::string out = write ? o.outputs[0] : std::string();
  const std::string stem = out.substr(0, out.find_last_of('.'));
  const std::string extension = gather ? ".vtu" : ".pvtu";
  const std::string pvd = stem + ".pvd";
  std::unique_ptr<StagingDirectory> staging;  // D18: removed after the temporaries it holds
  OutputSet pieces, index;  // index: rank 0's frames (.pvtu or --gather .vtu) and the .pvd, renamed last
  std::shared_ptr<const stuff::Shape> shape;
  distributed::RankAnimation settings;
  std::vector<std::pair<int, std::string>> frames;  // the .pvd index: timestep, file
  bool written = false;                             // this rank wrote a piece
  try {
    // D18: rank 0 removes what interrupted runs left, then makes the one
    // directory every rank stages its frames in.
    std::vector<std::string> stale;
    stage(comm, [&] {
      check_animate_options(o, gather);
      if (rank != 0 || !write) return;
      stale = clean_stale_staging(stem);
      staging = StagingDirectory::make(stem);
    });
    if (rank == 0 && !o.quiet)
      for (const std::string& line : stale) std::cerr << kTool << ": " << line << "\n";
    const std::string staged = write ? broadcast(staging ? staging->path() : std::string(), comm) : std::string();
    stage(comm, [&] {
      if (write && rank != 0) staging = StagingDirectory::adopt(staged);
      if (staging && !staging->warning().empty() && !o.quiet)  // D18: a lock not held, said by the rank
        std::cerr << kTool << ": rank " << rank << ": warning: " << staging->warning() << "\n";
      pieces.stage_in(staged);
      index.stage_in(staged);
      for (int k = 0; k <= o.animate && write; ++k) {
        if (!gather) pieces.open(piece_path(numbered(stem, k, extension), rank));
        if (rank == 0) index.open(numbered(stem, k, extension));
      }
      if (rank == 0 && write) index.open(pvd);
      shape = load_shape(o);
      settings.path = parse_path(o.path, *shape);
    });
    settings.lattice = lattice_options(o);
    settings.frames = o.animate;
    settings.pieces = write && !gather;
    settings.gather = gather;
    settings.check = o.check;
    settings.threshold = threshold;
    settings.compare = o.compare;
    AnimateReport report(o.compare);  // D17, rank 0's
    const auto on_frame = [&](const distributed::RankFrame& f) {
      const int k = f.index;
      distributed::RankRun& run = *f.run;
      const distributed::ForestStep& step = f.step;
      const std::string frame = numbered(stem, k, extension);
      const std::uint64_t mine = run.piece.mesh.tets.size();
      std::uint64_t tetrahedra = 0;
      for (const std::uint64_t n : run.tetrahedra) tetrahedra += n;
      if (rank == 0 && o.stats) report.add(f, tetrahedra);
      distributed::on_every_rank(comm, "writing frame " + std::to_string(k), [&] {
        if (!write) return;
        if (!gather && mine > 0) {  // a rank whose leaves make no tetrahedron writes no piece (D1)
          pieces.add(piece_path(frame, rank),
                     [&](std::ostream& s) { io::write_vtu_piece(s, run.piece.mesh, run.ids, encoding(o)); });
          written = true;
        }
        if (rank != 0) return;
        if (gather) {
          add_tetrahedra_output(index, frame, run.mesh, run.regions, encoding(o));
        } else {
          std::vector<std::string> names;
          for (int r = 0; r < size; ++r)
            if (run.tetrahedra[static_cast<std::size_t>(r)] > 0) names.push_back(file_name(piece_path(frame, r)));
          index.add(frame, [&](std::ostream& s) { io::write_pvtu(s, names); });
        }
        frames.emplace_back(k, file_name(frame));
      });
      if (rank == 0 && !o.quiet) {
        // S14's notice, in bccmis stuff --animate's words (the lattice fitted
        // on every rank before frame 0, so it does not throw here).
        if (k == 0)
          if (const auto notice = stuff::swept_box_notice(*shape, settings.path, settings.lattice))
            std::cerr << kTool << ": " << *notice << "\n";
        std::cerr << kTool << ": frame " << k << "/" << o.animate << ": " << tetrahedra << " tetrahedra";
        if (k > 0)  // D15: what the step did to the forest
          std::cerr << "; forest: " << step.coarsened << " coarsened, " << step.refined << " refined, "
                    << step.corrections << " corrections, imbalance " << step.imbalance
                    << (step.repartitioned ? ", repartitioned" : "");
        std::cerr << "\n";
      }
    };
    stage(comm, [&] { distributed::animate_on_ranks(shape, settings, comm, on_frame); });
    stage(comm, [&] {
      if (rank == 0 && write) index.add(pvd, [&](std::ostream& s) { io::write_pvd(s, frames); });
    });
    // The pieces renamed into place on every rank, then rank 0's files (D6).
    stage(comm, [&] {
      if (written) pieces.commit();
    });
    stage(comm, [&] {
      if (rank == 0) index.commit();
    });
    if (rank == 0 && o.stats) std::cout << report.finish(o.json) << std::flush;
    if (rank == 0 && !o.quiet && write)
      std::cerr << kTool << ": " << o.animate + 1 << " frames from " << size << " rank" << (size == 1 ? "" : "s")
                << " written to " << pvd << "\n";
  } catch (const Stop& stop) {
    return stop.code;
  }
  return kExitOk;
}

}  // namespace

int run_mpi(const StuffOptions& o, bool gather, std::optional<double> threshold, MPI_Comm comm) {
  int rank = 0, size = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (o.animate > 0) return run_animate(o, gather, threshold.value_or(distributed::kRepartitionThreshold), comm);
  OutputSet pieces, index;  // index: rank 0's .pvtu or --gather file, renamed last
  std::shared_ptr<const stuff::Shape> shape;
  const std::string& out = o.outputs.empty() ? std::string() : o.outputs[0];
  const bool write = !o.outputs.empty();  // else --stats alone (D11)
  const auto start = stuff::Clock::now();
  try {
    // (1) the options, the outputs' temporaries, the shape.
    stage(comm, [&] {
      check_options(o, gather, threshold.has_value());
      if (write && !gather) pieces.open(piece_path(out, rank));
      if (write && rank == 0)
        for (const std::string& path : o.outputs) index.open(path);
      shape = load_shape(o);
    });
    if (rank == 0 && !o.stats && !o.quiet) std::cerr << soup_notices(kTool, *shape);  // D1, as bccmis stuff
    // (2) the run on every rank (the library: D1-D13).
    distributed::RankSettings settings;
    settings.lattice = lattice_options(o);
    settings.features.on = o.features_on();
    if (o.feature_angle >= 0) settings.features.angle = o.feature_angle;
    settings.features.crease_cuts = o.crease_cuts;  // D16: S35.8 on rank 0 (features need --gather, D12)
    settings.check = o.check;
    settings.hausdorff = o.hausdorff;
    settings.statistics = o.stats;
    if (o.memory_limit_gb > 0) settings.memory_limit = o.memory_limit_gb * 1e9;  // D16: per rank
    settings.pieces = write && !gather;
    settings.gather = write && gather;
    distributed::RankRun run;
    stage(comm, [&] { run = distributed::stuff_on_ranks(*shape, settings, comm, start); });
    // (3) the outputs, into their temporaries.
    const std::uint64_t mine = run.piece.mesh.tets.size();
    std::uint64_t tetrahedra = 0;
    for (const std::uint64_t n : run.tetrahedra) tetrahedra += n;
    stage(comm, [&] {
      if (!write) return;
      if (!gather) {
        if (mine > 0)  // a rank whose leaves make no tetrahedron writes no piece (D1)
          pieces.add(piece_path(out, rank),
                     [&](std::ostream& s) { io::write_vtu_piece(s, run.piece.mesh, run.ids, encoding(o)); });
        if (rank == 0) {
          std::vector<std::string> names;
          for (int r = 0; r < size; ++r)
            if (run.tetrahedra[static_cast<std::size_t>(r)] > 0) names.push_back(file_name(piece_path(out, r)));
          index.add(out, [&](std::ostream& s) { io::write_pvtu(s, names); });
        }
      } else if (rank == 0) {
        add_mesh_outputs(index, o, run.mesh, run.regions, run.boundary);
      }
    });
    // (4) the pieces renamed into place on every rank, then the index.
    stage(comm, [&] {
      if (mine > 0) pieces.commit();  // an empty piece's temporary goes with `pieces`
    });
    stage(comm, [&] {
      if (rank == 0) index.commit();
    });
    stuff::PhaseSeconds seconds = run.seconds;  // D11: rank 0's wall seconds of the stages
    seconds.emplace_back("write", stuff::seconds_since(run.since));
    if (rank == 0 && run.warned && !o.quiet)  // D13, as bccmis stuff prints them
      for (const std::string& warning : run.report.warnings) std::cerr << kTool << ": warning: " << warning << "\n";
    if (rank == 0 && o.stats) std::cout << stats_text(shape->describe(), run.report, seconds, o.json) << std::flush;
    if (rank == 0 && !o.quiet && write)
      std::cerr << kTool << ": " << (gather ? run.mesh.tets.size() : tetrahedra)
                << " tetrahedra"  // gathered: after S35's splits and S35.8's choice
                << (gather ? ", " + std::to_string(run.mesh.vertices.size()) + " vertices,"
                           : " in " +
                                 std::to_string(std::count_if(run.tetrahedra.begin(), run.tetrahedra.end(),
                                                              [](std::uint64_t n) { return n > 0; })) +
                                 " pieces")
                << " from " << size << " rank" << (size == 1 ? "" : "s") << " written to "
                << (o.outputs.size() == 1 ? out : std::to_string(o.outputs.size()) + " files") << "\n";
  } catch (const Stop& stop) {
    return stop.code;
  }
  return kExitOk;
}

}  // namespace bccmis::cli
