// bccmis stuff INPUT|--shape NAME -o FILE...: a tetrahedral mesh of a closed
// shape by isosurface stuffing (spec/stuffing.md), written as .vtu, .msh or
// .mesh (the tetrahedra) and .off or .obj (the boundary surface), with
// --stats for counts, volume and dihedral angles (--hausdorff: also the
// sampled Hausdorff distance). The
// library does the work (bccmis/stuff/mesh_shape.h, animate_shape.h); this
// file parses, calls and prints.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "bccmis/io/pvd.h"
#include "bccmis/io/vtu.h"
#include "bccmis/json_writer.h"
#include "bccmis/stuff/animate_shape.h"
#include "bccmis/stuff/mesh_shape.h"
#include "bccmis/stuff/statistics_json.h"
#include "commands.h"
#include "io.h"
#include "stuff_input.h"
#include "stuff_stats.h"

namespace bccmis::cli {

namespace {

using stuff::Vec3;

bool is_surface_path(const std::string& path) { return ends_with(path, ".off") || ends_with(path, ".obj"); }

void check_stuff_path(const std::string& path) {
  if (path == "-") throw InputError("output '-': a mesh is written to a file whose extension names the format");
  if (!is_surface_path(path) && !ends_with(path, ".vtu") && !ends_with(path, ".msh") && !ends_with(path, ".mesh"))
    throw InputError("output '" + path +
                     "': unknown format; the extension names it: .vtu, .msh, .mesh (tetrahedra), .off, .obj "
                     "(boundary surface)");
}

std::string number(double x) { return JsonWriter::number(x); }

/// The library's progress lines on stderr, unless --quiet.
stuff::Progress progress_of(const StuffOptions& o) {
  if (o.quiet) return {};
  return [](std::string_view what) { std::cerr << "bccmis stuff: " << what << std::endl; };
}

/// --animate N -o OUT.pvd: frames 0..N (frame 0 the shape where it is),
/// written as OUT_0000.vtu ... beside the .pvd (spec/stuffing.md S15).
int run_animate(const StuffOptions& o, const std::shared_ptr<const stuff::Shape>& shape, stuff::StuffOptions so,
                OutputSet& outputs) {
  if (o.outputs.size() > 1 || (!o.outputs.empty() && !ends_with(o.outputs[0], ".pvd")))
    throw InputError("--animate writes one .pvd (ParaView's index) with its .vtu frames beside it: give -o FILE.pvd");
  if (o.outputs.empty() && !o.stats) throw InputError("nothing to do: give -o FILE.pvd or --stats");
  if (o.hausdorff) throw InputError("--hausdorff applies without --animate (a frame's statistics have no distance)");
  // spec/cli.md: what a moving shape does not take is refused, not ignored.
  if (o.features || o.feature_angle >= 0 || o.crease_cuts > 0)
    throw InputError("--features, --feature-angle and --crease-cuts apply without --animate");
  if (o.memory_limit_gb > 0)
    throw InputError(
        "--memory-limit applies without --animate (spec/stuffing.md S25 estimates one lattice, not a moving one)");
  if (o.impl != "fast")
    throw InputError("--impl " + o.impl + " applies without --animate (a step moves the fast lattice, S15)");
  stuff::AnimateSettings settings;
  settings.lattice = so;
  settings.frames = o.animate;
  settings.path = parse_path(o.path, *shape);
  settings.compare = o.compare;
  settings.check = o.check;
  const std::string pvd = o.outputs.empty() ? "" : o.outputs[0];
  const std::string stem = pvd.substr(0, pvd.size() - 4);
  const std::string base = stem.substr(stem.find_last_of('/') + 1);
  // The .pvd's temporary before the first frame is made (its directory is
  // the frames'); each frame's as the frame is written (spec/cli.md).
  outputs.open(pvd);
  std::vector<std::pair<int, std::string>> frames;  // the .pvd index: timestep, file
  JsonWriter json;
  json.begin_object().key("frames").begin_array();
  std::string table =
      "frame refines coarsens leaves restuffed_leaves restuffed_tetrahedra tetrahedra lattice_s stuff_s" +
      std::string(o.compare ? " scratch_s" : "") + "\n";
  const auto on_frame = [&](const stuff::Frame& f) {
    const int k = f.index;
    const stuff::FrameReport& r = f.report;
    const d3::TetMeshF& mesh = *f.mesh;
    if (!pvd.empty()) {
      outputs.add(numbered(stem, k, ".vtu"), [&](std::ostream& out) { io::write_vtu(out, mesh, encoding(o)); });
      frames.emplace_back(k, numbered(base, k, ".vtu"));
    }
    json.begin_object()
        .member("frame", k)
        .member("refines", r.refines)
        .member("coarsens", r.coarsens)
        .member("leaves", r.leaves)
        .member("restuffed_leaves", r.restuffed_leaves)
        .member("restuffed_tetrahedra", r.restuffed_tetrahedra)
        .member("tetrahedra", mesh.tets.size())
        .member("lattice_seconds", r.lattice_seconds)
        .member("stuff_seconds", r.stuff_seconds);
    if (o.compare) json.member("scratch_seconds", f.scratch_seconds);
    json.end_object();
    table += std::to_string(k) + " " + std::to_string(r.refines) + " " + std::to_string(r.coarsens) + " " +
             std::to_string(r.leaves) + " " + std::to_string(r.restuffed_leaves) + " " +
             std::to_string(r.restuffed_tetrahedra) + " " + std::to_string(mesh.tets.size()) + " " +
             number(r.lattice_seconds) + " " + number(r.stuff_seconds) +
             (o.compare ? " " + number(f.scratch_seconds) : "") + "\n";
    if (!o.quiet)
      std::cerr << "bccmis stuff: frame " << k << "/" << o.animate << ": " << r.refines << " refines, " << r.coarsens
                << " coarsens, " << mesh.tets.size() << " tetrahedra\n";
  };
  stuff::AnimationSummary summary;
  try {
    summary = stuff::animate_shape(shape, settings, on_frame, progress_of(o));
  } catch (const stuff::ShapeError& e) {  // S2, S14, S16: refused before any frame is made
    throw InputError(e.what());
  } catch (const stuff::CheckError& e) {
    throw CheckFailure(e.what());
  }
  if (!pvd.empty()) outputs.add(pvd, [&](std::ostream& out) { io::write_pvd(out, frames); });
  json.end_array().member("mean_step_seconds", summary.mean_step_seconds).member("operations", summary.operations);
  table += "mean_step_seconds " + number(summary.mean_step_seconds) + "\noperations " +
           std::to_string(summary.operations) + "\n";
  if (o.compare) {
    json.member("mean_scratch_seconds", summary.mean_scratch_seconds).member("speedup", summary.speedup());
    table += "mean_scratch_seconds " + number(summary.mean_scratch_seconds) + "\nspeedup " + number(summary.speedup()) +
             "\n";
  }
  json.end_object();
  if (o.stats) outputs.add("-", o.json ? json.str() + "\n" : table);
  outputs.commit();
  return kExitOk;
}

}  // namespace

int run(const StuffOptions& o) {
  if (o.animate == 0) {
    for (const std::string& path : o.outputs) check_stuff_path(path);
    if (o.outputs.empty() && !o.stats)
      throw InputError("nothing to do: give -o FILE (.vtu, .msh, .mesh, .off, .obj) or --stats");
  }
  // The outputs' temporaries are created before the work (spec/cli.md).
  OutputSet outputs;
  if (o.animate == 0)
    for (const std::string& path : o.outputs) outputs.open(path);
  const auto t0 = stuff::Clock::now();
  std::shared_ptr<const stuff::Shape> shape;
  try {
    shape = load_shape(o);
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  }
  stuff::PhaseSeconds seconds{{"input", stuff::seconds_since(t0)}};
  if (!o.stats && !o.quiet) std::cerr << soup_notices("bccmis stuff", *shape);  // S21, S22
  stuff::Settings settings;
  settings.lattice = lattice_options(o);
  if (o.animate > 0) return run_animate(o, shape, settings.lattice, outputs);
  if (!o.path.empty() || o.compare) throw InputError("--path and --compare apply with --animate");
  settings.impl = o.impl == "reference" ? stuff::Impl::reference : stuff::Impl::fast;
  settings.statistics = o.stats;
  settings.hausdorff = o.hausdorff;
  settings.check = o.check;
  settings.strict = o.strict;
  settings.features.on = o.features_on();
  settings.features.crease_cuts = o.crease_cuts;
  if (o.feature_angle >= 0) settings.features.angle = o.feature_angle;
  if (o.memory_limit_gb > 0) settings.memory_limit = o.memory_limit_gb * 1e9;
  // The outputs are written while the statistics are computed (S13a).
  settings.write = [&](const stuff::Meshed& r) { add_mesh_outputs(outputs, o, r.stuffed.mesh, r.regions, r.boundary); };
  stuff::Meshed m;
  try {
    m = stuff::mesh_shape(*shape, settings, progress_of(o));
  } catch (const stuff::ShapeError& e) {
    throw InputError(e.what());
  } catch (const stuff::CheckError& e) {
    throw CheckFailure(e.what());
  }
  seconds.insert(seconds.end(), m.seconds.begin(), m.seconds.end());
  if (!o.quiet)
    for (const std::string& warning : m.warnings) std::cerr << "bccmis stuff: warning: " << warning << "\n";

  const d3::TetMeshF& mesh = m.stuffed.mesh;
  if (o.stats) outputs.add("-", stats_text(shape->describe(), m, seconds, o.json));
  outputs.commit();
  if (!o.quiet && !o.outputs.empty())
    std::cerr << "bccmis stuff: " << mesh.vertices.size() << " vertices, " << mesh.tets.size()
              << " tetrahedra written to " << o.outputs.size() << " file" << (o.outputs.size() == 1 ? "" : "s") << "\n";
  return kExitOk;
}

}  // namespace bccmis::cli
